// Drive-system projects (catalogue components) to a Modelica model of HighLift and MSL
// components. The model is the element network of the model layer (model::BuildDriveModel,
// model/src/drive_network.cc), the one the simulator integrates, written element by element by
// WriteNetworkModel: HighLift classes for HighLift element types, MSL classes for MSL ones.
// Instance names are the element ids as Modelica identifiers (shaft_l1.e1 -> shaft_l1_e1), so
// the columns of `highlift simulate` and the variables of the exported model share their names.
#include <optional>
#include <set>
#include <sstream>

#include "highlift/core/error.h"
#include "highlift/model/drive_network.h"
#include "model_writer.h"
#include "writers.h"

namespace highlift::modelica_detail {

ModelOutput WriteDriveSystem(const Project& project, const std::string& model_name,
                             const ModelicaExportOptions& options) {
  const Scenario* scenario = SelectScenario(project, options);
  model::DriveNetworkOptions drive;
  drive.resolution =
      options.resolution == ModelResolution::kFull ? model::DriveResolution::kFull : model::DriveResolution::kReduced;
  const model::DriveModel model = model::BuildDriveModel(project, scenario, drive);

  // Renamed: a component id that is no identifier (or a reserved name), and an element whose
  // name is not its id with '.' and '-' as '_' (docs/modelica.md) because a project id holds
  // that name. The parts' ids ("shaft_1.e1" -> shaft_1_e1) change by that rule alone.
  std::set<std::string> component_ids;
  for (const Component& c : project.components) component_ids.insert(c.id);
  auto renamed_components = [&](const std::map<std::string, std::string>& renamed) {
    std::map<std::string, std::string> out;
    for (const auto& [from, to] : renamed)
      if (component_ids.count(from) || to != SanitizeModelicaIdentifier(from)) out.emplace(from, to);
    return out;
  };

  // The start: the caller's (the simulator's, from this very network), else none.
  std::optional<model::StartValues> start;
  if (options.start) start = options.start(model);
  if (start && !start->unreached.empty()) {
    std::string nodes;
    for (const auto& n : start->unreached) nodes += (nodes.empty() ? "" : ", ") + n;
    throw InternalError("the start of the flanges " + nodes +
                        " (inside composite elements) cannot be written: no flange of the network reaches them");
  }

  NetworkModel network;
  network.start = start ? &*start : nullptr;
  network.elements = &model.network.elements();
  network.connections = &model.network.connections();
  network.description = project.name;
  network.tables_in_file = options.tables_in_file;
  network.experiment.tolerance = model.relative_tolerance;
  network.experiment.interval = model.output_interval;
  network.experiment.stop_time = model.stop_time;
  network.documentation = [&](const std::map<std::string, std::string>& all_renamed) {
    const LoadCase* load_case = model.load_case.empty() ? nullptr : project.FindLoadCase(model.load_case);
    std::ostringstream doc;
    doc << "<html>\n<p>Drive system of the highlift project <strong>" << HtmlEscape(project.name)
        << "</strong>, exported by <code>highlift export</code> at "
        << (model.resolution == model::DriveResolution::kFull
                ? "full resolution (each torque shaft split into " + std::to_string(model.shaft_elements) + " elements)"
                : std::string("reduced resolution (inertias lumped at gearboxes and stations)"))
        << ". It is the element network that <code>highlift simulate</code> integrates; instance names are "
           "its element ids.</p>\n";
    if (!project.description.empty()) doc << "<p>" << HtmlEscape(project.description) << "</p>\n";
    if (scenario) {
      doc << "<p>Scenario <strong>" << HtmlEscape(scenario->name) << "</strong> (" << HtmlEscape(scenario->kind) << ")";
      if (load_case) doc << ", load case <strong>" << HtmlEscape(load_case->name) << "</strong> (" << load_case->direction << ")";
      doc << ".";
      if (!scenario->description.empty()) doc << " " << HtmlEscape(scenario->description);
      doc << "</p>\n";
    }
    doc << "<p>Positive rotation is the extend direction. ";
    if (start)
      doc << "The model starts where <code>highlift simulate</code> starts, at rest (fixed start values of one "
             "inertia per degree of freedom, initial equations on other flanges); the simulator's start: "
          << HtmlEscape(start->summary) << ".";
    else
      doc << "The model starts at rest with untwisted springs (exported with <code>--start rest</code>; "
             "<code>highlift simulate</code> starts from the static equilibrium of the loads held by the "
             "parked brakes).";
    doc << "</p>\n";
    if (!model.notes.empty()) {
      doc << "<p>Lumped chains (spring-damper or inertia: members):</p>\n<ul>\n";
      for (const auto& n : model.notes) doc << "<li>" << HtmlEscape(n) << "</li>\n";
      doc << "</ul>\n";
    }
    const auto renamed = renamed_components(all_renamed);
    if (!renamed.empty()) {
      doc << "<p>Renamed to valid Modelica identifiers:</p>\n<ul>\n";
      for (const auto& [from, to] : renamed) doc << "<li>" << HtmlEscape(from) << " &rarr; " << to << "</li>\n";
      doc << "</ul>\n";
    }
    doc << "</html>";
    return doc.str();
  };
  ModelOutput out = WriteNetworkModel(network, model_name);
  out.renamed = renamed_components(out.renamed);
  if (scenario) out.scenario = scenario->name;
  return out;
}

}  // namespace highlift::modelica_detail
