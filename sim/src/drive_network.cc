// Drive-system projects (catalogue components) as simulation models. The structure mirrors the
// Modelica export (export/src/drive_system_writer.cc): the same element types, parameters,
// lumping and scenario parts, so that a simulated model and an exported one agree.
#include "highlift/sim/drive_network.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <set>
#include <sstream>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "hydraulic_pdu.h"

namespace highlift::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDefaultDisconnectorStiffness = 1e6;  // N*m/rad, far above any shaft segment
constexpr double kDefaultDisconnectorDamping = 100;    // N*m*s/rad
constexpr double kJamStiffness = 1e5;                  // N*m/rad referred to the actuator input
constexpr double kFailureTime = 1.0;                   // s, sizing scenarios made up by peak
constexpr double kHoldLastPoint = 1;                   // Modelica.Blocks.Types.Extrapolation

std::optional<double> Value(const Component& c, const std::string& name) {
  auto it = c.parameters.find(name);
  if (it == c.parameters.end()) return std::nullopt;
  return it->second.nominal;
}

double ValueOr(const Component& c, const std::string& name, double fallback) {
  return Value(c, name).value_or(fallback);
}

double Require(const Component& c, const std::string& name) {
  auto it = c.parameters.find(name);
  if (it == c.parameters.end() || !it->second.nominal) {
    const bool part = it != c.parameters.end() && !it->second.database_part.empty();
    throw InputError("component '" + c.id + "' (" + c.type + "): parameter '" + name +
                         "' has no value to simulate with; " +
                         (part ? "it refers to database part '" + it->second.database_part +
                                     "': resolve it with 'highlift estimate' first, or give a value"
                               : std::string("give a value in the project file")),
                     it != c.parameters.end() && !it->second.where.empty() ? it->second.where : c.where);
  }
  return *it->second.nominal;
}

bool IsChainType(const std::string& type) {
  return type == "torque_shaft" || type == "steady_bearing" || type == "universal_joint";
}

bool IsActuator(const std::string& type) {
  return type == "geared_rotary_actuator" || type == "ballscrew_actuator";
}

// Speed of `to` / speed of `from` through a component entered at port `from`.
double SpeedFactor(const Component& c, const std::string& from, const std::string& to) {
  const std::string& t = c.type;
  if (t == "angle_gearbox" || IsActuator(t)) {
    const double ratio = Require(c, "ratio");
    if (from == "input" && to != "input") return 1.0 / ratio;
    if (to == "input" && from != "input") return ratio;
  }
  if (t == "branch_gearbox") {
    const double ratio = Require(c, "ratio");
    if (to == "branch" && from != "branch") return 1.0 / ratio;
    if (from == "branch" && to != "branch") return ratio;
  }
  return 1.0;
}

struct ShaftValues {
  double c = 0;     // N*m/rad, whole segment
  double J = 0;     // kg*m^2, whole segment
  double d = 0;     // N*m*s/rad
  double drag = 0;  // N*m, Coulomb drag of the whole segment
};

/// `beta`: the project's structural damping (d = beta*c when the shaft gives no damping).
ShaftValues ShaftData(const Component& s, double beta) {
  ShaftValues data;
  const double L = Require(s, "length");
  const auto D = Value(s, "outer_diameter");
  const auto t = Value(s, "wall_thickness");
  double polar = 0;  // polar second moment of area, m^4
  if (D && t) {
    const double d_in = std::max(0.0, *D - 2 * *t);
    polar = kPi / 32 * (std::pow(*D, 4) - std::pow(d_in, 4));
  }
  if (auto c = Value(s, "stiffness")) {
    data.c = *c;
  } else {
    if (polar <= 0)
      throw InputError("component '" + s.id + "' (torque_shaft): neither 'stiffness' nor a tube "
                       "geometry ('outer_diameter', 'wall_thickness') is given: give one of them",
                       s.where);
    data.c = Require(s, "shear_modulus") * polar / L;
  }
  if (auto J = Value(s, "inertia")) {
    data.J = *J;
  } else if (auto m_l = Value(s, "linear_density"); m_l && D && t) {
    const double d_in = std::max(0.0, *D - 2 * *t);
    data.J = *m_l * L * (*D * *D + d_in * d_in) / 8;
  } else {
    data.J = Require(s, "density") * polar * L;
  }
  data.d = ValueOr(s, "damping", beta * data.c);
  data.drag = ValueOr(s, "drag_per_length", 0.0) * L;
  return data;
}

using Scalars = std::map<std::string, double>;

class Builder {
 public:
  Builder(const Project& project, const Scenario* scenario, const DriveNetworkOptions& options)
      : project_(project), scenario_(scenario), options_(options) {}

  DriveModel Run();

 private:
  void Add(const std::string& type, const std::string& id, Scalars scalars, const std::string& component,
           std::map<std::string, Table> tables = {});
  void Connect(const std::string& a, const std::string& b) { model_.network.Connect(a, b); }
  void Map(const Component& c, const std::string& port, const std::string& ref) { ports_[{c.id, port}] = ref; }
  Scalars Stribeck(const Component& c) const;
  /// The project's structural damping beta (s): d = beta*c for elastic elements without their own.
  double Beta() const { return project_.settings.structural_damping; }
  /// `s` with the friction regularisation of the options (w_small), when it is on.
  Scalars Regularised(Scalars s) const {
    if (options_.friction_speed > 0) s["w_small"] = options_.friction_speed;
    return s;
  }

  void CheckScenario();
  void ComputeSpeedFactors();
  void EmitComponent(const Component& c);
  void EmitPdu(const Component& c);
  void EmitTorqueLimiter(const Component& c);
  void EmitShaftFull(const Component& c);
  void EmitSteadyBearing(const Component& c);
  void EmitUniversalJoint(const Component& c);
  void EmitGearbox(const Component& c);
  void EmitActuator(const Component& c);
  void EmitWingTipBrake(const Component& c);
  void EmitPositionSensor(const Component& c);
  void EmitDisconnector(const Component& c);
  void EmitJam(const Component& c);
  void FindChains();
  void EmitChain(std::size_t chain);
  std::vector<const Component*> EmissionOrder() const;
  void EmitLoads();
  void EmitMonitoring();
  void ConnectShutdown(const std::string& command);

