// optimize::Optimize with Options::tube_sizes: the chain's tube restricted to a table of sizes. The
// discrete optimum is the lightest size within the domains that meets the torque-capacity and
// stiffness requirements, found here by enumerating the table; the branch and bound must find it
// with status optimal and a certified bound at or above the continuous optimum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "highlift/componentdb/tube_sizes.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/model/laws.h"
#include "optimize/one_tube_chain.h"
#include "highlift/optimize/optimize.h"

namespace highlift::optimize {
namespace {

using testing::LoadChain;
using testing::OneTubeChain;

struct Lightest {
  double mass = std::numeric_limits<double>::infinity();
  std::string designation;
  double D = 0.0, t = 0.0;
};

/// By enumeration: the lightest size with D in [D_lo, D_hi] and t in [t_lo, t_hi] (m) whose tube
/// carries 1.5 kN*m at the lesser of 500 MPa and its torsional buckling stress (nu at 0.31, the
/// least of its default domain; knock-down 0.67) and is stiff enough (5000 N*m/rad over 2 m at G).
Lightest Enumerate(const componentdb::TubeSizeTable& table, double G, double D_lo = 0.020, double D_hi = 0.060,
                   double t_lo = 0.0005, double t_hi = 0.004) {
  const double L = 2.0, rho = 4420.0, tau = 500e6, T = 1500.0, c = 5000.0;
  Lightest best;
  for (const componentdb::TubeSize& s : table.sizes) {
    const double D = s.outer_diameter, t = s.wall_thickness;
    if (D < D_lo || D > D_hi || t < t_lo || t > t_hi) continue;
    const double Ip = std::numbers::pi / 32 * (std::pow(D, 4) - std::pow(D - 2 * t, 4));
    const double tau_cr = model::TubeBucklingStress(G, 0.31, 0.67, D, t, L);
    if (2 * std::min(tau, tau_cr) * Ip / D < T || G * Ip / L < c) continue;
    const double m = rho * std::numbers::pi * (D - t) * t * L;
    if (m < best.mass) best = {m, s.designation, D, t};
  }
  return best;
}

/// The continuous optimum (optimize_test.cc): D at 60 mm, the least wall meeting the larger Ip
/// (the stiffness binds there; the tube buckles above 1.5 kN*m).
double ContinuousMass(double G) {
  const double D = 0.060, L = 2.0, rho = 4420.0, tau = 500e6, T = 1500.0, c = 5000.0;
  const double Ip = std::max(T * D / (2 * tau), c * L / G);
  const double t = (D - std::pow(std::pow(D, 4) - 32 * Ip / std::numbers::pi, 0.25)) / 2;
  return rho * std::numbers::pi * (D - t) * t * L;
}

TEST(OptimizeTubeSizes, FindsTheLightestStandardSizeFoundByEnumeration) {
  Options o;
  o.tube_sizes = componentdb::StandardTubeSizes();
  const Report r = Optimize(LoadChain(OneTubeChain()), o);
  ASSERT_EQ(r.status, Status::kOptimal) << r.BriefReport() << "\n" << r.FullReport();
  const Lightest e = Enumerate(o.tube_sizes, 44e9);
  ASSERT_FALSE(e.designation.empty());
  EXPECT_NEAR(r.best, e.mass, 1e-9 * e.mass) << e.designation << "\n" << r.FullReport();
  EXPECT_LE(r.lower_bound, e.mass * (1 + 1e-12));
  // The discrete problem's bound is at least the continuous optimum (the sizes are a subset).
  EXPECT_GT(e.mass, ContinuousMass(44e9));
  EXPECT_GE(r.lower_bound, ContinuousMass(44e9));
  ASSERT_EQ(r.design.size(), 2u);
  EXPECT_DOUBLE_EQ(r.design[0].value_si, e.D);
  EXPECT_DOUBLE_EQ(r.design[1].value_si, e.t);
  EXPECT_EQ(r.design[0].tube_size, e.designation);
  EXPECT_EQ(r.design[1].tube_size, e.designation);
  ASSERT_EQ(r.tube_sizes.size(), 1u);
  EXPECT_EQ(r.tube_sizes[0], std::make_pair(std::string("shaft_1"), e.designation));
  EXPECT_EQ(r.tube_table, "standard");
  // What limits it: the next lighter size is not stiff enough.
  bool stiffness = false;
  for (const ActiveConstraint& a : r.active) stiffness = stiffness || a.label == "stiffness";
  EXPECT_TRUE(stiffness) << r.FullReport();
  EXPECT_NE(r.FullReport().find("tube of shaft_1: " + e.designation + " (--tube-sizes standard)"), std::string::npos);
  const nlohmann::json j = r.ToJson();
  EXPECT_EQ(j["tube_sizes"]["table"], "standard");
  EXPECT_EQ(j["tube_sizes"]["shafts"]["shaft_1"], e.designation);
  EXPECT_EQ(j["design"][0]["tube_size"], e.designation);
  ASSERT_TRUE(r.design_project);
  const Parameter& t = r.design_project->FindComponent("shaft_1")->parameters.at("wall_thickness");
  EXPECT_EQ(t.provenance, Provenance::kOptimized);
  EXPECT_DOUBLE_EQ(*t.nominal, e.t);
  EXPECT_NE(t.note.find(e.designation), std::string::npos) << t.note;
}

// The modulus an interval: the size must be stiff enough at 43 GPa.
TEST(OptimizeTubeSizes, IsRobustOverTheRemainingUncertainParameters) {
  Options o;
  o.tube_sizes = componentdb::StandardTubeSizes();
  const Report r = Optimize(LoadChain(OneTubeChain("[43, 51] GPa")), o);
  ASSERT_EQ(r.status, Status::kOptimal) << r.FullReport();
  const Lightest e = Enumerate(o.tube_sizes, 43e9);
  EXPECT_NEAR(r.best, e.mass, 1e-9 * e.mass) << e.designation << "\n" << r.FullReport();
  EXPECT_EQ(r.tube_sizes.at(0).second, e.designation);
}

// A stock list: the lightest size (70 x 1 mm, 1.92 kg, stiff enough) is outside the diameter's
// domain; 50 x 1.2 (1.63 kg, 2411 N*m/rad) and 60 x 1.4 (2.28 kg, 4871 N*m/rad) are not stiff
// enough; 60 x 1.6 (2.60 kg, 5511 N*m/rad) is, and lighter than 56 x 2 (3.00 kg) and 60 x 3.
TEST(OptimizeTubeSizes, UsesAStockListAndOnlyItsSizesWithinTheDomains) {
  Options o;
  o.tube_sizes = componentdb::ParseTubeSizes(
      "designation,outer_diameter [mm],wall_thickness [mm]\n"
      "big-thin,70,1\nsmall,50,1.2\nmid,60,1.4\nok,60,1.6\nalt,56,2\nheavy,60,3\n",
      "stock.csv");
  const Report r = Optimize(LoadChain(OneTubeChain()), o);
  ASSERT_EQ(r.status, Status::kOptimal) << r.FullReport();
  const Lightest e = Enumerate(o.tube_sizes, 44e9);
  EXPECT_EQ(e.designation, "ok");
  EXPECT_EQ(r.tube_sizes.at(0).second, "ok") << r.FullReport();
  EXPECT_NEAR(r.best, e.mass, 1e-9 * e.mass);
  EXPECT_EQ(r.tube_table, "stock.csv");
}

// The diameter fixed (56 mm): only the wall is a design variable, from the sizes of that diameter.
TEST(OptimizeTubeSizes, WithOnlyTheWallADesignVariableTheSizesOfTheGivenDiameter) {
  nlohmann::json j = OneTubeChain();
  j["components"][1]["parameters"]["outer_diameter"] = "56 mm";
  Options o;
  o.tube_sizes = componentdb::StandardTubeSizes();
  const Report r = Optimize(LoadChain(j), o);
  ASSERT_EQ(r.status, Status::kOptimal) << r.FullReport();
  const Lightest e = Enumerate(o.tube_sizes, 44e9, 0.056, 0.056);
  ASSERT_EQ(r.design.size(), 1u);
  EXPECT_DOUBLE_EQ(r.design[0].value_si, e.t);
  EXPECT_EQ(r.design[0].tube_size, e.designation);
  EXPECT_NEAR(r.best, e.mass, 1e-9 * e.mass);
}

std::string MessageOf(const nlohmann::json& project, const Options& o) {
  try {
    Optimize(LoadChain(project), o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(OptimizeTubeSizes, BadInputNamesTheShaftItsDomainsAndTheNearestSizes) {
  Options o;
  o.tube_sizes = componentdb::StandardTubeSizes();
  // No size within D in [41, 43] mm.
  nlohmann::json narrow = OneTubeChain();
  narrow["components"][1]["parameters"]["outer_diameter"] = {{"value", 42}, {"min", 41}, {"max", 43}, {"unit", "mm"},
                                                             {"design", true}};
  const std::string m = MessageOf(narrow, o);
  EXPECT_NE(m.find("--tube-sizes standard: no size of the table fits shaft 'shaft_1': outer_diameter [41, 43] mm"),
            std::string::npos) << m;
  EXPECT_NE(m.find("wall_thickness [0.5, 4] mm"), std::string::npos) << m;
  EXPECT_NE(m.find("the nearest of its"), std::string::npos) << m;
  EXPECT_NE(m.find("40x"), std::string::npos) << m;
  EXPECT_NE(m.find("45x"), std::string::npos) << m;
  EXPECT_NE(m.find("--tube-sizes FILE"), std::string::npos) << m;
  // Neither D nor t a design variable.
  nlohmann::json fixed = OneTubeChain();
  fixed["components"][1]["parameters"]["outer_diameter"] = "56 mm";
  fixed["components"][1]["parameters"]["wall_thickness"] = "2 mm";
  fixed["components"][1]["parameters"]["length"] = {{"value", 2}, {"min", 1}, {"max", 3}, {"unit", "m"}, {"design", true}};
  const std::string n = MessageOf(fixed, o);
  EXPECT_NE(n.find("no torque shaft has its outer_diameter or wall_thickness as a design variable"), std::string::npos)
      << n;
  EXPECT_NE(n.find("leave out --tube-sizes"), std::string::npos) << n;
  // Not with --choose-part.
  o.choose_part = {{"shaft_1", {PartOption{"a", {}}}}};
  EXPECT_THROW(o.Validate(), InputError);
}

}  // namespace
}  // namespace highlift::optimize
