// HighLift PDU, monitoring, sensors and tables (sim/src/drive_elements.cc).
#include <gtest/gtest.h>
