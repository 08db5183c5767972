#include "highlift/reduced_models/sizing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "graph_model.h"
#include "highlift/core/error.h"
#include "highlift/core/text_table.h"
#include "highlift/model/hydraulic_pdu.h"
#include "highlift/reduced_models/sampling.h"
#include "torque_flow.h"

namespace highlift::reduced_models {
namespace {

/// The actuator types of the catalogue, "a or b".
std::string ActuatorTypes() {
  std::string out;
  for (const std::string& t : ComponentTypesWith(&ComponentRoles::actuator)) out += (out.empty() ? "" : " or ") + t;
  return out;
}

using detail::Interval;
constexpr double kInf = std::numeric_limits<double>::infinity();

Bounded Make(double nominal, const Interval& bounds) { return {nominal, bounds.ToDomain()}; }
Bounded Make(double nominal) { return {nominal, Domain::Point(nominal)}; }

/// |x| as a bounded value: nominal |x|, bounds of |x| over the enclosure.
Bounded Magnitude(const Bounded& b) {
  const Interval a = detail::abs(Interval(b.bounds.lo, b.bounds.hi));
  return {std::abs(b.nominal), a.ToDomain()};
}
Bounded Max(const Bounded& a, const Bounded& b) {
  return {std::max(a.nominal, b.nominal), {std::max(a.bounds.lo, b.bounds.lo), std::max(a.bounds.hi, b.bounds.hi)}};
}

std::string Fmt(double v, int digits = 4) { return FormatNumber(v, digits); }
std::string FmtBounds(const Domain& d) { return d.is_point() ? "" : "[" + Fmt(d.lo) + ", " + Fmt(d.hi) + "]"; }

}  // namespace

double ShaftMass(const Project& project) {
  double mass = 0.0;
  for (const Component& c : project.components)
    if (detail::HasRole(c, &model::ComponentRoles::segment)) mass += detail::ShaftSegmentMass<double>(c, {});
  return mass;
}

SizingReport Size(const Project& project, const SizingOptions& options) {
  const detail::Graph g = detail::BuildGraph(project);
  if (project.load_cases.empty())
    throw InputError("project '" + project.name +
                     "' has no load cases; steady-state sizing needs at least one (actuator loads and "
                     "a PDU speed): add one under \"load_cases\"");
  SizingReport report;
  report.project = project.name;
  report.shaft_mass = ShaftMass(project);
  const detail::ParameterMode nominal_mode, interval_mode{detail::ParameterMode::kIntervals, {}, {}};
  const Component& pdu = *g.nodes[0].component;

  for (const LoadCase& load_case : project.load_cases) {
    for (const auto& [actuator, table] : load_case.actuator_loads) {
      const int node = g.Find(actuator);
      if (node < 0 || !g.IsActuator(node))
        throw InputError("load case '" + load_case.name + "': actuator load for '" + actuator +
                             "', which is not an actuator driven from the PDU; name an actuator of the project (" +
                             ActuatorTypes() + ")",
                         load_case.where);
    }
    const auto loads = detail::SizingLoads(load_case);
    const double w = detail::SizingSpeed(load_case, pdu);
    // The speed enclosure: the PDU's max_output_speed domain where the load case has no profile.
    const Interval w_all = options.intervals ? detail::SizingSpeed<Interval>(load_case, pdu, interval_mode) : Interval(w);
    const auto flow = detail::SolveFlow<double>(g, nominal_mode, loads, w);
    detail::Flow<Interval> wide;
    if (options.intervals) wide = detail::SolveFlow<Interval>(g, interval_mode, loads, w_all);
    LoadCaseSizing s;
    s.load_case = load_case.name;
    s.direction = load_case.direction;
    s.pdu_speed = w;
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      ComponentTorque t;
      t.component = g.Id(static_cast<int>(i));
      t.type = g.Type(static_cast<int>(i));
      t.speed = flow.w_in[i];
      t.torque = options.intervals ? Make(flow.tau_in[i], wide.tau_in[i]) : Make(flow.tau_in[i]);
      s.components.push_back(t);
    }
    s.pdu_torque = s.components[0].torque;
    const double eta = detail::NominalValue(pdu, "efficiency");
    s.pdu_power = {s.pdu_torque.nominal * w, {s.pdu_torque.bounds.lo * w, s.pdu_torque.bounds.hi * w}};
    if (options.intervals) {
      const Interval power = Interval(s.pdu_torque.bounds.lo, s.pdu_torque.bounds.hi) * w_all;
      const Interval input = detail::BySign(
          power, [&](const Interval& p) { return p / detail::Read<Interval>(pdu, "efficiency", interval_mode); },
          [&](const Interval& p) { return p * detail::Read<Interval>(pdu, "efficiency", interval_mode); });
      s.pdu_power = Make(s.pdu_torque.nominal * w, power);
      s.pdu_input_power = Make(s.pdu_power.nominal >= 0 ? s.pdu_power.nominal / eta : s.pdu_power.nominal * eta, input);
    } else {
      s.pdu_input_power = Make(s.pdu_power.nominal >= 0 ? s.pdu_power.nominal / eta : s.pdu_power.nominal * eta);
    }
    report.cases.push_back(std::move(s));
  }

