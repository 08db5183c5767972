#include "highlift/icsp/drive_system.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <functional>
#include <iterator>
#include <optional>
#include <queue>
#include <set>
#include <string>
#include <unordered_map>

#include "highlift/core/catalogue.h"
#include "highlift/core/units.h"
#include "highlift/icsp/parser.h"
#include "highlift/model/component_model.h"
#include "highlift/model/hydraulic_pdu.h"
#include "highlift/model/laws.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/lumped_model.h"
#include "highlift/reduced_models/modal.h"
#include "highlift/reduced_models/single_dof.h"

namespace highlift::icsp {

double ToDisplay(double si, const std::string& unit) {
  if (unit.empty() || unit == "1" || !std::isfinite(si)) return si;
  try {
    const UnitConversion u = ParseUnit(unit);
    return (si - u.offset) / u.scale;
  } catch (const InputError&) {
    return si;
  }
}

namespace {

using model::Sign;
using model::Sym;

/// Smallest eigenvalue w1 [rad/s] of K v = w^2 M v for a forest of free nodes in breadth-first
/// `order` (parent before child; `parent` -1 at a root), diagonal K, off-diagonal -c_parent
/// between a node and its parent, M > 0. Leaf-first elimination of K - lambda M has no fill-in on
/// a tree, and by Sylvester's law of inertia its negative pivots count the eigenvalues below
/// lambda; bisection on that count brackets w1^2 to a relative 1e-13 in O(n) per step. NaN when
/// there is a rigid-body mode (a part not held).
double FirstOmegaOfTree(const std::vector<int>& order, const std::vector<int>& parent, const std::vector<double>& c_parent,
                        const std::vector<double>& K, const std::vector<double>& M) {
  if (order.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> d(K.size());
  auto below = [&](double lambda) {  // number of eigenvalues below lambda
    for (int u : order) d[u] = K[u] - lambda * M[u];
    int negative = 0;
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
      const int u = *it;
      if (d[u] == 0.0) d[u] = -std::numeric_limits<double>::min();  // lambda is an eigenvalue: count it below
      if (d[u] < 0.0) ++negative;
      if (parent[u] >= 0) d[parent[u]] -= c_parent[u] * c_parent[u] / d[u];
    }
    return negative;
  };
  double scale = 0.0;  // Gershgorin bound of the largest eigenvalue of M^-1 K
  for (int u : order) scale = std::max(scale, 2.0 * K[u] / M[u]);
  if (!(scale > 0.0) || !std::isfinite(scale)) return std::numeric_limits<double>::quiet_NaN();
  if (below(1e-12 * scale) > 0) return std::numeric_limits<double>::quiet_NaN();  // a rigid-body mode
  double lo = 1e-12 * scale, hi = scale;
  while (below(hi) == 0) hi *= 2.0;
  while (hi - lo > 1e-13 * hi) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (below(mid) > 0 ? hi : lo) = mid;
  }
  return std::sqrt(0.5 * (lo + hi));
}

/// First eigenfrequency [rad/s] of a lumped model with node `stop` clamped: the smallest w with
/// K v = w^2 M v. The spring graph of a transmission is a tree, so K - lambda M factors leaf first
/// without fill-in, and by Sylvester's law of inertia the number of negative pivots is the number
/// of eigenvalues below lambda; bisection on that count brackets the first one to a relative
/// 1e-13 in O(n) per step (the dense solver of reduced_models::ComputeModes is O(n^3)). Falls back
/// to ComputeModes when the springs form a cycle. NaN when the model has no finite elastic first
/// mode (a free node without inertia, or a part not held by the stop).
double FirstOmega(const reduced_models::LumpedModel& m, int stop) {
  const int n = static_cast<int>(m.nodes.size());
  std::vector<double> K(n, 0.0), M(n, 0.0);
  std::vector<std::vector<std::pair<int, double>>> adjacent(n);
  for (const auto& s : m.springs) {
    if (s.a >= 0) K[s.a] += s.c;
    if (s.b >= 0) K[s.b] += s.c;
    if (s.a >= 0 && s.b >= 0 && s.a != stop && s.b != stop) {
      adjacent[s.a].push_back({s.b, s.c});
      adjacent[s.b].push_back({s.a, s.c});
    }
  }
  for (int i = 0; i < n; ++i) {
    M[i] = m.nodes[i].J;
    if (i != stop && !(M[i] > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  }
  // Breadth-first order of every free tree; the pivots are taken in reverse (leaves first).
  std::vector<int> order, parent(n, -2);
  std::vector<double> parent_c(n, 0.0);
  for (int r = 0; r < n; ++r) {
    if (r == stop || parent[r] != -2) continue;
    parent[r] = -1;
    const std::size_t begin = order.size();
    order.push_back(r);
    for (std::size_t k = begin; k < order.size(); ++k) {
      const int u = order[k];
      for (const auto& [v, c] : adjacent[u]) {
        if (v == parent[u]) continue;
        if (parent[v] != -2) {  // a cycle: not a tree
          reduced_models::ModalOptions modal;
          modal.clamped = {stop};
          modal.mode_shapes = 0;
          const double w = reduced_models::ComputeModes(m, modal).FirstElasticOmega();
          return w > 0.0 ? w : std::numeric_limits<double>::quiet_NaN();
        }
        parent[v] = u;
        parent_c[v] = c;
        order.push_back(v);
      }
    }
  }
  std::vector<double> c_parent(n, 0.0);
  for (int u : order) c_parent[u] = parent_c[u];
  return FirstOmegaOfTree(order, parent, c_parent, K, M);
}

/// One argument of a sizing case's first-mode function: a concentrated inertia at a transmission
/// point, or the stiffness or distributed inertia of a link.
struct ModeArg {
  enum Kind { kPointJ, kLinkC, kLinkJ } kind;
  int index;
};

/// w1 of a sizing case as a function of its arguments (see Builder::PeakCase). With one element
/// per link (`peak`'s default) reduced_models' lumped model has node p = point p, spring l = link
/// l and node J = point J + half the J of each link at it, and its tree order is fixed: an
/// evaluation fills arrays and bisects, without building the model. The fast model is checked
/// against reduced_models::BuildLumpedModel once, at construction; other element counts, or a
/// mismatch, build the lumped model on every evaluation.
class FirstModeFunction {
 public:
  FirstModeFunction(reduced_models::Transmission base, int stop, std::vector<ModeArg> args, int elements)
      : base_(std::move(base)), stop_(stop), args_(std::move(args)), elements_(elements) {
    for (auto& point : base_.points) point.J = 0.0;
    for (auto& link : base_.links) link.J = 0.0;
    fast_ = elements_ == 1 && Prepare();
  }

  double operator()(std::span<const double> x) const {
    for (double v : x)
      if (!(v >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
    return fast_ ? Fast(x) : Slow(x);
  }

 private:
  /// The transmission with the arguments filled in.
  reduced_models::Transmission Fill(std::span<const double> x) const {
    reduced_models::Transmission t = base_;
    for (std::size_t i = 0; i < args_.size(); ++i) {
      if (args_[i].kind == ModeArg::kPointJ) t.points[args_[i].index].J += x[i];
      else if (args_[i].kind == ModeArg::kLinkC) t.links[args_[i].index].c = x[i];
      else t.links[args_[i].index].J = x[i];
    }
    return t;
  }
  double Slow(std::span<const double> x) const {
    try {
      const reduced_models::LumpedModel m =
          reduced_models::BuildLumpedModel(Fill(x), reduced_models::Reduction::kFullResolution, elements_);
      return FirstOmega(m, m.NodeOfPoint(stop_));
    } catch (const std::exception&) {
      return std::numeric_limits<double>::quiet_NaN();  // degenerate corner: no finite w1
    }
  }
  /// Node inertias and link stiffnesses of the one-element model.
  void Arrays(std::span<const double> x, std::vector<double>& J, std::vector<double>& c) const {
    J.assign(base_.points.size(), 0.0);
    c.resize(base_.links.size());
    for (std::size_t l = 0; l < base_.links.size(); ++l) c[l] = base_.links[l].c;
    for (std::size_t i = 0; i < args_.size(); ++i) {
      const int k = args_[i].index;
      if (args_[i].kind == ModeArg::kPointJ) {
        J[k] += x[i];
      } else if (args_[i].kind == ModeArg::kLinkC) {
        c[k] = x[i];
      } else {
        J[base_.links[k].a] += 0.5 * x[i];
        J[base_.links[k].b] += 0.5 * x[i];
      }
    }
  }
  bool Prepare() {
    // Check the one-element rule against reduced_models at a probe point.
    std::vector<double> probe(args_.size());
    for (std::size_t i = 0; i < probe.size(); ++i) probe[i] = 1.0 + 0.001 * static_cast<double>(i);
    reduced_models::LumpedModel m;
    try {
      m = reduced_models::BuildLumpedModel(Fill(probe), reduced_models::Reduction::kFullResolution, 1);
    } catch (const std::exception&) {
      return false;
    }
    std::vector<double> J, c;
    Arrays(probe, J, c);
    if (m.nodes.size() != J.size() || m.springs.size() != c.size()) return false;
    for (std::size_t i = 0; i < J.size(); ++i)
      if (m.nodes[i].point != static_cast<int>(i) || std::fabs(m.nodes[i].J - J[i]) > 1e-12 * std::fabs(J[i])) return false;
    for (std::size_t l = 0; l < c.size(); ++l) {
      const auto& spring = m.springs[l];
      if (spring.link != static_cast<int>(l) || spring.a != base_.links[l].a || spring.b != base_.links[l].b ||
          spring.c != c[l])
        return false;
    }
    // The tree order of the free nodes (the stop is clamped).
    const int n = static_cast<int>(J.size());
    std::vector<std::vector<std::pair<int, int>>> adjacent(n);
    for (std::size_t l = 0; l < base_.links.size(); ++l) {
      const int a = base_.links[l].a, b = base_.links[l].b;
      if (a == stop_ || b == stop_) continue;
      adjacent[a].push_back({b, static_cast<int>(l)});
      adjacent[b].push_back({a, static_cast<int>(l)});
    }
    parent_.assign(n, -2);
    parent_link_.assign(n, -1);
    for (int r = 0; r < n; ++r) {
      if (r == stop_ || parent_[r] != -2) continue;
      parent_[r] = -1;
      const std::size_t begin = order_.size();
      order_.push_back(r);
      for (std::size_t k = begin; k < order_.size(); ++k) {
        const int u = order_[k];
        for (const auto& [v, l] : adjacent[u]) {
          if (l == parent_link_[u]) continue;
          if (parent_[v] != -2) return false;  // a cycle
          parent_[v] = u;
          parent_link_[v] = l;
          order_.push_back(v);
        }
      }
    }
    return !order_.empty();
  }
  double Fast(std::span<const double> x) const {
    Arrays(x, J_, c_);
    K_.assign(J_.size(), 0.0);
    for (std::size_t l = 0; l < c_.size(); ++l) {
      K_[base_.links[l].a] += c_[l];
      K_[base_.links[l].b] += c_[l];
    }
    c_parent_.assign(J_.size(), 0.0);
    for (int u : order_) {
      if (!(J_[u] > 0.0)) return std::numeric_limits<double>::quiet_NaN();
      if (parent_link_[u] >= 0) c_parent_[u] = c_[parent_link_[u]];
    }
    return FirstOmegaOfTree(order_, parent_, c_parent_, K_, J_);
  }

  reduced_models::Transmission base_;  // topology and the stiffnesses that are not arguments
  int stop_;
  std::vector<ModeArg> args_;
  int elements_;
  bool fast_ = false;
  std::vector<int> order_, parent_, parent_link_;  // free nodes breadth first; parent node and link
  mutable std::vector<double> J_, c_, K_, c_parent_;  // scratch
};

class Builder {
 public:
  explicit Builder(const Project& p) : project_(p) {}

  DriveSystemNetwork Build() {
    AddParameters();
    BuildTree();
    try {
      peaks_ = reduced_models::DescribePeaks(project_);
      for (std::size_t i = 0; i < peaks_->nodes.size(); ++i) node_index_[peaks_->nodes[i].id] = static_cast<int>(i);
    } catch (const InputError& e) {
      peaks_.reset();  // e.g. no load case: no sizing cases; a requirement that needs them says why
      peaks_error_ = e.message();
    }
    for (const Component& c : project_.components) {
      if (HasRole(c, &model::ComponentRoles::segment)) Shaft(c);
      else if (HasRole(c, &model::ComponentRoles::actuator)) Actuator(c);
    }
    Reflected();
    SeriesStiffness();
    TorqueFlows();
    TravelTimes();
    Peaks();
    Requirements();
    return std::move(out_);
  }

 private:
  Network& net() { return out_.network; }
  bool Has(const std::string& name) const { return out_.network.FindVariable(name).value >= 0; }
  const Component* Find(const std::string& id) const { return project_.FindComponent(id); }
  bool HasParam(const Component& c, const std::string& p) const { return Has(c.id + "." + p); }

  void Derived(const std::string& name, const std::string& unit, Interval domain = Interval(0.0, kInf)) {
    if (!Has(name)) net().AddVariable(name, domain, unit, "propagated");
  }
  void Law(const std::string& label, const std::string& description, const std::string& text) {
    AddConstraintText(net(), text, {label, description, ConstraintRole::kPhysics});
    ++out_.physics_constraints;
  }

  // ---------------------------------------------------------------------------------------------
  // The component laws (model/src/components) read through the symbolic scalar: each law is the
  // one its type writes for double and Interval, instantiated with model::Sym over the variables
  // of the network, and rendered as a constraint.

  static const model::ComponentModel* ModelOf(const Component& c) { return model::FindComponentModel(c.type); }
  static bool HasRole(const Component& c, bool model::ComponentRoles::*role) {
    const model::ComponentModel* m = ModelOf(c);
    return m && m->roles().*role;
  }

  /// The signs the variable `name` can take: its recorded sign (a parameter's domain or
  /// declaration, a derived variable's law), else its initial domain.
  Sign SignOf(const std::string& name) const {
    if (auto it = sign_.find(name); it != sign_.end()) return it->second;
    const VariableId v = out_.network.FindVariable(name);
    if (v.value < 0) return Sign::Unknown();
    const Interval& d = out_.network.variable(v).initial;
    return IsEmpty(d) ? Sign::Unknown() : Sign::OfRange(d.lower(), d.upper());
  }
  /// The variable `name` as a symbolic value.
  Sym Var(const std::string& name) const { return Sym::Variable(name, SignOf(name)); }

  /// A component's parameters as the network's variables (model::ParameterReader<Sym>): its own
  /// parameter is its variable; one it does not give is the catalogue default as a constant, as
  /// the reduced models read it; one without either is missing (the law that needs it is left out).
  class Reader final : public model::ParameterReader<Sym> {
   public:
    Reader(const Builder& b, const Component& c) : b_(b), c_(c) {}
    Sym operator()(std::string_view name) const override {
      const std::string var = c_.id + "." + std::string(name);
      if (b_.Has(var)) return b_.Var(var);
      if (reduced_models::HasReducedModelValue(c_, name)) return Sym(reduced_models::ReducedModelValue(c_, name));
      return Sym::Missing(var);
    }
    bool Has(std::string_view name) const override {
      return b_.Has(c_.id + "." + std::string(name)) || reduced_models::HasReducedModelValue(c_, name);
    }
    double Nominal(std::string_view name) const override { return reduced_models::ReducedModelValue(c_, name); }

   private:
    const Builder& b_;
    const Component& c_;
  };

  /// Derived variable `name` == `law`, with the signs of its law where its domain allows both;
  /// the variable, or the missing value when the law lacks a parameter (then nothing is added).
  Sym Define(const std::string& name, const std::string& unit, const std::string& description, const Sym& law,
             Interval domain = Interval(0.0, kInf), const Sym::Names& names = {}) {
    if (law.missing()) return law;
    Derived(name, unit, domain);
    Sign sign = Sign::OfRange(domain.lower(), domain.upper());
    if (law.sign().known()) sign = Sign(sign.bits() & law.sign().bits());
    sign_[name] = sign.known() ? sign : law.sign();
    Law(name, description, name + " == " + law.Text(names));
    return Var(name);
  }

  /// The speed law of the stage between component `id` and its parent: the parent's
  /// SpeedRatioLaw from its own entry port to the port `id` hangs on.
  model::PortRatio GearOf(const std::string& id) const {
    const std::string& up = parent_.at(id);
    const Component* parent = Find(up);
    const model::ComponentModel* m = parent ? ModelOf(*parent) : nullptr;
    return m ? m->SpeedRatioLaw(entry_port_.at(up), parent_port_.at(id)) : model::PortRatio{};
  }
  /// `x` times w_pdu / w_id: times the speed reduction of every stage between the PDU and `id`
  /// (its own entry stage included), one stage after the other from `id` inwards (a travel at
  /// `id` taken to the PDU; 1 / Inboard(1, id) is the speed ratio w_id / w_pdu).
  Sym Inboard(Sym x, const std::string& id) const {
    for (std::string u = id; parent_.count(u) && !parent_.at(u).empty(); u = parent_.at(u)) {
      const model::PortRatio law = GearOf(u);
      if (law.parameter.empty() || law.power == 0) continue;
      const Sym ratio = Reader(*this, *Find(parent_.at(u)))(law.parameter);
      x = law.power < 0 ? x * ratio : x / ratio;
    }
    return x;
  }
  /// Inboard(1, id): the speed reduction w_pdu / w_id, built once per component.
  const Sym& Reduction(const std::string& id) const {
    auto it = reduction_.find(id);
    if (it == reduction_.end()) it = reduction_.emplace(id, Inboard(Sym(1.0), id)).first;
    return it->second;
  }
  /// w_id / w_pdu.
  Sym SpeedRatioOf(const std::string& id) const { return Sym(1.0) / Reduction(id); }
  /// The steady-state law of component `c` (ComponentModel::InputTorque): what it passes on at
  /// its ports (`torques` by child id), the actuator load `load`, its input speed `w`.
  Sym InputTorque(const Component& c, const std::vector<std::pair<std::string, Sym>>& torques, const Sym& load,
                  const Sym& w, double friction) const {
    Sym through(0.0), branch(0.0);
    for (const auto& [child, tau] : torques) (parent_port_.at(child) == "branch" ? branch : through) += tau;
    const model::ComponentModel* m = ModelOf(c);
    if (!m) return through;
    return m->InputTorque(Reader(*this, c), model::SteadyFlow<Sym>{through, branch, load, w, Sym(friction)});
  }

  void AddParameters() {
    for (const Component& c : project_.components) {
      const ComponentTypeSpec* type = FindComponentType(c.type);
      for (const auto& [name, p] : c.parameters) {
        const ParameterSpec* spec = type ? type->FindParameter(name) : nullptr;
        if (spec && spec->kind != ParameterKind::kScalar && spec->kind != ParameterKind::kInteger) continue;
        Interval d;
        const bool whole = !std::isfinite(p.domain.lo) && !std::isfinite(p.domain.hi);
        if (!whole && !p.domain.empty()) d = Interval(p.domain.lo, p.domain.hi);
        else if (p.nominal) d = Interval(*p.nominal, *p.nominal);
        else if (spec && !(!std::isfinite(spec->default_domain.lo) && !std::isfinite(spec->default_domain.hi)))
          d = Interval(spec->default_domain.lo, spec->default_domain.hi);
        else d = Whole();
        const VariableId v = net().AddVariable(c.id + "." + name, d, spec ? spec->unit : "", ToString(p.provenance));
        // The nominal design: the nominal value, else the middle of a bounded domain (as
        // reduced_models reads a parameter given only as an interval).
        if (p.nominal && std::isfinite(*p.nominal)) out_.nominal.push_back({v.value, *p.nominal});
        else if (!p.nominal && std::isfinite(d.lower()) && std::isfinite(d.upper()) && d.lower() < d.upper())
          out_.nominal.push_back({v.value, 0.5 * (d.lower() + d.upper())});
      }
    }
  }

  /// The drive line as a tree rooted at the PDU (connections are undirected flange links).
  void BuildTree() {
    struct Link {
      std::string other, port, other_port;
    };
    std::map<std::string, std::vector<Link>> adj;
    for (const Connection& k : project_.connections) {
      adj[k.a.component].push_back({k.b.component, k.a.port, k.b.port});
      adj[k.b.component].push_back({k.a.component, k.b.port, k.a.port});
    }
    std::string root;
    for (const Component& c : project_.components) {
      if (HasRole(c, &model::ComponentRoles::drive_unit)) root = c.id;
    }
    if (root.empty()) return;
    root_ = root;
    std::queue<std::string> q;
    q.push(root);
    parent_[root] = "";
    entry_port_[root] = "";
    while (!q.empty()) {
      const std::string u = q.front();
      q.pop();
      order_.push_back(u);
      for (const Link& v : adj[u]) {
        if (parent_.count(v.other)) continue;
        parent_[v.other] = u;
        parent_port_[v.other] = v.port;
        entry_port_[v.other] = v.other_port;
        children_[u].push_back(v.other);
        q.push(v.other);
      }
    }
  }
  /// All components outboard of `id` (its subtree), including itself.
  std::vector<const Component*> Subtree(const std::string& id) const {
    std::vector<const Component*> out;
    std::vector<std::string> stack{id};
    while (!stack.empty()) {
      const std::string u = stack.back();
      stack.pop_back();
      if (const Component* c = Find(u)) out.push_back(c);
      auto it = children_.find(u);
      if (it != children_.end()) stack.insert(stack.end(), it->second.begin(), it->second.end());
    }
    return out;
  }
  /// The gear stage that feeds the station of actuator `id` from the drive line (the nearest
  /// inboard component with a speed ratio towards it, a branch gearbox), and the component of the
  /// station that hangs on it.
  std::pair<const Component*, std::string> StationStage(const std::string& id) const {
    for (std::string u = id; parent_.count(u) && !parent_.at(u).empty(); u = parent_.at(u)) {
      if (!GearOf(u).parameter.empty()) return {Find(parent_.at(u)), u};
    }
    return {nullptr, ""};
  }
  // ---------------------------------------------------------------------------------------------
  // What the reduced models read of a component, as text over the network's variables.

  /// A number as constraint text (round-trips exactly).
  static std::string Num(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string("(") + buf + ")";
  }
  /// The parameter as reduced_models reads it: the component's own (a variable of the network),
  /// else the catalogue default (a constant); empty when there is none.
  std::string Value(const Component& c, const std::string& name) const {
    if (HasParam(c, name)) return c.id + "." + name;
    if (reduced_models::HasReducedModelValue(c, name)) return Num(reduced_models::ReducedModelValue(c, name));
    return "";
  }
  bool HasValue(const Component& c, const std::string& name) const { return !Value(c, name).empty(); }
  /// What a system torque limiter `stl` passes on to a jam behind it when the static torque
  /// `tau_in` (at the reference speed) arrives: its type's law (model::LimiterPassedTorque, as
  /// peak and size read it), else the old cap by its lock-out torque.
  Sym SystemLimiterPasses(const Component& stl, const Sym& tau_in) const {
    const Reader r(*this, stl);
    if (const model::ComponentModel* m = ModelOf(stl))
      if (auto passed = m->JamPassedTorque(r, tau_in, SpeedRatioOf(stl.id)); passed && !passed->missing()) return *passed;
    if (r.Has("lockout_torque_extend")) return min(tau_in, r("lockout_torque_extend") * SpeedRatioOf(stl.id));
    return tau_in;
  }
  /// The PDU's stall torque as a term of a constraint (model::PduStallTorque: a hydraulic drive's
  /// from its motors, as simulated, through the variable `<pdu>.motor_stall_torque`); "0" when
  /// it has no stall torque.
  std::string StallTorque(const Component& pdu) {
    const Reader p(*this, pdu);
    if (!model::HasPduStallTorque(pdu, p)) return "0";
    if (!model::StallTorqueFromMotors(pdu, p)) return Value(pdu, "stall_torque");
    const std::string name = pdu.id + ".motor_stall_torque";
    if (Has(name)) return name;
    const Sym law = Define(name, "N*m",
                           "PDU stall torque from its motors: n_m V_m (p_s - p_r) i eta_m eta (docs/hydraulics.md)",
                           model::PduStallTorque(pdu, p));
    return law.missing() ? "0" : name;
  }
  /// Variable `name` for the text `expression` ("name" itself when it already is a variable).
  std::string VariableFor(const std::string& name, const std::string& unit, const std::string& expression,
                          const std::string& description) {
    if (Has(expression)) return expression;
    Derived(name, unit, Whole());
    Law(name, description, name + " == " + expression);
    return name;
  }

  /// A segment (torque shaft): its tube polar moment, mass and torque capacity (laws.h), and its
  /// stiffness c and inertia J by its type's lumped law, each a variable of the network.
  void Shaft(const Component& s) {
    const std::string p = s.id + ".";
    const Reader R(*this, s);
    const bool tube = HasParam(s, "outer_diameter") && HasParam(s, "wall_thickness") && HasParam(s, "length");
    const Sym D = R("outer_diameter"), t = R("wall_thickness"), L = R("length");
    Sym::Names names;
    if (tube) {
      const Sym Ip = model::TubePolarMoment(D, t);
      // pi/32 (D^4 - d^4) factored as pi/8 (D^2 + d^2)(D - t) t (every factor positive: tighter
      // enclosures); the laws below name it.
      names.push_back({Ip, p + "polar_moment"});
      Define(p + "polar_moment", "m^4", "tube polar moment Ip = pi/32 (D^4 - d^4) = pi/8 (D^2 + d^2)(D - t) t", Ip);
      PolarMomentIdentity(s);
    }
    // Stiffness and inertia as the reduced models take them (its type's lumped law): given
    // values override the tube.
    const model::Lumped<Sym> lumped = ModelOf(s)->LumpedAtInput(R);
    if (lumped.c)
      Define(p + "c", "N*m/rad", R.Has("stiffness") ? "segment stiffness, given" : "tube stiffness c = G Ip / L", *lumped.c,
             Interval(0.0, kInf), names);
    Define(p + "J", "kg*m^2",
           R.Has("inertia")          ? "segment inertia, given"
           : R.Has("linear_density") ? "thin tube inertia J = m' L r^2, r the mean radius"
                                     : "tube inertia J = rho Ip L",
           lumped.J, Interval(0.0, kInf), names);
    if (!tube) return;
    if (HasParam(s, "density"))
      Define(p + "mass", "kg", "tube mass m = rho pi (D - t) t L", model::ShaftMass(R("density"), D, t, L));
    const bool buckling = HasParam(s, "shear_modulus") && HasParam(s, "poisson_ratio") && HasParam(s, "buckling_knockdown");
    if (buckling) {
      Define(p + "buckling_stress", "MPa",
             "torsional buckling stress of the tube, tau_cr (elastic, long or moderate length, knock-down gamma; "
             "NASA SP-8007 s. 4.1.4)",
             model::TubeBucklingStress(R("shear_modulus"), R("poisson_ratio"), R("buckling_knockdown"), D, t, L));
    }
    if (HasParam(s, "allowable_shear_stress")) {
      if (buckling)
        Define(p + "torque_capacity", "N*m",
               "torque at the lesser of the allowable shear stress and the buckling stress, min(tau_allow, tau_cr) 2 Ip / D",
               model::TubeTorqueCapacityWithBuckling(R("allowable_shear_stress"), Var(p + "buckling_stress"), D,
                                                     Var(p + "polar_moment")));
      else
        Define(p + "torque_capacity", "N*m", "torque at the allowable shear stress, tau_allow 2 Ip / D",
               model::TubeTorqueCapacity(R("allowable_shear_stress"), D, Var(p + "polar_moment")));
    }
  }

  /// A requirement may write a tube's polar moment out in D and t, as the examples' capacity
  /// requirements do (`tau_allow * 0.19634954 * (D^4 - (D - 2 * t)^4) / D`). HC4 then projects
  /// the requirement's lower bound onto D and t one at a time, which cuts each only at its far
  /// end, and the tube's stiffness, inertia and capacity (each read through Ip) keep the lower
  /// ends of the box's thinnest corner however large a load the tube must carry. The identity
  /// D^4 - d^4 = 4 (D^2 + d^2)(D - t) t (d = D - 2t) is exact: 4 Ip / k with k the constant of
  /// TubePolarMoment (pi/8, enclosed as its law reads it). Requirements() puts it in, so the
  /// requirement bounds Ip, and through it c = G Ip / L, J = rho Ip L and tau_allow 2 Ip / D.
  void PolarMomentIdentity(const Component& s) {
    const std::string D = s.id + ".outer_diameter", t = s.id + ".wall_thickness", Ip = s.id + ".polar_moment";
    const ExprId written = ParseExpression(net(), D + "^4 - (" + D + " - 2 * " + t + ")^4", "the tube law of " + s.id);
    const ExprId named = ParseExpression(net(), "4 * " + Ip + " / " + Sym(std::numbers::pi / 8.0).Text(),
                                         "the tube law of " + s.id);
    identities_.emplace(written.value, named);
    // The identity also as a law of Ip: through the written form HC4 projects Ip's lower bound
    // onto D as sharply as it projected the requirement before (iterated, D^4 >= b + (D - 2t)^4
    // climbs to the least D that carries the load at the thickest wall), which the factored law
    // does not give back (docs/performance.md); the factored law encloses Ip more tightly forward.
    net().AddConstraint(named, Relation::kEqual, written,
                        {s.id + ".polar_moment", "tube polar moment, also written as 4 Ip / (pi/8) = D^4 - d^4",
                         ConstraintRole::kPhysics, ""});
    ++out_.physics_constraints;
  }

  void Actuator(const Component& g) {
    const std::string p = g.id + ".";
    double load = 0.0;
    bool any = false;
    for (const LoadCase& lc : project_.load_cases) {
      auto it = lc.actuator_loads.find(g.id);
      if (it == lc.actuator_loads.end()) continue;
      for (double y : it->second.y) load = std::max(load, std::fabs(y));
      any = true;
    }
    if (!any || !HasParam(g, "ratio")) return;
    // The airload at the actuator output (a ballscrew's load is its screw torque, as
    // reduced_models reads it), through its steady-state law without friction: opposing, and
    // aiding (its magnitude).
    Derived(p + "max_load", "N*m", Interval(load, load));
    const Sym max_load = Var(p + "max_load");
    if (HasParam(g, "eta_opposing"))
      Define(p + "input_torque_opposing", "N*m", "actuator input torque against the airload, T_out / (i eta_opp)",
             InputTorque(g, {}, max_load, Sym(0.0), 0.0));
    if (HasParam(g, "eta_aiding"))
      Define(p + "input_torque_aiding", "N*m", "actuator input torque with an aiding airload, T_out eta_aid / i",
             -InputTorque(g, {}, -max_load, Sym(0.0), 0.0));
    // The station's input torque on the drive line: through the gear stage that feeds it.
    const auto [stage, station] = StationStage(g.id);
    if (stage && HasParam(*stage, "ratio") && Has(p + "input_torque_opposing")) {
      Define(stage->id + ".station_torque", "N*m", "station input torque on the drive shaft, T_act / (i_branch eta^meshes)",
             InputTorque(*stage, {{station, Var(p + "input_torque_opposing")}}, Sym(0.0), Sym(0.0), 0.0));
      stations_.push_back({&g, stage});
    }
  }

  /// Travel time of every load case with a PDU speed profile, with the profile's ramps. The
  /// profile is run at the PDU's maximum speed w (its speeds are fractions of its peak); its
  /// ramps keep their durations and its slow phases (creep) keep their share of the travel and
  /// their fraction of w; the phase at full speed takes the rest of the travel. Then
  ///   T = sum_ramps dt (1 - (f_a + f_b)/2) + K Phi / w,  K = 1 - sum_slow s + sum_slow s / f
  /// with Phi the travel at the PDU (travel angle x actuator ratio x the gear ratios inboard),
  /// which reproduces the profile's own duration at its own travel and peak speed.
  void TravelTimes() {
    if (stations_.empty() || root_.empty() || !Has(root_ + ".max_output_speed")) return;
    // Travel at the actuator input: a GRA's output angle x its ratio; a ballscrew's stroke / lead
    // (lead in m/rad) x its gear ratio.
    const Component& g = *stations_.front().first;
    const Sym input_travel = ModelOf(g)->InputTravel(Reader(*this, g));
    if (input_travel.missing()) return;
    const std::string travel = Inboard(input_travel, g.id).Text();
    std::vector<std::string> extend;
    for (const LoadCase& lc : project_.load_cases) {
      const std::string name = "travel_time." + lc.name;
      if (!lc.pdu_speed || lc.pdu_speed->y.size() < 2 || lc.pdu_speed->abscissa != "time") continue;
      const Table& w = *lc.pdu_speed;
      double peak = 0.0;
      for (double y : w.y) peak = std::max(peak, std::fabs(y));
      if (!(peak > 0.0)) continue;
      double t_lost = 0.0, travel_profile = 0.0, slow_share = 0.0, slow_time_share = 0.0;
      for (std::size_t k = 0; k + 1 < w.x.size(); ++k) travel_profile += 0.5 * (std::fabs(w.y[k]) + std::fabs(w.y[k + 1])) * (w.x[k + 1] - w.x[k]);
      for (std::size_t k = 0; k + 1 < w.x.size(); ++k) {
        const double dt = w.x[k + 1] - w.x[k], fa = std::fabs(w.y[k]) / peak, fb = std::fabs(w.y[k + 1]) / peak;
        if (fa == fb && fa == 1.0) continue;  // the hold at full speed
        if (fa == fb && fa > 0.0) {           // a slow phase: its share of the travel at fa w
          const double s = fa * peak * dt / travel_profile;
          slow_share += s;
          slow_time_share += s / fa;
          continue;
        }
        t_lost += dt * (1.0 - 0.5 * (fa + fb));  // a ramp (or a standstill)
      }
      const double K = 1.0 - slow_share + slow_time_share;
      Derived(name, "s");
      Law(name, "travel time of '" + lc.name + "' with the ramps of its speed profile, T = t_ramps + K Phi / w",
          name + " == " + Num(t_lost) + " + " + Num(K) + " * " + travel + " / " + OperatingSpeed());
      if (lc.direction == "extend") extend.push_back(name);
    }
    if (extend.empty()) {
      Derived("travel_time.extension", "s");
      Law("travel_time.extension", "extension time at the PDU's maximum speed, Phi / w",
          "travel_time.extension == " + travel + " / " + root_ + ".max_output_speed");
      return;
    }
    std::string longest = extend.front();
    for (std::size_t k = 1; k < extend.size(); ++k) longest = "max(" + longest + ", " + extend[k] + ")";
    Derived("travel_time.extension", "s");
    Law("travel_time.extension", "extension time, the longest extending load case", "travel_time.extension == " + longest);
  }

  /// The PDU speed the load cases run at (rad/s): the PDU's maximum speed scaled by the load
  /// cases' peak over its nominal value (1 when the profile is written for the nominal speed).
  std::string OperatingSpeed() {
    const std::string name = root_ + ".operating_speed";
    if (Has(name)) return name;
    const Component& pdu = *Find(root_);
    double factor = 1.0;
    if (peaks_ && reduced_models::HasReducedModelValue(pdu, "max_output_speed")) {
      const double nominal = reduced_models::ReducedModelValue(pdu, "max_output_speed");
      if (nominal > 0.0 && peaks_->w_operating > 0.0) factor = peaks_->w_operating / nominal;
    }
    Derived(name, "rad/s");
    Law(name, "speed of the load cases, the PDU's maximum speed x their peak / its nominal value",
        name + " == " + Num(factor) + " * " + root_ + ".max_output_speed");
    return name;
  }

  /// The inertia and stiffness of every component reflected to the PDU speed (x (w / w_pdu)^2),
  /// by its type's lumped law (ComponentModel::LumpedAtInput, as the reduced models read it): a
  /// segment its variables c and J, the others their law over their parameters.
  void Reflected() {
    if (!peaks_) return;
    for (std::size_t i = 0; i < peaks_->nodes.size(); ++i) {
      const Component& c = *Find(peaks_->nodes[i].id);
      const std::string p = c.id + ".";
      model::Lumped<Sym> lumped;
      if (HasRole(c, &model::ComponentRoles::segment)) {
        lumped.J = Has(p + "J") ? Var(p + "J") : Sym(0.0);
        if (Has(p + "c")) lumped.c = Var(p + "c");
      } else if (const model::ComponentModel* m = ModelOf(c)) {
        lumped = m->LumpedAtInput(Reader(*this, c));
      }
      const Sym& gears = Reduction(c.id);
      auto reflect = [&](const Sym& x) { return x / pow(gears, 2); };
      double J0 = 0.0;
      if (!(lumped.J.constant(&J0) && J0 == 0.0))  // no inertia of its own (a jam, a disconnector)
        Define(p + "reflected_inertia", "kg*m^2", "inertia of " + c.id + " at the PDU speed, J (w / w_pdu)^2",
               reflect(lumped.J));
      if (lumped.c)
        Define(p + "reflected_stiffness", "N*m/rad", "stiffness of " + c.id + " at the PDU speed, c (w / w_pdu)^2",
               reflect(*lumped.c));
    }
  }

  /// The steady-state torque flow of every load case, as reduced_models' sizing (`highlift
  /// size`) computes it: each component's input-flange torque at its own speed (positive resists
  /// the motion), from the actuator airloads (the largest magnitude of each load table) through
  /// the gear stages (opposing and aiding efficiencies by the sign of the torque), plus the
  /// friction at the load case's speed (Stribeck, paper eq. 3; shafts their drag per length):
  ///   torque.<case>.<component>
  /// From it: shaft drive torque and shear stress, the torque through each limiter and its margin,
  /// the PDU output torque and power. The brake holds the wing's back-driving torque.
  void TorqueFlows() {
    if (!peaks_) return;
    const Component* pdu = root_.empty() ? nullptr : Find(root_);
    std::vector<std::vector<Sym>> flows;  // per load case: torque variable per node
    std::vector<std::string> directions;
    std::vector<std::map<std::string, double>> aidings;  // per load case: aiding output torques
    for (const LoadCase& lc : project_.load_cases) {
      if (lc.actuator_loads.empty()) continue;
      std::map<std::string, double> loads, aiding;
      for (const auto& [actuator, table] : lc.actuator_loads) {
        double best = 0.0;
        for (double y : table.y)
          if (std::fabs(y) > std::fabs(best)) best = y;
        loads[actuator] = best;
        aiding[actuator] = -std::fabs(best);
      }
      // The speed: the profile's peak, else the PDU's max_output_speed (its variable, so the
      // friction of the flow is enclosed over its domain, as reduced_models' sizing does).
      Sym w(0.0);
      if (lc.pdu_speed && !lc.pdu_speed->y.empty()) {
        double peak = 0.0;
        for (double y : lc.pdu_speed->y) peak = std::max(peak, std::fabs(y));
        w = Sym(peak);
      } else if (pdu && reduced_models::HasReducedModelValue(*pdu, "max_output_speed")) {
        w = Reader(*this, *pdu)("max_output_speed");
      }
      flows.push_back(Flow(lc, loads, w));
      directions.push_back(lc.direction);
      aidings.push_back(aiding);
    }
    if (flows.empty()) return;
    // The largest magnitude over the load cases (of one direction when `direction` is given and
    // some case has it).
    auto operating = [&](int k, const std::string& direction) {
      std::optional<Sym> out;
      bool any = false;
      for (std::size_t f = 0; f < flows.size(); ++f) any = any || directions[f] == direction;
      for (std::size_t f = 0; f < flows.size(); ++f) {
        if (!direction.empty() && any && directions[f] != direction) continue;
        out = out ? max(*out, abs(flows[f][k])) : abs(flows[f][k]);
      }
      return *out;
    };
    for (std::size_t k = 0; k < peaks_->nodes.size(); ++k) {
      const auto& node = peaks_->nodes[k];
      const Component& c = *Find(node.id);
      const std::string p = c.id + ".";
      const int i = static_cast<int>(k);
      const model::ComponentRoles roles = ModelOf(c) ? ModelOf(c)->roles() : model::ComponentRoles{};
      if (roles.segment) {
        const Sym drive = Define(p + "drive_torque", "N*m",
                                 "drive torque in the shaft, the largest over the load cases of the torque flow", operating(i, ""));
        if (Has(p + "polar_moment"))
          Define(p + "shear_stress", "MPa", "shear stress from the drive torque, T D / (2 Ip)",
                 model::TubeShearStress(drive, Reader(*this, c)("outer_diameter"), Var(p + "polar_moment")));
      } else if ((roles.wing_limiter || roles.station_limiter) && HasParam(c, "lockout_torque_extend") &&
                 LimitedNode(i) >= 0) {
        // As reduced_models' setting rules: a system limiter against the largest wing torque of
        // every case, a station limiter against its largest extending torque; both against the
        // torque through the limiter (at its input, or at the port of a down-drive limiter).
        const bool station = roles.station_limiter;
        const int limited = LimitedNode(i);
        auto setting = [&](const std::string& suffix, const std::string& lockout, const std::string& direction,
                           const std::string& in) {
          const Sym through = Define(p + "torque_through" + suffix, "N*m",
                                     station ? "operating torque through the limiter, the largest of the " + direction + "ing load cases"
                                             : "operating torque through the limiter, the largest of the load cases",
                                     operating(limited, station ? direction : ""));
          Define(p + "margin" + suffix, "N*m", "limiter margin" + in + ", lockout setting minus operating torque",
                 Var(p + lockout) - through, Whole());
        };
        setting("", "lockout_torque_extend", "extend", "");
        if (HasParam(c, "lockout_torque_retract")) setting("_retract", "lockout_torque_retract", "retract", " in retract");
        // As reduced_models' rule for max_brake_torque: in a jam behind it the limiter's brake
        // must ground the static torque the drive can put into it (the PDU stall torque capped by
        // the system torque limiters inboard, at its speed) minus its end-stop torque, for the
        // actuator to see no more than the end-stop torque (LimiterPassedTorque).
        const Component& pdu = *Find(root_);
        const Reader pdu_reader(*this, pdu);
        if (station && HasParam(c, "max_brake_torque") && HasValue(c, "end_stop_torque") &&
            model::HasPduStallTorque(pdu, pdu_reader)) {
          Sym available = model::PduStallTorque(pdu, pdu_reader);  // a hydraulic drive's from its motors
          for (int k = limited; k >= 0; k = peaks_->nodes[k].parent) {
            const Component& u = *Find(peaks_->nodes[k].id);
            if (HasRole(u, &model::ComponentRoles::wing_limiter)) available = SystemLimiterPasses(u, available);
          }
          const Sym grounding =
              Define(p + "jam_grounding", "N*m",
                     "torque the limiter's brake grounds in a jam behind it: the PDU stall torque capped by the system "
                     "torque limiters, at its speed, minus its end-stop torque",
                     available / SpeedRatioOf(peaks_->nodes[limited].id) - Reader(*this, c)("end_stop_torque"), Whole());
          Define(p + "brake_margin", "N*m", "limiter brake margin, max_brake_torque minus the jam torque it grounds",
                 Var(p + "max_brake_torque") - grounding, Whole());
        }
      } else if (roles.tip_brake && HasParam(c, "static_capacity")) {
        // Holding (as reduced_models' rule for the static capacity): the larger of the wing's
        // operating torque at its root and the back-drive of its actuators' airloads through
        // their aiding efficiencies, friction neglected.
        int wing = i;
        while (wing >= 0 && peaks_->nodes[wing].parent > 0) wing = peaks_->nodes[wing].parent;
        std::vector<Sym> terms;
        if (wing >= 0) terms.push_back(operating(wing, ""));
        for (const auto& aiding : aidings) {
          const Sym t = -Backdrive(wing, aiding);
          double zero = 0.0;
          if (t.missing() || (t.constant(&zero) && zero == 0.0)) continue;
          if (std::none_of(terms.begin(), terms.end(), [&](const Sym& u) { return u.Same(t); })) terms.push_back(t);
        }
        if (terms.empty()) continue;
        Sym sum = terms.front();
        for (std::size_t t = 1; t < terms.size(); ++t) sum = max(sum, terms[t]);
        const Sym holding = Define(p + "holding_torque", "N*m",
                                   "torque the brake holds, the larger of the wing's operating torque at its root and the "
                                   "back-driving torque of its airloads, the largest load case",
                                   sum);
        Define(p + "holding_margin", "N*m", "brake margin, static capacity minus holding torque",
               Var(p + "static_capacity") - holding, Whole());
      } else if (roles.drive_unit) {
        const Sym output = Define(p + "output_torque", "N*m", "PDU output torque, both sides, the largest over the load cases",
                                  operating(i, ""));
        if (Has(p + "max_output_speed") && Has(p + "efficiency"))
          Define(p + "required_power", "kW", "PDU power at full speed, T w / eta",
                 output * Var(p + "max_output_speed") / Var(p + "efficiency"));
      }
    }
  }

  /// The torque flow of one load case: a variable per node, leaves first, each the steady-state
  /// law of its type (ComponentModel::InputTorque) over the variables of its outboard nodes.
  std::vector<Sym> Flow(const LoadCase& lc, const std::map<std::string, double>& loads, const Sym& w) {
    const std::size_t n = peaks_->nodes.size();
    std::vector<Sym> var(n);
    for (std::size_t k = n; k-- > 0;) {
      const auto& node = peaks_->nodes[k];
      const Component& c = *Find(node.id);
      const std::string name = "torque." + lc.name + "." + node.id;
      std::vector<std::pair<std::string, Sym>> outboard;
      for (int child : node.children) outboard.push_back({peaks_->nodes[child].id, var[child]});
      const auto it = loads.find(c.id);
      const double load = it == loads.end() ? 0.0 : it->second;
      const Sym law = InputTorque(c, outboard, Sym(load), w * SpeedRatioOf(c.id), 1.0);
      std::string what = "by the steady-state law of its type " + c.type;
      if (load != 0.0) what += " with its airload " + std::string(load > 0.0 ? "opposing" : "aiding");
      var[k] = Define(name, "N*m", "torque at the input of " + c.id + " in '" + lc.name + "', " + what, law, Whole());
      if (law.missing()) {  // a parameter without a value: the torque is left free
        Derived(name, "N*m", Whole());
        sign_[name] = Sign::Either();
        var[k] = Var(name);
      }
    }
    return var;
  }

  /// The stiffness of the drive line from the PDU output to the outboard flange of every
  /// component, at the PDU speed: the reflected stiffnesses on the path in series,
  /// 1 / c_series = sum 1 / c_i (a rigid component passes the inboard value on).
  void SeriesStiffness() {
    if (!peaks_) return;
    std::vector<std::string> series(peaks_->nodes.size());
    for (std::size_t k = 0; k < peaks_->nodes.size(); ++k) {
      const auto& node = peaks_->nodes[k];
      if (node.parent < 0) continue;
      const std::string inboard = series[node.parent];
      const std::string own = NodeVar(static_cast<int>(k), "reflected_stiffness");
      if (inboard.empty() && own.empty()) continue;
      const std::string name = node.id + ".series_stiffness";
      const std::string law = inboard.empty() ? own : own.empty() ? inboard : "1 / (1 / " + inboard + " + 1 / " + own + ")";
      Derived(name, "N*m/rad");
      Law(name, "stiffness of the drive line from the PDU to " + node.id + ", in series, at the PDU speed", name + " == " + law);
      series[k] = name;
    }
  }

  /// The sizing cases of reduced_models (the jams and ruptures of `highlift peak`) that a scenario
  /// of the project names or a requirement mentions ("peak.<case>."), with the same physics:
  ///   w1 = first eigenfrequency of the part in focus with the stop clamped (a monotone black box
  ///        over the reflected stiffnesses, rising, and inertias, falling: reduced_models'
  ///        lumped model and modal analysis evaluated at the corners),
  ///   J* = its inertia without the stop, c* = J* w1^2, tau = w sqrt(c* J*) = w w1 J*  (eq. 1),
  ///   w  = the operating speed (jam) or the back-driven spin-up after a rupture until the brake
  ///        engages (reduced_models::ComputeRuptureSpeed, a monotone black box),
  /// plus the static part (jam: PDU stall torque through the system torque limiters; rupture:
  /// the airload's back-drive torque) and the load each component on the path carries.
  void Peaks() {
    if (!peaks_) return;
    std::set<std::string> wanted;
    for (const Scenario& s : project_.scenarios) wanted.insert(s.name);
    for (const reduced_models::PeakCaseStructure& pc : peaks_->cases) {
      const std::string key = "peak." + pc.name + ".";
      for (const Requirement& r : project_.requirements)
        if (r.expression.find(key) != std::string::npos) wanted.insert(pc.name);
    }
    for (const reduced_models::PeakCaseStructure& pc : peaks_->cases) {
      if (wanted.count(pc.name)) PeakCase(pc);
    }
  }

  const Component& NodeComponent(int k) const { return *Find(peaks_->nodes[k].id); }
  std::string NodeVar(int k, const char* what) const {
    const std::string name = peaks_->nodes[k].id + "." + what;
    return Has(name) ? name : std::string();
  }
  /// The node whose input torque passes node k's torque limiter: k for an in-line limiter, the
  /// child on the model's LimitedPort() for a limiter in a gearbox's down-drive (-1: none there).
  int LimitedNode(int k) const {
    const model::ComponentModel* m = ModelOf(NodeComponent(k));
    if (!m || m->LimitedPort().empty()) return k;
    for (int child : peaks_->nodes[k].children)
      if (parent_port_.at(peaks_->nodes[child].id) == m->LimitedPort()) return child;
    return -1;
  }
  /// 1 / (product of the gear ratios inboard of node k) as text: w_k / w_pdu.
  std::string SpeedRatio(int k) const { return "(" + SpeedRatioOf(peaks_->nodes[k].id).Text() + ")"; }

  void PeakCase(const reduced_models::PeakCaseStructure& pc) {
    const std::string p = "peak." + pc.name + ".";
    const int n_elements = peaks_->elements_per_segment;
    // Arguments of the eigenvalue: reflected link stiffnesses (rising) and inertias (falling).
    std::vector<ModeArg> args;
    std::vector<VariableId> vars;
    std::vector<Monotonicity> mono;
    std::string inertia;  // J*
    for (int k : pc.part) {
      const bool shaft = HasRole(NodeComponent(k), &model::ComponentRoles::segment);
      const std::string J = NodeVar(k, "reflected_inertia"), c = NodeVar(k, "reflected_stiffness");
      const int link = pc.link_of_node[k], point = pc.point_of_node[k];
      if (link >= 0 && !c.empty()) {
        args.push_back({ModeArg::kLinkC, link});
        vars.push_back(net().FindVariable(c));
        mono.push_back(Monotonicity::kIncreasing);
      }
      if (J.empty()) continue;
      if (shaft && link >= 0) {
        args.push_back({ModeArg::kLinkJ, link});
        vars.push_back(net().FindVariable(J));
        mono.push_back(Monotonicity::kDecreasing);
        // A link's distributed inertia goes J/(2n) to each end: the end at the stop is clamped.
        const auto& l = pc.transmission.links[link];
        const int ends_at_stop = (l.a == pc.stop_point) + (l.b == pc.stop_point);
        inertia += (inertia.empty() ? "" : " + ") +
                   (ends_at_stop ? Num(1.0 - ends_at_stop / (2.0 * n_elements)) + " * " : std::string()) + J;
      } else if (!shaft && point >= 0 && point != pc.stop_point) {
        args.push_back({ModeArg::kPointJ, point});
        vars.push_back(net().FindVariable(J));
        mono.push_back(Monotonicity::kDecreasing);
        inertia += (inertia.empty() ? "" : " + ") + J;
      }
    }
    if (args.empty() || inertia.empty()) return;
    MonotoneFunction first_mode;
    first_mode.f = FirstModeFunction(pc.transmission, pc.stop_point, args, n_elements);
    first_mode.monotonicity = mono;
    first_mode.relative_error = 1e-9;  // eigenvalue round-off, as reduced_models' enclosures
    first_mode.bisection_steps = 30;
    Derived(p + "omega", "rad/s");
    net().AddMonotone(net().FindVariable(p + "omega"), vars, std::move(first_mode),
                      {p + "omega", "first eigenfrequency w1 of '" + pc.name + "' with " + pc.acts_at +
                                        " clamped (reduced_models lumped model, monotone in every c and J)",
                       ConstraintRole::kPhysics});
    ++out_.physics_constraints;
    Derived(p + "inertia", "kg*m^2");
    Law(p + "inertia", "inertia J* of the moving part without the stop", p + "inertia == " + inertia);
    Derived(p + "stiffness", "N*m/rad");
    Law(p + "stiffness", "stiffness c* = J* w1^2 of the single-DOF oscillator", p + "stiffness == " + p + "inertia * " + p + "omega^2");

    // Speed at the stop and static torque.
    std::string static_torque;
    const Component& pdu = *Find(root_);
    if (pc.kind == kJamKind) {
      if (!Has(root_ + ".max_output_speed")) return;
      Derived(p + "speed", "rad/s");
      Law(p + "speed", "drive speed at the jam, the operating speed", p + "speed == " + OperatingSpeed());
      static_torque = StallTorque(pdu);
      for (const std::string& id : pc.load_path) {
        const Component& c = *Find(id);
        if (!HasRole(c, &model::ComponentRoles::wing_limiter)) continue;
        // model::LimiterPassedTorque (the law of peak's and size's): min(S, max(tau2 n, S - tauB n)).
        const std::string n = SpeedRatio(node_index_.at(id));
        if (HasValue(c, "end_stop_torque") && HasValue(c, "max_brake_torque"))
          static_torque = "min(" + static_torque + ", max(" + Value(c, "end_stop_torque") + " * " + n + ", " +
                          static_torque + " - " + Value(c, "max_brake_torque") + " * " + n + "))";
        else if (HasValue(c, "lockout_torque_extend"))
          static_torque = "min(" + static_torque + ", " + Value(c, "lockout_torque_extend") + " * " + n + ")";
      }
    } else {
      if (!RuptureSpeed(pc, p)) return;
      static_torque = p + "backdrive_torque";
    }
    Derived(p + "torque", "N*m");
    Law(p + "torque", "single-DOF peak load, paper equation (1): tau = w sqrt(c* J*) = w w1 J*",
        p + "torque == " + p + "speed * " + p + "omega * " + p + "inertia");
    Derived(p + "static_torque", "N*m", Whole());
    Law(p + "static_torque",
        pc.kind == kJamKind ? "static part of the jam: PDU stall torque through the system torque limiters"
                         : "static part after the rupture: the airload's back-drive torque",
        p + "static_torque == " + static_torque);
    // A stop that slips (the friction brake after a rupture) passes at most its slipping torque.
    std::string total = p + "torque + " + p + "static_torque", total_what = "dynamic plus static";
    if (pc.kind == "rupture" && !pc.brake.empty()) {
      const Component& stop = *Find(pc.brake);
      if (const model::ComponentModel* m = ModelOf(stop)) {
        if (const std::optional<Sym> limit = m->StopTorqueLimit(Reader(*this, stop)); limit && !limit->missing()) {
          total = "min(" + total + ", " + limit->Text() + ")";
          total_what += ", at most what " + stop.id + " passes before it slips";
        }
      }
    }
    Derived(p + "total_torque", "N*m", Whole());
    Law(p + "total_torque", "peak load of '" + pc.name + "', " + total_what, p + "total_torque == " + total);
    // The load of each component on the path (at the PDU speed); in a jam, what lies behind a
    // station torque limiter is what its type's law passes on (ComponentModel::JamPassedTorque,
    // the law reduced_models' peak uses: its end-stop torque while its brake grounds the excess).
    Sym through = Var(p + "total_torque");
    for (auto id = pc.load_path.rbegin(); id != pc.load_path.rend(); ++id) {
      const Component& c = *Find(*id);
      Derived(p + c.id, "N*m", Whole());
      Law(p + c.id, "peak load of '" + pc.name + "' at " + c.id, p + c.id + " == " + through.Text());
      // A limiter in a down-drive (LimitedPort) limits only when the path goes on through that port.
      const int k = node_index_.at(c.id), limited = LimitedNode(k);
      const bool behind = limited == k || (std::next(id) != pc.load_path.rend() && node_index_.at(*std::next(id)) == limited);
      const model::ComponentModel* m = ModelOf(c);
      if (pc.kind == kJamKind && behind && m && HasRole(c, &model::ComponentRoles::station_limiter)) {
        const std::optional<Sym> passed =
            m->JamPassedTorque(Reader(*this, c), through, SpeedRatioOf(peaks_->nodes[limited].id));
        if (passed && !passed->missing()) {
          Derived(p + c.id + ".passed", "N*m", Whole());
          Law(p + c.id + ".passed",
              "torque " + c.id + " passes on in '" + pc.name + "': its end-stop torque, or the excess over its brake",
              p + c.id + ".passed == " + passed->Text());
          through = Var(p + c.id + ".passed");
        }
      }
    }
  }

  /// Back-drive torque at the input of node k from the aiding airloads `aiding` (negative), no
  /// friction: each component's steady-state law in the aiding direction (gear stages pass
  /// tau eta_aiding / ratio, as reduced_models' torque flow). Negative; 0 when there is none.
  Sym Backdrive(int k) const { return Backdrive(k, peaks_->aiding); }
  Sym Backdrive(int k, const std::map<std::string, double>& aiding) const {
    const auto& node = peaks_->nodes[k];
    std::vector<std::pair<std::string, Sym>> outboard;
    for (int child : node.children) outboard.push_back({peaks_->nodes[child].id, Backdrive(child, aiding)});
    const auto it = aiding.find(node.id);
    return InputTorque(NodeComponent(k), outboard, Sym(it == aiding.end() ? 0.0 : it->second), Sym(0.0), 0.0);
  }

  /// Friction torque at the input of node k with no airload at the operating speed
  /// (reduced_models' drag flow): each component's steady-state law without load.
  Sym Drag(int k) const {
    const auto& node = peaks_->nodes[k];
    std::vector<std::pair<std::string, Sym>> outboard;
    for (int child : node.children) outboard.push_back({peaks_->nodes[child].id, Drag(child)});
    return InputTorque(NodeComponent(k), outboard, Sym(0.0), Sym(peaks_->w_operating) * SpeedRatioOf(node.id), 1.0);
  }

  /// w_max after a rupture: reduced_models::ComputeRuptureSpeed as a monotone black box of the
  /// speed at the rupture, the overspeed reference, the trip thresholds, the latencies (rising),
  /// the back-drive torque (rising), the friction and the inertia of the outboard part (falling).
  bool RuptureSpeed(const reduced_models::PeakCaseStructure& pc, const std::string& p) {
    if (!Has(root_ + ".max_output_speed")) return false;
    const Component* sensor = pc.sensor.empty() ? nullptr : Find(pc.sensor);
    const Component& wtb = *Find(pc.brake);
    const int root = pc.root;
    std::string part_inertia;
    for (int k : pc.part) {
      const std::string J = NodeVar(k, "reflected_inertia");
      if (!J.empty()) part_inertia += (part_inertia.empty() ? "" : " + ") + J;
    }
    const Sym back = -Backdrive(root), drag = Drag(root);
    if (back.missing() || drag.missing()) return false;
    const std::string latency = (sensor && HasValue(*sensor, "latency") ? Value(*sensor, "latency") : "0") + " + " +
                                Value(wtb, "engagement_latency") + " + 0.5 * " + Value(wtb, "time_to_max_torque");
    if (part_inertia.empty() || !HasValue(wtb, "engagement_latency") || !HasValue(wtb, "time_to_max_torque")) return false;
    std::vector<std::string> names = {
        OperatingSpeed(),
        root_ + ".max_output_speed",
        VariableFor(p + "overspeed_factor", "1", sensor ? Value(*sensor, "overspeed_factor") : Num(1.3),
                    "overspeed trip factor of the monitor"),
        VariableFor(p + "asymmetry_threshold", "rev", sensor ? Value(*sensor, "asymmetry_threshold") : Num(4.0 * std::numbers::pi),
                    "asymmetry trip threshold of the monitor"),
        VariableFor(p + "latency", "ms", latency, "monitor latency + brake engagement + half its rise time"),
        VariableFor(p + "backdrive_torque", "N*m", max(Sym(0.0), back * SpeedRatioOf(peaks_->nodes[root].id)).Text(),
                    "back-drive torque of the airload on the outboard part, at the PDU speed"),
        VariableFor(p + "drag_torque", "N*m", max(Sym(0.0), drag * SpeedRatioOf(peaks_->nodes[root].id)).Text(),
                    "friction of the outboard part, at the PDU speed"),
        VariableFor(p + "part_inertia", "kg*m^2", part_inertia, "inertia of the outboard part, at the PDU speed")};
    std::vector<VariableId> vars;
    for (const auto& n : names) vars.push_back(net().FindVariable(n));
    MonotoneFunction spin_up;
    spin_up.f = [](std::span<const double> x) {
      reduced_models::RuptureInput in;
      in.w0 = x[0];
      in.w_reference = x[1];
      in.overspeed_factor = x[2];
      in.asymmetry_threshold = x[3];
      in.latency = x[4];
      in.tau_aiding = x[5];
      in.tau_drag = x[6];
      in.J = x[7];
      if (!(in.J > 0.0)) return std::numeric_limits<double>::quiet_NaN();
      try {
        return reduced_models::ComputeRuptureSpeed(in).w_max;
      } catch (const std::exception&) {
        return std::numeric_limits<double>::quiet_NaN();
      }
    };
    using M = Monotonicity;
    spin_up.monotonicity = {M::kIncreasing, M::kIncreasing, M::kIncreasing, M::kIncreasing,
                            M::kIncreasing, M::kIncreasing, M::kDecreasing, M::kDecreasing};
    spin_up.relative_error = 1e-12;
    Derived(p + "speed", "rad/s");
    net().AddMonotone(net().FindVariable(p + "speed"), vars, std::move(spin_up),
                      {p + "speed", "speed of the back-driven part when " + pc.brake +
                                        " engages: w0 + alpha (t_detect + latency) (reduced_models)",
                       ConstraintRole::kPhysics});
    ++out_.physics_constraints;
    return true;
  }

  void Requirements() {
    for (const Requirement& r : project_.requirements) {
      ConstraintId id;
      try {
        // As AddConstraintText, with the identities of the laws put in (PolarMomentIdentity).
        const ParsedConstraint pc = ParseConstraint(net(), r.expression, "requirement '" + r.id + "'", r.where, {}, true);
        id = net().AddConstraint(net().Replace(pc.lhs, identities_), pc.relation, net().Replace(pc.rhs, identities_),
                                 {r.id, r.description, ConstraintRole::kRequirement, r.expression});
      } catch (const InputError& e) {
        if (peaks_error_.empty() ||
            (r.expression.find("peak.") == std::string::npos && r.expression.find("travel_time.") == std::string::npos))
          throw;
        throw InputError(e.message() + "\n(the sizing cases peak.<case>.* and the travel times could not be built: " + peaks_error_ +
                             ")",
                         r.where);
      }
      out_.requirement_of[id.value] = r.id;
      ++out_.requirement_constraints;
    }
  }

  const Project& project_;
  DriveSystemNetwork out_;
  std::string root_;
  std::map<std::string, std::string> parent_;
  std::map<std::string, std::string> parent_port_;  // component id -> the port of its parent it hangs on
  std::map<std::string, std::string> entry_port_;   // component id -> its own port towards its parent
  std::map<std::string, Sign> sign_;                 // variable -> the signs it can take (see SignOf)
  mutable std::map<std::string, Sym> reduction_;     // component id -> Reduction(id)
  std::map<std::string, std::vector<std::string>> children_;
  std::vector<std::string> order_;
  std::vector<std::pair<const Component*, const Component*>> stations_;  // actuator, branch gearbox
  std::optional<reduced_models::PeakStructure> peaks_;  // the sizing cases of reduced_models
  std::map<std::string, int> node_index_;               // component id -> node of peaks_
  std::string peaks_error_;                             // why there are no sizing cases
  std::unordered_map<int, ExprId> identities_;  // node as a requirement may write it -> an equal node
                                                // over the derived variables (PolarMomentIdentity)
};

}  // namespace

DriveSystemNetwork BuildDriveSystemNetwork(const Project& project) { return Builder(project).Build(); }

CheckResult CheckDriveSystem(const DriveSystemNetwork& dn, const PropagationOptions& options) {
  CheckResult result;
  const Network& net = dn.network;
  const Box initial = net.InitialBox();
  Box box = initial;
  Propagator prop(net, options);
  result.report = prop.Propagate(box);
  result.feasible = result.report.status != Status::kInfeasible;
  if (!result.feasible) result.explanation = Explain(net, initial, options);
  if (result.feasible && !dn.nominal.empty()) {
    Box nominal = initial;
    for (const auto& [v, value] : dn.nominal) {
      if (!IsEmpty(nominal[v]) && nominal[v].lower() <= value && value <= nominal[v].upper()) nominal[v] = Interval(value, value);
    }
    Box trial = nominal;
    result.nominal_checked = true;
    result.nominal_feasible = prop.Propagate(trial).status != Status::kInfeasible;
    if (!result.nominal_feasible) result.nominal_explanation = Explain(net, nominal, options);
  }
  for (int v = 0; v < net.num_variables(); ++v) {
    const VariableInfo& info = net.variable(VariableId{v});
    ParameterResult row;
    row.name = info.name;
    row.unit = info.unit;
    row.provenance = info.provenance;
    auto display = [&](const Interval& x) {
      if (IsEmpty(x)) return x;
      double a = ToDisplay(x.lower(), info.unit), b = ToDisplay(x.upper(), info.unit);
      if (a > b) std::swap(a, b);
      return Interval(a, b);
    };
    row.initial = display(initial[v]);
    row.final = result.feasible ? display(box[v]) : Empty();
    const double w0 = initial[v].upper() - initial[v].lower();
    const double w1 = box[v].upper() - box[v].lower();
    if (result.feasible && std::isfinite(w0) && w0 > 0) row.narrowing_percent = 100.0 * (1.0 - w1 / w0);
    else if (result.feasible && !std::isfinite(w0) && std::isfinite(w1)) row.narrowing_percent = 100.0;
    result.parameters.push_back(row);
  }
  return result;
}

}  // namespace highlift::icsp
