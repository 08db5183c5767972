// `highlift modes PROJECT.json [--json] [--elements N] [--modes K]`: lumped models of the
// transmission (full resolution, inertias accumulated at gearboxes and stations, two masses per
// section) and their eigenfrequencies, free and with the PDU clamped, with the first-mode error
// of each reduced model against full resolution. Exit 0, or 2 on invalid input.
#include <iostream>

#include "command.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"
#include "highlift/reduced_models/analyses.h"

namespace highlift::cli {
namespace {

/// Sub-elements per shaft segment for the mode analysis: its dense eigenvalue problem takes
/// about 1 s at 100 on an A380-class transmission, and minutes and gigabytes at 1000.
constexpr int kMaxModeElements = 100;

class ModesCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    options_.AddTo(app);
    app.add_option("--elements", modes_.elements_per_segment,
                   "sub-elements per shaft segment in the full-resolution model (default: project setting; at most "
                   "100: the eigenvalue problem grows with the cube)")
        ->check(NumberIn(0, kMaxModeElements));
    app.add_option("--modes", modes_.modes, "eigenfrequencies reported per model")->check(Positive());
  }
  int Run() override {
    const Project project = LoadValidProject(options_.project);
    const int elements = modes_.elements_per_segment > 0 ? modes_.elements_per_segment : project.settings.shaft_elements;
    if (elements > kMaxModeElements)
      throw InputError(std::to_string(elements) + " sub-elements per shaft segment" +
                       (modes_.elements_per_segment > 0 ? " (--elements)" : " (settings 'shaft_elements')") +
                       " are more than the mode analysis handles (" + std::to_string(kMaxModeElements) +
                       "; its dense eigenvalue problem grows with the cube of the model size): give --elements " +
                       std::to_string(kMaxModeElements) + " or fewer");
    const reduced_models::ModesReport report = reduced_models::AnalyseModes(project, modes_);
    if (options_.json)
      std::cout << JsonText(report.ToJson()) << "\n";
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