  // Largest operating torque magnitude per component and direction.
  auto operating = [&](int node, const std::string& direction) {
    Bounded best = Make(0.0);
    bool any = false;
    for (const LoadCaseSizing& s : report.cases)
      if (direction.empty() || s.direction == direction) {
        best = Max(best, Magnitude(s.components[node].torque));
        any = true;
      }
    if (!any && !direction.empty())  // no case in this direction: use every case
      for (const LoadCaseSizing& s : report.cases) best = Max(best, Magnitude(s.components[node].torque));
    return best;
  };
  auto recommend = [&](int node, const std::string& parameter, const std::string& rule, const Bounded& op,
                       double factor, double lo, double hi) {
    SettingRecommendation r;
    const Component& c = *g.nodes[node].component;
    r.component = c.id;
    r.parameter = parameter;
    r.rule = rule;
    r.operating = op;
    r.factor = factor;
    r.factor_min = lo;
    r.factor_max = hi;
    r.recommended = factor * op.nominal;
    r.recommended_robust = {lo * op.bounds.hi, hi * op.bounds.lo};
    if (detail::HasValue(c, parameter)) {
      r.current = detail::NominalValue(c, parameter);
      r.current_factor = op.nominal > 0 ? *r.current / op.nominal : kInf;
      r.ok = r.current_factor >= lo && r.current_factor <= hi;
      r.robust = r.recommended_robust.contains(*r.current);
    }
    report.settings.push_back(r);
  };
  // The torque a brake of node `node`'s wing holds: the larger of the wing's operating torque
  // at its root and its back-drive torque there, the airloads of the wing's actuators
  // back-driving the shaft through their aiding efficiencies, friction neglected (conservative).
  auto wing_holding = [&](int node) {
    int wing = node;
    while (g.nodes[wing].parent > 0) wing = g.nodes[wing].parent;
    Bounded holding = operating(wing, "");
    for (const LoadCase& load_case : project.load_cases) {
      std::map<std::string, double> aiding;
      for (const auto& [actuator, value] : detail::SizingLoads(load_case)) aiding[actuator] = -std::abs(value);
      const double w = detail::SizingSpeed(load_case, pdu);
      const auto flow = detail::SolveFlow<double>(g, nominal_mode, aiding, w, false);
      Bounded b = Make(std::max(0.0, -flow.tau_in[wing]));
      if (options.intervals) {
        const auto wide = detail::SolveFlow<Interval>(g, interval_mode, aiding,
                                                      detail::SizingSpeed<Interval>(load_case, pdu, interval_mode), false);
        b.bounds = {std::max(0.0, -wide.tau_in[wing].hi), std::max(0.0, -wide.tau_in[wing].lo)};
      }
      holding = Max(holding, b);
    }
    return holding;
  };
  // The torque a limiter (its limited node `limited`) grounds in a jam behind it: the static
  // torque the drive can put into it, the PDU stall torque through the system torque limiters
  // inboard, at its speed, minus its end-stop torque. Nullopt without a stall torque.
  const auto n_nominal = detail::SpeedRatios<double>(g, nominal_mode);
  const auto n_wide = detail::SpeedRatios<Interval>(g, options.intervals ? interval_mode : nominal_mode);
  auto jam_grounding = [&](int node, int limited) -> std::optional<Bounded> {
    const Component& limiter = *g.nodes[node].component;
    const detail::ParameterMode& mode = options.intervals ? interval_mode : nominal_mode;
    const detail::ModeReader<double> pdu_nominal(pdu, nominal_mode);
    const detail::ModeReader<Interval> pdu_all(pdu, mode);
    if (!model::HasPduStallTorque(pdu, pdu_nominal) || !detail::HasValue(limiter, "end_stop_torque")) return std::nullopt;
    // The PDU's stall torque by its law (a hydraulic drive's from its motors, as simulated).
    double available = model::PduStallTorque(pdu, pdu_nominal);
    Interval available_all = model::PduStallTorque(pdu, pdu_all);
    for (int k : g.PathToRoot(limited))
      if (g.Roles(k).wing_limiter) {
        const Component& stl = *g.nodes[k].component;
        available = detail::SystemLimiterPasses(stl, available, n_nominal[k], nominal_mode);
        available_all = detail::SystemLimiterPasses(stl, available_all, n_wide[k], mode);
      }
    const double nominal = available / n_nominal[limited] - detail::NominalValue(limiter, "end_stop_torque");
    const Interval all = available_all / n_wide[limited] - detail::Read<Interval>(limiter, "end_stop_torque", mode);
    return options.intervals ? Make(nominal, all) : Make(nominal);
  };
  // The settings by the sizing rules their component types declare.
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const int node = static_cast<int>(i);
    const model::ComponentModel* m = detail::ModelOf(*g.nodes[node].component);
    if (!m) continue;
    const int limited = g.LimitedNode(node);  // the torque through its limiter: at its input or a port
    for (const model::SettingRule& rule : m->SettingRules()) {
      using Against = model::SettingRule::Against;
      if (limited < 0 && rule.against != Against::kWingHolding) continue;
      std::optional<Bounded> grounding;
      if (rule.against == Against::kJamGrounding && !(grounding = jam_grounding(node, limited))) continue;
      const Bounded against = rule.against == Against::kOperating          ? operating(limited, "")
                              : rule.against == Against::kOperatingExtend  ? operating(limited, "extend")
                              : rule.against == Against::kOperatingRetract ? operating(limited, "retract")
                              : rule.against == Against::kJamGrounding     ? *grounding
                                                                           : wing_holding(node);
      recommend(node, rule.parameter, rule.rule, against, rule.factor, rule.factor_min, rule.factor_max);
    }
  }

  // Margins against allowables, on the largest operating torque (upper bound) at own speed and,
  // with intervals, the smallest allowable over the domains: a guaranteed lower bound of the margin.
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const int node = static_cast<int>(i);
    const Component& c = *g.nodes[node].component;
    const double load = operating(node, "").bounds.hi;
    const detail::ParameterMode& allowable_mode = options.intervals ? interval_mode : nominal_mode;
    auto add = [&](const std::string& name, const Interval& allowable, double at_load) {
      const double margin = at_load > 0 ? GuaranteedMargin(allowable.lo, at_load) : kInf;
      report.margins.push_back({c.id, name, at_load, allowable.lo, margin});
    };
    const model::ComponentModel* m = detail::ModelOf(c);
    const auto allowable = m ? m->SteadyAllowable(detail::ModeReader<Interval>(c, allowable_mode)) : std::nullopt;
    if (!allowable) continue;
    double at_load = load;
    if (allowable->against_output_load) {  // an actuator's output rating: its largest output load
      at_load = 0.0;
      for (const LoadCase& load_case : project.load_cases) {
        const auto loads = detail::SizingLoads(load_case);
        auto it = loads.find(c.id);
        if (it != loads.end()) at_load = std::max(at_load, std::abs(it->second));
      }
    }
    add(allowable->name, allowable->value, at_load);
  }
  if (options.intervals && options.tightness_samples > 0) MeasureTightness(project, options, &report);
  return report;
}

