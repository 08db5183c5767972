#include "highlift/estimation/estimator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/text_table.h"
#include "highlift/core/units.h"
#include "highlift/model/component_model.h"
#include "highlift/model/interval.h"

namespace highlift::estimation {
namespace {

using model::Interval;

int Rank(Provenance p) {
  switch (p) {
    case Provenance::kUser: return 0;
    case Provenance::kOptimized: return 0;
    case Provenance::kDatabase: return 1;
    case Provenance::kFit: return 2;
    case Provenance::kEstimated: return 3;
    case Provenance::kPropagated: return 3;
    case Provenance::kDefault: return 4;
  }
  return 4;
}

std::string SourceName(Provenance p) {
  switch (p) {
    case Provenance::kUser: return "the user value";
    case Provenance::kOptimized: return "the optimized value";
    case Provenance::kDatabase: return "the database value";
    case Provenance::kFit: return "the fit";
    case Provenance::kEstimated: return "the physics estimate";
    case Provenance::kPropagated: return "the propagated value";
    case Provenance::kDefault: return "the catalogue default";
  }
  return "?";
}

std::string WithUnit(double si, const ParameterSpec& spec) {
  if (std::isinf(si)) return si > 0 ? "inf" : "-inf";
  const std::string unit = spec.unit.empty() ? "1" : spec.unit;
  return FormatNumber(FromSI(si, unit, spec.dimension));
}

std::string Describe(const std::optional<double>& nominal, const Domain& d, const ParameterSpec& spec) {
  const std::string unit = (spec.unit.empty() || spec.unit == "1") ? "" : " " + spec.unit;
  if (d.is_point()) return WithUnit(d.lo, spec) + unit;
  std::string s = nominal ? WithUnit(*nominal, spec) + " " : "";
  return s + "[" + WithUnit(d.lo, spec) + ", " + WithUnit(d.hi, spec) + "]" + unit;
}

/// One source's estimate of one parameter.
struct Candidate {
  Provenance source = Provenance::kEstimated;
  std::optional<double> nominal;
  Domain domain;
  std::string note;
  bool from_defaults = false;  ///< some input was a catalogue default: fills defaults, never reports conflicts
};

/// A law input: its domain as an interval and its nominal value.
struct Input {
  bool usable = false;
  bool given = false;          ///< not a catalogue default
  Interval interval;
  std::optional<double> nominal;
};

/// "1200 kg" -> SI, checked against `dimension`; used for estimation inputs given as labels.
std::optional<double> LabelQuantity(const Component& c, const std::string& key, const Dimension& dimension) {
  const auto it = c.labels.find(key);
  if (it == c.labels.end()) return std::nullopt;
  const std::string& text = it->second;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str())
    throw InputError("component '" + c.id + "': label '" + key + "' = \"" + text +
                     "\" must be a number with a unit, e.g. \"1200 kg\"", c.where);
  std::string unit(end);
  while (!unit.empty() && unit.front() == ' ') unit.erase(unit.begin());
  if (unit.empty()) return v;
  try {
    return ToSI(v, unit, dimension);
  } catch (const InputError& e) {
    throw InputError("component '" + c.id + "': label '" + key + "': " + e.message(), c.where);
  }
}

class Estimator {
 public:
  Estimator(Project& project, const componentdb::ComponentDatabase* database, const EstimationOptions& options,
            EstimationReport& report)
      : project_(project), database_(database), options_(options), report_(report) {}

