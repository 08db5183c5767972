// Drive-system projects (catalogue components) to a Modelica model of HighLift and MSL
// components. Full resolution: every component is one instance and every torque shaft a chain
// of settings.shaft_elements (at least 4) spring-dampers between lumped shaft inertias.
// Reduced resolution (paper section 2, approach of [4]): inertias are lumped at the gearboxes
// and stations; the shafts, bearings and joints between them become one spring-damper with
// their series stiffness and their inertia and drag split between its two ends.
//
// The translation is the simulator's (sim/src/drive_network.cc, highlift::sim::BuildDriveNetwork):
// the same elements with the same parameter values and connections, so that a model simulated
// with `highlift simulate` and the exported one agree element by element
// (tests/export/drive_system_agreement_test.cc). Instance names are the simulator's element
// ids with the generator's Modelica spelling (shaft.e1 -> shaft_spring1, see that test).
#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <optional>
#include <set>
#include <sstream>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "model_writer.h"
#include "writers.h"

namespace highlift::modelica_detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDefaultDisconnectorStiffness = 1e6;  // N*m/rad, far above any shaft segment
constexpr double kDefaultDisconnectorDamping = 100;    // N*m*s/rad
constexpr double kJamStiffness = 1e5;                  // N*m/rad referred to the actuator input
// Regularisation speed w_small of the bearing, gear and actuator friction, rad/s: the default
// of DriveNetworkOptions::friction_speed (sim/include/highlift/sim/drive_network.h). Brakes
// (pressure-off, wing-tip and torque-limiter brakes) keep their exact stick/slip law.
constexpr double kFrictionSpeed = 0.1;
// Lower bound of the split of a shaft at full resolution (DriveNetworkOptions::kMinShaftElements).
constexpr int kMinShaftElements = 4;

std::optional<double> Value(const Component& c, const std::string& name) {
  auto it = c.parameters.find(name);
  if (it == c.parameters.end()) return std::nullopt;
  return it->second.nominal;
}

double ValueOr(const Component& c, const std::string& name, double fallback) {
  return Value(c, name).value_or(fallback);
}

std::string Real(double v, const Component& c, const std::string& name) {
  return FormatModelicaReal(v, "component '" + c.id + "' parameter '" + name + "'");
}

bool IsChainType(const std::string& type) {
  return type == "torque_shaft" || type == "steady_bearing" || type == "universal_joint";
}

bool IsActuator(const std::string& type) {
  return type == "geared_rotary_actuator" || type == "ballscrew_actuator";
}

/// A pdu whose text parameter `drive` is "hydraulic" (docs/hydraulics.md).
bool IsHydraulicPdu(const Component& c) {
  auto drive = c.texts.find("drive");
  return drive != c.texts.end() && drive->second == "hydraulic";
}

// Speed of `to` / speed of `from` through a component entered at port `from`.
double SpeedFactor(const Component& c, const std::string& from, const std::string& to) {
  const std::string& t = c.type;
  if (t == "angle_gearbox" || IsActuator(t)) {
    const double ratio = RequireValue(c, "ratio");
    if (from == "input" && to != "input") return 1.0 / ratio;
    if (to == "input" && from != "input") return ratio;
  }
  if (t == "branch_gearbox") {
    const double ratio = RequireValue(c, "ratio");
    if (to == "branch" && from != "branch") return 1.0 / ratio;
    if (from == "branch" && to != "branch") return ratio;
  }
  return 1.0;
}

struct TorqueShaftData {
  double c = 0;     // N*m/rad, whole segment
  double J = 0;     // kg*m^2, whole segment
  double d = 0;     // N*m*s/rad
  double drag = 0;  // N*m, Coulomb drag of the whole segment
};

/// `beta`: the project's structural damping (d = beta*c when the shaft gives no damping).
TorqueShaftData ShaftData(const Component& s, double beta) {
  TorqueShaftData data;
  const double L = RequireValue(s, "length");
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
    data.c = RequireValue(s, "shear_modulus") * polar / L;
  }
  if (auto J = Value(s, "inertia")) {
    data.J = *J;
  } else if (auto m_l = Value(s, "linear_density"); m_l && D && t) {
    const double d_in = std::max(0.0, *D - 2 * *t);
    data.J = *m_l * L * (*D * *D + d_in * d_in) / 8;
  } else {
    data.J = RequireValue(s, "density") * polar * L;
  }
  data.d = ValueOr(s, "damping", beta * data.c);
  data.drag = ValueOr(s, "drag_per_length", 0.0) * L;
  return data;
}

// A port reference as the generated model names it: "instance.connector".
using PortMap = std::map<std::pair<std::string, std::string>, std::string>;

class DriveSystemWriter {
 public:
  DriveSystemWriter(const Project& project, const std::string& model_name,
                    const ModelicaExportOptions& options)
      : project_(project),
        options_(options),
        model_name_(model_name),
        ids_({model_name, "Modelica", "HighLift", "time"}),
        writer_(model_name) {}

  ModelOutput Run();

 private:
  // --- instances of the components ---
  void EmitComponent(const Component& c);
  void EmitPdu(const Component& c);
  void EmitHydraulicPdu(const Component& c);  // drive = "hydraulic" (docs/hydraulics.md)
  /// The PDU speed command table of the load case, connected to `w_ref` (an input port).
  void EmitSpeedCommand(const Component& pdu, const std::string& w_ref);
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
  void EmitChains();  // reduced resolution
  void EmitLoads();
  void EmitMonitoring();
  /// The command that applies the wing-tip brakes also shuts the PDU down (the mechanical PDU's
  /// input `stop`, the hydraulic PDU's `<pdu>_stop`), as the simulator's translation does
  /// (ConnectShutdown in sim/src/drive_network.cc).
  bool PduShutdownConnected() const;
  void ConnectShutdown(const std::string& command);

  std::vector<Modifier> Stribeck(const Component& c) const;
  /// `mods` with the friction regularisation w_small of the drive translation.
  static std::vector<Modifier> Regularised(std::vector<Modifier> mods) {
    mods.push_back({"w_small", FormatModelicaReal(kFrictionSpeed), {}});
    return mods;
  }
  /// The project's structural damping beta (s): d = beta*c for elastic elements without their own.
  double Beta() const { return project_.settings.structural_damping; }
  /// Shaft elements at full resolution: the project's setting, at least kMinShaftElements.
  int ShaftElements() const { return std::max(kMinShaftElements, project_.settings.shaft_elements); }
  std::string Name(const std::string& base) { return ids_.Add(base); }
  void Add(std::string cls, std::string name, std::vector<Modifier> mods, std::string comment) {
    writer_.AddInstance({std::move(cls), std::move(name), std::move(mods), std::move(comment)});
  }
  void Map(const Component& c, const std::string& port, const std::string& ref) { ports_[{c.id, port}] = ref; }
  std::string TableModifier(const std::string& name, const std::vector<std::vector<double>>& rows,
                            std::vector<Modifier>& mods);

  double SpeedFactorFromPdu(const std::string& id) const {
    auto it = speed_factor_.find(id);
    return it == speed_factor_.end() ? 1.0 : it->second;
  }
  void ComputeSpeedFactors();

