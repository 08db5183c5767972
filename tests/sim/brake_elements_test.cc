// HighLift brakes, torque limiters and friction laws (sim/src/brake_elements.cc).
#include <gtest/gtest.h>