  void Run() {
    for (auto& c : project_.components) {
      const ComponentTypeSpec* type = FindComponentType(c.type);
      if (!type) continue;  // validation reports unknown types
      for (const auto& spec : type->parameters) {
        if (!IsValue(spec)) continue;
        if (!c.parameters.count(spec.name)) absent_.insert(Key(c, spec));
        Parameter& p = Get(c, spec);
        initial_[Key(c, spec)] = p;
        // A reference to a database part is unresolved until the database pass.
        if (p.provenance == Provenance::kDatabase && !p.database_part.empty()) pending_.insert(Key(c, spec));
      }
      if (database_ && options_.use_database) DatabasePass(c, *type);
      if (const model::ComponentModel* m = model::FindComponentModel(c.type)) {
        if (database_ && options_.use_fits) FitPass(c, *type, *m);
        if (options_.use_physics) PhysicsPass(c, *m);
      }
      for (const auto& spec : type->parameters) {
        if (!IsValue(spec)) continue;
        const std::string key = Key(c, spec);
        if (pending_.count(key))
          throw InputError("component '" + c.id + "' (" + c.type + "): parameter '" + spec.name +
                           "' refers to database part '" + Get(c, spec).database_part +
                           "' but no component database is open; pass --db PATH or leave out the part reference",
                           Get(c, spec).where);
        Record(c, spec);
        // Left to the design: an optional parameter the project did not give stays absent, so that
        // the network takes its law (a given stiffness would override the tube's).
        if (design_outputs_.count(key) && absent_.count(key) && Get(c, spec).provenance == Provenance::kDefault &&
            spec.optional && !spec.nominal)
          c.parameters.erase(spec.name);
      }
    }
    for (const auto& [key, ids] : extrapolated_) {
      const EmpiricalFit* fit = &fits_.at(key);
      std::string list;
      for (const auto& id : ids) list += (list.empty() ? "" : ", ") + id;
      report_.messages.push_back("the fit of " + fit->type + "." + fit->parameter + " extrapolates for " + list + ": " +
                                 fit->rating + " reaches outside [" + FormatNumber(fit->rating_range.lo) + ", " +
                                 FormatNumber(fit->rating_range.hi) + "] (SI) covered by its " +
                                 std::to_string(fit->law.n) + " database parts; its prediction interval widens there");
    }
    report_.status = report_.conflicts.empty() ? EstimationReport::Status::kOk : EstimationReport::Status::kConflicts;
  }

 private:
  static bool IsValue(const ParameterSpec& s) {
    return s.kind == ParameterKind::kScalar || s.kind == ParameterKind::kInteger;
  }
  static std::string Key(const Component& c, const ParameterSpec& s) { return c.id + "." + s.name; }

  static Parameter& Get(Component& c, const ParameterSpec& spec) {
    auto it = c.parameters.find(spec.name);
    if (it != c.parameters.end()) return it->second;
    Parameter p;  // the loader fills defaults; a project built in code may not have
    p.nominal = spec.nominal;
    p.domain = spec.default_domain;
    p.provenance = Provenance::kDefault;
    p.note = spec.source;
    return c.parameters.emplace(spec.name, p).first->second;
  }

  /// Combines a candidate with what is known, in trust order.
  void Apply(Component& c, const ParameterSpec& spec, const Candidate& cand) {
    Parameter& p = Get(c, spec);
    const std::string key = Key(c, spec);
    const bool pending = pending_.count(key) > 0;
    const std::string what = "component '" + c.id + "' (" + c.type + "): parameter '" + spec.name + "'";
    if (pending || Rank(p.provenance) > Rank(cand.source)) {
      // The candidate is more trusted: it replaces the value, within the valid range.
      const Domain d = cand.domain.intersect(spec.valid_range);
      if (d.empty()) {
        AddConflict(c, spec, p.provenance, p.domain, cand,
                    what + ": " + SourceName(cand.source) + " " + Describe(cand.nominal, cand.domain, spec) + " (" +
                        cand.note + ") lies outside the valid range " + Describe(std::nullopt, spec.valid_range, spec) +
                        "; kept " + SourceName(p.provenance) + " " + Describe(p.nominal, p.domain, spec) +
                        ". Check the source data or give the value");
        return;
      }
      p.domain = d;
      p.nominal = cand.nominal && d.contains(*cand.nominal) ? cand.nominal : std::nullopt;
      if (d.is_point()) p.nominal = d.lo;
      p.provenance = cand.source;
      p.note = cand.note;
      pending_.erase(key);
      return;
    }
    // What is known is at least as trusted: the candidate can only narrow it.
    const Domain d = p.domain.intersect(cand.domain);
    if (d.empty()) {
      if (cand.from_defaults) return;  // built on catalogue defaults: no evidence against a given value
      AddConflict(c, spec, p.provenance, p.domain, cand,
                  what + ": " + SourceName(p.provenance) + " " + Describe(p.nominal, p.domain, spec) +
                      (p.note.empty() ? "" : " (" + p.note + ")") + " and " + SourceName(cand.source) + " " +
                      Describe(cand.nominal, cand.domain, spec) + " (" + cand.note + ") do not overlap; kept " +
                      SourceName(p.provenance) + ". Check both, or remove the one that is wrong");
      return;
    }
    if (d != p.domain) {
      p.domain = d;
      if (p.nominal && !d.contains(*p.nominal)) p.nominal.reset();
      if (!p.nominal && cand.nominal && d.contains(*cand.nominal)) p.nominal = cand.nominal;
      p.note += (p.note.empty() ? "" : "; ") + std::string("narrowed by ") + cand.note;
    }
  }