  const Project& project_;
  const ModelicaExportOptions& options_;
  std::string model_name_;
  IdentifierMap ids_;
  ModelWriter writer_;
  PortMap ports_;
  const Scenario* scenario_ = nullptr;
  const LoadCase* load_case_ = nullptr;
  const Component* pdu_ = nullptr;
  std::string pdu_instance_;
  std::string speed_table_;                  // instance of the PDU speed command table
  std::string pdu_stop_;                     // hydraulic PDU: the BooleanToReal of its shutdown input
  std::map<std::string, double> speed_factor_;  // component id -> speed / PDU speed
  std::vector<const Component*> wtbs_;
  std::vector<std::string> wtb_instances_;
  std::vector<std::pair<const Component*, std::string>> sensors_;  // APPU components, inertia instance
  std::vector<GeneratedFile> extra_files_;
  std::ostringstream table_file_;
  std::vector<std::string> lumping_notes_;
  double direction_ = 1.0;  // +1 extend, -1 retract
};

std::vector<Modifier> DriveSystemWriter::Stribeck(const Component& c) const {
  std::vector<Modifier> mods;
  for (const auto& [param, symbol] : std::vector<std::pair<std::string, std::string>>{
           {"coulomb_torque", "tau_C"}, {"viscous_coefficient", "d_vis"}, {"stribeck_torque", "tau_S"},
           {"stribeck_decay", "f_exp"}}) {
    if (auto v = Value(c, param)) mods.push_back({symbol, Real(*v, c, param), {}});
  }
  return mods;
}

std::string DriveSystemWriter::TableModifier(const std::string& name,
                                             const std::vector<std::vector<double>>& rows,
                                             std::vector<Modifier>& mods) {
  if (options_.tables_in_file) {
    table_file_ << "double " << name << "(" << rows.size() << "," << (rows.empty() ? 0 : rows[0].size()) << ")\n";
    for (const auto& row : rows) {
      for (std::size_t i = 0; i < row.size(); ++i) table_file_ << (i ? " " : "") << FormatModelicaReal(row[i], name);
      table_file_ << "\n";
    }
    mods.push_back({"tableOnFile", "true", {}});
    mods.push_back({"tableName", "\"" + EscapeModelicaString(name) + "\"", {}});
    mods.push_back({"fileName", "Modelica.Utilities.Files.loadResource(\"modelica://" + model_name_ + "/" +
                                    model_name_ + ".txt\")", {}});
  } else {
    mods.push_back({"table", FormatMatrix(rows, "table " + name), {}});
  }
  return name;
}