  const Project& project_;
  const Scenario* scenario_;
  const DriveNetworkOptions& options_;
  DriveModel model_;
  std::map<std::pair<std::string, std::string>, std::string> ports_;
  const LoadCase* load_case_ = nullptr;
  const Component* pdu_ = nullptr;
  detail::PduPorts pdu_ports_;
  std::vector<const Component*> wtbs_;
  std::vector<const Component*> sensors_;  // APPUs (position sensors that are not the FPPU)
  std::string speed_command_;  // the CombiTimeTable of the PDU speed command
  struct Chain {
    std::vector<std::pair<const Component*, std::string>> members;  // component, entry port
  };
  std::vector<Chain> chains_;                  // reduced model: chains of shafts, bearings, joints
  std::map<std::string, std::size_t> chain_of_;  // member id -> chain
  double direction_ = 1.0;  // +1 extend, -1 retract
};

// Parameter maps carry the "table" kind separately; a helper type keeps the call sites short.
void Builder::Add(const std::string& type, const std::string& id, Scalars scalars, const std::string& component,
                  std::map<std::string, Table> tables) {
  ElementParameters p;
  p.scalars = std::move(scalars);
  for (auto& [name, table] : tables) {
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < table.x.size(); ++i) rows.push_back({table.x[i], table.y[i]});
    p.tables[name] = std::move(rows);
  }
  // Network::AddElement takes the ids of project files (no dots); the parts of a component are
  // "<component>.<part>" like the parts of a composite, so they are checked under a stand-in id
  // and adopted under their own (messages name the real id).
  std::string stand_in = id;
  std::replace(stand_in.begin(), stand_in.end(), '.', '_');
  Network scratch;
  try {
    scratch.AddElement(type, stand_in, std::move(p));
  } catch (const InputError& e) {
    std::string message = e.message();
    for (std::size_t at = message.find("'" + stand_in + "'"); at != std::string::npos;
         at = message.find("'" + stand_in + "'", at + id.size() + 2))
      message.replace(at + 1, stand_in.size(), id);
    throw InputError(message, e.where());
  }
  NetworkElement element = scratch.elements().front();
  element.id = id;
  model_.network.Adopt(element);
  model_.component_of[id] = component;
}

Scalars Builder::Stribeck(const Component& c) const {
  Scalars s;
  for (const auto& [param, symbol] : std::vector<std::pair<std::string, std::string>>{
           {"coulomb_torque", "tau_C"}, {"viscous_coefficient", "d_vis"}, {"stribeck_torque", "tau_S"},
           {"stribeck_decay", "f_exp"}}) {
    if (auto v = Value(c, param)) s[symbol] = *v;
  }
  return s;
}

Table Rows(const std::vector<std::vector<double>>& rows) {
  Table t;
  for (const auto& r : rows) {
    t.x.push_back(r[0]);
    t.y.push_back(r[1]);
  }
  return t;
}

void Builder::EmitPdu(const Component& c) {
  if (detail::IsHydraulicPdu(c)) {
    std::optional<double> motor_lost_time;  // the scenario value, as t_motor_lost below
    if (scenario_)
      if (auto it = scenario_->values.find("motor_lost_time"); it != scenario_->values.end()) motor_lost_time = it->second;
    // A shutdown input when the wing-tip brakes will be commanded (EmitMonitoring).
    bool wing_tip_brakes = false;
    for (const auto& component : project_.components) wing_tip_brakes = wing_tip_brakes || component.type == "wing_tip_brake";
    pdu_ports_ = detail::AddHydraulicPdu(model_.network, c, motor_lost_time, wing_tip_brakes);
    for (const auto& e : model_.network.elements())
      if (!model_.component_of.count(e.id)) model_.component_of[e.id] = c.id;
  } else {
    Scalars s = {{"n_m", ValueOr(c, "motor_count", 2)},
                 {"J_m", Require(c, "motor_inertia")},
                 {"ratio", Require(c, "ratio")},
                 {"J_g", Require(c, "gear_inertia")},
                 {"w_max", Require(c, "max_output_speed")},
                 {"tau_stall", Require(c, "stall_torque")},
                 {"P_max", Require(c, "power")},
                 {"t_ramp", Require(c, "speed_ramp_time")},
                 {"tauPOB", Require(c, "brake_torque")}};
    if (scenario_) {
      if (auto it = scenario_->values.find("motor_lost_time"); it != scenario_->values.end())
        s["t_motor_lost"] = it->second;
    }
    Add("PDU", c.id, s, c.id);
    pdu_ports_ = {c.id + ".flange_left", c.id + ".flange_right", c.id + ".w_ref", c.id + ".phi", c.id + ".w",
                  c.id + ".stop"};
  }
  Map(c, "left", pdu_ports_.flange_left);
  Map(c, "right", pdu_ports_.flange_right);
  const std::string table = c.id + ".speed_command";
  speed_command_ = table;
  Add("CombiTimeTable", table, {{"extrapolation", kHoldLastPoint}}, "", {{"table", Rows(SpeedCommandRows(load_case_))}});
  Connect(table + ".y", pdu_ports_.w_ref);
}

void Builder::EmitTorqueLimiter(const Component& c) {
  const double tau1_ext = Require(c, "lockout_torque_extend");
  const double tau1_ret = Require(c, "lockout_torque_retract");
  const double tau2 = Require(c, "end_stop_torque");
  if (!(tau2 > tau1_ext && tau2 > tau1_ret))
    throw InputError("component '" + c.id + "' (" + c.type + "): 'end_stop_torque' = " + std::to_string(tau2) +
                         " N*m must exceed both lock-out torques (" + std::to_string(tau1_ext) + ", " +
                         std::to_string(tau1_ret) + " N*m): raise it or lower the lock-out torques",
                     c.where);
  // The retract end stop keeps the extend ratio tau2/tau1 (as the export).
  Add("TorqueLimiter", c.id,
      {{"tau1_ext", tau1_ext},
       {"tau1_ret", tau1_ret},
       {"tau2_ext", tau2},
       {"tau2_ret", tau2 * tau1_ret / tau1_ext},
       {"c1", Require(c, "stiffness_normal")},
       {"d", Beta() * Require(c, "stiffness_normal")},  // structural damping of the balls and ramps
       {"c2", Require(c, "stiffness_lockout")},
       {"c3", Require(c, "stiffness_end_stop")},
       {"tauB_max", Require(c, "max_brake_torque")},
       {"J", Require(c, "inertia")}},
      c.id);
  Map(c, "input", c.id + ".flange_a");
  Map(c, "output", c.id + ".flange_b");
}

