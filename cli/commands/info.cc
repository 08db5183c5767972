// `highlift info PROJECT.json [--json] [--brief]`: a readable description of a project: components
// by type, shaft length and mass per wing, the stations, the inertia reflected to the PDU output,
// and the parameters that are still unknown or wide, with their provenance. The computation is
// highlift::model::DescribeProject (model/describe.h). Exit 0, or 2 when the project is invalid.
// `highlift info --types` / `--elements` list the catalogue's component / element types instead.
#include <cmath>
#include <iostream>

#include <nlohmann/json.hpp>

#include "command.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/core/text_table.h"
#include "highlift/core/units.h"
#include "highlift/core/validate.h"
#include "highlift/model/describe.h"

namespace highlift::cli {
namespace {

std::string ShowSI(double si, const ParameterSpec& p) {
  if (std::isinf(si)) return si > 0 ? "inf" : "-inf";
  try {
    return FormatNumber(FromSI(si, p.unit, p.dimension));
  } catch (const InputError&) {
    return FormatNumber(si);
  }
}

nlohmann::json TypeJson(const ComponentTypeSpec& t) {
  nlohmann::json ports = nlohmann::json::array();
  for (const auto& port : t.ports)
    ports.push_back({{"name", port.name},
                     {"kind", PortKindName(port.kind)},
                     {"required", port.required},
                     {"description", port.description}});
  nlohmann::json parameters = nlohmann::json::array();
  for (const auto& p : t.parameters) {
    nlohmann::json j = {{"name", p.name}, {"symbol", p.symbol}, {"unit", p.unit},
                        {"dimension", DescribeDimension(p.dimension)}, {"optional", p.optional},
                        {"description", p.description}, {"source", p.source},
                        {"referred_to", ToString(p.referred_to)}};
    if (p.kind == ParameterKind::kScalar || p.kind == ParameterKind::kInteger) {
      j["nominal"] = p.nominal ? nlohmann::json(ShowSI(*p.nominal, p)) : nlohmann::json(nullptr);
      j["default_domain"] = {ShowSI(p.default_domain.lo, p), ShowSI(p.default_domain.hi, p)};
      j["valid_range"] = {ShowSI(p.valid_range.lo, p), ShowSI(p.valid_range.hi, p)};
    }
    parameters.push_back(std::move(j));
  }
  return {{"name", t.name}, {"display_name", t.display_name}, {"description", t.description},
          {"ports", ports}, {"parameters", parameters}};
}

/// Lists component or element types: a table (type, ports, parameters with the gear side their
/// value counts on) or a JSON array.
int ListTypes(const std::vector<ComponentTypeSpec>& types, bool json) {
  if (json) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& t : types) a.push_back(TypeJson(t));
    std::cout << JsonText(a) << "\n";
    return kSuccess;
  }
  TextTable table({"type", "ports (* optional)", "parameters"});
  for (const auto& t : types) {
    std::string ports, parameters;
    for (const auto& port : t.ports) ports += (ports.empty() ? "" : " ") + port.name + (port.required ? "" : "*");
    // name@side for the values referred to a gear side (inertias, stiffnesses, torques, ...).
    for (const auto& p : t.parameters)
      parameters += (parameters.empty() ? "" : " ") + p.name +
                    (p.referred_to == ReferenceSide::kNone ? "" : std::string("@") + ToString(p.referred_to));
    table.AddRow({t.name, ports, parameters});
  }
  std::cout << table.ToString();
  return kSuccess;
}

class InfoCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    options_.AddTo(app, /*project_required=*/false);
    app.add_flag("--types", types_, "List the drive-system component types of the catalogue instead");
    app.add_flag("--elements", elements_, "List the element types (element-level networks) instead");
    app.add_flag("--brief", brief_, "Print the one-line summary only");
    app.add_option("--wide", describe_.wide_relative_width,
                   "Relative domain width (hi - lo) / |mid| above which a parameter is listed as wide")
        ->capture_default_str()
        ->check(NonNegative());
  }

  int Run() override {
    if (types_) return ListTypes(ComponentTypes(), options_.json);
    if (elements_) return ListTypes(ElementTypes(), options_.json);
    if (options_.project.empty()) {
      throw InputError("no project file given; usage: highlift info PROJECT.json [--json] [--brief], or "
                       "highlift info --types | --elements");
    }
    Project project;
    try {
      project = LoadProject(options_.project);
    } catch (const InputError& e) {
      return Fail(e.what(), e.message(), e.where());
    }
    const ValidationReport report = ValidateProject(project);
    if (!report.ok()) {
      for (const auto& issue : report.issues) {
        if (issue.severity != ValidationIssue::Severity::kError) continue;
        std::cerr << "error: " << issue.message;
        if (!issue.where.empty()) std::cerr << " [" << issue.where.ToString() << "]";
        std::cerr << "\n";
      }
      return Fail(options_.project + ": the component graph has errors; run `highlift validate " +
                      options_.project + "` and fix them",
                  "the component graph has errors", {});
    }
    const model::ProjectDescription description = model::DescribeProject(project, describe_);
    if (options_.json) {
      nlohmann::json doc = description.ToJson();
      doc["file"] = options_.project;
      doc["brief"] = description.BriefReport();
      std::cout << JsonText(doc) << "\n";
    } else if (brief_) {
      std::cout << description.BriefReport() << "\n";
    } else {
      std::cout << description.FullReport();
    }
    return kSuccess;
  }

 private:
  /// Reports an invalid input (stderr; with --json also a JSON document on stdout), exit 2.
  int Fail(const std::string& text, const std::string& message, const SourceLocation& where) {
    if (options_.json) {
      nlohmann::json location = nlohmann::json::object();
      if (!where.file.empty()) location["file"] = where.file;
      if (!where.json_pointer.empty()) location["json_pointer"] = where.json_pointer;
      if (where.line > 0) location["line"] = where.line;
      if (where.column > 0) location["column"] = where.column;
      std::cout << JsonText(nlohmann::json{{"file", options_.project},
                                           {"ok", false},
                                           {"error", {{"message", message}, {"location", location}}}})
                << "\n";
    }
    std::cerr << "highlift info: error: " << text << "\n";
    return kInvalidInput;
  }

  CommonOptions options_;
  model::DescribeOptions describe_;
  bool brief_ = false;
  bool types_ = false;
  bool elements_ = false;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(InfoCommand, "info",
                          "Describe a project: components, shafts, stations, reflected inertia, unknown parameters")

}  // namespace highlift::cli
