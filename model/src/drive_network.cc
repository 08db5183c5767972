// Drive-system projects (catalogue components) as element networks: the one translation that
// the simulator integrates and the Modelica export writes. Full resolution: every component is
// one element (a composite of the HighLift library) and every torque shaft a chain of
// spring-dampers between lumped shaft inertias. Reduced resolution (paper section 2, approach
// of [4]): inertias lumped at the gearboxes and stations; the shafts, bearings and joints
// between them become one spring-damper with their series stiffness and their inertia and drag
// split between its two ends.
#include "highlift/model/drive_network.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <set>
#include <sstream>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/text_table.h"
#include "highlift/core/message_number.h"
#include "components/component_util.h"
#include "highlift/model/component_model.h"

namespace highlift::model {
namespace {

constexpr double kFailureTime = 1.0;                   // s, sizing scenarios made up by peak
constexpr double kHoldLastPoint = 1;                   // Modelica.Blocks.Types.Extrapolation

using components::Require;

const ComponentModel* ModelOf(const Component& c) { return FindComponentModel(c.type); }

/// True when the component's type has the role (false for an unknown type).
bool Has(const Component& c, bool ComponentRoles::*role) {
  const ComponentModel* m = ModelOf(c);
  return m && m->roles().*role;
}

/// "torque_shaft or a disconnector" from the names of the types with a role ("x, y" for an
/// empty conjunction).
std::string Choices(bool ComponentRoles::*role, const std::string& conjunction) {
  const std::vector<std::string> names = TypesWithRole(role);
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() && !conjunction.empty() ? " " + conjunction + " " : ", ") + names[i];
  return text;
}

class Builder final : public ExpansionContext {
 public:
  Builder(const Project& project, const Scenario* scenario, const DriveNetworkOptions& options)
      : project_(project), scenario_(scenario), options_(options) {}

  DriveModel Run();

  // ExpansionContext: what a component's model uses to add its elements.
  const Project& project() const override { return project_; }
  const Scenario* scenario() const override { return scenario_; }
  int shaft_elements() const override { return model_.shaft_elements; }
  double beta() const override { return project_.settings.structural_damping; }
  Scalars Regularised(Scalars s) const override {
    if (options_.friction_speed > 0) s["w_small"] = options_.friction_speed;
    return s;
  }
  void Add(const std::string& type, const std::string& id, Scalars scalars, const std::string& component,
           std::map<std::string, Table> tables = {}, std::string description = {}) override;
  void Connect(const std::string& a, const std::string& b) override { model_.network.Connect(a, b); }
  void MapPort(const Component& c, const std::string& port, const std::string& ref) override {
    ports_[{c.id, port}] = ref;
  }
  Network& network() override { return model_.network; }
  DriveModel& model() override { return model_; }
  void SetDriveUnit(const Component& c, const DriveUnitPorts& ports) override;
  void AddTipBrake(const Component& c) override { wtbs_.push_back(&c); }
  void AddTipSensor(const Component& c) override { sensors_.push_back(&c); }
  bool HasTipBrakes() const override {
    return std::any_of(project_.components.begin(), project_.components.end(), [](const Component& c) {
      return Has(c, &ComponentRoles::tip_brake);
    });
  }