void Builder::EmitShaftFull(const Component& c) {
  const ShaftValues data = ShaftData(c, Beta());
  const int n = model_.shaft_elements;
  const bool ruptured = scenario_ && scenario_->rupture_component == c.id;
  const int broken = ruptured ? (n + 1) / 2 : 0;  // the spring-damper replaced by a Disconnector
  std::vector<std::string> masses;
  for (int i = 0; i <= n; ++i) {
    const double share = (i == 0 || i == n) ? 0.5 / n : 1.0 / n;
    const std::string mass = c.id + ".m" + std::to_string(i);
    // The drag of the segment (its bearings and joints) acts at its two ends, half at each, as
    // in the reduced model: interior masses without Coulomb friction avoid stick/slip events
    // of every sub-element while the shaft starts and stops.
    if (data.drag > 0 && (i == 0 || i == n))
      Add("LossyInertia", mass, Regularised({{"J", data.J * share}, {"tau_C", data.drag * 0.5}}), c.id);
    else
      Add("Inertia", mass, {{"J", data.J * share}}, c.id);
    masses.push_back(mass);
    if (i == 0) continue;
    const std::string spring = c.id + ".e" + std::to_string(i);
    Scalars s = {{"c", data.c * n}, {"d", data.d * n}};
    if (i == broken) {
      s["t_disconnect"] = *scenario_->rupture_time;
      Add("Disconnector", spring, s, c.id);
    } else {
      Add("SpringDamper", spring, s, c.id);
    }
    Connect(masses[i - 1] + ".flange_b", spring + ".flange_a");
    Connect(spring + ".flange_b", mass + ".flange_a");
  }
  Map(c, "a", masses.front() + ".flange_a");
  Map(c, "b", masses.back() + ".flange_b");
  model_.derived.push_back({c.id + ".tau", c.id + ".e1.tau", -1.0});
}

void Builder::EmitSteadyBearing(const Component& c) {
  Scalars s = Regularised(Stribeck(c));
  s["J"] = Require(c, "inertia");
  Add("LossyInertia", c.id, s, c.id);
  Map(c, "a", c.id + ".flange_a");
  Map(c, "b", c.id + ".flange_b");
}

void Builder::EmitUniversalJoint(const Component& c) {
  const auto c_joint = Value(c, "stiffness");
  const double b = ValueOr(c, "backlash", 0.0);
  if (b > 0 && !c_joint)
    throw InputError("component '" + c.id + "' (universal_joint): a backlash needs a stiffness: give 'stiffness'",
                     c.where);
  Scalars s = Regularised({{"J", Require(c, "inertia")}, {"eta_GE", Require(c, "efficiency")}});
  if (c_joint) {
    s["elastic"] = 1;
    s["c"] = *c_joint;
    s["d"] = Beta() * *c_joint;
    s["b"] = b;
    s["ratio"] = 1;
    Add("GeneralRotationalElement", c.id, s, c.id);
  } else {
    Add("LossyInertia", c.id, s, c.id);
  }
  Map(c, "a", c.id + ".flange_a");
  Map(c, "b", c.id + ".flange_b");
}

void Builder::EmitGearbox(const Component& c) {
  const auto stiffness = Value(c, "stiffness");
  const double b = ValueOr(c, "backlash", 0.0);
  if (b > 0 && !stiffness)
    throw InputError("component '" + c.id + "' (" + c.type + "): a backlash needs a stiffness: give 'stiffness'",
                     c.where);
  Scalars s = Regularised(Stribeck(c));
  s["ratio"] = Require(c, "ratio");
  s["elastic"] = stiffness ? 1 : 0;
  if (stiffness) {
    s["c"] = *stiffness;
    s["d"] = Beta() * *stiffness;
    s["b"] = b;
  }
  s["J"] = Require(c, "inertia");
  s["eta_GE"] = std::pow(Require(c, "eta_mesh"), ValueOr(c, "meshes", 1.0));
  if (c.type == "branch_gearbox") {
    Add("BranchGearbox", c.id, s, c.id);
    Map(c, "input", c.id + ".flange_a");
    Map(c, "through", c.id + ".flange_b");
    Map(c, "branch", c.id + ".flange_branch");
  } else {
    Add("GeneralRotationalElement", c.id, s, c.id);
    Map(c, "input", c.id + ".flange_a");
    Map(c, "output", c.id + ".flange_b");
  }
}

void Builder::EmitActuator(const Component& c) {
  const double ratio = Require(c, "ratio");
  Scalars s = Regularised(Stribeck(c));
  s["ratio"] = ratio;
  s["eta_op"] = Require(c, "eta_opposing");
  s["eta_ai"] = Require(c, "eta_aiding");
  s["J_in"] = Require(c, "input_inertia");
  if (auto J_load = Value(c, "load_inertia")) s["J_load"] = *J_load;
  if (auto phi = Value(c, "eta_settle_angle")) s["phi_eta"] = *phi;
  if (auto w = Value(c, "eta_speed_threshold")) s["w_eta"] = *w;
  if (auto stiffness = Value(c, "stiffness")) {
    s["elastic"] = 1;
    s["c"] = *stiffness;
    s["d"] = Beta() * *stiffness;
    s["b"] = ValueOr(c, "backlash", 0.0);
  } else if (ValueOr(c, "backlash", 0.0) > 0) {
    throw InputError("component '" + c.id + "' (" + c.type + "): a backlash needs a stiffness: give 'stiffness'",
                     c.where);
  }
  Add("GearedRotaryActuator", c.id, s, c.id);
  Map(c, "input", c.id + ".flange_a");
  // A jam of this actuator: its output is tied to the structure at the scenario's time.
  if (scenario_ && scenario_->jam_component == c.id) {
    const std::string jam = c.id + ".jam";
    const double c_jam = kJamStiffness * ratio * ratio;
    Add("Jam", jam, {{"c", c_jam}, {"d", Beta() * c_jam}, {"t_jam", *scenario_->jam_time}}, c.id);
    Connect(c.id + ".flange_b", jam + ".flange");
  }
}

