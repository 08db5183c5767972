// Checks of the component graph: unknown types or ports, a port connected twice, a required
// port left open, disconnected sub-systems, inconsistent gear-ratio conventions, parameters out
// of their valid range.
#pragma once

#include <filesystem>
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

/// LoadProject(file) followed by ValidateProject: the project every analysis command reads, so
/// that each refuses what `highlift validate` refuses (a shaft wall thicker than its radius, a
/// port connected twice, ...). Throws InputError with the first error (its location, the number
/// of further errors) when the project has any; warnings are left to `highlift validate`.
Project LoadValidProject(const std::filesystem::path& file);

}  // namespace highlift
