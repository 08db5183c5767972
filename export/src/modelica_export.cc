// Front end of the Modelica export: options, the library files, model naming, writing files.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "highlift/core/error.h"
#include "highlift/export/modelica.h"
#include "writers.h"

namespace highlift {
namespace modelica_detail {

const Scenario* SelectScenario(const Project& project, const ModelicaExportOptions& options) {
  if (options.scenario.empty()) return project.scenarios.empty() ? nullptr : &project.scenarios.front();
  for (const auto& s : project.scenarios)
    if (s.name == options.scenario) return &s;
  std::string names;
  for (const auto& s : project.scenarios) names += (names.empty() ? "" : ", ") + s.name;
  throw InputError("unknown scenario '" + options.scenario + "': " +
                   (names.empty() ? std::string("the project has no scenarios")
                                  : "use one of " + names));
}

double RequireValue(const Component& component, const std::string& parameter) {
  auto it = component.parameters.find(parameter);
  if (it == component.parameters.end())
    throw InputError("component '" + component.id + "' (" + component.type + "): parameter '" + parameter +
                         "' is missing: give it in the project file",
                     component.where);
  const Parameter& p = it->second;
  if (p.nominal) return *p.nominal;
  std::string remedy = !p.database_part.empty()
                           ? "it refers to database part '" + p.database_part +
                                 "': resolve it with 'highlift estimate' first, or give a value"
                           : "it has only an interval domain: give a value (e.g. {\"value\": ..., \"min\": ..., \"max\": ...})";
  throw InputError("component '" + component.id + "' (" + component.type + "): parameter '" + parameter +
                       "' has no value to export; " + remedy,
                   p.where.empty() ? component.where : p.where);
}

std::string HtmlEscape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace modelica_detail

namespace {

// Longest model name taken from a project name (a longer one is cut at a word): the model file
// name must stay below the file systems' 255 bytes, with room for ".mo"/".txt".
constexpr std::size_t kMaxDerivedModelName = 80;

// "A380-class flap transmission (both wings)" -> "A380ClassFlapTransmissionBothWings";
// letters with diacritics lose them ("Ünïcödé Rig" -> "UnicodeRig").
std::string ModelNameFromProject(const std::string& project_name) {
  std::string name;
  std::size_t last_word = 0;  // where the last word that fits starts
  bool start_word = true;
  for (char ch : TransliterateToAscii(project_name)) {
    const auto c = static_cast<unsigned char>(ch);
    if (std::isalnum(c) && c < 0x80) {
      if (start_word && name.size() <= kMaxDerivedModelName) last_word = name.size();
      name += start_word ? static_cast<char>(std::toupper(c)) : ch;
      start_word = false;
    } else {
      start_word = true;
    }
  }
  if (name.size() > kMaxDerivedModelName) name.resize(last_word > 0 ? last_word : kMaxDerivedModelName);
  if (name.empty()) name = "HighLiftModel";
  if (std::isdigit(static_cast<unsigned char>(name.front()))) name = "Model" + name;
  if (name == "HighLift" || name == "Modelica") name += "Model";
  return SanitizeModelicaIdentifier(name);
}

// HighLift/Models/package.mo: the package of the exported models.
std::string ModelsPackageText() {
  return "within HighLift;\n"
         "package Models \"Models of highlift projects, written by highlift export\"\n"
         "  extends Modelica.Icons.Package;\n"
         "\n"
         "  annotation (Documentation(info=\"<html>\n"
         "<p>\n"
         "The models of drive systems and element networks that <code>highlift export</code> wrote into\n"
         "this copy of the library, one class per export. Each is the element network that\n"
         "<code>highlift simulate</code> integrates; see its documentation for the scenario and the start.\n"
         "</p>\n"
         "</html>\"));\n"
         "end Models;\n";
}

}  // namespace

void ModelicaExportOptions::Validate() const {
  if (!model_name.empty() && !IsModelicaIdentifier(model_name))
    throw InputError("model name '" + model_name +
                     "' is no Modelica identifier: use letters, digits and '_', starting with a letter, "
                     "and no keyword (e.g. '" + SanitizeModelicaIdentifier(model_name) + "')");
  if (model_name == "HighLift" || model_name == "Modelica")
    throw InputError("model name '" + model_name + "' would hide the package of the same name: choose another");
}

std::vector<GeneratedFile> HighLiftLibraryFiles() {
  std::vector<GeneratedFile> files;
  for (const auto& [path, content] : modelica_detail::EmbeddedLibrary())
    files.push_back({std::string(path), std::string(content)});
  std::sort(files.begin(), files.end(), [](const GeneratedFile& a, const GeneratedFile& b) { return a.path < b.path; });
  return files;
}

std::string ModelicaExportReport::BriefReport() const {
  std::ostringstream s;
  s << "Modelica model '" << model_name << "' (" << kind;
  if (!scenario.empty()) s << ", scenario '" << scenario << "'";
  s << "): " << component_count << " instances, " << connection_count << " connections; start: " << start
    << "; " << files.size() << " files (the HighLift package with " << model_path << ")";
  return s.str();
}

ModelicaExportReport GenerateModelica(const Project& project, const ModelicaExportOptions& options) {
  options.Validate();
  ModelicaExportReport report;
  report.model_name = options.model_name.empty() ? ModelNameFromProject(project.name) : options.model_name;
  modelica_detail::ModelOutput model;
  if (!project.components.empty()) {
    report.kind = "drive system, " + ToString(options.resolution);
    model = modelica_detail::WriteDriveSystem(project, report.model_name, options);
  } else if (!project.elements.empty()) {
    report.kind = "element network";
    model = modelica_detail::WriteElementNetwork(project, report.model_name, options);
  } else {
    throw InputError("project '" + project.name +
                     "' has neither components nor elements: there is nothing to export; add "
                     "'components' (a drive system) or 'elements' (an element network)");
  }
  report.model_path = std::string(modelica_detail::kModelsPackage) + "." + report.model_name;
  report.model_file = std::string(modelica_detail::kModelsFolder) + "/" + report.model_name + ".mo";
  report.start = model.start;
  report.scenario = model.scenario;
  report.renamed = model.renamed;
  report.component_count = model.instances;
  report.connection_count = model.connects;
  report.files = HighLiftLibraryFiles();
  // The model is a class of HighLift.Models: one top-level class, loaded with HighLift.
  for (auto& f : report.files)
    if (f.path == "HighLift/package.order") f.content += "Models\n";
  report.files.push_back({std::string(modelica_detail::kModelsFolder) + "/package.mo", ModelsPackageText()});
  report.files.push_back({std::string(modelica_detail::kModelsFolder) + "/package.order", report.model_name + "\n"});
  report.files.push_back({report.model_file, model.text});
  for (auto& f : model.extra_files) report.files.push_back(std::move(f));
  std::sort(report.files.begin(), report.files.end(),
            [](const GeneratedFile& a, const GeneratedFile& b) { return a.path < b.path; });
  return report;
}

ModelicaExportReport ExportModelica(const Project& project, const ModelicaExportOptions& options,
                                    const std::filesystem::path& output_dir) {
  ModelicaExportReport report = GenerateModelica(project, options);
  // Several exports share the folder: the order lists every model in it.
  for (auto& f : report.files)
    if (f.path == std::string(modelica_detail::kModelsFolder) + "/package.order")
      f.content = modelica_detail::MergedModelsPackageOrder(output_dir, report.model_name);
  modelica_detail::WriteFilesAllOrNothing(report.files, output_dir);
  return report;
}

}  // namespace highlift