  void AddConflict(const Component& c, const ParameterSpec& spec, Provenance kept, const Domain& kept_domain,
                   const Candidate& cand, std::string message) {
    EstimationConflict conflict;
    conflict.component = c.id;
    conflict.parameter = spec.name;
    conflict.kept = kept;
    conflict.kept_domain = kept_domain;
    conflict.rejected = cand.source;
    conflict.rejected_domain = cand.domain;
    conflict.message = std::move(message);
    report_.conflicts.push_back(std::move(conflict));
  }

  const componentdb::Part& LookUpPart(const Component& c, const std::string& designation, const SourceLocation& where) {
    auto it = parts_.find(designation);
    if (it == parts_.end()) {
      auto part = database_->FindPart(designation);
      if (!part)
        throw InputError("component '" + c.id + "': database part '" + designation + "' is not in " +
                             database_->file().string() + "; find one with 'highlift db find " + c.type + "'",
                         where.empty() ? c.where : where);
      it = parts_.emplace(designation, std::move(*part)).first;
    }
    if (it->second.type != c.type)
      throw InputError("component '" + c.id + "' (" + c.type + "): database part '" + designation + "' is a " +
                           it->second.type + "; choose a part of type " + c.type,
                       where.empty() ? c.where : where);
    return it->second;
  }

  static Candidate FromQuantity(const componentdb::Quantity& q, const std::string& what) {
    Candidate cand;
    cand.source = Provenance::kDatabase;
    cand.nominal = q.value_si;
    cand.domain = q.domain_si;
    cand.note = what + " (" + componentdb::ToString(q.tag) + "): " + q.source;
    return cand;
  }

  void DatabasePass(Component& c, const ComponentTypeSpec& type) {
    // A whole component taken from a part: label "part".
    if (auto it = c.labels.find("part"); it != c.labels.end()) {
      const auto& part = LookUpPart(c, it->second, c.where);
      for (const auto& q : part.parameters) {
        const ParameterSpec* spec = type.FindParameter(q.name);
        if (!spec || !IsValue(*spec)) continue;
        if (!Get(c, *spec).database_part.empty()) continue;  // a per-parameter reference wins
        Apply(c, *spec, FromQuantity(q, "database part " + part.designation));
      }
    }
    // Single parameters taken from a part: {"part": "..."}.
    for (const auto& spec : type.parameters) {
      if (!IsValue(spec)) continue;
      Parameter& p = Get(c, spec);
      if (p.database_part.empty()) continue;
      const auto& part = LookUpPart(c, p.database_part, p.where);
      const auto* q = part.Find(spec.name);
      if (!q) {
        std::string have;
        for (const auto& x : part.parameters) have += (have.empty() ? "" : ", ") + x.name;
        throw InputError("component '" + c.id + "' (" + c.type + "): parameter '" + spec.name + "' refers to database part '" +
                             part.designation + "', which has no value for it (it has " + have +
                             "); give the value or choose another part",
                         p.where.empty() ? c.where : p.where);
      }
      Apply(c, spec, FromQuantity(*q, "database part " + part.designation));
    }
    // Material properties: label "material".
    if (auto it = c.labels.find("material"); it != c.labels.end()) {
      auto material = database_->FindMaterial(it->second);
      if (!material) {
        std::string names;
        for (const auto& m : database_->Materials()) names += (names.empty() ? "" : ", ") + m.name;
        throw InputError("component '" + c.id + "': material '" + it->second + "' is not in " + database_->file().string() +
                             "; materials: " + names,
                         c.where);
      }
      for (const auto& q : material->properties)
        if (const ParameterSpec* spec = type.FindParameter(q.name); spec && IsValue(*spec))
          Apply(c, *spec, FromQuantity(q, "material " + material->name));
    }
  }

  /// A rating or law input: usable when known beyond a catalogue default, or when the
  /// catalogue has a nominal value for it; bounded and positive.
  Input InputOf(Component& c, const std::string& name) {
    Input in;
    const ComponentTypeSpec* type = FindComponentType(c.type);
    const ParameterSpec* spec = type ? type->FindParameter(name) : nullptr;
    if (!spec) return in;
    const Parameter& p = Get(c, *spec);
    if (pending_.count(Key(c, *spec))) return in;
    in.given = p.provenance != Provenance::kDefault;
    if (!in.given && !p.nominal) return in;
    if (!(p.domain.lo > 0) || !std::isfinite(p.domain.hi)) return in;
    in.usable = true;
    in.interval = Interval(p.domain.lo, p.domain.hi);
    in.nominal = p.nominal;
    return in;
  }

