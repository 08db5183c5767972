// Issue 26 item 6, converged envelopes: the campaign's envelope at the default tolerance (the
// project's settings.relative_tolerance) equals the envelope at rtol 1e-8 within 1 % for every
// component. This is the reduced-size CI check (the reduced model, one jam and one rupture of the
// A380-class example, the nominal point and 2 Sobol points); the full comparison (every jam and
// rupture, 16 samples, reduced and full model) is bench/campaign/envelope_tolerance.sh, its table
// in docs/validation.md, "Envelope against tolerance".
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "highlift/campaign/campaign.h"
#include "highlift/core/project_io.h"
#include "highlift/sim/drive_network.h"
#include "test_util.h"

namespace highlift::campaign {
namespace {

constexpr double kEnvelopeTolerance = 0.01;  // relative, issue 26 item 6
constexpr double kConvergedRtol = 1e-8;

// (testing::A380()'s string concatenation, inlined here, trips GCC 12's -Warray-bounds.)
const Project& Example() {
  static const Project project =
      LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "a380_class_flaps.json");
  return project;
}

CampaignSummary RunAt(const CampaignOptions& options, const std::string& name) {
  const Plan plan = MakePlan(Example(), options);
  ExecutionOptions e;
  e.directory = testing::Scratch(name);
  e.jobs = 2;
  RunCampaign(Example(), plan, e);
  CampaignSummary summary = LoadSummary(e.directory);
  std::filesystem::remove_all(e.directory);
  return summary;
}

TEST(EnvelopeTolerance, DefaultToleranceEnvelopeIsWithinOnePercentOfTheConvergedOne) {
  CampaignOptions o;
  o.case_patterns = {"jam_l3", "rupture_shaft_l0b"};
  o.samples = 2;
  o.model = sim::DriveResolution::kReduced;
  const CampaignSummary standard = RunAt(o, "envelope_default_rtol");
  o.relative_tolerance = kConvergedRtol;
  const CampaignSummary converged = RunAt(o, "envelope_rtol_1e-8");

  EXPECT_EQ(standard.relative_tolerance, Example().settings.relative_tolerance);
  EXPECT_EQ(converged.relative_tolerance, kConvergedRtol);
  for (const CampaignSummary* s : {&standard, &converged}) {
    EXPECT_TRUE(s->complete());
    EXPECT_EQ(s->failures, 0) << s->relative_tolerance;
    EXPECT_EQ(s->not_passive, 0) << s->relative_tolerance;
  }
  std::map<std::string, double> reference;
  for (const EnvelopeRow& e : converged.envelope) reference[e.component] = std::abs(e.torque);
  ASSERT_GT(reference.size(), 20u);
  ASSERT_EQ(standard.envelope.size(), reference.size());
  double worst = 0.0;
  std::string worst_component;
  for (const EnvelopeRow& e : standard.envelope) {
    ASSERT_TRUE(reference.count(e.component)) << e.component;
    const double r = reference.at(e.component);
    ASSERT_GT(r, 0.0) << e.component;
    const double difference = std::abs(std::abs(e.torque) - r) / r;
    EXPECT_LE(difference, kEnvelopeTolerance)
        << e.component << ": " << std::abs(e.torque) << " N*m at rtol " << standard.relative_tolerance << " against "
        << r << " N*m at rtol " << kConvergedRtol << " (" << e.case_name << ", " << e.sample_label << ")";
    if (difference > worst) worst = difference, worst_component = e.component;
  }
  RecordProperty("largest_relative_difference", std::to_string(worst) + " at " + worst_component);
}


// The full-model jam_l2 at Sobol point 13 (sample 14 of `--samples 16`) failed at the default
// tolerance with CV_CONV_FAILURE at t = 1.939 s, every brake of the left wing stuck: KLU refactored
// with a pivot order that had become singular, and CVODE retried smaller steps on the same pivots.
// It now re-pivots and runs, at the peak of the converged run.
TEST(EnvelopeTolerance, FullModelJamThatStoppedTheSolverRunsAtTheDefaultTolerance) {
  CampaignOptions o;
  o.case_patterns = {"jam_l2"};
  o.samples = 16;
  o.model = sim::DriveResolution::kFull;
  constexpr int kRun = 14;  // sample 14: Sobol point 13
  const Plan standard = MakePlan(Example(), o);
  ASSERT_EQ(standard.SampleOf(kRun).label.rfind("sobol 13", 0), 0u) << standard.SampleOf(kRun).label;
  const RunResult r = ExecuteRun(Example(), standard, kRun);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_TRUE(r.passivity.passive()) << r.passivity.BriefReport();
  o.relative_tolerance = kConvergedRtol;
  const RunResult converged = ExecuteRun(Example(), MakePlan(Example(), o), kRun);
  ASSERT_TRUE(converged.ok) << converged.message;
  EXPECT_NEAR(r.peak, converged.peak, kEnvelopeTolerance * converged.peak) << r.peak_component;
}

// At rtol 1e-8, 24 full-model ruptures stopped at the step guard of rtol 1e-5 (10 000 steps per
// 1/20 of the run) while the wing-tip brake engaged; rupture_shaft_l3a at Sobol point 9 needs
// 10 000 to 12 000 there. The guard of the tolerance (--max-steps' default) lets it finish.
TEST(EnvelopeTolerance, StepGuardOfATightToleranceLetsAFullModelRuptureFinish) {
  CampaignOptions o;
  o.case_patterns = {"rupture_shaft_l3a"};
  o.samples = 16;
  o.relative_tolerance = kConvergedRtol;
  constexpr int kRun = 10;  // Sobol point 9
  const Plan tight = MakePlan(Example(), o);
  const RunResult r = ExecuteRun(Example(), tight, kRun);
  EXPECT_TRUE(r.ok) << r.message;
  o.max_steps_per_output = CampaignOptions::kMaxStepsPerOutputAtDefaultTolerance;
  const RunResult guarded = ExecuteRun(Example(), MakePlan(Example(), o), kRun);
  EXPECT_FALSE(guarded.ok);
  EXPECT_NE(guarded.message.find("CV_TOO_MUCH_WORK"), std::string::npos) << guarded.message;
  EXPECT_NE(guarded.message.find("(campaign --max-steps, 10000 in this campaign)"), std::string::npos) << guarded.message;
}

}  // namespace
}  // namespace highlift::campaign