// The hydraulic PDU: the parts of sim/src/hydraulic_pdu.cc (AddHydraulicPdu) as instances of
// HighLift.Hydraulics and the MSL, with the same values and connections (with the shutdown
// input when the project has wing-tip brakes, as AddHydraulicPdu's with_stop).
void DriveSystemWriter::EmitHydraulicPdu(const Component& c) {
  auto value = [&](const std::string& param) {
    if (auto v = Value(c, param)) return *v;
    const ComponentTypeSpec* spec = FindComponentType("pdu");
    const ParameterSpec* p = spec ? spec->FindParameter(param) : nullptr;
    if (p && p->nominal) return *p->nominal;
    return RequireValue(c, param);  // throws naming the parameter
  };
  auto real = [&](double v, const std::string& param) { return Real(v, c, param); };
  const int n_m = static_cast<int>(ValueOr(c, "motor_count", 2));
  if (n_m != 1 && n_m != 2)
    throw InputError("component '" + c.id + "' (pdu): parameter 'motor_count' = " + std::to_string(n_m) +
                         "; the hydraulic drive sums 1 or 2 motors (one differential); use 1 or 2",
                     c.where);
  const double ratio = value("ratio"), p_s = value("supply_pressure"), p_r = value("return_pressure");
  const double eta_m = value("motor_mechanical_efficiency") * value("efficiency");
  const double D_max = Value(c, "motor_displacement")
                           ? *Value(c, "motor_displacement")
                           : value("stall_torque") / (n_m * ratio * eta_m * (p_s - p_r));
  const double s_max = value("cylinder_stroke");
  const std::string supply = Name(c.id + "_supply"), tank = Name(c.id + "_tank");
  const std::string line = Name(c.id + "_supply_line"), volume = Name(c.id + "_supply_volume");
  Add("HighLift.Hydraulics.PressureSource", supply, {{"p_supply", real(p_s, "supply_pressure"), {}}}, "hydraulic supply");
  Add("HighLift.Hydraulics.Tank", tank, {{"p_return", real(p_r, "return_pressure"), {}}}, "return line");
  Add("HighLift.Hydraulics.TurbulentResistance", line, {{"A", real(value("supply_line_area"), "supply_line_area"), {}}},
      "supply line and filters");
  Add("HighLift.Hydraulics.Volume", volume,
      {{"V", real(value("supply_volume"), "supply_volume"), {}}, {"p_start", real(p_s, "supply_pressure"), {}}},
      "oil volume of the supply line");
  writer_.AddConnect(supply + ".port", line + ".port_a");
  writer_.AddConnect(line + ".port_b", volume + ".port");
  const std::string w_ref = Name(c.id + "_w_ref");
  Add("Modelica.Blocks.Math.Gain", w_ref, {{"k", "1", {}}}, "PDU output speed command to the motors");
  std::optional<double> t_lost;
  if (scenario_)
    if (auto it = scenario_->values.find("motor_lost_time"); it != scenario_->values.end()) t_lost = it->second;
  // Operation of each motor: "active" 1 while it runs; its pressure-off brake is commanded
  // 1 - active. The shutdown input (the wing-tip brake command, Boolean, as a 0/1 signal)
  // takes every motor out of operation; the lost motor also stops at motor_lost_time.
  const bool with_stop = PduShutdownConnected();
  std::string one, running;  // the constant 1; 1 - stop, when the PDU has a shutdown input
  if (with_stop || t_lost) {
    one = Name(c.id + "_one");
    Add("Modelica.Blocks.Sources.Constant", one, {{"k", "1", {}}}, "");
  }
  if (with_stop) {
    pdu_stop_ = Name(c.id + "_stop");
    const std::string sum = Name(c.id + "_running");
    Add("Modelica.Blocks.Math.BooleanToReal", pdu_stop_, {},
        "shutdown command (the wing-tip brake command) as a 0/1 signal");
    Add("Modelica.Blocks.Math.Add", sum, {{"k1", "1", {}}, {"k2", "-1", {}}}, "motors in operation: 1 - stop");
    writer_.AddConnect(one + ".y", sum + ".u1");
    writer_.AddConnect(pdu_stop_ + ".y", sum + ".u2");
    running = sum + ".y";
  }
  std::vector<std::string> rotors;
  for (int k = 1; k <= n_m; ++k) {
    const std::string n = std::to_string(k);
    const std::string valve = Name(c.id + "_valve" + n), cylinder = Name(c.id + "_cylinder" + n);
    const std::string rod = Name(c.id + "_rod" + n), control = Name(c.id + "_control" + n);
    const std::string motor = Name(c.id + "_motor" + n), rotor = Name(c.id + "_rotor" + n);
    Add("HighLift.Hydraulics.ServoValve", valve,
        {{"A_max", real(value("valve_area"), "valve_area"), {}},
         {"T_v", real(value("valve_time_constant"), "valve_time_constant"), {}}},
        "servo valve of the displacement cylinder of motor " + n);
    Add("HighLift.Hydraulics.DifferentialCylinder", cylinder,
        {{"A_A", real(value("cylinder_area"), "cylinder_area"), {}},
         {"A_B", real(value("cylinder_annulus_area"), "cylinder_annulus_area"), {}},
         {"s_max", real(s_max, "cylinder_stroke"), {}},
         {"V0_A", real(value("cylinder_dead_volume"), "cylinder_dead_volume"), {}},
         {"V0_B", real(value("cylinder_dead_volume"), "cylinder_dead_volume"), {}},
         {"d", real(value("cylinder_damping"), "cylinder_damping"), {}},
         {"s_start", real(0.5 * s_max, "cylinder_stroke"), {}}},
        "displacement cylinder of motor " + n + " (mid-stroke: zero displacement)");
    Add("Modelica.Mechanics.Translational.Components.Mass", rod, {{"m", real(value("cylinder_mass"), "cylinder_mass"), {}}},
        "piston, rod and swash plate of motor " + n);
    Add("HighLift.Hydraulics.MotorSpeedControl", control,
        {{"ratio", real(ratio, "ratio"), {}},
         {"k_w", real(value("speed_gain"), "speed_gain"), {}},
         {"T_i", real(value("speed_integral_time"), "speed_integral_time"), {}},
         {"k_s", real(value("position_gain"), "position_gain"), {}},
         {"s_max", real(s_max, "cylinder_stroke"), {}}},
        "speed loop of motor " + n);
    Add("HighLift.Hydraulics.VariableDisplacementMotor", motor,
        {{"D_max", real(D_max, "motor_displacement"), {}},
         {"G_leak", real(value("motor_leakage"), "motor_leakage"), {}},
         {"eta_m", real(eta_m, "motor_mechanical_efficiency"), {}}},
        "variable-displacement motor " + n + " (eta_m includes the PDU gearbox efficiency)");
    Add("Modelica.Mechanics.Rotational.Components.Inertia", rotor, {{"J", real(value("motor_inertia"), "motor_inertia"), {}}},
        "rotor of motor " + n);
    const bool lost = t_lost && k == n_m;
    std::string active = running;  // the signal "motor k in operation" (empty: always)
    if (lost) {
      const std::string step = Name(c.id + "_motor_lost");
      Add("Modelica.Blocks.Sources.Step", step,
          {{"height", "-1", {}}, {"offset", "1", {}}, {"startTime", FormatModelicaReal(*t_lost, "motor_lost_time"), {}}},
          "motor " + n + " lost");
      active = step + ".y";
      if (!running.empty()) {
        const std::string product = Name(c.id + "_active" + n);
        Add("Modelica.Blocks.Math.Product", product, {}, "motor " + n + " in operation");
        writer_.AddConnect(running, product + ".u1");
        writer_.AddConnect(active, product + ".u2");
        active = product + ".y";
      }
    }
    if (active.empty()) {
      // Always in operation (the simulator leaves the input open, which reads 1 there).
      const std::string constant = Name(c.id + "_active" + n);
      Add("Modelica.Blocks.Sources.Constant", constant, {{"k", "1", {}}}, "motor " + n + " in operation");
      writer_.AddConnect(constant + ".y", control + ".active");
    } else {
      writer_.AddConnect(active, control + ".active");
      const std::string command = Name(c.id + "_pob_command" + n), pob = Name(c.id + "_pob" + n);
      Add("Modelica.Blocks.Math.Add", command, {{"k1", "1", {}}, {"k2", "-1", {}}},
          "pressure-off brake of motor " + n + ": applied when the motor is out of operation");
      writer_.AddConnect(one + ".y", command + ".u1");
      writer_.AddConnect(active, command + ".u2");
      // Brake: tau = cgeo*mu*fn_max*f_normalized with mu = 0.5: the POB torque at the motor.
      Add("Modelica.Mechanics.Rotational.Components.Brake", pob,
          {{"fn_max", real(2.0 * value("brake_torque") / ratio, "brake_torque"), {}},
           {"mu_pos", "[0, 0.5]", {}}},
          "pressure-off brake of motor " + n + " (brake_torque at the output)");
      writer_.AddConnect(command + ".y", pob + ".f_normalized");
      writer_.AddConnect(rotor + ".flange_b", pob + ".flange_a");
    }
    writer_.AddConnect(valve + ".port_P", volume + ".port");
    writer_.AddConnect(valve + ".port_T", tank + ".port");
    writer_.AddConnect(valve + ".port_A", cylinder + ".port_A");
    writer_.AddConnect(valve + ".port_B", cylinder + ".port_B");
    writer_.AddConnect(cylinder + ".flange", rod + ".flange_a");
    writer_.AddConnect(w_ref + ".y", control + ".w_ref");
    writer_.AddConnect(rotor + ".flange_a", control + ".flange_m");
    writer_.AddConnect(rod + ".flange_b", control + ".flange_s");
    writer_.AddConnect(control + ".u", valve + ".u");
    writer_.AddConnect(control + ".eps", motor + ".eps");
    writer_.AddConnect(motor + ".port_A", volume + ".port");
    writer_.AddConnect(motor + ".port_B", tank + ".port");
    writer_.AddConnect(motor + ".flange", rotor + ".flange_a");
    rotors.push_back(rotor);
  }
  const std::string gear = Name(c.id + "_gear"), output = Name(c.id + "_output");
  Add("Modelica.Mechanics.Rotational.Components.IdealGear", gear, {{"ratio", real(ratio, "ratio"), {}}}, "PDU gearbox");
  if (n_m == 2) {
    const std::string differential = Name(c.id + "_differential");
    Add("Modelica.Mechanics.Rotational.Components.IdealPlanetary", differential, {{"ratio", "1", {}}},
        "speed-summing differential");
    writer_.AddConnect(rotors[0] + ".flange_b", differential + ".sun");
    writer_.AddConnect(rotors[1] + ".flange_b", differential + ".ring");
    writer_.AddConnect(differential + ".carrier", gear + ".flange_a");
  } else {
    writer_.AddConnect(rotors[0] + ".flange_b", gear + ".flange_a");
  }
  Add("Modelica.Mechanics.Rotational.Components.Inertia", output, {{"J", real(value("gear_inertia"), "gear_inertia"), {}}},
      "differential and gears at the output");
  writer_.AddConnect(gear + ".flange_b", output + ".flange_a");
  const std::string angle = Name(c.id);
  pdu_instance_ = angle;  // <pdu>.phi feeds the monitoring
  Add("Modelica.Mechanics.Rotational.Sensors.AngleSensor", angle, {}, c.description + " (output angle)");
  writer_.AddConnect(output + ".flange_a", angle + ".flange");
  Map(c, "left", output + ".flange_b");
  Map(c, "right", output + ".flange_a");

  EmitSpeedCommand(c, w_ref + ".u");
}

