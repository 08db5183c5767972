// The report's Synthesis section: a result of `highlift optimize --json` read back, checked
// against the project the report describes, and shaped for the page (status, objective with its
// certified bound, design table, what limits the design, mass by component, the Pareto front).
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "highlift/campaign/campaign.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/optimize/optimize.h"
#include "highlift/report/report.h"

namespace highlift::report {
namespace {

using Json = nlohmann::json;
using Pointer = nlohmann::json::json_pointer;

/// What a valid file is, for every message: the document `highlift optimize --json` prints.
constexpr const char* kValidResult =
    "give the document `highlift optimize PROJECT --json` prints, saved with `> FILE`, of this project";

/// Reads the optimize document with the JSON path of every value, so that a message names the
/// file, where in it, what was found and what would be valid.
class ResultReader {
 public:
  ResultReader(const Json& root, std::string file) : root_(root), file_(std::move(file)) {}

  [[noreturn]] void Fail(const Pointer& at, const std::string& problem) const {
    throw InputError("--optimize " + file_ + ": " + (at.empty() ? std::string("the document") : at.to_string()) + ": " +
                     problem + "; " + kValidResult);
  }
  const Json* Find(const Pointer& at) const { return root_.contains(at) ? &root_.at(at) : nullptr; }
  const Json& Get(const Pointer& at) const {
    const Json* j = Find(at);
    if (!j) Fail(at, "missing");
    return *j;
  }
  static std::string Found(const Json& j) {
    std::string text = j.dump(-1, ' ', false, Json::error_handler_t::replace);
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return std::string(j.type_name()) + " " + text;
  }
  std::string String(const Pointer& at) const {
    const Json& j = Get(at);
    if (!j.is_string()) Fail(at, "expected a string, found " + Found(j));
    return j.get<std::string>();
  }
  /// A finite number; `nullable`: null as well (returned as null).
  Json Number(const Pointer& at, bool nullable = false) const {
    const Json* j = Find(at);
    if (!j && nullable) return nullptr;
    if (!j) Fail(at, "missing");
    if (j->is_null() && nullable) return nullptr;
    if (!j->is_number()) Fail(at, std::string("expected a number") + (nullable ? " or null" : "") + ", found " + Found(*j));
    const double v = j->get<double>();
    if (!std::isfinite(v)) Fail(at, "expected a finite number, found " + Found(*j));
    return v;
  }
  const Json& Array(const Pointer& at) const {
    const Json& j = Get(at);
    if (!j.is_array()) Fail(at, "expected an array, found " + Found(j));
    return j;
  }
  const Json& Object(const Pointer& at) const {
    const Json& j = Get(at);
    if (!j.is_object()) Fail(at, "expected an object, found " + Found(j));
    return j;
  }

