// Issue 26, item 3: on every bundled example, for every jam and rupture, at the nominal point and
// at sampled points of the parameter domains, peak's single-DOF value of every component with an
// allowable is at least the transient peak of that component, or the component class is one
// where docs/validation.md says it is not a bound (and peak --transient flags the row).
//
// The sweep is the library path of `highlift peak --transient` (AnalysePeaks at the point,
// campaign::SimulateCase per case, campaign::CompareWithTransient), one class table per run.
// Its size is set by the environment, so that the same test is the normal suite's cheap check
// and the full measurement of docs/validation.md ("Single-DOF against transient"):
//   HIGHLIFT_BOUND_EXAMPLES  comma-separated example names (default a320_class_flaps)
//   HIGHLIFT_BOUND_SAMPLES   sampled points besides the nominal one (default 1)
//   HIGHLIFT_BOUND_MODEL     full or reduced (default reduced)
//   HIGHLIFT_BOUND_STRIDE    every n-th case (default 1: every jam and rupture)
//   HIGHLIFT_BOUND_WRITE     a folder: each point is written there as a project file
//                            (NAME_K.json, K = 0 the nominal point), to rerun one with the CLI
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <vector>

#include "highlift/campaign/bounds.h"
#include "highlift/campaign/campaign.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/core/text_table.h"
#include "highlift/model/component_model.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/sampling.h"
#include "highlift/sim/simulator.h"

