// Drive-system projects to simulation models, and the scenarios (sim/src/drive_network.cc).
#include <gtest/gtest.h>