 private:
  const Json& root_;
  std::string file_;
};

std::string StatusInWords(optimize::Status s) {
  switch (s) {
    case optimize::Status::kOptimal:
      return "optimal: the best design is within the gap tolerance of the certified lower bound";
    case optimize::Status::kStoppedAtLimit:
      return "stopped at a limit (boxes or time): a design, with the gap still open (the bound is certified, only "
             "looser)";
    case optimize::Status::kInfeasible:
      return "proved infeasible: no design within the domains of the design variables meets every constraint";
    case optimize::Status::kNoDesignFound:
      return "no design found within the limits: not a proof that none exists";
  }
  return "";
}

}  // namespace

nlohmann::json SynthesisJson(const Project& project, const nlohmann::json& result, const std::string& file) {
  const ResultReader in(result, file);
  if (!result.is_object()) in.Fail(Pointer(), "expected a JSON object, found " + ResultReader::Found(result));
  Json out;
  out["file"] = file;

  // Whose result: the project the report describes, as optimize read it, or the design it wrote.
  const std::string hash = campaign::ProjectHash(project);
  const std::string result_hash = in.String(Pointer("/project_hash"));
  const Json* design_hash = in.Find(Pointer("/design_hash"));
  const std::string result_name = result.contains("project_name") && result["project_name"].is_string()
                                      ? result["project_name"].get<std::string>()
                                      : std::string("?");
  if (result_hash == hash) {
    out["relation"] = "project";
  } else if (design_hash && design_hash->is_string() && design_hash->get<std::string>() == hash) {
    out["relation"] = "design";
  } else {
    in.Fail(Pointer("/project_hash"),
            "the result is of project '" + result_name + "' (content hash " + result_hash +
                (design_hash && design_hash->is_string() ? ", its written design " + design_hash->get<std::string>() : "") +
                "), and " + project.file + " holds '" + project.name + "' (hash " + hash +
                "): another project, or this one changed since optimize read it; valid are the project optimize read, "
                "unchanged, and the design its --write wrote; run `highlift optimize " + project.file +
                " --json > FILE` again");
  }
  out["project_name"] = result_name;
  out["project_file"] = result.contains("project") && result["project"].is_string() ? result["project"] : Json("");

  const std::string status_text = in.String(Pointer("/status"));
  const std::optional<optimize::Status> status = optimize::StatusFromString(status_text);
  if (!status)
    in.Fail(Pointer("/status"), "'" + status_text +
                                    "' is no status of optimize (optimal, stopped_at_limit, infeasible, no_design_found)");
  const bool found = *status == optimize::Status::kOptimal || *status == optimize::Status::kStoppedAtLimit;
  out["status"] = status_text;
  out["status_words"] = StatusInWords(*status);
  out["found"] = found;
  out["message"] = result.contains("message") && result["message"].is_string() ? result["message"] : Json("");
  out["objective"] = in.String(Pointer("/objective"));
  out["objective_unit"] = in.String(Pointer("/objective_unit"));
  out["best"] = in.Number(Pointer("/best"), !found);
  out["lower_bound"] = in.Number(Pointer("/lower_bound"), true);
  out["gap"] = in.Number(Pointer("/gap"), !found);

  // The design table; each name must be a parameter of this project.
  std::map<std::string, std::string> units;
  Json design = Json::array();
  const Json& variables = in.Array(Pointer("/design"));
  for (std::size_t i = 0; i < variables.size(); ++i) {
    const Pointer at = Pointer("/design") / i;
    const std::string name = in.String(at / "name");
    const auto dot = name.find('.');
    const Component* c = dot == std::string::npos ? nullptr : project.FindComponent(name.substr(0, dot));
    if (!c || !c->parameters.count(name.substr(dot + 1)))
      in.Fail(at / "name", "'" + name + "' is no parameter of " + project.file + " (give COMPONENT.PARAMETER of it)");
    const Json& domain = in.Array(at / "domain");
    if (domain.size() != 2) in.Fail(at / "domain", "expected [lower, upper], found " + ResultReader::Found(domain));
    const std::string unit = in.String(at / "unit");
    units[name] = unit;
    design.push_back({{"name", name},
                      {"component", c->id},
                      {"unit", unit},
                      {"value", in.Number(at / "value")},
                      {"lower", in.Number(at / "domain" / std::size_t{0})},
                      {"upper", in.Number(at / "domain" / std::size_t{1})},
                      {"nominal", in.Number(at / "nominal", true)},
                      {"at_bound", in.String(at / "at_bound")}});
  }
  out["design"] = design;

  Json active = Json::array();
  const Json& constraints = in.Array(Pointer("/active_constraints"));
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const Pointer at = Pointer("/active_constraints") / i;
    active.push_back({{"label", in.String(at / "label")},
                      {"description", in.String(at / "description")},
                      {"text", in.String(at / "text")}});
  }
  out["active_constraints"] = active;

