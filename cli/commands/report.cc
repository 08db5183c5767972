// `highlift report PROJECT.json [--out report.html] [--campaign DIR] [--optimize RESULT.json] [--no-transient]
// [--no-scenarios] [--elements N] [--threads N] [--json]`: the design report, one self-contained HTML file
// (report/include/highlift/report/report.h, docs/report.md): the verdict of the interval check
// first, the architecture along the span, the torque flow, the modes, the peak loads (single-DOF
// beside transient beside capacity; with --campaign the envelope over a campaign's samples), the
// time histories of the scenarios and, with --optimize, the result of `highlift optimize --json`
// (the Synthesis section, with the plot of a Pareto front). Prints one headline line (with --json a JSON document: file,
// size, verdict, timings). Exit 0 when the report was written and the domains can meet the
// requirements, 1 when the check found them infeasible, a simulation failed, or the campaign is
// incomplete, has failed runs or a negative margin, or the optimize result holds no design (the
// report is written all the same), 2 on invalid input (a campaign or optimize result of another
// project among them).
#include <filesystem>
#include <iostream>

#include "command.h"
#include "estimated_project.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"
#include "highlift/core/text_table.h"
#include "highlift/report/report.h"
#include "highlift/sim/drive_network.h"

namespace highlift::cli {
namespace {

class ReportCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    options_.AddTo(app);
    app.add_option("--out,--output", out_, "HTML file to write (default: report.html)");
    app.add_option("--campaign", report_.campaign,
                   "result folder (or .sqlite file) of `highlift campaign` on this project: adds the envelope over "
                   "its samples to the peak loads");
    app.add_option("--optimize", report_.optimize,
                   "a result of `highlift optimize PROJECT --json` (saved with > FILE) of this project, or of the "
                   "project its --write design came from: adds the Synthesis section (status, certified bound, design, "
                   "what limits it, mass; the plot of a --pareto front)");
    app.add_flag("--no-transient", no_transient_,
                 "skip the transient simulation of every sizing case (single-DOF peaks and capacities only)");
    app.add_flag("--no-scenarios", no_scenarios_, "skip the simulation of the project's scenarios (no time histories)");
    app.add_option("--elements", report_.shaft_elements,
                   "spring-dampers per torque shaft in the simulations (default: the project's shaft_elements, at "
                   "least 4; 1 to " + std::to_string(sim::DriveNetworkOptions::kMaxShaftElements) + ")")
        ->check(NumberIn(1, sim::DriveNetworkOptions::kMaxShaftElements));
    app.add_option("--threads", report_.threads, "simulations run side by side (default: all hardware threads)")
        ->check(NumberIn(1, 4096));
  }

  int Run() override {
    const Project project = LoadValidProject(options_.project);
    const EstimatedProject estimated = LoadEstimatedProject(options_, true);
    report_.transient = !no_transient_;
    report_.scenarios = !no_scenarios_;
    // The file is checked before the analyses (not an input, a regular file, a writable folder)
    // and replaced only when the report is complete (highlift::OutputFile).
    if (!report_.optimize.empty()) RegisterInputFile(report_.optimize);  // refused as --out at once
    OutputFile file(out_, "report file");
    report::DesignReport report;
    {
      // A signal stops the simulations (each after its current step) instead of the process.
      const InterruptibleScope interruptible;
      report = report::BuildDesignReport(project, estimated.project, estimated.estimation_brief, report_);
    }
    if (InterruptRequested()) {
      // Its simulations were cut short: a report of them would be wrong. The old file stays.
      std::cerr << "highlift report: interrupted by signal " << InterruptSignal()
                << " during the analyses and simulations: no report written; '" << out_
                << "' is as it was before (run the command again for the whole report)\n";
      return kInterruptedExit;
    }
    const std::string html = report::RenderHtml(report);
    file.Write(html);
    file.Commit();
    const auto& t = report.timings;
    if (options_.json) {
      nlohmann::json j = {{"file", out_},
                          {"bytes", html.size()},
                          {"verdict", report.data["verdict"]},
                          {"all_requirements_met", report.data["check"]["all_requirements_met"]},
                          {"simulations_ok", report.simulations_ok},
                          {"campaign_ok", report.campaign_ok},
                          {"synthesis_ok", report.synthesis_ok},
                          {"timings", report.data["timings"]}};
      std::cout << JsonText(j) << "\n";
    } else {
      std::cout << report.data["verdict"].value("headline", "") << "\n"
                << "wrote " << out_ << " (" << FormatNumber(html.size() / 1e6, 3) << " MB): open it in a browser, e.g. "
                << "xdg-open " << out_ << "\n"
                << "analyses " << FormatNumber(t.Tool(), 3) << " s, " << t.simulation_count << " simulations "
                << FormatNumber(t.simulations, 3) << " s" << (report.simulations_ok ? "" : " (some failed)") << "\n";
      if (!report.data["campaign"].is_null())
        std::cout << "campaign: " << report.data["campaign"].value("brief", std::string()) << "\n";
      if (!report.data["synthesis"].is_null())
        std::cout << "synthesis: " << report.data["synthesis"].value("status_words", std::string()) << "\n";
    }
    return report.feasible && report.simulations_ok && report.campaign_ok && report.synthesis_ok ? kSuccess : kViolated;
  }

 private:
  CommonOptions options_;
  report::ReportOptions report_;
  std::string out_ = "report.html";
  bool no_transient_ = false;
  bool no_scenarios_ = false;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(ReportCommand, "report",
                          "design report: one self-contained HTML file with the verdict, architecture, sizing, "
                          "modes, peak loads and scenario time histories")

}  // namespace highlift::cli