void MeasureTightness(const Project& project, const SizingOptions& options, SizingReport* report) {
  const std::vector<UncertainParameter> uncertain = UncertainParameters(project);
  // Every enclosure of the report in one list, in a fixed order: per load case the PDU torque,
  // power and input power and the component torques; then the settings' operating torques.
  auto enclosures = [](SizingReport& r) {
    std::vector<Bounded*> out;
    for (auto& c : r.cases) {
      out.insert(out.end(), {&c.pdu_torque, &c.pdu_power, &c.pdu_input_power});
      for (auto& t : c.components) out.push_back(&t.torque);
    }
    for (auto& s : r.settings) out.push_back(&s.operating);
    return out;
  };
  const std::vector<Bounded*> mine = enclosures(*report);
  SampledHull hull(mine.size());
  DomainSampler sampler(uncertain, options.tightness_seed);
  SizingOptions point_options = options;
  point_options.intervals = false;
  point_options.tightness_samples = 0;
  const int samples = uncertain.empty() ? 1 : options.tightness_samples;
  for (int k = 0; k < samples; ++k) {
    SizingReport at = Size(FixParameters(project, uncertain, sampler.Next()), point_options);
    const std::vector<Bounded*> theirs = enclosures(at);
    HIGHLIFT_CHECK(theirs.size() == mine.size(), "sizing reports differ between the enclosure and a point");
    for (std::size_t i = 0; i < theirs.size(); ++i) hull.Add(i, theirs[i]->nominal);
  }
  for (std::size_t i = 0; i < mine.size(); ++i) mine[i]->SetTightness(hull.lo[i], hull.hi[i]);
}

