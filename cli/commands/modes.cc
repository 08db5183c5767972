// `highlift modes PROJECT.json [--json] [--elements N] [--modes K]`: lumped models of the
// transmission (full resolution, inertias accumulated at gearboxes and stations, two masses per
// section) and their eigenfrequencies, free and with the PDU clamped, with the first-mode error
// of each reduced model against full resolution. Exit 0, or 2 on invalid input.
#include <iostream>

#include "command.h"
#include "highlift/core/project_io.h"
#include "highlift/reduced_models/analyses.h"

namespace highlift::cli {
namespace {

class ModesCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    options_.AddTo(app);
    app.add_option("--elements", modes_.elements_per_segment,
                   "sub-elements per shaft segment in the full-resolution model (default: project setting)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--modes", modes_.modes, "eigenfrequencies reported per model")->check(CLI::PositiveNumber);
  }
  int Run() override {
    const Project project = LoadProject(options_.project);
    const reduced_models::ModesReport report = reduced_models::AnalyseModes(project, modes_);
    if (options_.json)
      std::cout << report.ToJson().dump(2) << "\n";
    else
      std::cout << report.BriefReport() << "\n\n" << report.FullReport() << "\n";
    return kSuccess;
  }

 private:
  CommonOptions options_;
  reduced_models::ModesOptions modes_;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(ModesCommand, "modes", "lumped models and eigenfrequencies, free and PDU clamped")

}  // namespace highlift::cli
