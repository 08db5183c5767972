// `highlift export PROJECT.json --modelica OUTDIR [--model full|reduced] [--scenario NAME]
//  [--model-name NAME] [--tables-in-file] [--start equilibrium|rest] [--json]`: writes the
// HighLift Modelica package with a Modelica model of the project (HighLift.Models.<name>) into
// OUTDIR. A drive system starts where `highlift simulate` starts (the simulator computes the
// start from the network the export writes); `--start rest` writes no start values. Exit 0 on
// success, 2 on invalid input (a project that does not read or validate, an unknown scenario, a
// parameter without a value).
#include <iostream>

#include <nlohmann/json.hpp>

#include "command.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"
#include "highlift/export/modelica.h"
#include "highlift/sim/drive_network.h"

namespace highlift::cli {
namespace {

class ExportCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    common_.AddTo(app);
    app.add_option("--modelica", output_dir_, "Output folder for the Modelica files (created if needed)")
        ->required();
    app.add_option("--model", resolution_,
                   "Drive-system model: 'full' (each shaft split into settings.shaft_elements "
                   "elements) or 'reduced' (inertias lumped at gearboxes and stations)")
        ->default_val("full");
    app.add_option("--scenario", options_.scenario, "Scenario driving the model (default: the first)");
    app.add_option("--model-name", options_.model_name,
                   "Modelica name of the model (default: from the project name)");
    app.add_flag("--tables-in-file", options_.tables_in_file,
                 "Write the scenario tables to <model>.txt, read by CombiTimeTable, instead of inline");
    app.add_option("--start", start_,
                   "Start of a drive-system model: 'equilibrium' (where highlift simulate starts: at rest, "
                   "the loads held by the parked brakes, written as fixed start values) or 'rest' (no start "
                   "values: untwisted springs)")
        ->default_val("equilibrium")
        ->check(CLI::IsMember({"equilibrium", "rest"}));
  }

  int Run() override {
    options_.resolution = ModelResolutionFromString(resolution_);
    const Project project = LoadProject(common_.project);
    const ValidationReport validation = ValidateProject(project);
    bool errors = false;
    for (const auto& issue : validation.issues) {
      if (issue.severity != ValidationIssue::Severity::kError) continue;
      errors = true;
      std::cerr << "highlift export: error: " << issue.message;
      if (!issue.where.empty()) std::cerr << " [" << issue.where.ToString() << "]";
      std::cerr << "\n";
    }
    if (errors) {
      std::cerr << "highlift export: the project has errors (see above): fix them, then export "
                   "again ('highlift validate' lists them)\n";
      return kInvalidInput;
    }
    if (start_ == "equilibrium")
      options_.start = [&project](const model::DriveModel& model) {
        return sim::ComputeStartValues(model.network, sim::DriveModel{model}.Options(project));
      };
    ModelicaExportReport report;
    try {
      report = ExportModelica(project, options_, output_dir_);
    } catch (const InputError& e) {
      if (!InterruptRequested()) throw;
      std::cerr << "highlift export: " << e.what() << "\n";  // the folder is as it was
      return kInterruptedExit;
    }
    if (common_.json) {
      nlohmann::json files = nlohmann::json::array();
      for (const auto& f : report.files) files.push_back(f.path);
      nlohmann::json doc = {{"model", report.model_name},
                            {"model_path", report.model_path},
                            {"model_file", report.model_file},
                            {"start", report.start},
                            {"kind", report.kind},
                            {"scenario", report.scenario},
                            {"output_dir", output_dir_},
                            {"instances", report.component_count},
                            {"connections", report.connection_count},
                            {"renamed", report.renamed},
                            {"files", files}};
      std::cout << JsonText(doc) << "\n";
    } else {
      std::cout << report.BriefReport() << "\n";
      std::cout << "written to " << output_dir_ << "/ (load HighLift/package.mo, simulate " << report.model_path
                << "; see docs/modelica.md)\n";
      for (const auto& [from, to] : report.renamed)
        std::cout << "  renamed '" << from << "' -> " << to << "\n";
    }
    return kSuccess;
  }

 private:
  CommonOptions common_;
  ModelicaExportOptions options_;
  std::string output_dir_;
  std::string resolution_ = "full";
  std::string start_ = "equilibrium";
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(ExportCommand, "export",
                          "Write a Modelica model of the project and the HighLift library")

}  // namespace highlift::cli