bool SizingReport::ok() const {
  for (const auto& s : settings)
    if (!s.ok) return false;
  for (const auto& m : margins)
    if (m.margin < 0.0) return false;
  return true;
}

std::string SizingReport::BriefReport() const {
  std::string out = "sizing of '" + project + "': " + std::to_string(cases.size()) + " load case(s)";
  for (const auto& s : cases)
    out += "; " + s.load_case + ": PDU " + Fmt(s.pdu_torque.nominal) + " N*m, " + Fmt(s.pdu_power.nominal / 1e3) + " kW";
  int bad = 0;
  for (const auto& s : settings) bad += s.ok ? 0 : 1;
  for (const auto& m : margins) bad += m.margin < 0.0 ? 1 : 0;
  out += bad ? "; " + std::to_string(bad) + " setting(s) or margin(s) out of range" : "; all settings and margins ok";
  return out;
}

std::string SizingReport::FullReport() const {
  std::string out = "Steady-state sizing: " + project + "\nshaft mass " + Fmt(shaft_mass) + " kg\n";
  for (const auto& s : cases) {
    out += "\nload case '" + s.load_case + "' (" + s.direction + "), PDU speed " + Fmt(s.pdu_speed) +
           " rad/s: PDU output torque " + Fmt(s.pdu_torque.nominal) + " N*m " + FmtBounds(s.pdu_torque.bounds) +
           ", power " + Fmt(s.pdu_power.nominal / 1e3) + " kW, input power " + Fmt(s.pdu_input_power.nominal / 1e3) +
           " kW " + FmtBounds({s.pdu_input_power.bounds.lo / 1e3, s.pdu_input_power.bounds.hi / 1e3}) + "\n";
    TextTable table({"component", "type", "speed [rad/s]", "torque [N*m]", "enclosure [N*m]"}, {2, 3, 4});
    for (const auto& c : s.components)
      table.AddRow({c.component, c.type, Fmt(c.speed), Fmt(c.torque.nominal), FmtBounds(c.torque.bounds)});
    out += table.ToString();
  }
  out += "\nRecommended settings\n";
  TextTable settings_table({"component", "parameter", "operating [N*m]", "enclosure [N*m]", "factor", "recommended [N*m]",
                            "robust range [N*m]", "current [N*m]", "current factor", "status", "rule"},
                           {2, 3, 4, 5, 6, 7, 8});
  for (const auto& s : settings) {
    const std::string robust = s.recommended_robust.empty()
                                   ? "none"
                                   : "[" + Fmt(s.recommended_robust.lo) + ", " +
                                         (std::isinf(s.recommended_robust.hi) ? "inf" : Fmt(s.recommended_robust.hi)) + "]";
    settings_table.AddRow({s.component, s.parameter, Fmt(s.operating.nominal), FmtBounds(s.operating.bounds), Fmt(s.factor, 2),
                           Fmt(s.recommended), robust, s.current ? Fmt(*s.current) : "-",
                           s.current ? Fmt(s.current_factor, 3) : "-",
                           !s.ok ? "OUT OF RANGE" : (s.robust ? "ok" : "ok at nominal only"), s.rule});
  }
  out += settings_table.ToString();
  out += "\nMargins against allowables (largest operating torque, upper bound)\n";
  TextTable margin_table({"component", "allowable", "load [N*m]", "allowable [N*m]", "margin"}, {2, 3, 4});
  for (const auto& m : margins)
    margin_table.AddRow({m.component, m.allowable_name, Fmt(m.load), Fmt(m.allowable),
                         std::isinf(m.margin) ? "inf" : Fmt(100.0 * m.margin, 3) + " %"});
  out += margin_table.ToString();
  return out;
}

