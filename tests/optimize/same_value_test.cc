// Options::same_value: parameters that take one value (identical parts). On the A320-class flaps
// with one ratio for every geared rotary actuator as a design variable (100-300:1) beside the
// benchmark's shafts, settings and brakes: the ratio is one variable that every actuator follows,
// a requirement bounds it (the extension time, which reads it through the travel at the PDU), and
// the design, with every actuator at that ratio, passes the network and `size`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/estimation/estimator.h"
#include "highlift/icsp/drive_system.h"
#include "highlift/icsp/propagator.h"
#include "highlift/optimize/optimize.h"
#include "highlift/reduced_models/sizing.h"
#include "optimize/design_problem.h"

namespace highlift::optimize {
namespace {

/// bench/optimize's design problem on the A320-class flaps (physics estimates only; with
/// `ratio`, every actuator's ratio 100-300:1).
Project Flaps(bool ratio) { return testing::BenchmarkDesignProblem("a320_class_flaps.json", ratio, nullptr); }

Options Fast() {
  Options o;
  o.relative_gap = 0.01;
  o.max_seconds = 60.0;
  o.verify_peak = false;  // as the benchmark: every bundled example fails peak at every design
  return o;
}

TEST(OptimizeSameValue, OneRatioForEveryActuatorBoundedByTheExtensionTime) {
  const Project problem = Flaps(true);
  Options o = Fast();
  o.same_value = testing::SameRatio(problem);
  ASSERT_EQ(o.same_value.front().size(), 8u);
  const Report r = Optimize(problem, o);
  ASSERT_TRUE(r.found) << r.BriefReport() << "\n" << r.FullReport();
  EXPECT_EQ(r.status, Status::kOptimal) << r.BriefReport();
  // One design variable for the eight ratios; the other seven follow it in the design table.
  EXPECT_EQ(std::count(r.design_variables.begin(), r.design_variables.end(), "gra_l1.ratio"), 1);
  EXPECT_EQ(std::count(r.design_variables.begin(), r.design_variables.end(), "gra_r4.ratio"), 0);
  const DesignValue* leader = nullptr;
  int followers = 0;
  for (const DesignValue& v : r.design)
    if (v.name == "gra_l1.ratio") leader = &v;
  ASSERT_NE(leader, nullptr) << r.FullReport();
  for (const DesignValue& v : r.design)
    if (v.same_as == "gra_l1.ratio") {
      ++followers;
      EXPECT_EQ(v.value_si, leader->value_si) << v.name;
    }
  EXPECT_EQ(followers, 7) << r.FullReport();
  // Not the domain's end: the extension time (travel at the PDU = travel angle x ratio x gears)
  // bounds the ratio from above, and a larger ratio only lightens the shafts.
  EXPECT_TRUE(leader->at_bound.empty()) << r.FullReport();
  EXPECT_GT(leader->value, 200.0) << r.FullReport();
  bool time = false;
  for (const ActiveConstraint& a : r.active) time = time || a.label == "extension_time";
  EXPECT_TRUE(time) << r.FullReport();
  // The written design: every actuator at that ratio, fixed; the network and size pass it.
  ASSERT_TRUE(r.design_project);
  for (const Component& c : r.design_project->components)
    if (c.type == "geared_rotary_actuator") {
      const Parameter& ratio = c.parameters.at("ratio");
      EXPECT_EQ(*ratio.nominal, leader->value_si) << c.id;
      EXPECT_TRUE(ratio.domain.is_point()) << c.id;
      EXPECT_EQ(ratio.provenance, Provenance::kOptimized) << c.id;
    }
  icsp::DriveSystemNetwork dsn = icsp::BuildDriveSystemNetwork(*r.design_project);
  icsp::Box box = dsn.network.InitialBox();
  EXPECT_NE(icsp::Propagator(dsn.network).Propagate(box).status, icsp::Status::kInfeasible);
  EXPECT_TRUE(reduced_models::Size(*r.design_project).ok());
  // The baselines' evaluator takes the same one variable and accepts the design with its mass.
  DesignEvaluator e(problem, o);
  std::vector<double> x;
  for (const std::string& name : e.variables())
    for (const DesignValue& v : r.design)
      if (v.name == name) x.push_back(v.value_si);
  ASSERT_EQ(x.size(), e.variables().size());
  const PointCheck at = e.Check(x);
  EXPECT_TRUE(at.feasible) << at.failure;
  EXPECT_NEAR(at.objective, r.best, 1e-9 * r.best);
  // At the domain's upper end (every actuator 300:1) the flaps extend too slowly.
  for (std::size_t i = 0; i < x.size(); ++i)
    if (e.variables()[i] == "gra_l1.ratio") x[i] = 300.0;
  const PointCheck slow = e.Check(x);
  EXPECT_FALSE(slow.feasible);
  EXPECT_NE(slow.failure.find("extension_time"), std::string::npos) << slow.failure;
}

TEST(OptimizeSameValue, BadGroupsAreNamed) {
  const Project problem = Flaps(true);
  auto message = [&](const std::vector<std::vector<std::string>>& groups) {
    Options o = Fast();
    o.same_value = groups;
    try {
      DesignEvaluator e(problem, o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({{"gra_l1.ratio"}}).find("at least two"), std::string::npos);
  EXPECT_NE(message({{"gra_l1.ratio", "gra_l2.ratio"}, {"gra_l3.ratio", "gra_l2.ratio"}}).find("named twice"),
            std::string::npos);
  EXPECT_NE(message({{"gra_l1.ratio", "gra_l2.nope"}}).find("not a parameter of the project"), std::string::npos);
  Project apart = problem;
  apart.FindComponent("gra_l2")->parameters.at("ratio").domain = {301.0, 400.0};
  Options o = Fast();
  o.same_value = {{"gra_l1.ratio", "gra_l2.ratio"}};
  try {
    DesignEvaluator e(apart, o);
    ADD_FAILURE() << "disjoint domains accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no common range"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace highlift::optimize
