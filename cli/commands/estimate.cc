// highlift estimate PROJECT.json: fills in parameters without a user value from the component
// database, fits over its parts and physics laws, in trust order, and reports each value with
// its provenance. --write OUT.json saves the project with the estimates filled in.
#include <iostream>

#include "command.h"
#include "estimated_project.h"
#include "highlift/componentdb/database.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"
#include "highlift/estimation/estimator.h"

namespace highlift::cli {
namespace {

class EstimateCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    common_.AddTo(app);
    app.add_option("--write", write_, "Write the project with the estimates filled in to this file");
    app.add_flag("--all", all_, "List every parameter, not only the ones the estimator changed");
    app.add_flag("--no-db", no_db_, "Do not use the component database (physics laws only)");
    app.add_option("--confidence", options_.confidence, "Confidence of the fits' prediction intervals (default 0.9)");
    app.add_option("--min-fit-parts", options_.min_fit_parts, "Fewest database parts for a fit (default 4)")
        ->check(NumberIn(3, 1e6));  // unsigned: CLI11 would wrap -1 to 2^64-1
  }

  int Run() override {
    options_.Validate();
    Project project = LoadValidProject(common_.project);
    std::optional<componentdb::ComponentDatabase> database;
    if (!no_db_) database.emplace(OpenEstimationDatabase(common_.db));
    const auto report = estimation::EstimateProject(project, database ? &*database : nullptr, options_);
    if (!write_.empty()) SaveProject(project, write_);
    if (common_.json) {
      auto j = report.ToJson();
      j["project"] = common_.project;
      j["database"] = database ? database->file().string() : "";
      if (!write_.empty()) j["written"] = write_;
      std::cout << JsonText(j) << "\n";
    } else {
      std::cout << report.BriefReport() << "\n"
                << "project " << common_.project << ", database "
                << (database ? database->file().string() : std::string("(none)")) << "\n\n"
                << report.FullReport(all_);
      if (!write_.empty()) std::cout << "wrote " << write_ << "\n";
    }
    for (const auto& c : report.conflicts) std::cerr << "highlift estimate: conflict: " << c.message << "\n";
    return report.status == estimation::EstimationReport::Status::kOk ? kSuccess : kViolated;
  }

 private:
  CommonOptions common_;
  estimation::EstimationOptions options_;
  std::string write_;
  bool all_ = false;
  bool no_db_ = false;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(EstimateCommand, "estimate",
                          "Estimate unknown parameters from the component database, fits and physics, with provenance")

}  // namespace highlift::cli
