// `highlift check PROJECT.json [--json] [--all] [--ratio R] [--max-revisions N]`: interval
// constraint propagation over the project. Answer first: the verdict (report::DescribeVerdict),
// one statement about the parameter domains (some values within them meet every requirement, or
// which requirements no values can meet together, exit 1) and one about the nominal design (every
// parameter at its nominal value), then the chain of constraints through which a conflict
// arises, then the propagation counters. The full parameter table (initial and final domain,
// narrowing, provenance) only with --all; the JSON keeps everything. When propagation stops at a
// limit before a fixed point, that is said instead: nothing was proved either way (exit 0, JSON
// "all_requirements_met": null).
#include <cstdint>
#include <iostream>

#include <nlohmann/json.hpp>

#include "command.h"
#include "estimated_project.h"
#include "highlift/core/project_io.h"
#include "highlift/core/text_table.h"
#include "highlift/icsp/drive_system.h"
#include "highlift/report/report.h"

namespace highlift::cli {
namespace {

using icsp::Interval;

std::string Range(const Interval& x) {
  if (icsp::IsEmpty(x)) return "empty";
  if (x.lower() == x.upper()) return FormatNumber(x.lower(), 5);
  return "[" + FormatNumber(x.lower(), 5) + ", " + FormatNumber(x.upper(), 5) + "]";
}

class CheckCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    options_.AddTo(app);
    app.add_flag("--no-estimate", no_estimate_,
                 "Use the project's own domains only: no database, fit or physics estimates");
    app.add_flag("--all", all_, "also print every parameter: initial and final domain, narrowing, provenance");
    app.add_option("--ratio", ratio_, "stop re-revising when no domain shrinks by more than this fraction (0: exact fixed point)")
        ->check(NumberIn(0.0, 0.999));
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
    const bool stopped = r.report.status == icsp::Status::kStoppedAtLimit;
    const nlohmann::json doc = report::CheckDocument(project, net, r, loaded.estimation_brief);
    if (options_.json) {
      std::cout << JsonText(doc) << "\n";
    } else {
      const report::Verdict verdict = report::DescribeVerdict(doc);
      std::cout << verdict.headline << "\n" << "scope: " << report::kCheckScope << "\n\n" << verdict.domains << "\n";
      if (!verdict.nominal.empty()) std::cout << verdict.nominal << "\n";
      const std::string explanation = !r.feasible ? r.explanation.text
                                      : r.nominal_checked && !r.nominal_feasible ? r.nominal_explanation.text
                                                                                  : std::string();
      if (!explanation.empty()) std::cout << "\nWhy:\n" << explanation;
      if (!explanation.empty() && explanation.back() != '\n') std::cout << "\n";
      std::cout << "\n" << net.physics_constraints << " physics constraints, " << net.requirement_constraints
                << " requirements: " << r.report.BriefReport() << "\n";
      if (!loaded.estimation_brief.empty()) std::cout << "domains: " << loaded.estimation_brief << "\n";
      if (stopped) std::cout << "stopped: " << r.report.message << "\n";
      if (all_) {
        TextTable t({"parameter", "unit", "initial", "final", "narrowed %", "provenance"}, {4});
        for (const auto& p : r.parameters)
          t.AddRow({p.name, p.unit, Range(p.initial), Range(p.final), FormatNumber(p.narrowing_percent, 3), p.provenance});
        std::cout << "\n" << t.ToString();
      } else {
        std::cout << "(" << r.parameters.size() << " parameter domains, initial and final: --all, or --json)\n";
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
  bool all_ = false;          // print the full parameter table
  double ratio_ = 0.0;
  std::int64_t max_revisions_ = 0;  // 0: the propagator's default limit
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(CheckCommand, "check",
                          "narrow every parameter domain by interval propagation and check the requirements")

}  // namespace highlift::cli