void DriveSystemWriter::EmitPdu(const Component& c) {
  if (IsHydraulicPdu(c)) {
    EmitHydraulicPdu(c);
    return;
  }
  const std::string name = Name(c.id);
  pdu_instance_ = name;
  std::vector<Modifier> mods = {
      {"n_m", std::to_string(static_cast<int>(ValueOr(c, "motor_count", 2))), {}},
      {"J_m", Real(RequireValue(c, "motor_inertia"), c, "motor_inertia"), {}},
      {"ratio", Real(RequireValue(c, "ratio"), c, "ratio"), {}},
      {"J_g", Real(RequireValue(c, "gear_inertia"), c, "gear_inertia"), {}},
      {"w_max", Real(RequireValue(c, "max_output_speed"), c, "max_output_speed"), {}},
      {"tau_stall", Real(RequireValue(c, "stall_torque"), c, "stall_torque"), {}},
      {"P_max", Real(RequireValue(c, "power"), c, "power"), {}},
      {"t_ramp", Real(RequireValue(c, "speed_ramp_time"), c, "speed_ramp_time"), {}},
      {"tauPOB", Real(RequireValue(c, "brake_torque"), c, "brake_torque"), {}},
  };
  if (scenario_) {
    if (auto it = scenario_->values.find("motor_lost_time"); it != scenario_->values.end())
      mods.push_back({"t_motor_lost", FormatModelicaReal(it->second, "scenario value motor_lost_time"), {}});
  }
  if (PduShutdownConnected()) mods.push_back({"useStopInput", "true", {}});
  Add("HighLift.Drives.PDU", name, mods, c.description);
  Map(c, "left", name + ".flange_left");
  Map(c, "right", name + ".flange_right");

  EmitSpeedCommand(c, name + ".w_ref");
}

// The speed command: the load case's PDU speed profile, signed by the direction.
void DriveSystemWriter::EmitSpeedCommand(const Component& pdu, const std::string& w_ref) {
  speed_table_ = Name(pdu.id + "_speed");
  std::vector<Modifier> table_mods;
  TableModifier(speed_table_, SpeedCommandRows(load_case_), table_mods);
  table_mods.push_back({"extrapolation", "Modelica.Blocks.Types.Extrapolation.HoldLastPoint", {}});
  Add("Modelica.Blocks.Sources.CombiTimeTable", speed_table_, table_mods,
      "PDU output speed command [rad/s]" + std::string(load_case_ ? " of load case " + load_case_->name : ""));
  writer_.AddConnect(speed_table_ + ".y[1]", w_ref);
}

void DriveSystemWriter::EmitTorqueLimiter(const Component& c) {
  const std::string name = Name(c.id);
  const double tau1_ext = RequireValue(c, "lockout_torque_extend");
  const double tau1_ret = RequireValue(c, "lockout_torque_retract");
  const double tau2 = RequireValue(c, "end_stop_torque");
  if (!(tau2 > tau1_ext && tau2 > tau1_ret))
    throw InputError("component '" + c.id + "' (" + c.type + "): 'end_stop_torque' = " +
                         FormatModelicaReal(tau2) + " N*m must exceed both lock-out torques (" +
                         FormatModelicaReal(tau1_ext) + ", " + FormatModelicaReal(tau1_ret) +
                         " N*m): raise it or lower the lock-out torques",
                     c.where);
  // The retract end stop keeps the extend ratio tau2/tau1.
  const double tau2_ret = tau2 * tau1_ret / tau1_ext;
  Add("HighLift.Mechanical.TorqueLimiter", name,
      {{"tau1_ext", Real(tau1_ext, c, "lockout_torque_extend"), {}},
       {"tau1_ret", Real(tau1_ret, c, "lockout_torque_retract"), {}},
       {"tau2_ext", Real(tau2, c, "end_stop_torque"), {}},
       {"tau2_ret", Real(tau2_ret, c, "end_stop_torque"), {}},
       {"c1", Real(RequireValue(c, "stiffness_normal"), c, "stiffness_normal"), {}},
       // Structural damping of the balls and ramps.
       {"d", Real(Beta() * RequireValue(c, "stiffness_normal"), c, "stiffness_normal"), {}},
       {"c2", Real(RequireValue(c, "stiffness_lockout"), c, "stiffness_lockout"), {}},
       {"c3", Real(RequireValue(c, "stiffness_end_stop"), c, "stiffness_end_stop"), {}},
       {"tauB_max", Real(RequireValue(c, "max_brake_torque"), c, "max_brake_torque"), {}},
       {"J", Real(RequireValue(c, "inertia"), c, "inertia"), {}}},
      c.description);
  Map(c, "input", name + ".flange_a");
  Map(c, "output", name + ".flange_b");
}

void DriveSystemWriter::EmitShaftFull(const Component& c) {
  const TorqueShaftData data = ShaftData(c, Beta());
  const int n = ShaftElements();
  const bool ruptured = scenario_ && scenario_->rupture_component == c.id;
  const int broken = ruptured ? (n + 1) / 2 : 0;  // the spring replaced by a Disconnector
  std::vector<std::string> masses;
  for (int i = 0; i <= n; ++i) {
    const double share = (i == 0 || i == n) ? 0.5 / n : 1.0 / n;
    const std::string name = Name(c.id + "_mass" + std::to_string(i));
    std::vector<Modifier> mods = {{"J", Real(data.J * share, c, "inertia"), {}}};
    // The drag of the segment (its bearings and joints) acts at its two end masses, half at
    // each, as in the reduced model (interior masses without friction).
    if (data.drag > 0 && (i == 0 || i == n)) {
      mods.push_back({"tau_C", Real(data.drag * 0.5, c, "drag_per_length"), {}});
      Add("HighLift.Mechanical.LossyInertia", name, Regularised(mods), "");
    } else {
      Add("Modelica.Mechanics.Rotational.Components.Inertia", name, mods, "");
    }
    masses.push_back(name);
    if (i == 0) continue;
    const std::string spring = Name(c.id + "_spring" + std::to_string(i));
    std::vector<Modifier> smods = {{"c", Real(data.c * n, c, "stiffness"), {}},
                                   {"d", Real(data.d * n, c, "damping"), {}}};
    if (i == broken) {
      smods.push_back({"t_disconnect", FormatModelicaReal(*scenario_->rupture_time, "rupture time"), {}});
      Add("HighLift.Mechanical.Disconnector", spring, smods, "rupture of " + c.id);
    } else {
      Add("Modelica.Mechanics.Rotational.Components.SpringDamper", spring, smods, "");
    }
    writer_.AddConnect(masses[i - 1] + ".flange_b", spring + ".flange_a");
    writer_.AddConnect(spring + ".flange_b", name + ".flange_a");
  }
  Map(c, "a", masses.front() + ".flange_a");
  Map(c, "b", masses.back() + ".flange_b");
}

void DriveSystemWriter::EmitSteadyBearing(const Component& c) {
  const std::string name = Name(c.id);
  std::vector<Modifier> mods = {{"J", Real(RequireValue(c, "inertia"), c, "inertia"), {}}};
  for (auto& m : Stribeck(c)) mods.push_back(m);
  Add("HighLift.Mechanical.LossyInertia", name, Regularised(mods), c.description);
  Map(c, "a", name + ".flange_a");
  Map(c, "b", name + ".flange_b");
}

