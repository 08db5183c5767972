// `highlift peak PROJECT.json [--case NAME] [--json] [--no-intervals]`: single-DOF peak loads
// (paper eq. 1) of every sizing case (jam at each actuator, wing-tip brake after the rupture of
// each shaft segment) with tau_max, where it acts, interval enclosures and the parameters ranked
// by their share of the width; and the worst case per component with its margin. Exit 0 when
// every margin is >= 0, 1 otherwise, 2 on invalid input (an unknown --case lists the cases).
#include <iostream>

#include "command.h"
#include "highlift/core/project_io.h"
#include "highlift/reduced_models/analyses.h"

namespace highlift::cli {
namespace {

class PeakCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    options_.AddTo(app);
    app.add_option("--case", peak_.only_case, "only this sizing case (e.g. jam_l3, rupture_shaft_l2a)");
    app.add_flag("--no-intervals", no_intervals_, "point values only (no enclosures, no ranking)");
  }
  int Run() override {
    const Project project = LoadProject(options_.project);
    peak_.intervals = !no_intervals_;
    peak_.rank = !no_intervals_;
    const reduced_models::PeakReport report = reduced_models::AnalysePeaks(project, peak_);
    if (options_.json)
      std::cout << report.ToJson().dump(2) << "\n";
    else
      std::cout << report.FullReport() << "\n" << report.BriefReport() << "\n";
    return report.ok() ? kSuccess : kViolated;
  }

 private:
  CommonOptions options_;
  reduced_models::PeakOptions peak_;
  bool no_intervals_ = false;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(PeakCommand, "peak", "single-DOF peak loads of the jam and rupture sizing cases")

}  // namespace highlift::cli
