#include "highlift/icsp/drive_system.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <set>

#include "highlift/core/catalogue.h"
#include "highlift/core/units.h"
#include "highlift/icsp/parser.h"

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

class Builder {
 public:
  explicit Builder(const Project& p) : project_(p) {}

  DriveSystemNetwork Build() {
    AddParameters();
    BuildTree();
    for (const Component& c : project_.components) {
      if (c.type == "torque_shaft") Shaft(c);
      else if (c.type == "geared_rotary_actuator") Actuator(c);
      else if (c.type == "pdu") Pdu(c);
    }
    DriveTorques();
    for (const Scenario& s : project_.scenarios) Peak(s);
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
        net().AddVariable(c.id + "." + name, d, spec ? spec->unit : "", ToString(p.provenance));
      }
    }
  }

  /// The drive line as a tree rooted at the PDU (connections are undirected flange links).
  void BuildTree() {
    std::map<std::string, std::vector<std::string>> adj;
    for (const Connection& k : project_.connections) {
      adj[k.a.component].push_back(k.b.component);
      adj[k.b.component].push_back(k.a.component);
    }
    std::string root;
    for (const Component& c : project_.components) {
      if (c.type == "pdu") root = c.id;
    }
    if (root.empty()) return;
    root_ = root;
    std::queue<std::string> q;
    q.push(root);
    parent_[root] = "";
    while (!q.empty()) {
      const std::string u = q.front();
      q.pop();
      order_.push_back(u);
      for (const std::string& v : adj[u]) {
        if (parent_.count(v)) continue;
        parent_[v] = u;
        children_[u].push_back(v);
        q.push(v);
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
  /// Components from the PDU (excluded) out to `id` (included), inboard first.
  std::vector<const Component*> PathFromPdu(const std::string& id) const {
    std::vector<const Component*> path;
    for (std::string u = id; !u.empty() && u != root_; u = parent_.at(u)) {
      if (const Component* c = Find(u)) path.push_back(c);
      if (!parent_.count(u)) break;
    }
    std::reverse(path.begin(), path.end());
    return path;
  }
  /// The branch gearbox feeding an actuator (nearest inboard one).
  const Component* BranchOf(const std::string& id) const {
    for (std::string u = id; parent_.count(u) && !parent_.at(u).empty(); u = parent_.at(u)) {
      const Component* c = Find(parent_.at(u));
      if (c && c->type == "branch_gearbox") return c;
    }
    return nullptr;
  }
  /// "rgb.ratio^2 * " for every angle gearbox inboard of `id`: compliance reflected to the PDU.
  std::string Reflection(const std::string& id) const {
    std::string r;
    for (std::string u = id; parent_.count(u) && !parent_.at(u).empty(); u = parent_.at(u)) {
      const Component* c = Find(parent_.at(u));
      if (c && c->type == "angle_gearbox" && HasParam(*c, "ratio")) r += c->id + ".ratio^2 * ";
    }
    return r;
  }

  void Shaft(const Component& s) {
    const std::string p = s.id + ".";
    for (const char* need : {"outer_diameter", "wall_thickness", "length"}) {
      if (!HasParam(s, need)) return;
    }
    const std::string D = p + "outer_diameter", t = p + "wall_thickness", L = p + "length";
    Derived(p + "polar_moment", "m^4");
    Law(p + "polar_moment", "tube polar moment Ip = pi/32 (D^4 - d^4)",
        p + "polar_moment == 0.098174770424681 * (" + D + "^4 - (" + D + " - 2 * " + t + ")^4)");
    if (HasParam(s, "shear_modulus")) {
      Derived(p + "c", "N*m/rad");
      Law(p + "c", "tube stiffness c = G Ip / L", p + "c == " + p + "shear_modulus * " + p + "polar_moment / " + L);
    }
    if (HasParam(s, "density")) {
      Derived(p + "J", "kg*m^2");
      Law(p + "J", "tube inertia J = rho Ip L", p + "J == " + p + "density * " + p + "polar_moment * " + L);
      Derived(p + "mass", "kg");
      Law(p + "mass", "tube mass m = rho pi/4 (D^2 - d^2) L",
          p + "mass == " + p + "density * 0.78539816339745 * (" + D + "^2 - (" + D + " - 2 * " + t + ")^2) * " + L);
    }
    if (HasParam(s, "allowable_shear_stress")) {
      Derived(p + "torque_capacity", "N*m");
      Law(p + "torque_capacity", "torque at the allowable shear stress, tau_allow 2 Ip / D",
          p + "torque_capacity == " + p + "allowable_shear_stress * 2 * " + p + "polar_moment / " + D);
    }
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
    Derived(p + "max_load", "N*m", Interval(load, load));
    if (HasParam(g, "eta_opposing")) {
      Derived(p + "input_torque_opposing", "N*m");
      Law(p + "input_torque_opposing", "actuator input torque against the airload, T_out / (i eta_opp)",
          p + "input_torque_opposing == " + p + "max_load / (" + p + "ratio * " + p + "eta_opposing)");
    }
    if (HasParam(g, "eta_aiding")) {
      Derived(p + "input_torque_aiding", "N*m");
      Law(p + "input_torque_aiding", "actuator input torque with an aiding airload, T_out eta_aid / i",
          p + "input_torque_aiding == " + p + "max_load * " + p + "eta_aiding / " + p + "ratio");
    }
    if (HasParam(g, "input_inertia") && HasParam(g, "load_inertia")) {
      Derived(p + "reflected_inertia", "kg*m^2");
      Law(p + "reflected_inertia", "actuator inertia at its input, J_in + J_load / i^2",
          p + "reflected_inertia == " + p + "input_inertia + " + p + "load_inertia / " + p + "ratio^2");
    }
    const Component* branch = BranchOf(g.id);
    if (branch && HasParam(*branch, "ratio") && Has(p + "input_torque_opposing")) {
      const std::string b = branch->id + ".";
      const std::string eta = HasParam(*branch, "eta_mesh") ? " * " + b + "eta_mesh" : "";
      Derived(b + "station_torque", "N*m");
      Law(b + "station_torque", "station input torque on the drive shaft, T_act / (i_branch eta)",
          b + "station_torque == " + p + "input_torque_opposing / (" + b + "ratio" + eta + ")");
      stations_.push_back({&g, branch});
      if (!Has("travel_time.extension") && HasParam(g, "travel_angle") && Has(root_ + ".max_output_speed")) {
        Derived("travel_time.extension", "s");
        Law("travel_time.extension", "extension time at the PDU's maximum speed, phi_travel i_act i_branch / w_max",
            "travel_time.extension == " + p + "travel_angle * " + p + "ratio * " + b + "ratio / " + root_ +
                ".max_output_speed");
      }
    }
  }

  void Pdu(const Component& c) {
    const std::string p = c.id + ".";
    if (HasParam(c, "motor_inertia") && HasParam(c, "ratio")) {
      const std::string count = HasParam(c, "motor_count") ? p + "motor_count * " : "";
      const std::string gear = HasParam(c, "gear_inertia") ? " + " + p + "gear_inertia" : "";
      Derived(p + "reflected_inertia", "kg*m^2");
      Law(p + "reflected_inertia", "PDU inertia at its output, n J_motor i^2 + J_gear",
          p + "reflected_inertia == " + count + p + "motor_inertia * " + p + "ratio^2" + gear);
    }
  }

  /// Torque of the stations outboard of `id` summed, as text ("0" when none).
  std::string StationSum(const std::string& id) const {
    std::string sum;
    for (const Component* c : Subtree(id)) {
      if (c->type == "branch_gearbox" && Has(c->id + ".station_torque")) {
        sum += (sum.empty() ? "" : " + ") + c->id + ".station_torque";
      }
    }
    return sum;
  }

  void DriveTorques() {
    for (const Component& c : project_.components) {
      const std::string p = c.id + ".";
      if (!parent_.count(c.id)) continue;
      if (c.type == "torque_shaft") {
        const std::string sum = StationSum(c.id);
        if (sum.empty()) continue;
        Derived(p + "drive_torque", "N*m");
        Law(p + "drive_torque", "drive torque in the shaft, the station torques outboard summed",
            p + "drive_torque == " + sum);
        if (Has(p + "polar_moment")) {
          Derived(p + "shear_stress", "MPa");
          Law(p + "shear_stress", "shear stress from the drive torque, T D / (2 Ip)",
              p + "shear_stress == " + p + "drive_torque * " + p + "outer_diameter / (2 * " + p + "polar_moment)");
        }
      } else if ((c.type == "system_torque_limiter" || c.type == "station_torque_limiter") &&
                 HasParam(c, "lockout_torque_extend")) {
        std::string through;
        if (c.type == "station_torque_limiter") {
          for (const Component* d : Subtree(c.id)) {
            if (d->type == "geared_rotary_actuator" && Has(d->id + ".input_torque_opposing")) {
              through = d->id + ".input_torque_opposing";
            }
          }
        } else {
          through = StationSum(c.id);
        }
        if (through.empty()) continue;
        Derived(p + "torque_through", "N*m");
        Law(p + "torque_through", "operating torque through the limiter", p + "torque_through == " + through);
        Derived(p + "margin", "N*m", Whole());
        Law(p + "margin", "limiter margin, lockout setting minus operating torque",
            p + "margin == " + p + "lockout_torque_extend - " + p + "torque_through");
      } else if (c.type == "wing_tip_brake" && HasParam(c, "static_capacity")) {
        // Holding: the aiding airload of the stations on this side back-drives the shaft.
        std::string side = c.id;
        while (parent_.count(side) && parent_.at(side) != root_ && !parent_.at(side).empty()) side = parent_.at(side);
        std::string sum;
        for (const auto& [g, branch] : stations_) {
          if (!Has(g->id + ".input_torque_aiding")) continue;
          const auto members = Subtree(side);
          if (std::find(members.begin(), members.end(), g) == members.end()) continue;
          sum += (sum.empty() ? "" : " + ") + g->id + ".input_torque_aiding / " + branch->id + ".ratio";
        }
        if (sum.empty()) continue;
        Derived(p + "holding_torque", "N*m");
        Law(p + "holding_torque", "back-driving torque the brake holds, aiding station torques summed",
            p + "holding_torque == " + sum);
        Derived(p + "holding_margin", "N*m", Whole());
        Law(p + "holding_margin", "brake margin, static capacity minus holding torque",
            p + "holding_margin == " + p + "static_capacity - " + p + "holding_torque");
      }
    }
    if (!root_.empty()) {
      const std::string sum = StationSum(root_);
      if (!sum.empty()) {
        Derived(root_ + ".output_torque", "N*m");
        Law(root_ + ".output_torque", "PDU output torque, all station torques summed", root_ + ".output_torque == " + sum);
        if (Has(root_ + ".max_output_speed") && Has(root_ + ".efficiency")) {
          Derived(root_ + ".required_power", "kW");
          Law(root_ + ".required_power", "PDU power at full speed, T w / eta",
              root_ + ".required_power == " + root_ + ".output_torque * " + root_ + ".max_output_speed / " + root_ +
                  ".efficiency");
        }
      }
    }
  }

  /// Series stiffness and inertia of a load path; peak torque by the paper's equation (1).
  void Peak(const Scenario& s) {
    std::vector<const Component*> path;  // components the peak passes through
    std::string speed;
    std::vector<std::string> inertia_terms;
    if (s.kind == "jam" && s.jam_component && parent_.count(*s.jam_component)) {
      path = PathFromPdu(*s.jam_component);
      if (Has(root_ + ".max_output_speed")) speed = root_ + ".max_output_speed";
      if (Has(root_ + ".reflected_inertia")) inertia_terms.push_back(root_ + ".reflected_inertia");
    } else if (s.kind == "rupture" && s.rupture_component && parent_.count(*s.rupture_component)) {
      // The outboard part, back-driven by the airload, is stopped by the wing-tip brake.
      const auto outboard = Subtree(*s.rupture_component);
      const Component* wtb = nullptr;
      const Component* sensor = nullptr;
      for (const Component* c : outboard) {
        if (c->type == "wing_tip_brake") wtb = c;
        if (c->type == "position_sensor" && HasParam(*c, "overspeed_factor")) sensor = c;
      }
      if (!wtb) return;
      const auto to_wtb = PathFromPdu(wtb->id);
      bool inside = false;
      for (const Component* c : to_wtb) {
        if (c->id == *s.rupture_component) {
          inside = true;
          continue;  // the ruptured shaft carries nothing
        }
        if (inside) path.push_back(c);
      }
      for (const Component* c : outboard) {
        if (c->type == "geared_rotary_actuator" && Has(c->id + ".reflected_inertia")) {
          const Component* b = BranchOf(c->id);
          inertia_terms.push_back(c->id + ".reflected_inertia" + (b && HasParam(*b, "ratio") ? " / " + b->id + ".ratio^2" : ""));
        }
      }
      if (Has(root_ + ".max_output_speed")) {
        speed = (sensor ? sensor->id + ".overspeed_factor * " : std::string()) + root_ + ".max_output_speed";
      }
    } else {
      return;
    }
    std::string compliance;
    for (const Component* c : path) {
      if (c->type == "torque_shaft" && Has(c->id + ".c")) {
        compliance += (compliance.empty() ? "" : " + ") + Reflection(c->id) + "1 / " + c->id + ".c";
        if (Has(c->id + ".J")) inertia_terms.push_back(c->id + ".J");
      }
    }
    if (compliance.empty() || speed.empty() || inertia_terms.empty()) return;
    const std::string p = "peak." + s.name + ".";
    Derived(p + "stiffness", "N*m/rad");
    Law(p + "stiffness", "series stiffness c* of the shafts on the load path",
        p + "stiffness == 1 / (" + compliance + ")");
    std::string inertia;
    for (const auto& t : inertia_terms) inertia += (inertia.empty() ? "" : " + ") + t;
    Derived(p + "inertia", "kg*m^2");
    Law(p + "inertia", "inertia J* the stop absorbs", p + "inertia == " + inertia);
    Derived(p + "speed", "rad/s");
    Law(p + "speed", "drive speed before the stop", p + "speed == " + speed);
    Derived(p + "torque", "N*m");
    Law(p + "torque", "single-DOF peak load, paper equation (1): tau = w sqrt(c* J*)",
        p + "torque == " + p + "speed * sqrt(" + p + "stiffness * " + p + "inertia)");
    std::vector<const Component*> named = path;
    if (s.kind == "rupture") {
      for (const Component* c : Subtree(*s.rupture_component)) {
        if (c->type == "wing_tip_brake") named.push_back(c);
      }
    }
    for (const Component* c : named) {
      Derived(p + c->id, "N*m");
      Law(p + c->id, "peak load of '" + s.name + "' at " + c->id, p + c->id + " == " + p + "torque");
    }
  }

  void Requirements() {
    for (const Requirement& r : project_.requirements) {
      const ConstraintId id = AddConstraintText(net(), r.expression,
                                                {r.id, r.description, ConstraintRole::kRequirement}, r.where);
      out_.requirement_of[id.value] = r.id;
      ++out_.requirement_constraints;
    }
  }

  const Project& project_;
  DriveSystemNetwork out_;
  std::string root_;
  std::map<std::string, std::string> parent_;
  std::map<std::string, std::vector<std::string>> children_;
  std::vector<std::string> order_;
  std::vector<std::pair<const Component*, const Component*>> stations_;  // actuator, branch gearbox
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
