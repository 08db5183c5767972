// Internal interface between the export front end (modelica_export.cc) and the two model
// writers.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "highlift/export/modelica.h"

namespace highlift::modelica_detail {

struct ModelOutput {
  std::string text;                        // the model file
  std::vector<GeneratedFile> extra_files;  // e.g. the scenario tables for CombiTimeTable
  std::map<std::string, std::string> renamed;
  std::string scenario;
  int instances = 0;
  int connects = 0;
};

/// A model using MSL classes directly, one instance per element.
ModelOutput WriteElementNetwork(const Project& project, const std::string& model_name,
                                const ModelicaExportOptions& options);

/// A model of the drive system built from HighLift and MSL components.
ModelOutput WriteDriveSystem(const Project& project, const std::string& model_name,
                             const ModelicaExportOptions& options);

/// The HighLift library files, embedded at build time (generated source).
const std::vector<std::pair<std::string_view, std::string_view>>& EmbeddedLibrary();

/// The scenario the options select: the named one (InputError listing the scenarios when it
/// does not exist), else the first one, else nullptr.
const Scenario* SelectScenario(const Project& project, const ModelicaExportOptions& options);

/// A value of a parameter: its nominal value; InputError naming the component, the parameter
/// and the remedy when it has none (an interval only, or a database part not yet resolved).
double RequireValue(const Component& component, const std::string& parameter);

}  // namespace highlift::modelica_detail

namespace highlift::modelica_detail {

/// `text` with &, < and > replaced by HTML entities (for documentation annotations).
std::string HtmlEscape(std::string_view text);

}  // namespace highlift::modelica_detail
