// `highlift size PROJECT.json [--json] [--no-intervals]`: steady-state sizing (reduced_models):
// torque in every component for every load case, PDU torque and power, recommended limiter and
// brake settings, margins against allowables. Exit 0 when every setting and margin is within
// its rule, 1 otherwise, 2 on invalid input.
#include <iostream>

#include "command.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"
#include "highlift/reduced_models/sizing.h"

namespace highlift::cli {
namespace {

class SizeCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    options_.AddTo(app);
    app.add_flag("--no-intervals", no_intervals_, "point values only (no enclosures over the parameter domains)");
    app.add_option("--tightness", tightness_,
                   "points of the domains sampled to measure how tight each enclosure is (width over the hull of "
                   "the sampled values, in the JSON); default 32 with --json, else 0")
        ->check(NumberIn(0, 100000));
  }
  int Run() override {
    const Project project = LoadValidProject(options_.project);
    reduced_models::SizingOptions options;
    options.intervals = !no_intervals_;
    options.tightness_samples = tightness_ >= 0 ? tightness_ : (options_.json ? kDefaultTightnessSamples : 0);
    const reduced_models::SizingReport report = reduced_models::Size(project, options);
    if (options_.json)
      std::cout << JsonText(report.ToJson()) << "\n";
    else
      std::cout << report.BriefReport() << "\n\n" << report.FullReport() << "\n";
    return report.ok() ? kSuccess : kViolated;
  }

 private:
  CommonOptions options_;
  bool no_intervals_ = false;
  int tightness_ = -1;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(SizeCommand, "size", "steady-state sizing: torque flow, PDU power, limiter and brake settings")

}  // namespace highlift::cli