  /// The fits the component's model declares (ComponentModel::FitRules).
  void FitPass(Component& c, const ComponentTypeSpec& type, const model::ComponentModel& m) {
    for (const model::FitRule& rule : m.FitRules()) {
      const ParameterSpec* spec = type.FindParameter(rule.parameter);
      if (!spec || !type.FindParameter(rule.rating)) continue;
      const Input rating = InputOf(c, rule.rating);
      if (!rating.usable || !rating.given) continue;  // a fit at a default rating says nothing new
      const EmpiricalFit& fit = Fit(c.type, rule);
      if (!fit.ok()) continue;  // the report lists the fit and why it failed
      const Domain rd = rating.interval.ToDomain();
      Candidate cand;
      cand.source = Provenance::kFit;
      cand.domain = fit.PredictionInterval(rd);
      cand.nominal = fit.Predict(rating.nominal ? *rating.nominal : 0.5 * (rd.lo + rd.hi));
      cand.note = "fit " + fit.BriefReport();
      if (fit.Extrapolates(rd)) extrapolated_[FitKey(c.type, rule)].push_back(c.id);
      Apply(c, *spec, cand);
    }
  }

  static std::string FitKey(const std::string& type, const model::FitRule& rule) {
    return type + "." + rule.parameter + "/" + rule.rating;
  }

  const EmpiricalFit& Fit(const std::string& type, const model::FitRule& rule) {
    const std::string key = FitKey(type, rule);
    auto it = fits_.find(key);
    if (it == fits_.end()) {
      FitOptions fo;
      fo.confidence = options_.confidence;
      fo.min_parts = options_.min_fit_parts;
      it = fits_.emplace(key, FitParameter(*database_, type, rule.parameter, rule.rating, fo)).first;
      report_.fits.push_back(it->second);
      if (!it->second.ok()) report_.messages.push_back(it->second.message);
    }
    return it->second;
  }

  /// A law input: a parameter (InputOf), a label quantity (usable when given and positive) or a
  /// constant range (usable, not a given value).
  Input InputOf(Component& c, const model::LawInput& in) {
    Input out;
    switch (in.kind) {
      case model::LawInput::Kind::kParameter: return InputOf(c, in.name);
      case model::LawInput::Kind::kLabel:
        if (const auto v = LabelQuantity(c, in.name, in.dimension)) {
          out.usable = out.given = *v > 0;
          out.interval = Interval(*v);
          out.nominal = *v;
        }
        return out;
      case model::LawInput::Kind::kConstant:
        out.usable = true;
        out.interval = in.range;
        out.nominal = in.nominal;
        return out;
    }
    return out;
  }

  /// The law on the inputs' domains and, when every input has one, on their nominal values.
  /// False when an input is not usable.
  static bool Evaluate(const model::EstimationLaw& law, const std::vector<Input>& inputs, Domain* domain,
                       std::optional<double>* nominal) {
    std::vector<Interval> iv;
    std::vector<double> point;
    bool all_nominal = true;
    for (const auto& in : inputs) {
      if (!in.usable) return false;
      iv.push_back(in.interval);
      point.push_back(in.nominal.value_or(0.0));
      all_nominal = all_nominal && in.nominal.has_value();
    }
    *domain = law.enclosure(iv).ToDomain();
    if (all_nominal) *nominal = law.nominal(point);
    return true;
  }