void DriveSystemWriter::EmitUniversalJoint(const Component& c) {
  const std::string name = Name(c.id);
  const auto c_joint = Value(c, "stiffness");
  const double b = ValueOr(c, "backlash", 0.0);
  if (b > 0 && !c_joint)
    throw InputError("component '" + c.id + "' (universal_joint): a backlash needs a stiffness: give 'stiffness'",
                     c.where);
  std::vector<Modifier> mods = {{"J", Real(RequireValue(c, "inertia"), c, "inertia"), {}},
                                {"eta_GE", Real(RequireValue(c, "efficiency"), c, "efficiency"), {}}};
  if (c_joint) {
    mods.insert(mods.begin(), {{"elastic", "true", {}},
                               {"c", Real(*c_joint, c, "stiffness"), {}},
                               {"d", Real(Beta() * *c_joint, c, "stiffness"), {}},
                               {"b", Real(b, c, "backlash"), {}}});
    mods.push_back({"ratio", "1", {}});
    Add("HighLift.Mechanical.GeneralRotationalElement", name, Regularised(mods), c.description);
  } else {
    Add("HighLift.Mechanical.LossyInertia", name, Regularised(mods), c.description);
  }
  Map(c, "a", name + ".flange_a");
  Map(c, "b", name + ".flange_b");
}

void DriveSystemWriter::EmitGearbox(const Component& c) {
  const std::string name = Name(c.id);
  const auto stiffness = Value(c, "stiffness");
  const double b = ValueOr(c, "backlash", 0.0);
  if (b > 0 && !stiffness)
    throw InputError("component '" + c.id + "' (" + c.type + "): a backlash needs a stiffness: give 'stiffness'",
                     c.where);
  const double eta = std::pow(RequireValue(c, "eta_mesh"), ValueOr(c, "meshes", 1.0));
  std::vector<Modifier> mods = {{"ratio", Real(RequireValue(c, "ratio"), c, "ratio"), {}},
                                {"elastic", stiffness ? "true" : "false", {}}};
  if (stiffness) {
    mods.push_back({"c", Real(*stiffness, c, "stiffness"), {}});
    mods.push_back({"d", Real(Beta() * *stiffness, c, "stiffness"), {}});
    mods.push_back({"b", Real(b, c, "backlash"), {}});
  }
  mods.push_back({"J", Real(RequireValue(c, "inertia"), c, "inertia"), {}});
  for (auto& m : Stribeck(c)) mods.push_back(m);
  mods.push_back({"eta_GE", Real(eta, c, "eta_mesh"), {}});
  mods = Regularised(std::move(mods));
  if (c.type == "branch_gearbox") {
    Add("HighLift.Mechanical.BranchGearbox", name, mods, c.description);
    Map(c, "input", name + ".flange_a");
    Map(c, "through", name + ".flange_b");
    Map(c, "branch", name + ".flange_branch");
  } else {
    Add("HighLift.Mechanical.GeneralRotationalElement", name, mods, c.description);
    Map(c, "input", name + ".flange_a");
    Map(c, "output", name + ".flange_b");
  }
}

void DriveSystemWriter::EmitActuator(const Component& c) {
  const std::string name = Name(c.id);
  const double ratio = RequireValue(c, "ratio");
  std::vector<Modifier> mods = {{"ratio", Real(ratio, c, "ratio"), {}},
                                {"eta_op", Real(RequireValue(c, "eta_opposing"), c, "eta_opposing"), {}},
                                {"eta_ai", Real(RequireValue(c, "eta_aiding"), c, "eta_aiding"), {}},
                                {"J_in", Real(RequireValue(c, "input_inertia"), c, "input_inertia"), {}}};
  if (auto J_load = Value(c, "load_inertia")) mods.push_back({"J_load", Real(*J_load, c, "load_inertia"), {}});
  if (auto phi = Value(c, "eta_settle_angle")) mods.push_back({"phi_eta", Real(*phi, c, "eta_settle_angle"), {}});
  if (auto w = Value(c, "eta_speed_threshold")) mods.push_back({"w_eta", Real(*w, c, "eta_speed_threshold"), {}});
  if (auto stiffness = Value(c, "stiffness")) {
    mods.push_back({"elastic", "true", {}});
    mods.push_back({"c", Real(*stiffness, c, "stiffness"), {}});
    mods.push_back({"d", Real(Beta() * *stiffness, c, "stiffness"), {}});
    mods.push_back({"b", Real(ValueOr(c, "backlash", 0.0), c, "backlash"), {}});
  } else if (ValueOr(c, "backlash", 0.0) > 0) {
    throw InputError("component '" + c.id + "' (" + c.type + "): a backlash needs a stiffness: give 'stiffness'",
                     c.where);
  }
  for (auto& m : Stribeck(c)) mods.push_back(m);
  Add("HighLift.Mechanical.GearedRotaryActuator", name, Regularised(mods), c.description);
  Map(c, "input", name + ".flange_a");

  // A jam of this actuator: its output is tied to the structure at the scenario's time.
  if (scenario_ && scenario_->jam_component == c.id) {
    const std::string jam = Name(c.id + "_jam");
    const double c_jam = kJamStiffness * ratio * ratio;
    Add("HighLift.Mechanical.Jam", jam,
        {{"c", FormatModelicaReal(c_jam), {}},
         {"d", FormatModelicaReal(Beta() * c_jam), {}},
         {"t_jam", FormatModelicaReal(*scenario_->jam_time, "jam time"), {}}},
        "jam of " + c.id + " (stiffness " + FormatModelicaReal(kJamStiffness) + " N*m/rad at the input)");
    writer_.AddConnect(name + ".flange_b", jam + ".flange");
  }
}

void DriveSystemWriter::EmitWingTipBrake(const Component& c) {
  const std::string name = Name(c.id);
  Add("HighLift.Mechanical.WingTipBrake", name,
      {{"tauB_max", Real(RequireValue(c, "max_dynamic_torque"), c, "max_dynamic_torque"), {}},
       {"tauB_lim", Real(RequireValue(c, "static_capacity"), c, "static_capacity"), {}},
       {"t_B", Real(RequireValue(c, "time_to_max_torque"), c, "time_to_max_torque"), {}},
       {"t_lat", Real(RequireValue(c, "engagement_latency"), c, "engagement_latency"), {}},
       {"J", Real(RequireValue(c, "inertia"), c, "inertia"), {}}},
      c.description);
  Map(c, "a", name + ".flange_a");
  Map(c, "b", name + ".flange_b");
  wtbs_.push_back(&c);
  wtb_instances_.push_back(name);
}

void DriveSystemWriter::EmitPositionSensor(const Component& c) {
  const std::string name = Name(c.id);
  Add("Modelica.Mechanics.Rotational.Components.Inertia", name,
      {{"J", Real(RequireValue(c, "inertia"), c, "inertia"), {}}}, c.description);
  Map(c, "a", name + ".flange_a");
  Map(c, "b", name + ".flange_b");
  auto role = c.texts.find("role");
  if (role == c.texts.end() || role->second != "fppu") sensors_.emplace_back(&c, name);
}

void DriveSystemWriter::EmitDisconnector(const Component& c) {
  const std::string name = Name(c.id);
  std::vector<Modifier> mods = {
      {"c", Real(ValueOr(c, "stiffness", kDefaultDisconnectorStiffness), c, "stiffness"), {}},
      {"d", FormatModelicaReal(kDefaultDisconnectorDamping), {}}};
  if (scenario_ && scenario_->rupture_component == c.id)
    mods.push_back({"t_disconnect", FormatModelicaReal(*scenario_->rupture_time, "rupture time"), {}});
  Add("HighLift.Mechanical.Disconnector", name, mods, c.description);
  Map(c, "a", name + ".flange_a");
  Map(c, "b", name + ".flange_b");
}