  Json mass = Json::array();
  const Json& terms = in.Array(Pointer("/mass_terms"));
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const Pointer at = Pointer("/mass_terms") / i;
    mass.push_back({{"component", in.String(at / "component")},
                    {"law", in.String(at / "law")},
                    {"min", in.Number(at / "min", true)},
                    {"max", in.Number(at / "max", true)}});
  }
  out["mass_terms"] = mass;

  out["explanation"] = in.Find(Pointer("/explanation")) ? Json(in.String(Pointer("/explanation"))) : Json("");
  Json rejections = Json::array();
  if (in.Find(Pointer("/rejections"))) {
    const Json& r = in.Array(Pointer("/rejections"));
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Pointer at = Pointer("/rejections") / i;
      rejections.push_back({{"check", in.String(at / "check")}, {"candidates", in.Number(at / "candidates")}});
    }
  }
  out["rejections"] = rejections;
  Json parts = Json::object();
  if (in.Find(Pointer("/parts")))
    for (const auto& [component, designation] : in.Object(Pointer("/parts")).items())
      parts[component] = in.String(Pointer("/parts") / component);
  out["parts"] = parts;
  // With --tube-sizes: the table and each restricted shaft's size.
  Json tubes = Json::object();
  if (in.Find(Pointer("/tube_sizes"))) {
    const Pointer at = Pointer("/tube_sizes");
    tubes["table"] = in.String(at / "table");
    Json shafts = Json::object();
    for (const auto& [component, size] : in.Object(at / "shafts").items()) shafts[component] = in.String(at / "shafts" / component);
    tubes["shafts"] = shafts;
  }
  out["tube_sizes"] = tubes;
  out["counters"] = in.Find(Pointer("/counters")) ? in.Object(Pointer("/counters")) : Json::object();

  // The Pareto front: each point with its design as rows (name, value, unit).
  out["pareto"] = nullptr;
  if (in.Find(Pointer("/pareto"))) {
    const Pointer p("/pareto");
    in.Object(p);
    const Json& objectives = in.Array(p / "objectives");
    const Json& pareto_units = in.Array(p / "units");
    if (objectives.size() != 2) in.Fail(p / "objectives", "expected [OBJ1, OBJ2], found " + ResultReader::Found(objectives));
    if (pareto_units.size() != 2) in.Fail(p / "units", "expected [unit1, unit2], found " + ResultReader::Found(pareto_units));
    Json front = Json::array();
    const Json& points = in.Array(p / "front");
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Pointer at = p / "front" / i;
      Json point_design = Json::array();
      for (const auto& [name, value] : in.Object(at / "design").items()) {
        const auto u = units.find(name);
        if (u == units.end()) in.Fail(at / "design" / name, "'" + name + "' is none of the result's design variables (/design)");
        point_design.push_back({{"name", name}, {"value", in.Number(at / "design" / name)}, {"unit", u->second}});
      }
      front.push_back({{"epsilon", in.Number(at / "epsilon")},
                       {"objective", in.Number(at / "objective", true)},
                       {"lower_bound", in.Number(at / "lower_bound", true)},
                       {"second", in.Number(at / "second", true)},
                       {"status", in.String(at / "status")},
                       {"design", point_design}});
    }
    out["pareto"] = {{"objectives", {in.String(p / "objectives" / std::size_t{0}), in.String(p / "objectives" / std::size_t{1})}},
                     {"units", {in.String(p / "units" / std::size_t{0}), in.String(p / "units" / std::size_t{1})}},
                     {"front", front}};
  }
  return out;
}

nlohmann::json ReadSynthesis(const Project& project, const std::filesystem::path& file) {
  RegisterInputFile(file);  // the report is never written over it
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file))
    throw InputError("--optimize " + file.string() + ": cannot read the file (" +
                     (std::filesystem::exists(file) ? "not a readable file" : "no such file") + "); " + kValidResult);
  std::ostringstream text;
  text << in.rdbuf();
  nlohmann::json result;
  try {
    result = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError("--optimize " + file.string() + ": not JSON (" + e.what() + "); " + kValidResult);
  }
  return SynthesisJson(project, result, file.string());
}

}  // namespace highlift::report
