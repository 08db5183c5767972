#include "estimated_project.h"

#include <iostream>

#include "highlift/componentdb/database.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"
#include "highlift/estimation/estimator.h"

namespace highlift::cli {

void MarkDesign(Project& project, const std::vector<std::string>& design) {
  for (const std::string& name : design) {
    const auto dot = name.find('.');
    if (dot == std::string::npos) continue;
    Component* c = project.FindComponent(name.substr(0, dot));
    if (!c) continue;
    const auto it = c->parameters.find(name.substr(dot + 1));
    if (it != c->parameters.end()) it->second.design = true;
  }
}

EstimatedProject LoadEstimatedProject(const CommonOptions& options, bool estimate,
                                      const std::vector<std::string>& design) {
  EstimatedProject out{LoadValidProject(options.project), "", 0};
  MarkDesign(out.project, design);
  if (!estimate) return out;
  componentdb::ComponentDatabase database = OpenEstimationDatabase(options.db);
  const estimation::EstimationReport report = estimation::EstimateProject(out.project, &database, {});
  out.estimation_brief = report.BriefReport();
  out.conflicts = static_cast<int>(report.conflicts.size());
  return out;
}

componentdb::ComponentDatabase OpenEstimationDatabase(const std::string& db_option) {
  componentdb::ComponentDatabase database =
      componentdb::OpenDatabase(db_option, componentdb::ComponentDatabase::Mode::kReadOnly);
  if (!db_option.empty()) return database;  // the user's own choice: no seed to compare with
  const std::vector<std::string> differ = componentdb::DifferencesFromSeed(database);
  if (!differ.empty())
    std::cerr << "note: the component database " << database.file().string() << " lacks or holds with other values "
              << differ.size() << " of the parts and materials this highlift ships (e.g. '" << differ.front()
              << "'): it was created by an earlier version, or edited; the estimates use what it holds. To take this "
                 "version's parts run 'highlift db import --seed --replace' (parts you added are kept), or remove "
                 "the file to re-create it\n";
  return database;
}

}  // namespace highlift::cli
