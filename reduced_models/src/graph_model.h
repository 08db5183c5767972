// The component graph seen from the PDU: components in power-flow order with their parents,
// and the templated builders of the transmission (for the lumped models) and of the torque flow
// (for steady-state sizing). Private to reduced_models; templated on the scalar (double for
// point values, detail::Interval for enclosures) so every law is written once.
#pragma once

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/message_number.h"
#include "highlift/core/project.h"
#include "highlift/model/component_model.h"
#include "highlift/reduced_models/lumped_model.h"
#include "interval.h"
#include "laws.h"

namespace highlift::reduced_models::detail {

struct GraphNode {
  const Component* component = nullptr;
  int parent = -1;          ///< index of the upstream component, -1 for the PDU
  std::string parent_port;  ///< port of the parent it hangs on ("left", "output", "branch", ...)
  std::vector<int> children;
  std::string entry_port;   ///< its own port towards the parent ("input", "a"; "" for the PDU)
  const model::ComponentModel* model = nullptr;  ///< its type's model (nullptr: unknown type)
};

/// The component model of the component's type (model/src/components), or nullptr.
inline const model::ComponentModel* ModelOf(const Component& c) { return model::FindComponentModel(c.type); }
/// True when the component's type has the role (false for an unknown type).
inline bool HasRole(const Component& c, bool model::ComponentRoles::*role) {
  const model::ComponentModel* m = ModelOf(c);
  return m && m->roles().*role;
}

/// Components reachable from the PDU, parents before children. Throws InputError when the
/// project has no PDU, or a component is entered through its far flange (ratio convention).
struct Graph {
  std::vector<GraphNode> nodes;
  std::map<std::string, int, std::less<>> index;
  int Find(std::string_view id) const {
    auto it = index.find(id);
    return it == index.end() ? -1 : it->second;
  }
  const std::string& Id(int i) const { return nodes[i].component->id; }
  const std::string& Type(int i) const { return nodes[i].component->type; }
  /// The roles of node i's component type (its catalogue declaration).
  ComponentRoles Roles(int i) const { return RolesOf(Type(i)); }
  bool IsActuator(int i) const { return Has(i, &model::ComponentRoles::actuator); }
  /// True when node i's type has the role.
  bool Has(int i, bool model::ComponentRoles::*role) const {
    const model::ComponentModel* m = nodes[i].model;
    return m && m->roles().*role;
  }
  /// The node whose input torque passes node i's torque limiter: node i itself for an in-line
  /// limiter, the child on its model's LimitedPort() for a limiter inside a gearbox's down-drive
  /// (-1 when nothing is connected there).
  int LimitedNode(int i) const {
    const model::ComponentModel* m = nodes[i].model;
    if (!m || m->LimitedPort().empty()) return i;
    for (int child : nodes[i].children)
      if (nodes[child].parent_port == m->LimitedPort()) return child;
    return -1;
  }
  /// Path from node i up to the PDU (i first).
  std::vector<int> PathToRoot(int i) const {
    std::vector<int> path;
    for (; i >= 0; i = nodes[i].parent) path.push_back(i);
    return path;
  }
  /// All nodes of the subtree under i (i first).
  std::vector<int> Subtree(int i) const {
    std::vector<int> out{i};
    for (std::size_t k = 0; k < out.size(); ++k)
      for (int c : nodes[out[k]].children) out.push_back(c);
    return out;
  }
};
Graph BuildGraph(const Project& project);

/// How parameter values are read: nominal values, full interval domains, or the nominal value
/// everywhere except one parameter that takes its domain (for ranking shares of a width).
struct ParameterMode {
  enum Kind { kNominal, kIntervals, kOne } kind = kNominal;
  std::string component;
  std::string parameter;
};

/// The value of a parameter: the component's own Parameter, else the catalogue default.
/// Throws InputError naming the component and parameter when no value is known.
/// What the laws read of a parameter (no strings: this is on the hot path of every evaluation).
struct ParameterView {
  std::optional<double> nominal;
  Domain domain;
  Provenance provenance = Provenance::kDefault;
};
std::optional<ParameterView> FindParameter(const Component& c, std::string_view name);
/// The value of a parameter: its nominal value, else the middle of a domain the user (or the
/// database, an estimate) gave. A default domain without a nominal value is the valid range:
/// not a value (nullopt).
inline std::optional<double> ValueOf(const ParameterView& p) {
  if (p.nominal) return p.nominal;
  if (p.provenance != Provenance::kDefault && p.domain.bounded() && !p.domain.empty()) return p.domain.mid();
  return std::nullopt;
}
double NominalValue(const Component& c, std::string_view name);
bool HasValue(const Component& c, std::string_view name);

template <class T>
T Read(const Component& c, std::string_view name, const ParameterMode& mode);
template <>
inline double Read<double>(const Component& c, std::string_view name, const ParameterMode&) {
  return NominalValue(c, name);
}
template <>
inline Interval Read<Interval>(const Component& c, std::string_view name, const ParameterMode& mode) {
  const bool wide = mode.kind == ParameterMode::kIntervals ||
                    (mode.kind == ParameterMode::kOne && mode.component == c.id && mode.parameter == name);
  // One lookup: the nominal value is NominalValue's, read from the same view (the lookup is most
  // of a read's cost, and the peak analysis reads every parameter once per uncertain one).
  const auto p = FindParameter(c, name);
  if (wide && p && p->domain.bounded() && !p->domain.empty() && !p->domain.is_point())
    return Interval(p->domain.lo, p->domain.hi);
  if (const std::optional<double> value = p ? ValueOf(*p) : std::nullopt) return Interval(*value);
  return Interval(NominalValue(c, name));  // no value: NominalValue's error
}

/// The uncertain parameters (bounded, non-point domains) that the reduced models read, as
/// (component id, parameter name).
std::vector<std::pair<std::string, std::string>> UncertainParameters(const Graph& graph);

/// "inertia = 1e+308, ratio = 1e+200": the parameters a law read, for a message.
inline std::string ParameterList(const std::vector<std::pair<std::string, double>>& read) {
  std::string text;
  for (const auto& [name, value] : read) text += (text.empty() ? "" : ", ") + name + " = " + FormatMessageNumber(value);
  return text.empty() ? "no parameter" : text;
}

/// A derived value of a component that is not finite (an overflow to inf, or inf - inf, 0 * inf
/// = nan) names that component, the value and the parameters it came from (issue 27 item 19:
/// a "J = -nan" message named a lumped node whose own component was not the culprit).
[[noreturn]] inline void ThrowNotFinite(const Component& c, const std::string& what, double value,
                                        const std::string& from) {
  throw InputError("component '" + c.id + "': its " + what + " is not finite (" + FormatMessageNumber(value) +
                   "), computed from " + from +
                   "; give values whose products and sums stay within the range of numbers (about 1e308 in SI "
                   "units; check the units of these parameters)");
}

/// Speed of each node's input flange relative to the PDU output speed (w_in / w_pdu).
template <class T>
std::vector<T> SpeedRatios(const Graph& g, const ParameterMode& mode) {
  std::vector<T> n(g.nodes.size(), T(1.0));
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const GraphNode& node = g.nodes[i];
    if (node.parent < 0) continue;
    const GraphNode& up = g.nodes[node.parent];
    const Component& parent = *up.component;
    const model::ComponentModel* m = up.model;
    const model::PortRatio law = m ? m->SpeedRatioLaw(up.entry_port, node.parent_port) : model::PortRatio{};
    if (law.parameter.empty() || law.power == 0)
      n[i] = n[node.parent];
    else if (law.power < 0)
      n[i] = n[node.parent] / Read<T>(parent, law.parameter, mode);
    else
      n[i] = n[node.parent] * Read<T>(parent, law.parameter, mode);
    if constexpr (std::is_same_v<T, double>) {
      if (!std::isfinite(n[i]) || n[i] == 0.0)
        ThrowNotFinite(parent, "speed ratio towards '" + node.component->id + "' (w / w_pdu)", n[i],
                       "its parameter " + std::string(law.parameter) + " = " +
                           FormatMessageNumber(Read<double>(parent, law.parameter, mode)) +
                           " and the speed ratio at its own input, " + FormatMessageNumber(n[node.parent]));
    }
  }
  return n;
}