void DriveSystemWriter::EmitJam(const Component& c) {
  const std::string name = Name(c.id);
  std::vector<Modifier> mods = {{"c", Real(RequireValue(c, "stiffness"), c, "stiffness"), {}},
                                {"d", Real(Beta() * RequireValue(c, "stiffness"), c, "stiffness"), {}}};
  if (scenario_ && scenario_->jam_component == c.id)
    mods.push_back({"t_jam", FormatModelicaReal(*scenario_->jam_time, "jam time"), {}});
  Add("HighLift.Mechanical.Jam", name, mods, c.description);
  Map(c, "a", name + ".flange");
}

void DriveSystemWriter::EmitComponent(const Component& c) {
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
    throw InputError("component '" + c.id + "': type '" + t + "' has no Modelica model in the exporter",
                     c.where);
}

// Reduced resolution: maximal chains of shafts, bearings and joints between the lumping
// components become one spring-damper (series stiffness) with the chain's inertia and drag
// split between two end inertias; a chain without any elastic member is one rigid inertia.
void DriveSystemWriter::EmitChains() {
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
    std::vector<std::pair<const Component*, std::string>> members;  // component, entry port
    const Component* current = first;
    std::string in = entry;
    while (true) {
      members.emplace_back(current, in);
      done.insert(current->id);
      const std::string out = in == "a" ? "b" : "a";
      auto it = peer.find({current->id, out});
      if (it == peer.end()) break;
      const Component* next = project_.FindComponent(it->second.component);
      if (!next || !IsChainType(next->type) || done.count(next->id)) break;
      in = it->second.port;
      current = next;
    }
    // Series stiffness, total inertia and drag of the chain.
    double compliance = 0, J = 0, drag = 0, damping_compliance = 0;
    bool elastic = false, ruptured = false;
    std::string members_text;
    for (const auto& [m, port] : members) {
      members_text += (members_text.empty() ? "" : ", ") + m->id;
      if (scenario_ && scenario_->rupture_component == m->id) ruptured = true;
      if (m->type == "torque_shaft") {
        const TorqueShaftData d = ShaftData(*m, Beta());
        compliance += 1.0 / d.c;
        if (d.d > 0) damping_compliance += 1.0 / d.d;
        J += d.J;
        drag += d.drag;
        elastic = true;
      } else {
        J += RequireValue(*m, "inertia");
        drag += ValueOr(*m, "coulomb_torque", 0.0);
        if (auto c = Value(*m, "stiffness")) {
          compliance += 1.0 / *c;
          if (Beta() > 0) damping_compliance += 1.0 / (Beta() * *c);
          elastic = true;
        }
      }
    }
    const std::string base = members.size() == 1 ? first->id : first->id + "_" + members.back().first->id;
    lumping_notes_.push_back(base + ": " + members_text);
    auto mass = [&](const std::string& name, double share) {
      std::vector<Modifier> mods = {{"J", FormatModelicaReal(J * share, "inertia of " + base), {}}};
      if (drag > 0) {
        mods.push_back({"tau_C", FormatModelicaReal(drag * share, "drag of " + base), {}});
        Add("HighLift.Mechanical.LossyInertia", name, Regularised(mods), "lumped: " + members_text);
      } else {
        Add("Modelica.Mechanics.Rotational.Components.Inertia", name, mods, "lumped: " + members_text);
      }
    };
    std::string ref_a, ref_b;
    if (!elastic) {
      const std::string name = Name(base);
      mass(name, 1.0);
      ref_a = name + ".flange_a";
      ref_b = name + ".flange_b";
    } else {
      const std::string mass_a = Name(base + "_massA"), spring = Name(base), mass_b = Name(base + "_massB");
      mass(mass_a, 0.5);
      std::vector<Modifier> smods = {
          {"c", FormatModelicaReal(1.0 / compliance, "stiffness of " + base), {}},
          {"d", FormatModelicaReal(damping_compliance > 0 ? 1.0 / damping_compliance : 0.0), {}}};
      if (ruptured) {
        smods.push_back({"t_disconnect", FormatModelicaReal(*scenario_->rupture_time, "rupture time"), {}});
        Add("HighLift.Mechanical.Disconnector", spring, smods, "series stiffness of " + members_text + " (ruptures)");
      } else {
        Add("Modelica.Mechanics.Rotational.Components.SpringDamper", spring, smods,
            "series stiffness of " + members_text);
      }
      mass(mass_b, 0.5);
      writer_.AddConnect(mass_a + ".flange_b", spring + ".flange_a");
      writer_.AddConnect(spring + ".flange_b", mass_b + ".flange_a");
      ref_a = mass_a + ".flange_a";
      ref_b = mass_b + ".flange_b";
    }
    // The chain's end ports stand for the member ports at its ends.
    Map(*first, entry, ref_a);
    const auto& [last, last_in] = members.back();
    Map(*last, last_in == "a" ? "b" : "a", ref_b);
  }
}

// Actuator loads of the load case: a torque on each actuator output, from a table against time
// or against flap position (the output angle over the travel).
void DriveSystemWriter::EmitLoads() {
  if (!load_case_) return;
  for (const auto& [actuator_id, table] : load_case_->actuator_loads) {
    const Component* a = project_.FindComponent(actuator_id);
    if (!a || !IsActuator(a->type))
      throw InputError("load case '" + load_case_->name + "': actuator load for '" + actuator_id +
                           "', which is no actuator of the project: name a geared_rotary_actuator or "
                           "ballscrew_actuator",
                       load_case_->where);
    const std::string gra = ids_.Get(a->id);
    // Opposing loads act against the commanded motion: -load when extending.
    const double sign = -direction_;
    const std::string torque = Name(a->id + "_load");
    Add("Modelica.Mechanics.Rotational.Sources.Torque", torque, {},
        "airload on " + a->id + " (positive table values oppose the motion)");
    writer_.AddConnect(torque + ".flange", gra + ".flange_b");
    std::vector<std::vector<double>> rows;
    if (table.abscissa == "position") {
      double travel = 0;
      if (a->type == "geared_rotary_actuator") {
        travel = RequireValue(*a, "travel_angle");
      } else {
        const auto stroke = Value(*a, "stroke");
        if (!stroke)
          throw InputError("component '" + a->id + "' (ballscrew_actuator): a load against position "
                           "needs the 'stroke': give it",
                           a->where);
        travel = *stroke / RequireValue(*a, "lead");
      }
      // Position 0..1 of full travel -> output angle from the start of the motion. Retracting
      // from full travel the output angle runs from 0 down to -travel, so the keys
      // (x - 1)*travel of the positions x in increasing order are already increasing.
      for (std::size_t i = 0; i < table.x.size(); ++i)
        rows.push_back({direction_ > 0 ? table.x[i] * travel : (table.x[i] - 1) * travel, sign * table.y[i]});
      const std::string sensor = Name(a->id + "_angle");
      Add("Modelica.Mechanics.Rotational.Sensors.AngleSensor", sensor, {}, "output angle of " + a->id);
      writer_.AddConnect(gra + ".flange_b", sensor + ".flange");
      const std::string lookup = Name(a->id + "_loadTable");
      std::vector<Modifier> mods;
      TableModifier(lookup, rows, mods);
      mods.push_back({"extrapolation", "Modelica.Blocks.Types.Extrapolation.HoldLastPoint", {}});
      Add("Modelica.Blocks.Tables.CombiTable1Ds", lookup, mods,
          "airload [N*m] against the output angle of " + a->id + " [rad]");
      writer_.AddConnect(sensor + ".phi", lookup + ".u");
      writer_.AddConnect(lookup + ".y[1]", torque + ".tau");
    } else {
      for (std::size_t i = 0; i < table.x.size(); ++i) rows.push_back({table.x[i], sign * table.y[i]});
      const std::string lookup = Name(a->id + "_loadTable");
      std::vector<Modifier> mods;
      TableModifier(lookup, rows, mods);
      mods.push_back({"extrapolation", "Modelica.Blocks.Types.Extrapolation.HoldLastPoint", {}});
      Add("Modelica.Blocks.Sources.CombiTimeTable", lookup, mods, "airload [N*m] on " + a->id + " against time");
      writer_.AddConnect(lookup + ".y[1]", torque + ".tau");
    }
  }
}

