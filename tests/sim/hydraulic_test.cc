// Hydraulic components and the hydraulic PDU (sim/src/hydraulic_elements.cc).
#include <gtest/gtest.h>
