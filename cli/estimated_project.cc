#include "estimated_project.h"

#include "highlift/componentdb/database.h"
#include "highlift/core/project_io.h"
#include "highlift/estimation/estimator.h"

namespace highlift::cli {

EstimatedProject LoadEstimatedProject(const CommonOptions& options, bool estimate) {
  EstimatedProject out{LoadProject(options.project), "", 0};
  if (!estimate) return out;
  componentdb::ComponentDatabase database =
      componentdb::OpenDatabase(options.db, componentdb::ComponentDatabase::Mode::kReadOnly);
  const estimation::EstimationReport report = estimation::EstimateProject(out.project, &database, {});
  out.estimation_brief = report.BriefReport();
  out.conflicts = static_cast<int>(report.conflicts.size());
  return out;
}

}  // namespace highlift::cli