// Speed of every component relative to the PDU output, through the gear ratios.
void DriveSystemWriter::ComputeSpeedFactors() {
  if (!pdu_) return;
  std::map<std::pair<std::string, std::string>, PortRef> peer;
  for (const auto& conn : project_.connections) {
    peer[{conn.a.component, conn.a.port}] = conn.b;
    peer[{conn.b.component, conn.b.port}] = conn.a;
  }
  std::deque<std::pair<const Component*, std::string>> queue;  // component, entry port
  speed_factor_[pdu_->id] = 1.0;
  for (const auto& port : {"left", "right"}) {
    auto it = peer.find({pdu_->id, port});
    if (it == peer.end()) continue;
    if (const Component* c = project_.FindComponent(it->second.component); c && !speed_factor_.count(c->id)) {
      speed_factor_[c->id] = 1.0;
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
      if (!next || speed_factor_.count(next->id)) continue;
      speed_factor_[next->id] = speed_factor_[c->id] * SpeedFactor(*c, entry, p.name);
      queue.emplace_back(next, it->second.port);
    }
  }
}

// The monitor: APPU angles and speeds at the tips (or the WTB rotors), the FPPU angle at the
// PDU and the commanded angle feed HighLift.Control.Monitoring, whose command applies the WTBs.
// With trigger "time" a BooleanStep applies them instead.
void DriveSystemWriter::EmitMonitoring() {
  if (wtbs_.empty()) return;
  if (scenario_ && scenario_->wtb_trigger == "time") {
    const std::string command = Name("wtbCommand");
    Add("Modelica.Blocks.Sources.BooleanStep", command,
        {{"startTime", FormatModelicaReal(scenario_->wtb_time.value_or(0.0), "wtb time"), {}}},
        "wing-tip brake command at the scenario's time");
    for (const auto& wtb : wtb_instances_) writer_.AddConnect(command + ".y", wtb + ".apply");
    ConnectShutdown(command + ".y");
    return;
  }
  if (!pdu_) return;  // no PDU angle to monitor: the WTBs stay released
  {
    const std::string command = Name("monitor");
    // Thresholds from the APPU, else the catalogue defaults of a position sensor.
    const Component* appu = sensors_.empty() ? nullptr : sensors_.front().first;
    auto sensor_value = [&](const std::string& name) {
      if (appu) return RequireValue(*appu, name);
      const ComponentTypeSpec* spec = FindComponentType("position_sensor");
      const ParameterSpec* p = spec ? spec->FindParameter(name) : nullptr;
      HIGHLIFT_CHECK(p && p->nominal, "catalogue: position_sensor." + name + " has no default");
      return *p->nominal;
    };
    const double w_max = RequireValue(*pdu_, "max_output_speed");
    Add("HighLift.Control.Monitoring", command,
        {{"phi_asym", FormatModelicaReal(sensor_value("asymmetry_threshold")), {}},
         {"w_over", FormatModelicaReal(sensor_value("overspeed_factor") * w_max), {}},
         {"phi_unc", FormatModelicaReal(sensor_value("asymmetry_threshold")), {}},
         {"t_detect", FormatModelicaReal(sensor_value("latency")), {}}},
        "failure monitoring: asymmetry, overspeed, uncommanded movement");
    // Tip signals: one per side, from the APPUs or else from the WTB rotors.
    std::vector<std::pair<std::string, std::string>> tips;  // (angle ref, speed ref)
    auto tip = [&](const Component& c, const std::string& flange) {
      const std::string angle = Name(c.id + "_phi"), speed = Name(c.id + "_w");
      Add("Modelica.Mechanics.Rotational.Sensors.AngleSensor", angle, {}, "shaft angle at " + c.id);
      Add("Modelica.Mechanics.Rotational.Sensors.SpeedSensor", speed, {}, "shaft speed at " + c.id);
      writer_.AddConnect(flange, angle + ".flange");
      writer_.AddConnect(flange, speed + ".flange");
      std::string angle_ref = angle + ".phi", speed_ref = speed + ".w";
      // Refer the tip signals to the PDU shaft through the gear ratios.
      const double k = 1.0 / SpeedFactorFromPdu(c.id);
      if (std::abs(k - 1.0) > 1e-12) {
        const std::string ga = Name(c.id + "_phiAtPdu"), gw = Name(c.id + "_wAtPdu");
        Add("Modelica.Blocks.Math.Gain", ga, {{"k", FormatModelicaReal(k), {}}}, "");
        Add("Modelica.Blocks.Math.Gain", gw, {{"k", FormatModelicaReal(k), {}}}, "");
        writer_.AddConnect(angle_ref, ga + ".u");
        writer_.AddConnect(speed_ref, gw + ".u");
        angle_ref = ga + ".y";
        speed_ref = gw + ".y";
      }
      tips.emplace_back(angle_ref, speed_ref);
    };
    if (!sensors_.empty()) {
      for (const auto& [c, inst] : sensors_) tip(*c, inst + ".flange_a");
    } else {
      for (std::size_t i = 0; i < wtbs_.size(); ++i) tip(*wtbs_[i], wtb_instances_[i] + ".flange_a");
    }
    // Left is the tip labelled "left" (else the first), right the other (else the same).
    std::size_t left = 0, right = tips.size() > 1 ? 1 : 0;
    const auto& tip_components = sensors_.empty() ? wtbs_ : [&] {
      std::vector<const Component*> v;
      for (const auto& s : sensors_) v.push_back(s.first);
      return v;
    }();
    for (std::size_t i = 0; i < tip_components.size() && i < tips.size(); ++i) {
      auto side = tip_components[i]->labels.find("side");
      if (side == tip_components[i]->labels.end()) continue;
      if (side->second == "left") left = i;
      if (side->second == "right") right = i;
    }
    writer_.AddConnect(tips[left].first, command + ".phi_left");
    writer_.AddConnect(tips[left].second, command + ".w_left");
    writer_.AddConnect(tips[right].first, command + ".phi_right");
    writer_.AddConnect(tips[right].second, command + ".w_right");
    writer_.AddConnect(pdu_instance_ + ".phi", command + ".phi_pdu");
    const std::string integrator = Name("commandedAngle");
    Add("Modelica.Blocks.Continuous.Integrator", integrator, {}, "commanded PDU angle");
    writer_.AddConnect(speed_table_ + ".y[1]", integrator + ".u");
    writer_.AddConnect(integrator + ".y", command + ".phi_cmd");
    for (const auto& wtb : wtb_instances_) writer_.AddConnect(command + ".wtb", wtb + ".apply");
    ConnectShutdown(command + ".wtb");
  }
}