void Builder::EmitWingTipBrake(const Component& c) {
  Add("WingTipBrake", c.id,
      {{"tauB_max", Require(c, "max_dynamic_torque")},
       {"tauB_lim", Require(c, "static_capacity")},
       {"t_B", Require(c, "time_to_max_torque")},
       {"t_lat", Require(c, "engagement_latency")},
       {"J", Require(c, "inertia")}},
      c.id);
  Map(c, "a", c.id + ".flange_a");
  Map(c, "b", c.id + ".flange_b");
  wtbs_.push_back(&c);
}

void Builder::EmitPositionSensor(const Component& c) {
  Add("Inertia", c.id, {{"J", Require(c, "inertia")}}, c.id);
  Map(c, "a", c.id + ".flange_a");
  Map(c, "b", c.id + ".flange_b");
  auto role = c.texts.find("role");
  if (role == c.texts.end() || role->second != "fppu") sensors_.push_back(&c);
}

void Builder::EmitDisconnector(const Component& c) {
  Scalars s = {{"c", ValueOr(c, "stiffness", kDefaultDisconnectorStiffness)}, {"d", kDefaultDisconnectorDamping}};
  if (scenario_ && scenario_->rupture_component == c.id) s["t_disconnect"] = *scenario_->rupture_time;
  Add("Disconnector", c.id, s, c.id);
  Map(c, "a", c.id + ".flange_a");
  Map(c, "b", c.id + ".flange_b");
}

void Builder::EmitJam(const Component& c) {
  Scalars s = {{"c", Require(c, "stiffness")}, {"d", Beta() * Require(c, "stiffness")}};
  if (scenario_ && scenario_->jam_component == c.id) s["t_jam"] = *scenario_->jam_time;
  Add("Jam", c.id, s, c.id);
  Map(c, "a", c.id + ".flange");
}

void Builder::EmitComponent(const Component& c) {
  const std::string& t = c.type;
  if (t == "pdu") EmitPdu(c);
  else if (t == "system_torque_limiter" || t == "station_torque_limiter") EmitTorqueLimiter(c);
  else if (t == "torque_shaft") EmitShaftFull(c);
  else if (t == "steady_bearing") EmitSteadyBearing(c);
  else if (t == "universal_joint") EmitUniversalJoint(c);
  else if (t == "angle_gearbox" || t == "branch_gearbox") EmitGearbox(c);
  else if (IsActuator(t)) EmitActuator(c);
  else if (t == "wing_tip_brake") EmitWingTipBrake(c);
  else if (t == "position_sensor") EmitPositionSensor(c);
  else if (t == "disconnector") EmitDisconnector(c);
  else if (t == "jam") EmitJam(c);
  else
    throw InputError("component '" + c.id + "': type '" + t +
                         "' has no simulation model; use one of the catalogue types (highlift info --types)",
                     c.where);
}

// Reduced resolution: maximal chains of shafts, bearings and joints between the lumping
// components become one spring-damper (series stiffness) with the chain's inertia and drag
// split between two end inertias; a chain without any elastic member is one rigid inertia.
void Builder::FindChains() {
  std::map<std::pair<std::string, std::string>, PortRef> peer;
  for (const auto& conn : project_.connections) {
    peer[{conn.a.component, conn.a.port}] = conn.b;
    peer[{conn.b.component, conn.b.port}] = conn.a;
  }
  std::set<std::string> done;
  for (const auto& start : project_.components) {
    if (!IsChainType(start.type) || done.count(start.id)) continue;
    // Walk to one end of the chain (through port "a"), then collect the members towards "b".
    const Component* first = &start;
    std::string entry = "a";  // port by which the chain enters `first`
    std::set<std::string> seen{start.id};
    while (true) {
      auto it = peer.find({first->id, entry});
      if (it == peer.end()) break;
      const Component* prev = project_.FindComponent(it->second.component);
      if (!prev || !IsChainType(prev->type) || seen.count(prev->id)) break;
      seen.insert(prev->id);
      entry = it->second.port == "a" ? "b" : "a";
      first = prev;
    }
    Chain chain;
    const Component* current = first;
    std::string in = entry;
    while (true) {
      chain.members.emplace_back(current, in);
      done.insert(current->id);
      chain_of_[current->id] = chains_.size();
      const std::string out = in == "a" ? "b" : "a";
      auto it = peer.find({current->id, out});
      if (it == peer.end()) break;
      const Component* next = project_.FindComponent(it->second.component);
      if (!next || !IsChainType(next->type) || done.count(next->id)) break;
      in = it->second.port;
      current = next;
    }
    chains_.push_back(std::move(chain));
  }
}

