// `highlift check PROJECT.json [--json] [--ratio R] [--max-revisions N]`: interval constraint
// propagation over the project. Prints every parameter (initial domain, final domain, narrowing,
// provenance), then either "all requirements can be met" (exit 0) or the requirements that cannot
// be met together with the chain of constraints through which the conflict arises (exit 1). When
// the domains can meet the requirements but the nominal design cannot, that is said too (with its
// explanation; exit 0: the design space holds solutions). When propagation stops at a limit
// before a fixed point, that is said instead: nothing was proved either way (exit 0, JSON
// "all_requirements_met": null).
#include <cmath>
#include <cstdint>
#include <iostream>

#include <nlohmann/json.hpp>

#include "command.h"
#include "estimated_project.h"
#include "highlift/core/project_io.h"
#include "highlift/core/text_table.h"
#include "highlift/icsp/drive_system.h"

namespace highlift::cli {
namespace {

using icsp::Interval;

std::string Range(const Interval& x) {
  if (icsp::IsEmpty(x)) return "empty";
  if (x.lower() == x.upper()) return FormatNumber(x.lower(), 5);
  return "[" + FormatNumber(x.lower(), 5) + ", " + FormatNumber(x.upper(), 5) + "]";
}
nlohmann::json RangeJson(const Interval& x) {
  if (icsp::IsEmpty(x)) return nullptr;
  auto num = [](double v) -> nlohmann::json {
    if (std::isfinite(v)) return v;
    return v > 0 ? "inf" : "-inf";
  };
  return nlohmann::json::array({num(x.lower()), num(x.upper())});
}

class CheckCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    options_.AddTo(app);
    app.add_flag("--no-estimate", no_estimate_,
                 "Use the project's own domains only: no database, fit or physics estimates");
    app.add_option("--ratio", ratio_, "stop re-revising when no domain shrinks by more than this fraction (0: exact fixed point)")
        ->check(CLI::Range(0.0, 0.999));
    app.add_option("--max-revisions", max_revisions_,
                   "stop propagating after this many constraint revisions (the result then proves nothing)")
        ->check(Positive());
  }

  int Run() override {
    const EstimatedProject loaded = LoadEstimatedProject(options_, !no_estimate_);
    const Project& project = loaded.project;
    const icsp::DriveSystemNetwork net = icsp::BuildDriveSystemNetwork(project);
    icsp::PropagationOptions po;
    po.ratio = ratio_;
    if (max_revisions_ > 0) po.max_revisions = max_revisions_;
    const icsp::CheckResult r = icsp::CheckDriveSystem(net, po);
    // Stopped at a limit: no conflict was proved, and none was ruled out either.
    const bool stopped = r.report.status == icsp::Status::kStoppedAtLimit;
    auto labels = [&](const icsp::Explanation& e) {
      std::vector<std::string> out;
      for (int c : e.conflict) out.push_back(net.network.constraint(icsp::ConstraintId{c}).info.label);
      return out;
    };
    const std::vector<std::string> violated = labels(r.explanation);
    const std::vector<std::string> nominal_violated = labels(r.nominal_explanation);
    if (options_.json) {
      nlohmann::json params = nlohmann::json::array();
      for (const auto& p : r.parameters) {
        params.push_back({{"name", p.name}, {"unit", p.unit}, {"provenance", p.provenance},
                          {"initial", RangeJson(p.initial)}, {"final", RangeJson(p.final)},
                          {"narrowing_percent", p.narrowing_percent}});
      }
      nlohmann::json doc = {{"project", project.name},
                            {"status", icsp::ToString(r.report.status)},
                            {"all_requirements_met", stopped ? nlohmann::json(nullptr) : nlohmann::json(r.feasible)},
                            {"revisions", r.report.revisions},
                            {"seconds", r.report.seconds},
                            {"physics_constraints", net.physics_constraints},
                            {"requirements", net.requirement_constraints},
                            {"estimation", loaded.estimation_brief},
                            {"parameters", params}};
      if (r.nominal_checked) {
        nlohmann::json nominal = {{"all_requirements_met", r.nominal_feasible}};
        if (!r.nominal_feasible) {
          nominal["violated_requirements"] = nominal_violated;
          nominal["explanation"] = r.nominal_explanation.text;
        }
        doc["nominal_design"] = nominal;
      }
      if (!r.feasible) {
        doc["violated_requirements"] = violated;
        doc["physics_alone"] = r.explanation.physics_alone;
        doc["explanation"] = r.explanation.text;
      }
      std::cout << doc.dump(2) << "\n";
    } else {
      TextTable t({"parameter", "unit", "initial", "final", "narrowed %", "provenance"}, {4});
      for (const auto& p : r.parameters) {
        t.AddRow({p.name, p.unit, Range(p.initial), Range(p.final), FormatNumber(p.narrowing_percent, 3), p.provenance});
      }
      std::cout << t.ToString() << "\n";
      if (!loaded.estimation_brief.empty()) std::cout << "domains: " << loaded.estimation_brief << "\n";
      std::cout << net.physics_constraints << " physics constraints, " << net.requirement_constraints
                << " requirements: " << r.report.BriefReport() << "\n\n";
      if (stopped) {
        std::cout << "propagation stopped at a limit (" << r.report.message
                  << ") before a fixed point: no requirement was proved violated, but the domains may narrow further and "
                     "a conflict may remain; raise the limit or use --ratio\n";
      } else if (r.feasible) {
        std::cout << "all requirements can be met\n";
        if (r.nominal_checked && !r.nominal_feasible) {
          std::cout << "\nbut not by the nominal design (every parameter at its nominal value): requirements violated "
                       "there: ";
          for (std::size_t i = 0; i < nominal_violated.size(); ++i) std::cout << (i ? ", " : "") << nominal_violated[i];
          std::cout << (nominal_violated.empty() ? "(none: the nominal component data alone conflict)" : "") << "\n"
                    << "The domains above are narrowed to where the requirements hold; the nominal values lie outside.\n\n"
                    << r.nominal_explanation.text;
        }
      } else {
        std::cout << "requirements violated: ";
        for (std::size_t i = 0; i < violated.size(); ++i) std::cout << (i ? ", " : "") << violated[i];
        std::cout << (violated.empty() ? "(none: the component data alone conflict)" : "") << "\n\n";
        std::cout << r.explanation.text;
      }
    }
    if (r.report.status == icsp::Status::kStoppedAtLimit) {
      std::cerr << "highlift check: warning: propagation stopped at a limit: " << r.report.message << "\n";
    }
    return r.feasible ? kSuccess : kViolated;
  }

 private:
  CommonOptions options_;
  bool no_estimate_ = false;  // skip the estimator (domains as given and catalogue defaults)
  double ratio_ = 0.0;
  std::int64_t max_revisions_ = 0;  // 0: the propagator's default limit
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(CheckCommand, "check",
                          "narrow every parameter domain by interval propagation and check the requirements")

}  // namespace highlift::cli
