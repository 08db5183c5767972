// Internal interface between the export front end (modelica_export.cc) and the two model
// writers.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "highlift/export/modelica.h"
#include "highlift/model/network.h"
#include "highlift/model/start_values.h"
#include "model_writer.h"

namespace highlift::modelica_detail {

struct ModelOutput {
  std::string text;                        // the model file
  std::string start = "rest";              // the start written (StartValues::summary)
  std::vector<GeneratedFile> extra_files;  // e.g. the scenario tables for CombiTimeTable
  std::map<std::string, std::string> renamed;
  std::string scenario;
  int instances = 0;
  int connects = 0;
};

/// An element network as a Modelica model: one instance per element, the HighLift class of a
/// HighLift element type and the MSL class of an MSL one, named after the element id (made a
/// valid identifier: "shaft_l1.e1" -> shaft_l1_e1), with the parameters the element was given
/// (the class defaults are the element types' defaults) and its description as comment.
struct NetworkModel {
  const std::vector<model::NetworkElement>* elements = nullptr;
  const std::vector<model::NetworkConnection>* connections = nullptr;
  std::string description;      ///< the model's description string
  Experiment experiment;
  bool tables_in_file = false;  ///< tables of CombiTimeTable/CombiTable1Ds in HighLift/Models/<model>.txt
  /// The start to write (fixed start values of inertias, initial equations on other flanges);
  /// null: the model starts as the classes' defaults say.
  const model::StartValues* start = nullptr;
  /// The HTML documentation, given the ids renamed to Modelica identifiers (id -> name).
  std::function<std::string(const std::map<std::string, std::string>&)> documentation;
};
ModelOutput WriteNetworkModel(const NetworkModel& network, const std::string& model_name);

/// A model using MSL classes directly, one instance per element of the project's element
/// network (WriteNetworkModel).
ModelOutput WriteElementNetwork(const Project& project, const std::string& model_name,
                                const ModelicaExportOptions& options);

/// A model of the drive system: the element network of the model layer
/// (model::BuildDriveModel, the one the simulator integrates) written by WriteNetworkModel.
ModelOutput WriteDriveSystem(const Project& project, const std::string& model_name,
                             const ModelicaExportOptions& options);

/// The package of the exported models, "HighLift.Models", and its folder "HighLift/Models".
inline constexpr const char* kModelsPackage = "HighLift.Models";
inline constexpr const char* kModelsFolder = "HighLift/Models";

/// HighLift/Models/package.order for a folder that gets the model `model_name`: the models the
/// folder's order lists whose file exists, the model files it does not list (sorted), then
/// `model_name` unless listed.
std::string MergedModelsPackageOrder(const std::filesystem::path& output_dir, const std::string& model_name);

/// Writes `files` below `output_dir`, all or none (see ExportModelica).
void WriteFilesAllOrNothing(const std::vector<GeneratedFile>& files, const std::filesystem::path& output_dir);

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