void Builder::EmitChain(std::size_t index) {
  const auto& members = chains_[index].members;
  const Component* first = members.front().first;
  const std::string entry = members.front().second;
  {
    double compliance = 0, J = 0, drag = 0, damping_compliance = 0;
    bool elastic = false, ruptured = false;
    std::string members_text;
    for (const auto& [m, port] : members) {
      members_text += (members_text.empty() ? "" : ", ") + m->id;
      if (scenario_ && scenario_->rupture_component == m->id) ruptured = true;
      if (m->type == "torque_shaft") {
        const ShaftValues d = ShaftData(*m, Beta());
        compliance += 1.0 / d.c;
        if (d.d > 0) damping_compliance += 1.0 / d.d;
        J += d.J;
        drag += d.drag;
        elastic = true;
      } else {
        J += Require(*m, "inertia");
        drag += ValueOr(*m, "coulomb_torque", 0.0);
        if (auto c = Value(*m, "stiffness")) {
          compliance += 1.0 / *c;
          if (Beta() > 0) damping_compliance += 1.0 / (Beta() * *c);
          elastic = true;
        }
      }
    }
    const std::string base = members.size() == 1 ? first->id : first->id + "-" + members.back().first->id;
    model_.notes.push_back(base + ": " + members_text);
    auto mass = [&](const std::string& name, double share) {
      if (drag > 0)
        Add("LossyInertia", name, Regularised({{"J", J * share}, {"tau_C", drag * share}}), "");
      else
        Add("Inertia", name, {{"J", J * share}}, "");
    };
    std::string ref_a, ref_b;
    if (!elastic) {
      mass(base, 1.0);
      ref_a = base + ".flange_a";
      ref_b = base + ".flange_b";
    } else {
      const std::string mass_a = base + ".mass_a", spring = base + ".spring", mass_b = base + ".mass_b";
      mass(mass_a, 0.5);
      Scalars s = {{"c", 1.0 / compliance}, {"d", damping_compliance > 0 ? 1.0 / damping_compliance : 0.0}};
      if (ruptured) {
        s["t_disconnect"] = *scenario_->rupture_time;
        Add("Disconnector", spring, s, "");
      } else {
        Add("SpringDamper", spring, s, "");
      }
      mass(mass_b, 0.5);
      Connect(mass_a + ".flange_b", spring + ".flange_a");
      Connect(spring + ".flange_b", mass_b + ".flange_a");
      ref_a = mass_a + ".flange_a";
      ref_b = mass_b + ".flange_b";
      // Every shaft of the chain carries the spring's torque (the chain is massless inside).
      for (const auto& [m, port] : members)
        if (m->type == "torque_shaft") model_.derived.push_back({m->id + ".tau", spring + ".tau", port == "a" ? -1.0 : 1.0});
    }
    Map(*first, entry, ref_a);
    const auto& [last, last_in] = members.back();
    Map(*last, last_in == "a" ? "b" : "a", ref_b);
  }
}

// The order in which the components become elements, which is the order of the states: the
// left side from its tip to the PDU, the PDU, the right side from the PDU to its tip, each
// station branch next to its gearbox, so that the Jacobian is banded with a narrow band.
std::vector<const Component*> Builder::EmissionOrder() const {
  std::vector<const Component*> order;
  if (!pdu_) {
    for (const auto& c : project_.components) order.push_back(&c);
    return order;
  }
  std::map<std::pair<std::string, std::string>, PortRef> peer;
  for (const auto& conn : project_.connections) {
    peer[{conn.a.component, conn.a.port}] = conn.b;
    peer[{conn.b.component, conn.b.port}] = conn.a;
  }
  std::set<std::string> visited{pdu_->id};
  std::function<void(const Component*, const std::string&, std::vector<const Component*>&)> visit =
      [&](const Component* c, const std::string& entry, std::vector<const Component*>& out) {
        out.push_back(c);
        const ComponentTypeSpec* spec = FindComponentType(c->type);
        if (!spec) return;
        std::vector<std::string> ports;
        for (const PortSpec& p : spec->ports)
          if (p.name != entry) ports.push_back(p.name);
        std::stable_partition(ports.begin(), ports.end(), [](const std::string& p) { return p == "branch"; });
        for (const auto& port : ports) {
          auto it = peer.find({c->id, port});
          if (it == peer.end()) continue;
          const Component* next = project_.FindComponent(it->second.component);
          if (!next || visited.count(next->id)) continue;
          visited.insert(next->id);
          visit(next, it->second.port, out);
        }
      };
  std::vector<std::vector<const Component*>> sides;
  const ComponentTypeSpec* pdu_spec = FindComponentType(pdu_->type);
  for (const PortSpec& p : pdu_spec->ports) {
    auto it = peer.find({pdu_->id, p.name});
    if (it == peer.end()) continue;
    const Component* next = project_.FindComponent(it->second.component);
    if (!next || visited.count(next->id)) continue;
    visited.insert(next->id);
    sides.emplace_back();
    visit(next, it->second.port, sides.back());
  }
  if (!sides.empty()) order.insert(order.end(), sides[0].rbegin(), sides[0].rend());
  order.push_back(pdu_);
  for (std::size_t i = 1; i < sides.size(); ++i) order.insert(order.end(), sides[i].begin(), sides[i].end());
  for (const auto& c : project_.components)
    if (!visited.count(c.id)) order.push_back(&c);
  return order;
}

// Actuator loads of the load case: a torque on each actuator output, from a table against time
// or against flap position (the output angle over the travel). Positive table values oppose
// the commanded motion.
void Builder::EmitLoads() {
  if (!load_case_) return;
  for (const auto& [actuator_id, table] : load_case_->actuator_loads) {
    const Component* a = project_.FindComponent(actuator_id);
    if (!a || !IsActuator(a->type))
      throw InputError("load case '" + load_case_->name + "': actuator load for '" + actuator_id +
                           "', which is no actuator of the project: name a geared_rotary_actuator or "
                           "ballscrew_actuator",
                       load_case_->where);
    const double sign = -direction_;
    const std::string torque = a->id + ".airload";
    Add("Torque", torque, {}, a->id);
    Connect(torque + ".flange", a->id + ".flange_b");
    std::vector<std::vector<double>> rows;
    const std::string lookup = a->id + ".airload_table";
    if (table.abscissa == "position") {
      double travel = 0;
      if (a->type == "geared_rotary_actuator") {
        travel = Require(*a, "travel_angle");
      } else {
        const auto stroke = Value(*a, "stroke");
        if (!stroke)
          throw InputError("component '" + a->id + "' (ballscrew_actuator): a load against position "
                           "needs the 'stroke': give it",
                           a->where);
        travel = *stroke / Require(*a, "lead");
      }
      for (std::size_t i = 0; i < table.x.size(); ++i)
        rows.push_back({direction_ > 0 ? table.x[i] * travel : (table.x[i] - 1) * travel, sign * table.y[i]});
      // Retracting from full travel: the output angle runs from 0 down to -travel, so the
      // keys (x - 1)*travel of the positions x in increasing order are already increasing.
      const std::string sensor = a->id + ".output_angle";
      Add("AngleSensor", sensor, {}, a->id);
      Connect(a->id + ".flange_b", sensor + ".flange");
      Add("CombiTable1Ds", lookup, {{"extrapolation", kHoldLastPoint}}, a->id, {{"table", Rows(rows)}});
      Connect(sensor + ".phi", lookup + ".u");
      Connect(lookup + ".y", torque + ".tau");
    } else {
      for (std::size_t i = 0; i < table.x.size(); ++i) rows.push_back({table.x[i], sign * table.y[i]});
      Add("CombiTimeTable", lookup, {{"extrapolation", kHoldLastPoint}}, a->id, {{"table", Rows(rows)}});
      Connect(lookup + ".y", torque + ".tau");
    }
  }
}

