// HighLift gears and failure elements (sim/src/gear_elements.cc).
#include <gtest/gtest.h>