  /// The estimation laws the component's model declares (ComponentModel::EstimationLaws): a
  /// parameter law gives a physics candidate when at least one input is known beyond a catalogue
  /// default; a derived quantity is reported whenever its inputs are usable.
  void PhysicsPass(Component& c, const model::ComponentModel& m) {
    const ComponentTypeSpec* type = FindComponentType(c.type);
    for (const model::EstimationLaw& law : m.EstimationLaws()) {
      std::vector<Input> inputs;
      for (const model::LawInput& in : law.inputs) inputs.push_back(InputOf(c, in));
      if (law.derived) {
        DerivedQuantity q;
        if (!Evaluate(law, inputs, &q.domain, &q.nominal)) continue;
        q.component = c.id;
        q.name = law.output;
        q.unit = law.unit;
        q.note = law.note;
        report_.derived.push_back(std::move(q));
        continue;
      }
      const ParameterSpec* spec = type->FindParameter(law.output);
      if (!spec) continue;
      // A design variable's domain is a choice, not an uncertainty: a law over it would pin the
      // output to an interval over every choice and cut its tie to the design (`check` and
      // `optimize` derive it by the same law in their constraint network).
      if (const auto design = DesignInput(c, law)) {
        report_.messages.push_back(c.id + "." + law.output + " is not estimated: it follows the design variable " +
                                   c.id + "." + *design + " through its law in the constraint network");
        design_outputs_.insert(Key(c, *spec));
        continue;
      }
      const bool any_given = std::any_of(inputs.begin(), inputs.end(), [](const Input& in) { return in.given; });
      if (!any_given) continue;  // only catalogue defaults: nothing new to say
      Candidate cand;
      if (!Evaluate(law, inputs, &cand.domain, &cand.nominal)) continue;
      cand.source = Provenance::kEstimated;
      cand.from_defaults = std::any_of(inputs.begin(), inputs.end(), [](const Input& in) { return !in.given; });
      cand.note = law.note;
      Apply(c, *spec, cand);
    }
  }

  /// The first input of `law` that is a parameter of `c` marked as a design variable.
  static std::optional<std::string> DesignInput(const Component& c, const model::EstimationLaw& law) {
    for (const model::LawInput& in : law.inputs) {
      if (in.kind != model::LawInput::Kind::kParameter) continue;
      const auto it = c.parameters.find(in.name);
      if (it != c.parameters.end() && it->second.design) return in.name;
    }
    return std::nullopt;
  }

  void Record(Component& c, const ParameterSpec& spec) {
    const Parameter& p = Get(c, spec);
    const Parameter& before = initial_[Key(c, spec)];
    ParameterEstimate e;
    e.component = c.id;
    e.type = c.type;
    e.parameter = spec.name;
    e.unit = spec.unit;
    e.nominal = p.nominal;
    e.domain = p.domain;
    e.provenance = p.provenance;
    e.note = p.note;
    e.changed = p.nominal != before.nominal || !(p.domain == before.domain) || p.provenance != before.provenance;
    if (e.changed) {
      if (p.provenance == Provenance::kDatabase) ++report_.from_database;
      if (p.provenance == Provenance::kFit) ++report_.from_fit;
      if (p.provenance == Provenance::kEstimated) ++report_.from_physics;
    }
    report_.parameters.push_back(std::move(e));
  }

  Project& project_;
  const componentdb::ComponentDatabase* database_;
  const EstimationOptions& options_;
  EstimationReport& report_;
  std::map<std::string, Parameter> initial_;
  std::set<std::string> pending_;
  std::set<std::string> absent_;          ///< parameters the project did not give (keys)
  std::set<std::string> design_outputs_;  ///< parameters whose law reads a design variable (keys)
  std::map<std::string, componentdb::Part> parts_;
  std::map<std::string, EmpiricalFit> fits_;
  std::map<std::string, std::vector<std::string>> extrapolated_;  ///< by FitKey: messages in a stable order
};

nlohmann::json DomainJson(const std::optional<double>& nominal, const Domain& d) {
  nlohmann::json j = nlohmann::json::object();
  const auto num = [](double v) -> nlohmann::json {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
  };
  j["value"] = nominal ? nlohmann::json(*nominal) : nlohmann::json(nullptr);
  j["min"] = num(d.lo);
  j["max"] = num(d.hi);
  return j;
}

}  // namespace

void EstimationOptions::Validate() const {
  FitOptions fo;
  fo.confidence = confidence;
  fo.min_parts = min_fit_parts;
  fo.Validate();
}

std::string ToString(EstimationReport::Status status) {
  return status == EstimationReport::Status::kOk ? "ok" : "conflicts";
}

std::string EstimationReport::BriefReport() const {
  std::size_t changed = 0;
  for (const auto& p : parameters) changed += p.changed ? 1 : 0;
  return "estimated " + std::to_string(changed) + " of " + std::to_string(parameters.size()) + " parameters (database " +
         std::to_string(from_database) + ", fit " + std::to_string(from_fit) + ", physics " +
         std::to_string(from_physics) + "), " + std::to_string(conflicts.size()) + " conflict" +
         (conflicts.size() == 1 ? "" : "s");
}