namespace highlift::campaign {
namespace {

std::string Env(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : fallback;
}

std::string ClassOf(const Project& p, const std::string& id) {
  const Component* c = p.FindComponent(id);
  const ComponentTypeSpec* spec = c ? FindComponentType(c->type) : nullptr;
  if (!spec) return "";
  const ComponentRoles& r = spec->roles;
  if (r.actuator) return "actuators (input)";
  if (r.station_limiter) return "station torque limiters";
  if (r.wing_limiter) return "system torque limiters";
  if (r.tip_brake) return "wing-tip brakes";
  if (r.segment) return "torque shafts";
  if (r.drive_unit) return "PDU";
  if (c->type.find("gearbox") != std::string::npos) return "gearboxes (input)";
  return "";
}

struct ClassStats {
  int rows = 0;
  int not_bound = 0;
  double max_ratio = 0;
  std::string where;
};

TEST(SingleDofAgainstTransient, EveryComponentClassOnTheExamplesAtTheNominalAndSampledPoints) {
  std::vector<std::string> examples;
  std::stringstream list(Env("HIGHLIFT_BOUND_EXAMPLES", "a320_class_flaps"));
  for (std::string e; std::getline(list, e, ',');) examples.push_back(e);
  const int samples = std::stoi(Env("HIGHLIFT_BOUND_SAMPLES", "1"));
  const int stride = std::max(1, std::stoi(Env("HIGHLIFT_BOUND_STRIDE", "1")));
  sim::DriveNetworkOptions network;
  network.resolution = model::ParseDriveResolution(Env("HIGHLIFT_BOUND_MODEL", "reduced"));

  std::map<std::string, ClassStats> stats;
  int points = 0, rejected = 0, simulations = 0;
  for (const std::string& name : examples) {
    const Project base = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/" + name + ".json");
    // The domains the example gives (a catalogue default domain, e.g. a backlash without a
    // stiffness, is no design the example states).
    auto uncertain = reduced_models::UncertainParameters(base);
    std::erase_if(uncertain, [&](const reduced_models::UncertainParameter& u) {
      const Component* c = base.FindComponent(u.component);
      if (!c) return true;
      const auto it = c->parameters.find(u.parameter);
      return it == c->parameters.end() || it->second.provenance == Provenance::kDefault;
    });
    reduced_models::DomainSampler sampler(uncertain, 26);
    for (int k = 0; k <= samples; ++k) {
      SCOPED_TRACE(name + (k == 0 ? std::string(" nominal") : " sample " + std::to_string(k)));
      // A sampled point must be a design: the relations the domains cannot express (a brake's
      // static capacity at least its dynamic torque, a lock-out below the end stop) are checked
      // by building and assembling its drive model before any simulation, and a point that breaks one is drawn
      // again (counted). The nominal point must be one.
      Project point;
      reduced_models::PeakReport report;
      reduced_models::PeakOptions options;
      options.intervals = false;
      options.rank = false;
      bool design = false;
      for (int attempt = 0; attempt < 100 && !design; ++attempt) {
        try {
          point = k == 0 ? base : reduced_models::FixParameters(base, uncertain, sampler.Interior());
          const sim::DriveModel model = sim::BuildDriveNetwork(point, sim::DriveNetworkOptions{});
          const sim::Simulator assembled(model.network);  // the element laws check their relations
          report = reduced_models::AnalysePeaks(point, options);
          design = true;
        } catch (const InputError& e) {
          ASSERT_NE(k, 0) << e.what();
          ++rejected;
        }
      }
      ASSERT_TRUE(design) << "100 draws broke a relation";
      if (const std::string dir = Env("HIGHLIFT_BOUND_WRITE", ""); !dir.empty())
        SaveProject(point, std::filesystem::path(dir) / (name + "_" + std::to_string(k) + ".json"));
      std::vector<SimulatedCase> simulated;
      for (std::size_t i = 0; i < report.cases.size(); i += stride) {
        const auto& pc = report.cases[i];
        const Scenario scenario = sim::SizingScenario(point, pc.kind, pc.component);
        const CaseSimulation s = SimulateCase(point, scenario, pc.load_path, network);
        EXPECT_TRUE(s.report.ok()) << pc.name << ": " << s.report.message;
        ++simulations;
        simulated.push_back({pc.name, s.report.ok(), ComponentTorquesAtInput(point, s.components)});
      }
      ++points;
      for (const ComponentBound& c : CompareWithTransient(report, simulated)) {
        const std::string cls = ClassOf(point, c.component);
        if (cls.empty() || c.transient <= 0) continue;
        ClassStats& st = stats[cls];
        ++st.rows;
        st.not_bound += !c.bound();
        const double ratio = c.single_dof > 0 ? c.transient / c.single_dof : INFINITY;
        if (ratio > st.max_ratio) {
          st.max_ratio = ratio;
          st.where = name + (k == 0 ? "" : " #" + std::to_string(k)) + " " + c.component + " (" + c.transient_case + ")";
        }
      }
      // One line per point: a sweep of the full model runs for half an hour, and its partial
      // result is worth keeping when it is stopped.
      std::cout << name << (k == 0 ? " nominal" : " #" + std::to_string(k)) << " done (" << simulations
                << " simulations so far); largest transient / single-DOF so far:";
      for (const auto& [cls, st] : stats)
        std::cout << " " << cls << " " << FormatNumber(st.max_ratio, 4) << " (" << st.not_bound << " not a bound)";
      std::cout << std::endl;
    }
  }
  TextTable table({"class", "rows", "not a bound", "largest transient / single-DOF", "where"}, {1, 2, 3});
  for (const auto& [cls, st] : stats)
    table.AddRow({cls, std::to_string(st.rows), std::to_string(st.not_bound), FormatNumber(st.max_ratio, 4), st.where});
  std::cout << points << " points (" << rejected << " draws rejected: a relation broken), " << simulations << " simulations, model "
            << model::ToString(network.resolution) << "\n" << table.ToString();
  EXPECT_GT(points, samples > 0 ? 1 : 0);

  // The claims of docs/validation.md: bounds for the actuators, the station limiters, the
  // gearboxes and the wing-tip brakes; the rupture cap of the shafts next to a wing-tip brake is
  // an estimate (within 10 %; measured up to 1.017); the PDU's jam case loads one wing's path
  // while it drives both, no bound (within 25 %; measured up to 1.16, A380-class flaps, reduced
  // model, sampled point 3).
  for (const char* cls : {"actuators (input)", "station torque limiters", "gearboxes (input)", "wing-tip brakes",
                          "system torque limiters"})
    if (stats.count(cls)) {
      EXPECT_EQ(stats.at(cls).not_bound, 0) << cls << ": " << stats.at(cls).where << " ratio " << stats.at(cls).max_ratio;
    }
  ASSERT_TRUE(stats.count("actuators (input)"));
  if (stats.count("torque shafts")) {
    EXPECT_LE(stats.at("torque shafts").max_ratio, 1.10) << stats.at("torque shafts").where;
  }
  if (stats.count("PDU")) {
    EXPECT_LE(stats.at("PDU").max_ratio, 1.25) << stats.at("PDU").where;
  }
}

}  // namespace
}  // namespace highlift::campaign