/// A component's parameters as its laws read them (model::ParameterReader) in a ParameterMode.
template <class T>
class ModeReader final : public model::ParameterReader<T> {
 public:
  /// `log` (double only): every parameter the law reads, with its value, for messages.
  ModeReader(const Component& c, const ParameterMode& mode,
             std::vector<std::pair<std::string, double>>* log = nullptr)
      : c_(c), mode_(mode), log_(log) {}
  T operator()(std::string_view name) const override {
    T value = Read<T>(c_, name, mode_);
    if constexpr (std::is_same_v<T, double>) {
      if (log_ != nullptr) log_->emplace_back(std::string(name), value);
    }
    return value;
  }
  bool Has(std::string_view name) const override { return HasValue(c_, name); }
  double Nominal(std::string_view name) const override { return NominalValue(c_, name); }

 private:
  const Component& c_;
  const ParameterMode& mode_;
  std::vector<std::pair<std::string, double>>* log_;
};

/// What a system torque limiter passes on to a jam behind it when the static torque `tau_in`
/// (at the reference speed; `n` its speed ratio) arrives: its type's law
/// (ComponentModel::JamPassedTorque, model::LimiterPassedTorque: its end-stop torque, or the
/// excess over its brake torque), the same law as the station limiters'; without the settings
/// the cap by its lock-out torque; without that, `tau_in`.
template <class T>
T SystemLimiterPasses(const Component& stl, const T& tau_in, const T& n, const ParameterMode& mode) {
  const ModeReader<T> reader(stl, mode);
  if (const model::ComponentModel* m = ModelOf(stl))
    if (auto passed = m->JamPassedTorque(reader, tau_in, n)) return *passed;
  if (!HasValue(stl, "lockout_torque_extend")) return tau_in;
  using std::min;
  return min(tau_in, Read<T>(stl, "lockout_torque_extend", mode) * n);
}

