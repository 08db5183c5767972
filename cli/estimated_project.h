// Loading a project for the analyses that work on interval domains (check, tradeoff): the
// parameters without a user value take the estimator's domains (database part, fit, physics
// law, default, in that trust order), with their provenance.
#pragma once

#include <string>
#include <vector>

#include "command.h"
#include "highlift/componentdb/database.h"
#include "highlift/core/project.h"

namespace highlift::cli {

struct EstimatedProject {
  Project project;
  std::string estimation_brief;  ///< "estimated N parameters (...)", empty when not estimated
  int conflicts = 0;             ///< estimates that disagreed with a more trusted source
};

/// Loads `options.project`; unless `estimate` is false, runs the estimator with the database
/// `options.db` (the shipped default when empty). The parameters named in `design`
/// ("component.parameter", e.g. optimize's --design) are marked as design variables first, so
/// that the estimator leaves what follows from them to the constraint network; names the
/// project does not give are left for the caller to report.
EstimatedProject LoadEstimatedProject(const CommonOptions& options, bool estimate,
                                      const std::vector<std::string>& design = {});

/// Marks the parameters named "component.parameter" as design variables (those the project gives).
void MarkDesign(Project& project, const std::vector<std::string>& design);

/// The database for the estimator: `db_option`, or the shipped default when empty. When it is
/// the default and its shipped parts differ from this version's seed (it was created by an
/// earlier highlift, or edited), says so on stderr with the way to take the new parts.
componentdb::ComponentDatabase OpenEstimationDatabase(const std::string& db_option);

}  // namespace highlift::cli