double GuaranteedMargin(double allowable, double load) {
  // q = allowable / load rounded to nearest; fma gives the sign of its error exactly.
  double q = allowable / load;
  if (std::fma(q, load, -allowable) > 0.0) q = std::nextafter(q, -kInf);
  // m = q - 1 with the error of the subtraction from the two-sum: exact for q in [0.5, 2].
  double m = q - 1.0;
  const double b = m - q;
  const double error = (q - (m - b)) + (-1.0 - b);
  if (error < 0.0) m = std::nextafter(m, -kInf);
  return m;
}

void Bounded::SetTightness(double lo, double hi) {
  const double scale = std::max({std::abs(bounds.lo), std::abs(bounds.hi), std::abs(lo), std::abs(hi)});
  const double floor = std::max(1e-6 * scale, std::numeric_limits<double>::min());
  tightness = std::max(bounds.hi - bounds.lo, floor) / std::max(hi - lo, floor);
}

SampledHull::SampledHull(std::size_t count)
    : lo(count, std::numeric_limits<double>::infinity()), hi(count, -std::numeric_limits<double>::infinity()) {}

void SampledHull::Add(std::size_t i, double value) {
  lo[i] = std::min(lo[i], value);
  hi[i] = std::max(hi[i], value);
}

nlohmann::json ToJson(const Bounded& b) {
  nlohmann::json j = {{"nominal", b.nominal}, {"min", b.bounds.lo}, {"max", b.bounds.hi}};
  if (b.tightness > 0) j["tightness"] = b.tightness;
  return j;
}

namespace {
nlohmann::json Finite(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
}  // namespace

nlohmann::json SizingReport::ToJson() const {
  nlohmann::json j;
  j["project"] = project;
  j["ok"] = ok();
  j["shaft_mass_kg"] = shaft_mass;
  j["load_cases"] = nlohmann::json::array();
  for (const auto& s : cases) {
    nlohmann::json c = {{"name", s.load_case}, {"direction", s.direction}, {"pdu_speed_rad_s", s.pdu_speed},
                        {"pdu_torque_N_m", reduced_models::ToJson(s.pdu_torque)},
                        {"pdu_power_W", reduced_models::ToJson(s.pdu_power)},
                        {"pdu_input_power_W", reduced_models::ToJson(s.pdu_input_power)}};
    c["components"] = nlohmann::json::array();
    for (const auto& t : s.components)
      c["components"].push_back({{"component", t.component}, {"type", t.type}, {"speed_rad_s", t.speed},
                                 {"torque_N_m", reduced_models::ToJson(t.torque)}});
    j["load_cases"].push_back(c);
  }
  j["settings"] = nlohmann::json::array();
  for (const auto& s : settings)
    j["settings"].push_back({{"component", s.component}, {"parameter", s.parameter}, {"rule", s.rule},
                             {"operating_N_m", reduced_models::ToJson(s.operating)}, {"factor", s.factor},
                             {"factor_min", s.factor_min}, {"factor_max", Finite(s.factor_max)},
                             {"recommended_N_m", s.recommended},
                             {"robust_range_N_m", s.recommended_robust.empty()
                                                      ? nlohmann::json(nullptr)
                                                      : nlohmann::json{s.recommended_robust.lo, Finite(s.recommended_robust.hi)}},
                             {"robust", s.robust},
                             {"current_N_m", s.current ? nlohmann::json(*s.current) : nlohmann::json(nullptr)},
                             {"current_factor", Finite(s.current_factor)}, {"ok", s.ok}});
  j["margins"] = nlohmann::json::array();
  for (const auto& m : margins)
    j["margins"].push_back({{"component", m.component}, {"allowable_name", m.allowable_name}, {"load_N_m", m.load},
                            {"allowable_N_m", m.allowable}, {"margin", Finite(m.margin)}});
  return j;
}

}  // namespace highlift::reduced_models
