// The reduced models on the A380-class example (examples/a380_class_flaps.json, domain.md s3)
// and the size / modes / peak commands of the CLI.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/run_cli.h"
#include "highlift/core/project_io.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/sizing.h"
#include "torque_flow.h"

namespace highlift::reduced_models {
namespace {

const std::string kExample = std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps.json";

TEST(A380Example, SizingMatchesTheDomainEstimates) {
  const Project project = LoadProject(kExample);
  const SizingReport r = Size(project);
  const LoadCaseSizing* extend = nullptr;
  for (const auto& c : r.cases)
    if (c.direction == "extend") extend = &c;
  ASSERT_NE(extend, nullptr);
  // domain.md s3 (E): PCU about 720 N*m and 18 kW for both wings (within 25 %: drags and
  // efficiencies of the example's components differ from the round figures).
  EXPECT_NEAR(extend->pdu_torque.nominal, 720.0, 0.25 * 720.0);
  EXPECT_NEAR(extend->pdu_power.nominal / 1e3, 18.0, 0.25 * 18.0);
  EXPECT_TRUE(extend->pdu_torque.bounds.contains(extend->pdu_torque.nominal));
  EXPECT_NEAR(r.shaft_mass, 51.0 * 1.2, 0.2 * 51.0 * 1.2);  // about 51 m of 1.08-1.33 kg/m tube
}

TEST(A380Example, ReducedModelsFirstModeErrorIsSmall) {
  const ModesReport r = AnalyseModes(LoadProject(kExample));
  for (const auto& m : r.models) EXPECT_LT(std::abs(m.first_clamped_error), 0.05) << ToString(m.reduction);
}

TEST(A380Example, PeakListsEveryJamAndRupture) {
  const PeakReport r = AnalysePeaks(LoadProject(kExample));
  int jams = 0;
  for (const auto& c : r.cases) {
    jams += c.kind == "jam";
    EXPECT_TRUE(c.tau_dynamic.bounds.contains(c.tau_dynamic.nominal)) << c.name;
  }
  EXPECT_EQ(jams, 12);
  EXPECT_GT(r.cases.size(), 12u);
}

TEST(ReducedModelsCli, SizeModesAndPeakPrintOneJsonDocument) {
  for (const char* command : {"size", "modes", "peak"}) {
    const highlift::testing::CliResult r = highlift::testing::RunCli({command, "examples/a380_class_flaps.json", "--json"});
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << command << ": " << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j.contains("project")) << command;
  }
}

TEST(ReducedModelsCli, PeakUnknownCaseExitsTwoAndListsTheCases) {
  const highlift::testing::CliResult r = highlift::testing::RunCli({"peak", "examples/a380_class_flaps.json", "--case", "jam_nowhere"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("peak case 'jam_nowhere' does not exist; the cases are:"), std::string::npos) << r.err;
}

// The static part of a jam is the PDU stall torque through the system torque limiter, by the
// limiter's own law min(tau, max(tau_2, tau - tau_B_max)), and a hydraulic PDU stalls where its
// motors do: n_m V_m (p_s - p_r) i eta_m eta (docs/reduced_models.md, "The system torque limiter
// in a jam"). Computed here from the parameters by hand, at the example's displacement (the
// STL's brake holds: its end stop passes) and at the top of its domain (the brake slips: the
// excess passes).
TEST(HydraulicExample, JamStaticPartIsTheMotorsStallTorqueThroughTheSystemLimiter) {
  Project project = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/hydraulic_pdu_flaps.json");
  Component& pdu = *project.FindComponent("pdu");
  const double rev = 2.0 * std::acos(-1.0);
  const double p_s = 345e5, p_r = 5e5, ratio = 20, eta_m = 0.95, eta = 0.9;  // example and catalogue values
  const double tau2 = 1.25 * 470, tauB = 2 * 470;  // the STL's catalogue end stop and brake
  for (const double displacement_cm3 : {5.4, 13.0}) {
    SCOPED_TRACE(displacement_cm3);
    const double V = displacement_cm3 * 1e-6 / rev;
    Parameter& d = pdu.parameters.at("motor_displacement");
    d.nominal = V;
    d.domain = Domain::Point(V);
    const double stall = 2 * V * (p_s - p_r) * ratio * eta_m * eta;
    const double expected = std::min(stall, std::max(tau2, stall - tauB));
    const PeakReport r = AnalysePeaks(project);
    int jams = 0;
    for (const auto& c : r.cases) {
      if (c.kind != "jam") continue;
      ++jams;
      EXPECT_NEAR(c.tau_static, expected, 1e-9 * expected) << c.name;
      EXPECT_LE(c.tau_static_bounds.lo, expected) << c.name;
      EXPECT_GE(c.tau_static_bounds.hi, expected) << c.name;
    }
    EXPECT_EQ(jams, 12);
    // Upstream of the STL the PDU carries the whole stall torque with the jam's dynamic part.
    double pdu_row = 0.0, largest_jam_dynamic = 0.0;
    for (const auto& w : r.worst)
      if (w.component == "pdu") pdu_row = w.torque.nominal;
    for (const auto& c : r.cases)
      if (c.kind == "jam") largest_jam_dynamic = std::max(largest_jam_dynamic, c.tau_dynamic.nominal);
    EXPECT_NEAR(pdu_row, largest_jam_dynamic + stall, 1e-9 * pdu_row);
    if (displacement_cm3 > 10) {
      EXPECT_GT(expected, 1.5 * tau2);  // the case where the brake slips
    }
  }
}

// The peak analysis solves the torque flow once per uncertain parameter, and takes the nominal
// flow's torque wherever the parameter cannot reach (SolveFlow's `nominal`). That must be the
// torque the full solve gives, to the bit: for every uncertain parameter of the example, with
// and without friction, with the airloads and without.
TEST(A380Example, TheFlowOfOneParameterReusesOnlyWhatItCannotChange) {
  Project project = LoadProject(kExample);
  // And a ratio that spans a domain, which moves the speeds of everything behind it.
  Component* tgb = nullptr;
  for (Component& c : project.components)
    if (c.id == "tgb_l4") tgb = &c;
  ASSERT_NE(tgb, nullptr);
  tgb->parameters["ratio"].domain = {1.96, 2.04};
  const detail::Graph g = detail::BuildGraph(project);
  ASSERT_FALSE(project.load_cases.empty());
  const std::map<std::string, double> loads = detail::SizingLoads(project.load_cases.front());
  ASSERT_FALSE(loads.empty());
  const detail::Interval w(detail::SizingSpeed(project.load_cases.front(), *g.nodes[0].component));
  const auto uncertain = detail::UncertainParameters(g);
  ASSERT_GT(uncertain.size(), 50u);
  int reused = 0, solved = 0, ratios = 0;
  for (const bool friction : {false, true})
    for (const auto* airloads : {&loads, static_cast<const std::map<std::string, double>*>(nullptr)}) {
      const std::map<std::string, double> none;
      const auto& l = airloads ? *airloads : none;
      const detail::Flow<detail::Interval> nominal = detail::SolveFlow<detail::Interval>(g, {}, l, w, friction);
      for (const auto& [component, parameter] : uncertain) {
        const detail::ParameterMode one{detail::ParameterMode::kOne, component, parameter};
        const auto full = detail::SolveFlow<detail::Interval>(g, one, l, w, friction);
        const auto fast = detail::SolveFlow<detail::Interval>(g, one, l, w, friction, &nominal);
        ASSERT_EQ(full.tau_in.size(), fast.tau_in.size());
        // The mode's speed ratios given (as AnalysePeaks gives them) change nothing; a friction
        // parameter's are the nominal mode's, which AnalysePeaks gives for them.
        const std::vector<detail::Interval> own = detail::SpeedRatios<detail::Interval>(g, one);
        const auto given = detail::SolveFlow<detail::Interval>(g, one, l, w, friction, &nominal, &own);
        for (std::size_t k = 0; k < full.tau_in.size(); ++k) {
          EXPECT_EQ(std::bit_cast<std::uint64_t>(given.tau_in[k].lo), std::bit_cast<std::uint64_t>(fast.tau_in[k].lo));
          EXPECT_EQ(std::bit_cast<std::uint64_t>(given.tau_in[k].hi), std::bit_cast<std::uint64_t>(fast.tau_in[k].hi));
          EXPECT_EQ(std::bit_cast<std::uint64_t>(given.w_in[k].lo), std::bit_cast<std::uint64_t>(fast.w_in[k].lo));
          EXPECT_EQ(std::bit_cast<std::uint64_t>(given.w_in[k].hi), std::bit_cast<std::uint64_t>(fast.w_in[k].hi));
        }
        if (parameter == "coulomb_torque" || parameter == "viscous_coefficient" || parameter == "stribeck_torque" ||
            parameter == "stribeck_decay" || parameter == "drag_per_length")
          for (std::size_t k = 0; k < own.size(); ++k) {
            EXPECT_EQ(std::bit_cast<std::uint64_t>(own[k].lo), std::bit_cast<std::uint64_t>(nominal.n[k].lo));
            EXPECT_EQ(std::bit_cast<std::uint64_t>(own[k].hi), std::bit_cast<std::uint64_t>(nominal.n[k].hi));
          }
        bool moved = false;
        for (std::size_t k = 0; k < full.tau_in.size(); ++k) {
          EXPECT_EQ(full.tau_in[k].lo, fast.tau_in[k].lo) << component << "." << parameter << " node " << k;
          EXPECT_EQ(full.tau_in[k].hi, fast.tau_in[k].hi) << component << "." << parameter << " node " << k;
          const bool same = detail::SameValue(full.tau_in[k], nominal.tau_in[k]);
          reused += same;
          solved += !same;
          moved = moved || !same;
        }
        // The ratio moves the speeds, and the torques, of the station behind the gearbox.
        if (component == "tgb_l4" && parameter == "ratio" && moved)
          for (std::size_t k = 0; k < full.w_in.size(); ++k) ratios += !detail::SameValue(full.w_in[k], nominal.w_in[k]);
      }
    }
  EXPECT_GT(reused, solved);  // most of the tree is out of one parameter's reach
  EXPECT_GT(solved, 0);
  EXPECT_GT(ratios, 0);
}

}  // namespace
}  // namespace highlift::reduced_models