/// The component's contribution to the lumped models, from its type's lumped law
/// (ComponentModel::LumpedAtInput); the default law for a type without a model. For double, a
/// value that is not finite is an InputError naming the component and the parameters read.
template <class T>
model::Lumped<T> LumpedOf(const Component& c, const ParameterMode& mode, const model::ComponentModel* m) {
  std::vector<std::pair<std::string, double>> read;
  const ModeReader<T> reader(c, mode, &read);
  model::Lumped<T> lumped = m ? m->LumpedAtInput(reader) : model::DefaultLumped<T>(reader);
  if constexpr (std::is_same_v<T, double>) {
    if (!std::isfinite(lumped.J))
      ThrowNotFinite(c, "lumped inertia J [kg*m^2]", lumped.J, "its parameters " + ParameterList(read));
    if (lumped.c && !std::isfinite(*lumped.c))
      ThrowNotFinite(c, "lumped stiffness c [N*m/rad]", *lumped.c, "its parameters " + ParameterList(read));
  }
  return lumped;
}
template <class T>
model::Lumped<T> LumpedOf(const Component& c, const ParameterMode& mode) {
  return LumpedOf<T>(c, mode, ModelOf(c));
}

template <class T>
T ShaftSegmentMass(const Component& c, const ParameterMode& mode) {
  if (HasValue(c, "linear_density")) return Read<T>(c, "linear_density", mode) * Read<T>(c, "length", mode);
  return ShaftMass(Read<T>(c, "density", mode), Read<T>(c, "outer_diameter", mode),
                   Read<T>(c, "wall_thickness", mode), Read<T>(c, "length", mode));
}

/// A transmission with scalar T; Project() turns it into the public double Transmission.
template <class T>
struct TransmissionDraft {
  struct Point { std::string name; T J; bool accumulate; std::string component; };
  struct Link { int a, b; T c; T J; std::string name; std::string component; };
  std::vector<Point> points;
  std::vector<Link> links;
  std::vector<int> point_of_node;  ///< graph node -> point holding its inertia (far end for shafts)
  std::vector<int> link_of_node;   ///< graph node -> its link, -1 if rigid

  template <class PickJ, class PickC>
  Transmission Project(PickJ pick_J, PickC pick_c) const {
    Transmission t;
    for (const auto& p : points) t.AddPoint(p.name, pick_J(p.J), p.accumulate, p.component);
    for (const auto& l : links) t.AddLink(l.a, l.b, pick_c(l.c), pick_J(l.J), l.name, l.component);
    return t;
  }
};

