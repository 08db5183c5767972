// `highlift peak PROJECT.json [--case NAME] [--json] [--no-intervals] [--transient
// [--elements N]]`: single-DOF peak loads (paper eq. 1) of every sizing case (jam at each
// actuator, wing-tip brake after the rupture of each shaft segment) with tau_max, where it acts,
// interval enclosures and the parameters ranked by their share of the width; and the worst case
// per component with its margin. With --transient each case also runs as a full-resolution
// simulation (campaign::SimulateCase, as every run of `highlift campaign`) and the transient
// peak shaft torque on the case's load path is printed beside the single-DOF estimate, with the
// ratio. Exit 0 when every margin is >= 0 (and every simulation succeeded), 1 otherwise, 2 on
// invalid input (an unknown --case lists the cases).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>

#include "command.h"
#include "highlift/campaign/bounds.h"
#include "highlift/campaign/campaign.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"
#include "highlift/core/text_table.h"
#include "highlift/model/component_model.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/sim/drive_network.h"

namespace highlift::cli {
namespace {

struct TransientPeak {
  std::string name;       ///< the case
  std::string kind;       ///< jam or rupture
  std::string scenario;   ///< scenario simulated (the project's or made up)
  std::string load_case;  ///< its load case
  double single_dof = 0;  ///< N*m at the shaft (reference) speed, tau_total nominal
  double transient = 0;   ///< N*m at the shaft speed, largest on the load path
  std::string at;         ///< component carrying it
  double time = 0;        ///< s
  bool ok = true;
  bool interrupted = false;  ///< SIGINT/SIGTERM stopped the simulation: no result
  std::string message;    ///< the simulation's failure
  double wall_seconds = 0;
  sim::PassivityReport passivity;  ///< elements whose dissipated power fell below zero
  std::map<std::string, double> components;  ///< |torque| N*m at each component's own speed
  double Ratio() const { return single_dof > 0 ? transient / single_dof : NAN; }
  /// The single-DOF estimate (a rupture's: capped where the brake slips) is at least the simulated
  /// peak on the load path, within kBoundTolerance.
  bool Bound() const;
};

bool TransientPeak::Bound() const { return transient <= single_dof * (1.0 + campaign::kBoundTolerance); }

std::vector<campaign::SimulatedCase> Simulated(const std::vector<TransientPeak>& transient) {
  std::vector<campaign::SimulatedCase> out;
  for (const auto& t : transient) out.push_back({t.name, t.ok, t.components});
  return out;
}

TransientPeak RunCase(const Project& project, const reduced_models::PeakCase& pc, int elements) {
  TransientPeak t;
  t.name = pc.name;
  t.kind = pc.kind;
  t.single_dof = pc.tau_total.nominal;
  const Scenario scenario = sim::SizingScenario(project, pc.kind, pc.component);
  t.scenario = scenario.name;
  t.load_case = scenario.load_case;
  sim::DriveNetworkOptions options;
  options.shaft_elements = elements;
  // The largest shaft (or brake) torque on the load path, referred to the shaft speed.
  const campaign::CaseSimulation simulation = campaign::SimulateCase(project, scenario, pc.load_path, options);
  t.ok = simulation.report.ok();
  t.interrupted = simulation.report.status == sim::SimulationStatus::kInterrupted;
  t.message = simulation.report.message;
  t.wall_seconds = simulation.report.wall_seconds;
  t.passivity = simulation.report.passivity;
  t.transient = simulation.load_path_peak.tau;
  t.at = simulation.load_path_peak.element;
  t.time = simulation.load_path_peak.time;
  t.components = campaign::ComponentTorquesAtInput(project, simulation.components);
  return t;
}

class PeakCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    options_.AddTo(app);
    app.add_option("--case", peak_.only_case, "only this sizing case (e.g. jam_l3, rupture_shaft_l2a)");
    app.add_flag("--no-intervals", no_intervals_, "point values only (no enclosures, no ranking)");
    app.add_option("--tightness", tightness_,
                   "points of the domains sampled to measure how tight each enclosure is (width over the hull of "
                   "the sampled values, in the JSON); default 32 with --json, else 0")
        ->check(NumberIn(0, 100000));
    app.add_flag("--transient", transient_,
                 "also simulate each case at full resolution and print the transient peak shaft torque "
                 "beside the single-DOF estimate");
    app.add_option("--elements", elements_,
                   "with --transient: spring-dampers per torque shaft (default: the project's "
                   "shaft_elements, at least 4; 1 to " +
                       std::to_string(sim::DriveNetworkOptions::kMaxShaftElements) + ")")
        ->check(NumberIn(1, sim::DriveNetworkOptions::kMaxShaftElements));
  }
  int Run() override {
    const Project project = LoadValidProject(options_.project);
    if (elements_ != 0 && !transient_)
      throw InputError("--elements sets the resolution of the transient simulations: give --transient as well");
    if (elements_ < 0)
      throw InputError("--elements " + std::to_string(elements_) + ": give 1 or more spring-dampers per shaft");
    peak_.intervals = !no_intervals_;
    peak_.rank = !no_intervals_;
    peak_.tightness_samples = tightness_ >= 0 ? tightness_ : (options_.json ? kDefaultTightnessSamples : 0);
    const reduced_models::PeakReport report = reduced_models::AnalysePeaks(project, peak_);
    std::vector<TransientPeak> transient;
    bool all_ok = true;
    if (transient_) {
      if (!sim::IsDriveSystemProject(project))
        throw InputError("--transient simulates the drive system of the project, which has no components: "
                         "add \"components\" and \"connections\"");
      // A signal stops the simulation in progress (after its current step) instead of the
      // process; no case starts after it, and none of them counts as a result.
      const InterruptibleScope interruptible;
      for (const auto& pc : report.cases) {
        if (InterruptRequested()) break;
        transient.push_back(RunCase(project, pc, elements_));
        all_ok = all_ok && transient.back().ok;
      }
    }
    const int interrupted = transient_ && InterruptRequested() ? InterruptSignal() : 0;
    std::size_t simulated = 0;  // cases whose simulation ran to its end
    for (const auto& t : transient) simulated += !t.interrupted;
    if (options_.json) {
      nlohmann::json j = report.ToJson();
      if (transient_) {
        nlohmann::json cases = nlohmann::json::array();
        for (const auto& t : transient) {
          nlohmann::json c = {{"case", t.name},          {"kind", t.kind},
                              {"scenario", t.scenario},  {"load_case", t.load_case},
                              {"single_dof", t.single_dof},
                              {"transient", t.transient}, {"at", t.at},
                              {"time", t.time},          {"ok", t.ok},
                              {"wall_seconds", t.wall_seconds}};
          c["ratio"] = std::isfinite(t.Ratio()) ? nlohmann::json(t.Ratio()) : nlohmann::json(nullptr);
          c["bound"] = t.Bound();  // false: the single-DOF value is not a bound of this simulation
          if (!t.ok) c["message"] = t.message;
          nlohmann::json violations = nlohmann::json::array();
          for (const auto& v : t.passivity.violations)
            violations.push_back({{"element", v.element}, {"time", v.time}, {"power", v.power}, {"duration", v.duration}});
          c["passivity"] = {{"passive", t.passivity.passive()}, {"violations", violations}};
          c["status"] = t.interrupted ? "interrupted" : t.ok ? "ok" : "failed";
          cases.push_back(c);
        }
        j["transient"] = cases;
        if (interrupted != 0) {
          // The document describes an unfinished command: never "ok".
          j["ok"] = false;
          j["status"] = "interrupted";
          j["interrupted"] = {{"signal", interrupted},
                              {"cases", report.cases.size()},
                              {"simulated", simulated},
                              {"message", "interrupted by signal " + std::to_string(interrupted) + " after " +
                                              std::to_string(simulated) + " of " + std::to_string(report.cases.size()) +
                                              " simulations; the transient peaks are incomplete"}};
        }
        nlohmann::json components = nlohmann::json::array();
        for (const auto& c : campaign::CompareWithTransient(report, Simulated(transient)))
          components.push_back({{"component", c.component},
                                 {"single_dof_N_m", c.single_dof},
                                 {"single_dof_case", c.single_dof_case},
                                 {"transient_N_m", c.transient},
                                 {"transient_case", c.transient_case},
                                 {"bound", c.bound()},
                                 {"exceeded_by", std::isfinite(c.exceeded_by) ? nlohmann::json(c.exceeded_by)
                                                                              : nlohmann::json(nullptr)}});
        j["transient_components"] = components;
      }
      std::cout << JsonText(j) << "\n";
    } else {
      // Headline first: the worst case, the negative margins, and how the simulations went.
      std::cout << report.BriefReport();
      if (transient_) {
        int failed = 0, not_passive = 0;
        const TransientPeak* worst = nullptr;
        for (const auto& t : transient) {
          failed += !t.ok;
          not_passive += !t.passivity.passive();
          if (t.ok && (!worst || t.transient > worst->transient)) worst = &t;
        }
        if (worst) std::cout << "; transient worst " << worst->name << ": " << FormatNumber(worst->transient, 4) << " N*m at " << worst->at;
        if (interrupted != 0)
          std::cout << "; interrupted by signal " << interrupted << " after " << simulated << " of "
                    << report.cases.size() << " simulations";
        else if (failed) std::cout << "; " << failed << " simulation(s) failed";
        if (not_passive) std::cout << "; " << not_passive << " simulation(s) with negative dissipation";
      }
      std::cout << "\n\n" << report.FullReport() << "\n";
      if (transient_) {
        std::cout << "Transient peaks (full-resolution simulation) beside the single-DOF estimate, N*m at the "
                     "shaft speed\n(jams while extending, ruptures while retracting with the airload aiding the motion,\nfailure at "
                     "1 s, as the single-DOF estimate assumes):\n";
        TextTable table({"case", "simulated as (load case)", "single-DOF", "transient", "ratio", "single-DOF value", "at",
                         "t [s]", "simulation"},
                        {2, 3, 4, 7});
        for (const auto& t : transient)
          table.AddRow({t.name, t.scenario + (t.load_case.empty() ? "" : " (" + t.load_case + ")"),
                        FormatNumber(t.single_dof, 4), FormatNumber(t.transient, 4),
                        std::isfinite(t.Ratio()) ? FormatNumber(t.Ratio(), 3) : "-",
                        !t.ok ? "-" : t.Bound() ? "bound" : "NOT A BOUND: exceeded by " + FormatNumber(100.0 * (t.Ratio() - 1.0), 3) + " %",
                        t.at.empty() ? "-" : t.at, FormatNumber(t.time, 4),
                        (t.interrupted ? std::string("interrupted") : t.ok ? std::string("ok") : "failed: " + t.message) +
                            (t.passivity.passive() ? "" : "; " + t.passivity.BriefReport())});
        std::cout << table.ToString();
        std::cout << "\nPer component: the single-DOF value (nominal, its worst case) beside the largest transient torque of "
                     "any simulated case,\nN*m at the component's own speed; \"not a bound\" when the simulation exceeds "
                     "the single-DOF value:\n";
        TextTable per({"component", "single-DOF", "case", "transient", "case", "single-DOF value"}, {1, 3});
        int exceeded = 0;
        for (const auto& c : campaign::CompareWithTransient(report, Simulated(transient))) {
          exceeded += !c.bound();
          per.AddRow({c.component, FormatNumber(c.single_dof, 4), c.single_dof_case, FormatNumber(c.transient, 4),
                      c.transient_case.empty() ? "-" : c.transient_case, c.Flag()});
        }
        std::cout << per.ToString();
        if (exceeded) std::cout << exceeded << " component(s) where the single-DOF value is not a bound\n";
      }
    }
    if (interrupted != 0) return kInterruptedExit;
    return report.ok() && all_ok ? kSuccess : kViolated;
  }

 private:
  CommonOptions options_;
  reduced_models::PeakOptions peak_;
  bool no_intervals_ = false;
  int tightness_ = -1;
  bool transient_ = false;
  int elements_ = 0;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(PeakCommand, "peak",
                          "single-DOF peak loads of the jam and rupture sizing cases (--transient: beside "
                          "full simulations)")

}  // namespace highlift::cli
