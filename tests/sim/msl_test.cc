// msl.<Example>: every MSL reference example as an element network (tests/sim/msl/*.json,
// same instance names), simulated and compared with the Modelica reference result: each
// comparison signal within 2e-3 x its range (floor 1e-9), each mode switch within 1 ms.
#include <gtest/gtest.h>

#include "common/shared_reference.h"
#include "msl_compare.h"

namespace highlift::testing {
namespace {

void Check(const std::string& example) {
  HIGHLIFT_REQUIRE_SHARED(dir, "msl");
  const ExampleSpec* spec = nullptr;
  for (const auto& e : MslExamples())
    if (e.name == example) spec = &e;
  ASSERT_NE(spec, nullptr);
  const ExampleComparison c = CompareExample(example, dir, spec->csv, spec->informative);
  ASSERT_TRUE(c.report.ok()) << c.report.FullReport();
  ASSERT_FALSE(c.signals.empty());
  for (const auto& s : c.signals) {
    if (s.informative) continue;
    EXPECT_TRUE(s.passed) << example << ": " << s.name << " max error " << s.max_error << " at t = "
                          << s.at_time << " (tolerance " << s.tolerance << ") " << s.note;
  }
}

TEST(msl, First) { Check("First"); }
TEST(msl, Backlash) { Check("Backlash"); }
TEST(msl, Friction) { Check("Friction"); }
TEST(msl, CoupledClutches) { Check("CoupledClutches"); }
TEST(msl, LossyGearDemo1) { Check("LossyGearDemo1"); }
TEST(msl, LossyGearDemo2) { Check("LossyGearDemo2"); }
TEST(msl, TestBraking) { Check("TestBraking"); }

}  // namespace
}  // namespace highlift::testing
