// Checks of the component graph: unknown types or ports, a port connected twice, a required
// port left open, disconnected sub-systems, inconsistent gear-ratio conventions, parameters out
// of their valid range.
#pragma once

#include <string>
#include <vector>

#include "highlift/core/project.h"

namespace highlift {

struct ValidationIssue {
  enum class Severity { kError, kWarning };
  Severity severity = Severity::kError;
  std::string component;   ///< component id, empty for project-wide issues
  std::string port;        ///< port name where relevant
  std::string message;     ///< names the thing, the problem and the remedy
  SourceLocation where;
};

struct ValidationReport {
  std::vector<ValidationIssue> issues;
  bool ok() const;         ///< no errors (warnings allowed)
  std::string BriefReport() const;
  std::string FullReport() const;
};

ValidationReport ValidateProject(const Project& project);

}  // namespace highlift