// EmitMonitoring connects a brake command whenever the project has wing-tip brakes (the monitor
// needs the PDU angle, so with a PDU there is always one). The mechanical PDU takes it at its
// input `stop` (useStopInput), the hydraulic one at the BooleanToReal `<pdu>_stop`.
bool DriveSystemWriter::PduShutdownConnected() const {
  if (!pdu_) return false;
  return std::any_of(project_.components.begin(), project_.components.end(),
                     [](const Component& c) { return c.type == "wing_tip_brake"; });
}

void DriveSystemWriter::ConnectShutdown(const std::string& command) {
  if (!PduShutdownConnected()) return;
  writer_.AddConnect(command, IsHydraulicPdu(*pdu_) ? pdu_stop_ + ".u" : pdu_instance_ + ".stop");
}

ModelOutput DriveSystemWriter::Run() {
  scenario_ = SelectScenario(project_, options_);
  if (scenario_ && !scenario_->load_case.empty()) {
    load_case_ = project_.FindLoadCase(scenario_->load_case);
    if (!load_case_)
      throw InputError("scenario '" + scenario_->name + "': unknown load case '" + scenario_->load_case +
                           "': name one of the project's load cases",
                       scenario_->where);
  }
  if (load_case_ && load_case_->direction == "retract") direction_ = -1.0;
  if (scenario_ && scenario_->kind == "rupture" && scenario_->rupture_component) {
    const Component* r = project_.FindComponent(*scenario_->rupture_component);
    if (!r || (r->type != "torque_shaft" && r->type != "disconnector"))
      throw InputError("scenario '" + scenario_->name + "': rupture component '" + *scenario_->rupture_component +
                           "' must be a torque_shaft or a disconnector of the project",
                       scenario_->where);
    if (!scenario_->rupture_time)
      throw InputError("scenario '" + scenario_->name + "': the rupture has no time: give rupture.time",
                       scenario_->where);
  }
  if (scenario_ && scenario_->kind == "jam" && scenario_->jam_component) {
    const Component* j = project_.FindComponent(*scenario_->jam_component);
    if (!j || (j->type != "jam" && !IsActuator(j->type)))
      throw InputError("scenario '" + scenario_->name + "': jam component '" + *scenario_->jam_component +
                           "' must be a jam element or an actuator (geared_rotary_actuator, "
                           "ballscrew_actuator) of the project",
                       scenario_->where);
    if (!scenario_->jam_time)
      throw InputError("scenario '" + scenario_->name + "': the jam has no time: give jam.time", scenario_->where);
  }
  for (const auto& c : project_.components) {
    if (c.type == "pdu") {
      if (pdu_)
        throw InputError("component '" + c.id + "': a second pdu ('" + pdu_->id +
                             "' is the first): a drive system has one power drive unit",
                         c.where);
      pdu_ = &c;
    }
  }
  ComputeSpeedFactors();
  // Identifiers of the components first, so that they keep their names.
  for (const auto& c : project_.components)
    if (!(options_.resolution == ModelResolution::kReduced && IsChainType(c.type)) && c.type != "torque_shaft")
      ids_.Add(c.id);
  for (const auto& c : project_.components) {
    if (IsChainType(c.type) && options_.resolution == ModelResolution::kReduced) continue;
    EmitComponent(c);
  }
  if (options_.resolution == ModelResolution::kReduced) EmitChains();
  for (const auto& conn : project_.connections) {
    auto a = ports_.find({conn.a.component, conn.a.port});
    auto b = ports_.find({conn.b.component, conn.b.port});
    if (a == ports_.end() || b == ports_.end()) {
      // Inside a lumped chain (reduced resolution) there is nothing to connect.
      const Component* ca = project_.FindComponent(conn.a.component);
      const Component* cb = project_.FindComponent(conn.b.component);
      if (options_.resolution == ModelResolution::kReduced && ca && cb && IsChainType(ca->type) &&
          IsChainType(cb->type))
        continue;
      throw InputError("connection " + conn.a.ToString() + " - " + conn.b.ToString() +
                           ": unknown component or port; check it with 'highlift validate'",
                       conn.where);
    }
    writer_.AddConnect(a->second, b->second);
  }
  EmitLoads();
  EmitMonitoring();

  Experiment experiment;
  experiment.tolerance = project_.settings.relative_tolerance;
  experiment.interval = project_.settings.output_interval;
  if (scenario_ && scenario_->output_interval) experiment.interval = *scenario_->output_interval;
  experiment.stop_time = scenario_ ? scenario_->stop_time : 10.0;
  writer_.SetExperiment(experiment);
  writer_.SetDescription(project_.name);

  std::ostringstream doc;
  doc << "<html>\n<p>Drive system of the highlift project <strong>" << HtmlEscape(project_.name)
      << "</strong>, exported by <code>highlift export</code> at "
      << (options_.resolution == ModelResolution::kFull
              ? "full resolution (each torque shaft split into " + std::to_string(ShaftElements()) + " elements)"
              : std::string("reduced resolution (inertias lumped at gearboxes and stations)"))
      << ".</p>\n";
  if (!project_.description.empty()) doc << "<p>" << HtmlEscape(project_.description) << "</p>\n";
  if (scenario_) {
    doc << "<p>Scenario <strong>" << HtmlEscape(scenario_->name) << "</strong> (" << HtmlEscape(scenario_->kind) << ")";
    if (load_case_) doc << ", load case <strong>" << HtmlEscape(load_case_->name) << "</strong> (" << load_case_->direction << ")";
    doc << ".";
    if (!scenario_->description.empty()) doc << " " << HtmlEscape(scenario_->description);
    doc << "</p>\n";
  }
  doc << "<p>Positive rotation is the extend direction. The model starts at rest with untwisted springs "
         "(the simulator starts from the static equilibrium of the loads held by the parked brakes; "
         "see docs/modelica.md for the same start in a Modelica tool).</p>\n";
  if (!lumping_notes_.empty()) {
    doc << "<p>Lumped chains (spring-damper or inertia: members):</p>\n<ul>\n";
    for (const auto& n : lumping_notes_) doc << "<li>" << HtmlEscape(n) << "</li>\n";
    doc << "</ul>\n";
  }
  const auto renamed = ids_.Renamed();
  if (!renamed.empty()) {
    doc << "<p>Renamed to valid Modelica identifiers:</p>\n<ul>\n";
    for (const auto& [from, to] : renamed) doc << "<li>" << HtmlEscape(from) << " &rarr; " << to << "</li>\n";
    doc << "</ul>\n";
  }
  doc << "</html>";
  writer_.SetDocumentation(doc.str());

  ModelOutput out;
  out.text = writer_.Render();
  out.renamed = renamed;
  out.instances = writer_.instance_count();
  out.connects = writer_.connect_count();
  if (scenario_) out.scenario = scenario_->name;
  if (options_.tables_in_file)
    out.extra_files.push_back({model_name_ + ".txt", "#1\n" + table_file_.str()});
  return out;
}

}  // namespace

ModelOutput WriteDriveSystem(const Project& project, const std::string& model_name,
                             const ModelicaExportOptions& options) {
  DriveSystemWriter writer(project, model_name, options);
  return writer.Run();
}

}  // namespace highlift::modelica_detail
