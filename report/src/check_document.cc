// The `highlift check --json` document, shared by `highlift check` and the report's summary so
// that both say the same.
#include <cmath>

#include "highlift/report/report.h"

namespace highlift::report {
namespace {

nlohmann::json RangeJson(const icsp::Interval& x) {
  if (icsp::IsEmpty(x)) return nullptr;
  auto number = [](double v) -> nlohmann::json {
    if (std::isfinite(v)) return v;
    return v > 0 ? "inf" : "-inf";
  };
  return nlohmann::json::array({number(x.lower()), number(x.upper())});
}

}  // namespace

std::vector<std::string> ConflictLabels(const icsp::DriveSystemNetwork& net, const icsp::Explanation& explanation) {
  std::vector<std::string> out;
  for (int c : explanation.conflict) out.push_back(net.network.constraint(icsp::ConstraintId{c}).info.label);
  return out;
}

nlohmann::json CheckDocument(const Project& project, const icsp::DriveSystemNetwork& net,
                             const icsp::CheckResult& r, const std::string& estimation_brief) {
  // Stopped at a limit: no conflict was proved, and none was ruled out either.
  const bool stopped = r.report.status == icsp::Status::kStoppedAtLimit;
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : r.parameters) {
    params.push_back({{"name", p.name}, {"unit", p.unit}, {"provenance", p.provenance},
                      {"initial", RangeJson(p.initial)}, {"final", RangeJson(p.final)},
                      {"narrowing_percent", p.narrowing_percent}});
  }
  nlohmann::json doc = {{"project", project.name},
                        {"status", icsp::ToString(r.report.status)},
                        {"all_requirements_met", stopped ? nlohmann::json(nullptr) : nlohmann::json(r.feasible)},
                        {"revisions", r.report.revisions},
                        {"seconds", r.report.seconds},
                        {"physics_constraints", net.physics_constraints},
                        {"requirements", net.requirement_constraints},
                        {"estimation", estimation_brief},
                        {"scope", kCheckScope},
                        {"parameters", params}};
  if (r.nominal_checked) {
    nlohmann::json nominal = {{"all_requirements_met", r.nominal_feasible}};
    if (!r.nominal_feasible) {
      nominal["violated_requirements"] = ConflictLabels(net, r.nominal_explanation);
      nominal["explanation"] = r.nominal_explanation.text;
    }
    doc["nominal_design"] = nominal;
  }
  if (!r.feasible) {
    doc["violated_requirements"] = ConflictLabels(net, r.explanation);
    doc["physics_alone"] = r.explanation.physics_alone;
    doc["explanation"] = r.explanation.text;
  }
  return doc;
}

}  // namespace highlift::report

namespace highlift::report {
namespace {

std::string JoinNames(const nlohmann::json& names, const std::string& last_separator) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? last_separator : ", ";
    out += names[i].get<std::string>();
  }
  return out;
}

}  // namespace

Verdict DescribeVerdict(const nlohmann::json& doc) {
  Verdict v;
  const int requirements = doc.value("requirements", 0);
  const std::string count = std::to_string(requirements) + (requirements == 1 ? " requirement" : " requirements");
  const nlohmann::json& met = doc.at("all_requirements_met");
  if (met.is_null()) {
    v.status = "undecided";
    v.headline = "undecided: interval propagation stopped at a limit before a fixed point";
    v.domains = "Parameter domains: no requirement was proved violated, but the domains may narrow further and a "
                "conflict may remain; raise the limit or use --ratio.";
    return v;
  }
  if (!met.get<bool>()) {
    const nlohmann::json& violated = doc.at("violated_requirements");
    v.status = "infeasible";
    if (violated.empty()) {
      v.headline = "infeasible: the component data alone conflict, before any requirement";
      v.domains = "Parameter domains: no values within them satisfy the physics of the components (no requirement "
                  "takes part in the conflict).";
    } else {
      v.headline = "infeasible: no values within the parameter domains meet " + JoinNames(violated, " and ") +
                   (violated.size() > 1 ? " together" : "");
      v.domains = "Parameter domains: the requirement" + std::string(violated.size() > 1 ? "s " : " ") +
                  JoinNames(violated, ", ") + (violated.size() > 1 ? " cannot be met together" : " cannot be met") +
                  " by any values within the domains (of the " + count + ").";
    }
    return v;
  }
  v.domains = "Parameter domains: all " + count +
              " can be met by values within the domains (interval propagation found no conflict; the narrowed "
              "domains are listed with --all).";
  const bool nominal_checked = doc.contains("nominal_design");
  const bool nominal_ok = !nominal_checked || doc["nominal_design"].value("all_requirements_met", true);
  if (nominal_ok) {
    v.status = "feasible";
    v.headline = nominal_checked ? "feasible: the nominal design meets all " + count + " of the project"
                                 : "feasible: the parameter domains can meet all " + count;
    if (nominal_checked)
      v.nominal = "Nominal design (every parameter at its nominal value): meets all " + count + ".";
    return v;
  }
  const nlohmann::json& violated = doc["nominal_design"].at("violated_requirements");
  v.status = "feasible_domains_nominal_violates";
  v.headline = violated.empty()
                   ? "feasible domains, but the nominal component data conflict"
                   : "feasible domains, but the nominal design violates " + JoinNames(violated, " and ");
  v.nominal = violated.empty()
                  ? "Nominal design (every parameter at its nominal value): the nominal component data alone "
                    "conflict; the narrowed domains exclude the nominal values."
                  : "Nominal design (every parameter at its nominal value): violates " + JoinNames(violated, ", ") +
                        "; the narrowed domains exclude the nominal values.";
  return v;
}

}  // namespace highlift::report