 private:
  void CheckScenario();
  void ComputeSpeedFactors();
  void EmitComponent(const Component& c);
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
  DriveUnitPorts pdu_ports_;
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
                  std::map<std::string, Table> tables, std::string description) {
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
  if (description.empty() && id == component)
    if (const Component* c = project_.FindComponent(component)) description = c->description;
  element.description = std::move(description);
  model_.network.Adopt(element);
  model_.component_of[id] = component;
}

Table Rows(const std::vector<std::vector<double>>& rows) {
  Table t;
  for (const auto& r : rows) {
    t.x.push_back(r[0]);
    t.y.push_back(r[1]);
  }
  return t;
}

// The drive unit's speed command: the load case's PDU speed profile, signed by the direction.
void Builder::SetDriveUnit(const Component& c, const DriveUnitPorts& ports) {
  pdu_ports_ = ports;
  MapPort(c, "left", ports.flange_left);
  MapPort(c, "right", ports.flange_right);
  const std::string table = c.id + ".speed_command";
  speed_command_ = table;
  Add("CombiTimeTable", table, {{"extrapolation", kHoldLastPoint}}, "", {{"table", Rows(SpeedCommandRows(load_case_))}},
      "PDU output speed command [rad/s]" + std::string(load_case_ ? " of load case " + load_case_->name : ""));
  Connect(table + ".y", ports.w_ref);
}

void Builder::EmitComponent(const Component& c) {
  const ComponentModel* m = ModelOf(c);
  if (!m)
    throw InputError("component '" + c.id + "': type '" + c.type +
                         "' has no simulation model; use one of the catalogue types (highlift info --types)",
                     c.where);
  m->Expand(c, *this);
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
    if (!Has(start, &ComponentRoles::chain_member) || done.count(start.id)) continue;
    // Walk to one end of the chain (through port "a"), then collect the members towards "b".
    const Component* first = &start;
    std::string entry = "a";  // port by which the chain enters `first`
    std::set<std::string> seen{start.id};
    while (true) {
      auto it = peer.find({first->id, entry});
      if (it == peer.end()) break;
      const Component* prev = project_.FindComponent(it->second.component);
      if (!prev || !Has(*prev, &ComponentRoles::chain_member) || seen.count(prev->id)) break;
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
      if (!next || !Has(*next, &ComponentRoles::chain_member) || done.count(next->id)) break;
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
      const ChainMember member = ModelOf(*m)->Chain(*m, beta());
      J += member.J;
      drag += member.drag;
      if (member.c) {
        compliance += 1.0 / *member.c;
        if (member.d && *member.d > 0) damping_compliance += 1.0 / *member.d;
        elastic = true;
      }
    }
    const std::string base = members.size() == 1 ? first->id : first->id + "-" + members.back().first->id;
    model_.notes.push_back(base + ": " + members_text);
    auto mass = [&](const std::string& name, double share) {
      if (drag > 0)
        Add("LossyInertia", name, Regularised({{"J", J * share}, {"tau_C", drag * share}}), "", {},
            "lumped: " + members_text);
      else
        Add("Inertia", name, {{"J", J * share}}, "", {}, "lumped: " + members_text);
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
        Add("Disconnector", spring, s, "", {}, "series stiffness of " + members_text + " (ruptures)");
      } else {
        Add("SpringDamper", spring, s, "", {}, "series stiffness of " + members_text);
      }
      mass(mass_b, 0.5);
      Connect(mass_a + ".flange_b", spring + ".flange_a");
      Connect(spring + ".flange_b", mass_b + ".flange_a");
      ref_a = mass_a + ".flange_a";
      ref_b = mass_b + ".flange_b";
      // Every shaft of the chain carries the spring's torque (the chain is massless inside).
      for (const auto& [m, port] : members)
        if (ModelOf(*m)->Chain(*m, beta()).torque_column) model_.derived.push_back({m->id + ".tau", spring + ".tau", port == "a" ? -1.0 : 1.0});
    }
    MapPort(*first, entry, ref_a);
    const auto& [last, last_in] = members.back();
    MapPort(*last, last_in == "a" ? "b" : "a", ref_b);
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
// or against flap position (the output angle over the travel). In the project file positive
// table values oppose the commanded motion; the element network's tables hold the torque on the
// output flange in the network's sign convention (positive drives in the extend direction),
// that is the project's values times -1 when extending and +1 when retracting.
void Builder::EmitLoads() {
  if (!load_case_) return;
  for (const auto& [actuator_id, table] : load_case_->actuator_loads) {
    const Component* a = project_.FindComponent(actuator_id);
    if (!a || !Has(*a, &ComponentRoles::actuator))
      throw InputError("load case '" + load_case_->name + "': actuator load for '" + actuator_id +
                           "', which is no actuator of the project: name a " +
                           Choices(&ComponentRoles::actuator, "or"),
                       load_case_->where);
    const double sign = -direction_;
    const std::string torque = a->id + ".airload";
    Add("Torque", torque, {}, a->id, {},
        "airload on " + a->id + " (torque on the output, positive in the extend direction: the load case's "
        "table times " + (direction_ > 0 ? "-1" : "+1") + ", as its positive values oppose the " +
        (direction_ > 0 ? "extension" : "retraction") + ")");
    Connect(torque + ".flange", a->id + ".flange_b");
    std::vector<std::vector<double>> rows;
    const std::string lookup = a->id + ".airload_table";
    if (table.abscissa == "position") {
      const double travel = ModelOf(*a)->TravelAngle(*a);
      for (std::size_t i = 0; i < table.x.size(); ++i)
        rows.push_back({direction_ > 0 ? table.x[i] * travel : (table.x[i] - 1) * travel, sign * table.y[i]});
      // Retracting from full travel: the output angle runs from 0 down to -travel, so the
      // keys (x - 1)*travel of the positions x in increasing order are already increasing.
      const std::string sensor = a->id + ".output_angle";
      Add("AngleSensor", sensor, {}, a->id, {}, "output angle of " + a->id);
      Connect(a->id + ".flange_b", sensor + ".flange");
      Add("CombiTable1Ds", lookup, {{"extrapolation", kHoldLastPoint}}, a->id, {{"table", Rows(rows)}},
          "airload [N*m] against the output angle of " + a->id + " [rad]");
      Connect(sensor + ".phi", lookup + ".u");
      Connect(lookup + ".y", torque + ".tau");
    } else {
      for (std::size_t i = 0; i < table.x.size(); ++i) rows.push_back({table.x[i], sign * table.y[i]});
      Add("CombiTimeTable", lookup, {{"extrapolation", kHoldLastPoint}}, a->id, {{"table", Rows(rows)}},
          "airload [N*m] on " + a->id + " against time");
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
      factor[next->id] = factor[c->id] * ModelOf(*c)->SpeedRatio(*c, entry, p.name);
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
    Add("Step", command, {{"height", 1.0}, {"startTime", scenario_->wtb_time.value_or(0.0)}}, "", {},
        "wing-tip brake command at the scenario's time");
    for (const Component* wtb : wtbs_) Connect(command + ".y", wtb->id + ".apply");
    ConnectShutdown(command + ".y");
    return;
  }
  if (!pdu_) return;  // no PDU angle to monitor: the WTBs stay released
  const MonitorThresholds thresholds = MonitorSettings(sensors_.empty() ? nullptr : sensors_.front());
  const std::string monitor = "monitor";
  Add("Monitoring", monitor,
      {{"phi_asym", thresholds.phi_asym},
       {"w_over", thresholds.overspeed_factor * Require(*pdu_, "max_output_speed")},
       {"phi_unc", thresholds.phi_asym},
       {"t_detect", thresholds.t_detect}},
      "", {}, "failure monitoring: asymmetry, overspeed, uncommanded movement");
  std::vector<std::pair<std::string, std::string>> tips;  // (angle ref, speed ref)
  auto tip = [&](const Component& c, const std::string& flange) {
    const std::string angle = c.id + ".angle_sensor", speed = c.id + ".speed_sensor";
    Add("AngleSensor", angle, {}, c.id, {}, "shaft angle at " + c.id);
    Add("SpeedSensor", speed, {}, c.id, {}, "shaft speed at " + c.id);
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
  Add("Integrator", commanded, {}, "", {}, "commanded PDU angle");
  Connect(speed_command_ + ".y", commanded + ".u");
  Connect(commanded + ".y", monitor + ".phi_cmd");
  for (const Component* wtb : wtbs_) Connect(monitor + ".wtb", wtb->id + ".apply");
  ConnectShutdown(monitor + ".wtb");
}

// The command that applies the wing-tip brakes also shuts the PDU down (its pressure-off
// brakes), as the flight control computer does: the healthy side is not driven into its brake.
void Builder::ConnectShutdown(const std::string& command) {
  if (!pdu_) return;
  if (!pdu_ports_.stop.empty()) Connect(command, pdu_ports_.stop);
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
                           "rupture.component (a " + Choices(&ComponentRoles::rupturable, "or") + ")",
                       scenario_->where);
    const Component* r = project_.FindComponent(*scenario_->rupture_component);
    if (!r || !Has(*r, &ComponentRoles::rupturable))
      throw InputError("scenario '" + scenario_->name + "': rupture component '" + *scenario_->rupture_component +
                           "' must be a " + Choices(&ComponentRoles::rupturable, "or a") + " of the project",
                       scenario_->where);
    if (!scenario_->rupture_time)
      throw InputError("scenario '" + scenario_->name + "': the rupture has no time: give rupture.time",
                       scenario_->where);
  }
  if (scenario_->kind == kJamKind) {
    if (!scenario_->jam_component)
      throw InputError("scenario '" + scenario_->name + "': a jam scenario names no component: give jam.component "
                           "(an actuator or a jam element)",
                       scenario_->where);
    const Component* j = project_.FindComponent(*scenario_->jam_component);
    if (!j || !Has(*j, &ComponentRoles::jammable))
      throw InputError("scenario '" + scenario_->name + "': jam component '" + *scenario_->jam_component +
                           "' must be a jam element or an actuator (" + Choices(&ComponentRoles::actuator, "") +
                           ") of the project",
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
  model_.relative_tolerance = project_.settings.relative_tolerance;
  model_.friction_speed = options_.friction_speed;
  model_.output_interval = project_.settings.output_interval;
  if (scenario_) {
    model_.scenario = *scenario_;
    model_.stop_time = scenario_->stop_time;
    if (scenario_->output_interval) model_.output_interval = *scenario_->output_interval;
  }
  CheckScenario();
  if (load_case_) model_.load_case = load_case_->name;
  for (const auto& c : project_.components) {
    if (!Has(c, &ComponentRoles::drive_unit)) continue;
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
    if (reduced && Has(*c, &ComponentRoles::chain_member)) {
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
      if (reduced && ca && cb && Has(*ca, &ComponentRoles::chain_member) && Has(*cb, &ComponentRoles::chain_member))
        continue;
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
  if (shaft_elements < 0 || shaft_elements > kMaxShaftElements)
    throw InputError("option shaft_elements = " + std::to_string(shaft_elements) +
                     " must be 0 (the project's setting, at least 4) or 1.." + std::to_string(kMaxShaftElements) +
                     " spring-dampers per shaft");
  if (!(friction_speed >= 0 && friction_speed < 1e3))
    throw InputError("option friction_speed = " + FormatMessageNumber(friction_speed) +
                     " rad/s must be >= 0 (0: exact stick/slip) and small against the shaft speed, "
                     "e.g. 0.01 rad/s");
}

bool IsDriveSystemProject(const Project& project) {
  return !project.components.empty() && project.elements.empty();
}

DriveModel BuildDriveModel(const Project& project, const DriveNetworkOptions& options) {
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
  return BuildDriveModel(project, scenario, options);
}

DriveModel BuildDriveModel(const Project& project, const Scenario* scenario, const DriveNetworkOptions& options) {
  Builder builder(project, scenario, options);
  return builder.Run();
}

Scenario SizingScenario(const Project& project, const std::string& kind, const std::string& component) {
  if (kind != kJamKind && kind != "rupture")
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
    const auto& target = kind == kJamKind ? s.jam_component : s.rupture_component;
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
  if (kind == kJamKind) {
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

}  // namespace highlift::model