std::string EstimationReport::FullReport(bool all_parameters) const {
  std::string out;
  TextTable table({"component", "parameter", "value", "unit", "provenance", "note"});
  for (const auto& p : parameters) {
    if (!all_parameters && !p.changed) continue;
    const ComponentTypeSpec* type = FindComponentType(p.type);
    const ParameterSpec* spec = type ? type->FindParameter(p.parameter) : nullptr;
    std::string value;
    if (spec) {
      ParameterSpec display = *spec;
      display.unit = spec->unit.empty() ? "1" : spec->unit;
      value = p.domain.is_point() ? WithUnit(p.domain.lo, display)
                                  : (p.nominal ? WithUnit(*p.nominal, display) + " " : "") + "[" +
                                        WithUnit(p.domain.lo, display) + ", " + WithUnit(p.domain.hi, display) + "]";
    }
    std::string note = p.note;
    if (note.size() > 90) note = note.substr(0, 87) + "...";
    table.AddRow({p.component, p.parameter, value, p.unit, highlift::ToString(p.provenance), note});
  }
  out += table.ToString();
  if (!derived.empty()) {
    TextTable d({"component", "quantity", "value", "unit", "law"});
    for (const auto& q : derived)
      d.AddRow({q.component, q.name,
                (q.nominal ? FormatNumber(*q.nominal) + " " : "") + "[" + FormatNumber(q.domain.lo) + ", " +
                    FormatNumber(q.domain.hi) + "]",
                q.unit + " (SI)", q.note});
    out += "\nderived quantities\n" + d.ToString();
  }
  if (!fits.empty()) {
    out += "\nfits\n";
    for (const auto& f : fits) out += "  " + f.BriefReport() + "\n";
  }
  if (!conflicts.empty()) {
    out += "\nconflicts\n";
    for (const auto& c : conflicts) out += "  " + c.message + "\n";
  }
  for (const auto& m : messages) out += "note: " + m + "\n";
  out += BriefReport() + "\n";
  return out;
}

nlohmann::json EstimationReport::ToJson() const {
  nlohmann::json j;
  j["status"] = ToString(status);
  j["brief"] = BriefReport();
  j["parameters"] = nlohmann::json::array();
  for (const auto& p : parameters) {
    nlohmann::json e = DomainJson(p.nominal, p.domain);
    e["component"] = p.component;
    e["parameter"] = p.parameter;
    e["unit"] = "SI";
    e["display_unit"] = p.unit;
    e["provenance"] = highlift::ToString(p.provenance);
    e["note"] = p.note;
    e["changed"] = p.changed;
    j["parameters"].push_back(std::move(e));
  }
  j["conflicts"] = nlohmann::json::array();
  for (const auto& c : conflicts)
    j["conflicts"].push_back({{"component", c.component},
                              {"parameter", c.parameter},
                              {"kept", highlift::ToString(c.kept)},
                              {"kept_domain", DomainJson(std::nullopt, c.kept_domain)},
                              {"rejected", highlift::ToString(c.rejected)},
                              {"rejected_domain", DomainJson(std::nullopt, c.rejected_domain)},
                              {"message", c.message}});
  j["derived"] = nlohmann::json::array();
  for (const auto& q : derived) {
    nlohmann::json e = DomainJson(q.nominal, q.domain);
    e["component"] = q.component;
    e["quantity"] = q.name;
    e["unit"] = q.unit;
    e["law"] = q.note;
    j["derived"].push_back(std::move(e));
  }
  j["fits"] = nlohmann::json::array();
  for (const auto& f : fits) {
    nlohmann::json e{{"type", f.type},
                     {"parameter", f.parameter},
                     {"rating", f.rating},
                     {"status", f.ok() ? "ok" : "too_few_parts"},
                     {"message", f.message},
                     {"parts", f.parts_used},
                     {"confidence", f.confidence}};
    if (f.ok()) {
      e["coefficient"] = f.law.coefficient;
      e["exponent"] = f.law.exponent;
      e["r_squared"] = f.law.r_squared;
      e["log_sigma"] = f.law.residual_sigma;
    }
    j["fits"].push_back(std::move(e));
  }
  j["messages"] = messages;
  j["seconds"] = seconds;
  return j;
}

EstimationReport EstimateProject(Project& project, const componentdb::ComponentDatabase* database,
                                 const EstimationOptions& options) {
  options.Validate();
  const auto start = std::chrono::steady_clock::now();
  EstimationReport report;
  Estimator(project, database, options, report).Run();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace highlift::estimation