void Builder::ComputeSpeedFactors() {
  if (!pdu_) return;
  std::map<std::pair<std::string, std::string>, PortRef> peer;
  for (const auto& conn : project_.connections) {
    peer[{conn.a.component, conn.a.port}] = conn.b;
    peer[{conn.b.component, conn.b.port}] = conn.a;
  }
  auto& factor = model_.speed_factor;
  std::deque<std::pair<const Component*, std::string>> queue;  // component, entry port
  factor[pdu_->id] = 1.0;
  for (const auto& port : {"left", "right"}) {
    auto it = peer.find({pdu_->id, port});
    if (it == peer.end()) continue;
    if (const Component* c = project_.FindComponent(it->second.component); c && !factor.count(c->id)) {
      factor[c->id] = 1.0;
      queue.emplace_back(c, it->second.port);
    }
  }
  while (!queue.empty()) {
    auto [c, entry] = queue.front();
    queue.pop_front();
    const ComponentTypeSpec* spec = FindComponentType(c->type);
    if (!spec) continue;
    for (const PortSpec& p : spec->ports) {
      if (p.name == entry) continue;
      auto it = peer.find({c->id, p.name});
      if (it == peer.end()) continue;
      const Component* next = project_.FindComponent(it->second.component);
      if (!next || factor.count(next->id)) continue;
      factor[next->id] = factor[c->id] * SpeedFactor(*c, entry, p.name);
      queue.emplace_back(next, it->second.port);
    }
  }
}

// The monitor: APPU angles and speeds at the tips (or the WTB rotors), the PDU angle and the
// commanded angle feed Monitoring, whose command applies the WTBs. With trigger "time" a Step
// applies them instead.
void Builder::EmitMonitoring() {
  if (wtbs_.empty()) return;
  if (scenario_ && scenario_->wtb_trigger == "time") {
    const std::string command = "wtb_command";
    Add("Step", command, {{"height", 1.0}, {"startTime", scenario_->wtb_time.value_or(0.0)}}, "");
    for (const Component* wtb : wtbs_) Connect(command + ".y", wtb->id + ".apply");
    ConnectShutdown(command + ".y");
    return;
  }
  if (!pdu_) return;  // no PDU angle to monitor: the WTBs stay released
  const Component* appu = sensors_.empty() ? nullptr : sensors_.front();
  auto sensor_value = [&](const std::string& name) {
    if (appu) return Require(*appu, name);
    const ComponentTypeSpec* spec = FindComponentType("position_sensor");
    const ParameterSpec* p = spec ? spec->FindParameter(name) : nullptr;
    HIGHLIFT_CHECK(p && p->nominal, "catalogue: position_sensor." + name + " has no default");
    return *p->nominal;
  };
  const std::string monitor = "monitor";
  Add("Monitoring", monitor,
      {{"phi_asym", sensor_value("asymmetry_threshold")},
       {"w_over", sensor_value("overspeed_factor") * Require(*pdu_, "max_output_speed")},
       {"phi_unc", sensor_value("asymmetry_threshold")},
       {"t_detect", sensor_value("latency")}},
      "");
  std::vector<std::pair<std::string, std::string>> tips;  // (angle ref, speed ref)
  auto tip = [&](const Component& c, const std::string& flange) {
    const std::string angle = c.id + ".angle_sensor", speed = c.id + ".speed_sensor";
    Add("AngleSensor", angle, {}, c.id);
    Add("SpeedSensor", speed, {}, c.id);
    Connect(flange, angle + ".flange");
    Connect(flange, speed + ".flange");
    std::string angle_ref = angle + ".phi", speed_ref = speed + ".w";
    auto it = model_.speed_factor.find(c.id);
    const double k = it == model_.speed_factor.end() ? 1.0 : 1.0 / it->second;
    if (std::abs(k - 1.0) > 1e-12) {
      const std::string ga = c.id + ".angle_at_pdu", gw = c.id + ".speed_at_pdu";
      Add("Gain", ga, {{"k", k}}, c.id);
      Add("Gain", gw, {{"k", k}}, c.id);
      Connect(angle_ref, ga + ".u");
      Connect(speed_ref, gw + ".u");
      angle_ref = ga + ".y";
      speed_ref = gw + ".y";
    }
    tips.emplace_back(angle_ref, speed_ref);
  };
  const std::vector<const Component*>& tip_components = sensors_.empty() ? wtbs_ : sensors_;
  for (const Component* c : tip_components) tip(*c, c->id + ".flange_a");
  std::size_t left = 0, right = tips.size() > 1 ? 1 : 0;
  for (std::size_t i = 0; i < tip_components.size(); ++i) {
    auto side = tip_components[i]->labels.find("side");
    if (side == tip_components[i]->labels.end()) continue;
    if (side->second == "left") left = i;
    if (side->second == "right") right = i;
  }
  Connect(tips[left].first, monitor + ".phi_left");
  Connect(tips[left].second, monitor + ".w_left");
  Connect(tips[right].first, monitor + ".phi_right");
  Connect(tips[right].second, monitor + ".w_right");
  Connect(pdu_ports_.phi, monitor + ".phi_pdu");
  const std::string commanded = monitor + ".commanded_angle";
  Add("Integrator", commanded, {}, "");
  Connect(speed_command_ + ".y", commanded + ".u");
  Connect(commanded + ".y", monitor + ".phi_cmd");
  for (const Component* wtb : wtbs_) Connect(monitor + ".wtb", wtb->id + ".apply");
  ConnectShutdown(monitor + ".wtb");
}