/// The transmission of the graph (all values reflected to the PDU output speed). `skip` is a
/// graph node whose link is left out (a ruptured shaft): then only the subtree beyond it is
/// built when `only_subtree_of` >= 0.
template <class T>
TransmissionDraft<T> BuildTransmission(const Graph& g, const ParameterMode& mode, int only_subtree_of = -1) {
  TransmissionDraft<T> t;
  const std::vector<T> n = SpeedRatios<T>(g, mode);
  t.point_of_node.assign(g.nodes.size(), -1);
  t.link_of_node.assign(g.nodes.size(), -1);
  std::vector<bool> include(g.nodes.size(), only_subtree_of < 0);
  if (only_subtree_of >= 0)
    for (int i : g.Subtree(only_subtree_of)) include[i] = true;
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    if (!include[i]) continue;
    const Component& c = *g.nodes[i].component;
    const T n2 = n[i] * n[i];
    const int parent = g.nodes[i].parent;
    const bool root = parent < 0 || (only_subtree_of >= 0 && static_cast<int>(i) == only_subtree_of);
    int at = root ? -1 : t.point_of_node[parent];
    const model::ComponentModel* m = g.nodes[i].model;
    const model::Lumped<T> lumped = LumpedOf<T>(c, mode, m);
    if constexpr (std::is_same_v<T, double>) {
      // Finite factors whose product overflows: named here, not at the lumped node they reach.
      const std::string reflected = " reflected to the PDU output speed";
      const std::string from = " x (w / w_pdu)^2 = " + FormatMessageNumber(n2) + " (the speed ratio at its input)";
      if (!std::isfinite(lumped.J * n2))
        ThrowNotFinite(c, "inertia" + reflected + " [kg*m^2]", lumped.J * n2,
                       "its lumped inertia " + FormatMessageNumber(lumped.J) + from);
      if (lumped.c && !std::isfinite(*lumped.c * n2))
        ThrowNotFinite(c, "stiffness" + reflected + " [N*m/rad]", *lumped.c * n2,
                       "its lumped stiffness " + FormatMessageNumber(*lumped.c) + from);
    }
    if (m && m->roles().segment) {
      if (root) at = static_cast<int>(t.points.size()), t.points.push_back({c.id + ".a", T(0.0), false, ""});
      const int end = static_cast<int>(t.points.size());
      t.points.push_back({c.id + ".b", T(0.0), false, ""});
      t.link_of_node[i] = static_cast<int>(t.links.size());
      t.links.push_back({at, end, *lumped.c * n2, lumped.J * n2, c.id, c.id});
      t.point_of_node[i] = end;
      continue;
    }
    const T J = lumped.J * n2;
    const std::optional<T> stiffness = lumped.c;
    const bool accumulate = m && m->roles().lumps_inertia;
    if (root || stiffness) {
      const int point = static_cast<int>(t.points.size());
      t.points.push_back({c.id, J, accumulate, c.id});
      if (!root) {
        t.link_of_node[i] = static_cast<int>(t.links.size());
        t.links.push_back({at, point, *stiffness * n2, T(0.0), c.id, c.id});
      }
      t.point_of_node[i] = point;
      continue;
    }
    auto& p = t.points[at];
    if constexpr (std::is_same_v<T, double>) {
      if (!std::isfinite(p.J + J))
        ThrowNotFinite(c, "inertia" + std::string(" [kg*m^2], added to that of '") + p.name + "'", p.J + J,
                       FormatMessageNumber(J) + " (its own, at the PDU output speed) + " + FormatMessageNumber(p.J) +
                           " (of '" + p.name + "')");
    }
    p.J = p.J + J;
    if (accumulate && p.component.empty()) {
      p.name = c.id;
      p.component = c.id;
    }
    p.accumulate = p.accumulate || accumulate;
    t.point_of_node[i] = at;
  }
  return t;
}

}  // namespace highlift::reduced_models::detail

namespace highlift::reduced_models::detail {

/// The value of a table with the largest magnitude (the sizing point of a load profile).
inline double PeakOfTable(const Table& table) {
  double best = 0.0;
  for (double y : table.y)
    if (std::abs(y) > std::abs(best)) best = y;
  return best;
}

/// Actuator output torques of a load case at their sizing points (largest magnitude).
inline std::map<std::string, double> SizingLoads(const LoadCase& load_case) {
  std::map<std::string, double> loads;
  for (const auto& [actuator, table] : load_case.actuator_loads) loads[actuator] = PeakOfTable(table);
  return loads;
}

/// The largest PDU speed of a load case; the PDU's max_output_speed when it has no profile (its
/// domain under ParameterMode::kIntervals, so an uncertain speed is enclosed, not taken at nominal).
template <class T = double>
T SizingSpeed(const LoadCase& load_case, const Component& pdu, const ParameterMode& mode = {}) {
  if (load_case.pdu_speed && !load_case.pdu_speed->y.empty()) {
    double best = 0.0;
    for (double y : load_case.pdu_speed->y) best = std::max(best, std::abs(y));
    return T(best);
  }
  return Read<T>(pdu, "max_output_speed", mode);
}

/// Largest of two values; for intervals, the enclosure of max(x, y) over both.
inline double Max(double a, double b) { return std::max(a, b); }
inline Interval Max(const Interval& a, const Interval& b) { return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)}; }
/// Smallest of two values; for intervals, the enclosure of min(x, y) over both.
inline double Min(double a, double b) { return std::min(a, b); }
inline Interval Min(const Interval& a, const Interval& b) { return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)}; }

}  // namespace highlift::reduced_models::detail