// The command that applies the wing-tip brakes also shuts the PDU down (its pressure-off
// brakes), as the flight control computer does: the healthy side is not driven into its brake.
void Builder::ConnectShutdown(const std::string& command) {
  if (!pdu_) return;
  if (!detail::IsHydraulicPdu(*pdu_)) Connect(command, pdu_->id + ".stop");
  else if (!pdu_ports_.stop.empty()) Connect(command, pdu_ports_.stop);
}

void Builder::CheckScenario() {
  if (!scenario_) return;
  if (!scenario_->load_case.empty()) {
    load_case_ = project_.FindLoadCase(scenario_->load_case);
    if (!load_case_) {
      std::vector<std::string> names;
      for (const auto& lc : project_.load_cases) names.push_back(lc.name);
      throw InputError("scenario '" + scenario_->name + "': unknown load case '" + scenario_->load_case +
                           "'" + SuggestionHint(scenario_->load_case, names, "load cases"),
                       scenario_->where);
    }
  }
  if (load_case_ && load_case_->direction == "retract") direction_ = -1.0;
  if (scenario_->kind == "rupture") {
    if (!scenario_->rupture_component)
      throw InputError("scenario '" + scenario_->name + "': a rupture scenario names no component: give "
                           "rupture.component (a torque_shaft or disconnector)",
                       scenario_->where);
    const Component* r = project_.FindComponent(*scenario_->rupture_component);
    if (!r || (r->type != "torque_shaft" && r->type != "disconnector"))
      throw InputError("scenario '" + scenario_->name + "': rupture component '" + *scenario_->rupture_component +
                           "' must be a torque_shaft or a disconnector of the project",
                       scenario_->where);
    if (!scenario_->rupture_time)
      throw InputError("scenario '" + scenario_->name + "': the rupture has no time: give rupture.time",
                       scenario_->where);
  }
  if (scenario_->kind == "jam") {
    if (!scenario_->jam_component)
      throw InputError("scenario '" + scenario_->name + "': a jam scenario names no component: give jam.component "
                           "(an actuator or a jam element)",
                       scenario_->where);
    const Component* j = project_.FindComponent(*scenario_->jam_component);
    if (!j || (j->type != "jam" && !IsActuator(j->type)))
      throw InputError("scenario '" + scenario_->name + "': jam component '" + *scenario_->jam_component +
                           "' must be a jam element or an actuator (geared_rotary_actuator, "
                           "ballscrew_actuator) of the project",
                       scenario_->where);
    if (!scenario_->jam_time)
      throw InputError("scenario '" + scenario_->name + "': the jam has no time: give jam.time", scenario_->where);
  }
}

DriveModel Builder::Run() {
  options_.Validate();
  if (project_.components.empty())
    throw InputError("project '" + project_.name + "' has no drive-system components to simulate; add "
                     "\"components\" and \"connections\" (or simulate an element network under \"elements\")");
  model_.resolution = options_.resolution;
  model_.shaft_elements = options_.shaft_elements > 0
                              ? options_.shaft_elements
                              : std::max(DriveNetworkOptions::kMinShaftElements, project_.settings.shaft_elements);
  if (scenario_) {
    model_.scenario = *scenario_;
    model_.stop_time = scenario_->stop_time;
  }
  CheckScenario();
  if (load_case_) model_.load_case = load_case_->name;
  for (const auto& c : project_.components) {
    if (c.type != "pdu") continue;
    if (pdu_)
      throw InputError("component '" + c.id + "': a second pdu ('" + pdu_->id +
                           "' is the first): a drive system has one power drive unit",
                       c.where);
    pdu_ = &c;
  }
  ComputeSpeedFactors();
  const bool reduced = options_.resolution == DriveResolution::kReduced;
  if (reduced) FindChains();
  std::set<std::size_t> chains_done;
  for (const Component* c : EmissionOrder()) {
    if (reduced && IsChainType(c->type)) {
      const std::size_t chain = chain_of_.at(c->id);
      if (chains_done.insert(chain).second) EmitChain(chain);
      continue;
    }
    EmitComponent(*c);
  }
  for (const auto& conn : project_.connections) {
    auto a = ports_.find({conn.a.component, conn.a.port});
    auto b = ports_.find({conn.b.component, conn.b.port});
    if (a == ports_.end() || b == ports_.end()) {
      const Component* ca = project_.FindComponent(conn.a.component);
      const Component* cb = project_.FindComponent(conn.b.component);
      if (reduced && ca && cb && IsChainType(ca->type) && IsChainType(cb->type)) continue;
      throw InputError("connection " + conn.a.ToString() + " - " + conn.b.ToString() +
                           ": unknown component or port; check it with 'highlift validate'",
                       conn.where);
    }
    Connect(a->second, b->second);
  }
  EmitLoads();
  EmitMonitoring();
  return std::move(model_);
}

}  // namespace

std::string ToString(DriveResolution resolution) {
  return resolution == DriveResolution::kFull ? "full" : "reduced";
}

DriveResolution ParseDriveResolution(const std::string& text) {
  if (text == "full") return DriveResolution::kFull;
  if (text == "reduced") return DriveResolution::kReduced;
  throw InputError("model '" + text + "' is not a model resolution; choose 'full' (every shaft split into "
                   "elements) or 'reduced' (inertias lumped at gearboxes and stations)");
}

void DriveNetworkOptions::Validate() const {
  if (shaft_elements < 0 || shaft_elements > 1000)
    throw InputError("option shaft_elements = " + std::to_string(shaft_elements) +
                     " must be 0 (the project's setting, at least 4) or 1..1000 spring-dampers per shaft");
  if (!(friction_speed >= 0 && friction_speed < 1e3))
    throw InputError("option friction_speed = " + std::to_string(friction_speed) +
                     " rad/s must be >= 0 (0: exact stick/slip) and small against the shaft speed, "
                     "e.g. 0.01 rad/s");
}

SimulationOptions DriveModel::Options(const Project& project) const {
  SimulationOptions o;
  o.stop_time = stop_time;
  o.relative_tolerance = project.settings.relative_tolerance;
  o.output_interval = project.settings.output_interval;
  if (scenario && scenario->output_interval) o.output_interval = *scenario->output_interval;
  o.initial_equilibrium = true;  // the drive starts held, the loads acting (airloads on a brake)
  o.torque_tolerance = 1e-3;     // N*m: twists of stiff jams and end stops resolved in torque
  return o;
}

bool IsDriveSystemProject(const Project& project) {
  return !project.components.empty() && project.elements.empty();
}

DriveModel BuildDriveNetwork(const Project& project, const DriveNetworkOptions& options) {
  const Scenario* scenario = nullptr;
  if (!options.scenario.empty()) {
    scenario = project.FindScenario(options.scenario);
    if (!scenario) {
      std::vector<std::string> names;
      for (const auto& s : project.scenarios) names.push_back(s.name);
      throw InputError("scenario '" + options.scenario + "' is not in the project" +
                       SuggestionHint(options.scenario, names, "scenarios"));
    }
  } else if (project.scenarios.size() == 1) {
    scenario = &project.scenarios.front();
  }
  return BuildDriveNetwork(project, scenario, options);
}

DriveModel BuildDriveNetwork(const Project& project, const Scenario* scenario, const DriveNetworkOptions& options) {
  Builder builder(project, scenario, options);
  return builder.Run();
}

Scenario SizingScenario(const Project& project, const std::string& kind, const std::string& component) {
  if (kind != "jam" && kind != "rupture")
    throw InputError("sizing case kind '" + kind + "' is unknown; choose 'jam' or 'rupture'");
  // A jam at full speed while extending (the kinetic energy of the drive goes into the jammed
  // load path); a rupture while retracting, when the airload aids the motion: the outboard part
  // then speeds up from its operating speed until the brake engages, the worst case that the
  // single-DOF estimate of highlift peak assumes (extending against an opposing load it first
  // stops and reverses).
  const std::string preferred = kind == "rupture" ? "retract" : "extend";
  auto direction_of = [&](const std::string& load_case) {
    const LoadCase* lc = project.FindLoadCase(load_case);
    return lc ? lc->direction : std::string();
  };
  bool has_preferred = false;
  for (const LoadCase& lc : project.load_cases) has_preferred = has_preferred || lc.direction == preferred;
  for (const Scenario& s : project.scenarios) {
    if (s.kind != kind) continue;
    const auto& target = kind == "jam" ? s.jam_component : s.rupture_component;
    if (target && *target == component && (!has_preferred || direction_of(s.load_case) == preferred)) return s;
  }
  Scenario s;
  s.name = kind + "_" + component;
  s.kind = kind;
  s.description = "sizing case of highlift peak";
  for (const LoadCase& lc : project.load_cases)
    if (lc.direction == preferred) {
      s.load_case = lc.name;
      break;
    }
  if (s.load_case.empty())
    for (const LoadCase& lc : project.load_cases)
      if (lc.direction == "extend") {
        s.load_case = lc.name;
        break;
      }
  if (s.load_case.empty() && !project.load_cases.empty()) s.load_case = project.load_cases.front().name;
  if (kind == "jam") {
    s.jam_component = component;
    s.jam_time = kFailureTime;
    s.stop_time = 2 * kFailureTime;
  } else {
    s.rupture_component = component;
    s.rupture_time = kFailureTime;
    s.stop_time = 3 * kFailureTime;
  }
  return s;
}

DerivedColumnSink::DerivedColumnSink(std::vector<DerivedColumn> derived, OutputSink& next)
    : derived_(std::move(derived)), next_(next) {}

void DerivedColumnSink::Begin(const std::vector<std::string>& columns) {
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < columns.size(); ++i) index[columns[i]] = static_cast<int>(i);
  std::vector<std::string> all = columns;
  sources_.clear();
  for (const auto& d : derived_) {
    auto it = index.find(d.source);
    if (it == index.end() || index.count(d.name)) continue;
    all.push_back(d.name);
    sources_.emplace_back(it->second, d.factor);
  }
  next_.Begin(all);
}

void DerivedColumnSink::Row(double time, const std::vector<double>& values) {
  if (sources_.empty()) {
    next_.Row(time, values);
    return;
  }
  row_.assign(values.begin(), values.end());
  for (const auto& [i, factor] : sources_) row_.push_back(factor * values[i]);
  next_.Row(time, row_);
}

void DerivedColumnSink::End() { next_.End(); }

std::vector<PeakTorque> ComponentPeakTorques(const DriveModel& model, const Project& project,
                                             const SimulationReport& report) {
  std::map<std::string, PeakTorque> best;
  for (const PeakTorque& p : report.peak_torques) {
    std::string component;
    if (auto it = model.component_of.find(p.element); it != model.component_of.end()) {
      component = it->second;
    } else {
      // A part of a composite ("stl_left.brake"): the longest owner id that prefixes it.
      for (const auto& [id, owner] : model.component_of)
        if (!owner.empty() && p.element.size() > id.size() && p.element.compare(0, id.size(), id) == 0 &&
            p.element[id.size()] == '.' && id.size() > component.size())
          component = owner;
    }
    if (component.empty()) continue;
    const Component* c = project.FindComponent(component);
    if (!c) continue;
    // Scenario parts of an actuator (its airload, its jam) are not its torque.
    if (p.element != component && IsActuator(c->type)) continue;
    PeakTorque q = p;
    q.element = component;
    if (c->type == "torque_shaft") q.tau = -p.tau;  // as the derived column <shaft>.tau
    auto it = best.find(component);
    if (it == best.end() || std::abs(q.tau) > std::abs(it->second.tau)) best[component] = q;
  }
  std::vector<PeakTorque> out;
  for (const Component& c : project.components)
    if (auto it = best.find(c.id); it != best.end()) out.push_back(it->second);
  return out;
}

}  // namespace highlift::sim
