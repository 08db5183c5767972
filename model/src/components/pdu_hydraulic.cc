// The hydraulic power drive unit as a sub-network of hydraulic and mechanical elements
// (docs/hydraulics.md). Secondary control: the motors run on the constant supply pressure and
// the speed loop sets their displacement.
//
//   supply --supply_line-- supply_volume --+-- motor<k>.port_A      motor<k>.port_B -- tank
//                                          +-- valve<k>.port_P      valve<k>.port_T -- tank
//   valve<k>.port_A/B -- cylinder<k>.port_A/B; cylinder<k>.flange -- rod<k> (Mass)
//   control<k>: w_ref (from `ref`), motor speed (rotor<k>), rod position -> valve<k>.u, motor<k>.eps
//   rotor<k> -- differential (IdealPlanetary, ratio 1: sun motor 1, ring motor 2, carrier out)
//            -- gear (IdealGear, i_PDU) -- output (Inertia J_g) -- left and right transmissions
//
// One motor lost (the scenario value `motor_lost_time`, passed in by the drive network): the
// last motor's displacement is commanded to 0 and its pressure-off brake (Brake, holding
// brake_torque/(n_m*ratio) at the motor, brake_torque at the output) holds it; the differential
// then delivers half the speed of the remaining motor at the full torque.
#include "highlift/model/hydraulic_pdu.h"

#include <cmath>
#include <numbers>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/message_number.h"

namespace highlift::model::detail {
namespace {

std::string Where(const Component& pdu) { return "component '" + pdu.id + "' (pdu)"; }

/// The nominal value of a pdu parameter in SI: the component's, else the catalogue default.
/// Throws InputError naming the parameter when neither exists.
double Value(const Component& pdu, const std::string& name, const char* remedy = nullptr) {
  auto it = pdu.parameters.find(name);
  if (it != pdu.parameters.end() && it->second.nominal) return *it->second.nominal;
  const ComponentTypeSpec* spec = FindComponentType("pdu");
  const ParameterSpec* p = spec != nullptr ? spec->FindParameter(name) : nullptr;
  if (p != nullptr && p->nominal) return *p->nominal;
  throw InputError(Where(pdu) + ": the hydraulic drive needs parameter '" + name + "'; " +
                   (remedy != nullptr ? remedy : "give its value"));
}

bool Has(const Component& pdu, const std::string& name) {
  auto it = pdu.parameters.find(name);
  return it != pdu.parameters.end() && it->second.nominal.has_value();
}

}  // namespace

bool IsHydraulicPdu(const Component& pdu) {
  auto it = pdu.texts.find("drive");
  if (it == pdu.texts.end() || it->second == "speed_controlled") return false;
  if (it->second == "hydraulic") return true;
  throw InputError(Where(pdu) + ": parameter 'drive' = \"" + it->second +
                   "\" is not a drive kind; use \"speed_controlled\" or \"hydraulic\"");
}

PduPorts AddHydraulicPdu(Network& net, const Component& pdu, std::optional<double> motor_lost_time,
                         bool with_stop) {
  const std::string& id = pdu.id;
  auto part = [&](const std::string& name) { return id + "." + name; };
  auto port = [&](const std::string& name, const std::string& p) { return id + "." + name + "." + p; };

  const double motor_count = Value(pdu, "motor_count");
  if (motor_count != 1 && motor_count != 2)
    throw InputError(Where(pdu) + ": parameter 'motor_count' = " + std::to_string(static_cast<int>(motor_count)) +
                     "; the hydraulic drive sums 1 or 2 motors (one differential); use 1 or 2");
  const int n_m = static_cast<int>(motor_count);
  const double ratio = Value(pdu, "ratio");
  const double p_s = Value(pdu, "supply_pressure", "give the aircraft system pressure, e.g. 345 bar (A380) or 207 bar (A320)");
  const double p_r = Value(pdu, "return_pressure");
  if (!(p_s > p_r))
    throw InputError(Where(pdu) + ": parameter 'supply_pressure' = " + FormatMessageNumber(p_s * 1e-5) +
                     " bar must exceed 'return_pressure' = " + FormatMessageNumber(p_r * 1e-5) + " bar");
  const double eta_m = Value(pdu, "motor_mechanical_efficiency") * Value(pdu, "efficiency");
  if (!(eta_m > 0))
    throw InputError(Where(pdu) + ": parameters 'motor_mechanical_efficiency' and 'efficiency' must be > 0");
  // Displacement: given, or sized so that all motors at full displacement give the stall torque.
  double D_max = 0.0;
  if (Has(pdu, "motor_displacement")) {
    D_max = Value(pdu, "motor_displacement");  // SI: m^3 per radian (cm^3/rev converted)
  } else {
    D_max = Value(pdu, "stall_torque") / (n_m * ratio * eta_m * (p_s - p_r));
  }
  if (!(D_max > 0))
    throw InputError(Where(pdu) + ": parameter 'motor_displacement' must be > 0 (4-13 cm^3/rev)");
  const double s_max = Value(pdu, "cylinder_stroke");

  auto scalars = [](std::map<std::string, double> s) { return ElementParameters{std::move(s), {}}; };
  // Parts are "<pdu>.<part>": validated under a plain id in a scratch network, then adopted.
  auto add = [&](const std::string& type, const std::string& full_id, ElementParameters parameters,
                 std::string description = {}) {
    Network scratch;
    try {
      scratch.AddElement(type, "part", std::move(parameters));
    } catch (const InputError& error) {
      std::string message = error.what();
      const auto at = message.find("'part'");
      if (at != std::string::npos) message.replace(at, 6, "'" + full_id + "'");
      throw InputError(Where(pdu) + ": " + message);
    }
    NetworkElement e = scratch.elements().front();
    e.id = full_id;
    e.description = std::move(description);
    net.Adopt(e);
  };

  // Supply.
  add("PressureSource", part("supply"), scalars({{"p_supply", p_s}}), "hydraulic supply");
  add("Tank", part("tank"), scalars({{"p_return", p_r}}), "return line");
  add("TurbulentResistance", part("supply_line"), scalars({{"A", Value(pdu, "supply_line_area")}}),
      "supply line and filters");
  add("Volume", part("supply_volume"), scalars({{"V", Value(pdu, "supply_volume")}, {"p_start", p_s}}),
      "oil volume of the supply line");
  net.Connect(port("supply", "port"), port("supply_line", "port_a"));
  net.Connect(port("supply_line", "port_b"), port("supply_volume", "port"));
  // The speed command, fanned out to the motors' speed loops.
  add("Gain", part("w_ref"), scalars({{"k", 1.0}}), "PDU output speed command to the motors");

  if (motor_lost_time && !std::isfinite(*motor_lost_time))
    throw InputError(Where(pdu) + ": scenario value 'motor_lost_time' is not a finite time; give "
                     "the time in s at which the last motor is lost, or leave it out");
  const bool motor_lost = motor_lost_time.has_value();
  // Operation of each motor: "active" 1 while it runs; its pressure-off brake is commanded
  // 1 - active. The shutdown input (stop, > 0.5 from the monitor's wing-tip brake command)
  // takes every motor out of operation; the lost motor also stops at motor_lost_time.
  std::string running;  // 1 - stop, when the PDU has a shutdown input
  if (with_stop || motor_lost) add("Constant", part("one"), scalars({{"k", 1.0}}));
  if (with_stop) {
    add("Gain", part("stop"), scalars({{"k", 1.0}}),
        "shutdown command (the wing-tip brake command) as a 0/1 signal");
    add("Add", part("running"), scalars({{"k1", 1.0}, {"k2", -1.0}}), "motors in operation: 1 - stop");
    net.Connect(port("one", "y"), port("running", "u1"));
    net.Connect(port("stop", "y"), port("running", "u2"));
    running = port("running", "y");
  }
  for (int k = 1; k <= n_m; ++k) {
    const std::string n = std::to_string(k);
    add("ServoValve", part("valve" + n),
        scalars({{"A_max", Value(pdu, "valve_area")}, {"T_v", Value(pdu, "valve_time_constant")}}),
        "servo valve of the displacement cylinder of motor " + n);
    add("DifferentialCylinder", part("cylinder" + n),
                   scalars({{"A_A", Value(pdu, "cylinder_area")},
                            {"A_B", Value(pdu, "cylinder_annulus_area")},
                            {"s_max", s_max},
                            {"V0_A", Value(pdu, "cylinder_dead_volume")},
                            {"V0_B", Value(pdu, "cylinder_dead_volume")},
                            {"d", Value(pdu, "cylinder_damping")},
                            {"s_start", 0.5 * s_max}}),
        "displacement cylinder of motor " + n + " (mid-stroke: zero displacement)");
    add("Mass", part("rod" + n), scalars({{"m", Value(pdu, "cylinder_mass")}}),
        "piston, rod and swash plate of motor " + n);
    add("MotorSpeedControl", part("control" + n),
                   scalars({{"ratio", ratio},
                            {"k_w", Value(pdu, "speed_gain")},
                            {"T_i", Value(pdu, "speed_integral_time")},
                            {"k_s", Value(pdu, "position_gain")},
                            {"s_max", s_max}}),
        "speed loop of motor " + n);
    add("VariableDisplacementMotor", part("motor" + n),
        scalars({{"D_max", D_max}, {"G_leak", Value(pdu, "motor_leakage")}, {"eta_m", eta_m}}),
        "variable-displacement motor " + n + " (eta_m includes the PDU gearbox efficiency)");
    add("Inertia", part("rotor" + n), scalars({{"J", Value(pdu, "motor_inertia")}}), "rotor of motor " + n);

    net.Connect(port("valve" + n, "port_P"), port("supply_volume", "port"));
    net.Connect(port("valve" + n, "port_T"), port("tank", "port"));
    net.Connect(port("valve" + n, "port_A"), port("cylinder" + n, "port_A"));
    net.Connect(port("valve" + n, "port_B"), port("cylinder" + n, "port_B"));
    net.Connect(port("cylinder" + n, "flange"), port("rod" + n, "flange_a"));
    net.Connect(port("w_ref", "y"), port("control" + n, "w_ref"));
    net.Connect(port("rotor" + n, "flange_a"), port("control" + n, "flange_m"));
    net.Connect(port("rod" + n, "flange_b"), port("control" + n, "flange_s"));
    net.Connect(port("control" + n, "u"), port("valve" + n, "u"));
    net.Connect(port("control" + n, "eps"), port("motor" + n, "eps"));
    net.Connect(port("motor" + n, "port_A"), port("supply_volume", "port"));
    net.Connect(port("motor" + n, "port_B"), port("tank", "port"));
    net.Connect(port("motor" + n, "flange"), port("rotor" + n, "flange_a"));

    const bool lost = motor_lost && k == n_m;
    std::string active;  // the signal "motor k in operation", or none (always)
    if (lost) {
      add("Step", part("motor_lost"), scalars({{"height", -1.0}, {"offset", 1.0}, {"startTime", *motor_lost_time}}),
          "motor " + n + " lost");
      active = port("motor_lost", "y");
      if (!running.empty()) {
        add("Product", part("active" + n), {}, "motor " + n + " in operation");
        net.Connect(running, port("active" + n, "u1"));
        net.Connect(active, port("active" + n, "u2"));
        active = port("active" + n, "y");
      }
    } else {
      active = running;
    }
    if (!active.empty()) {
      net.Connect(active, port("control" + n, "active"));
      add("Add", part("pob_command" + n), scalars({{"k1", 1.0}, {"k2", -1.0}}),
          "pressure-off brake of motor " + n + ": applied when the motor is out of operation");
      net.Connect(port("one", "y"), port("pob_command" + n, "u1"));
      net.Connect(active, port("pob_command" + n, "u2"));
      // Brake: tau = cgeo*mu*fn_max*f_normalized with mu = 0.5. brake_torque is the holding
      // torque of the PDU at its output: each of the n_m brakes holds brake_torque/(n_m*ratio)
      // at its motor, since through the speed-summing differential each motor carries 1/n_m of
      // the gear input torque (the brakes together, or a lost motor's brake against the running
      // motor, hold brake_torque at the output).
      const double holding = Value(pdu, "brake_torque") / (n_m * ratio);
      add("Brake", part("pob" + n), {{{"fn_max", 2.0 * holding}, {"cgeo", 1.0}}, {{"mu_pos", {{0.0, 0.5}}}}},
          "pressure-off brake of motor " + n +
              " (brake_torque/(n_m*ratio) at the motor: the brakes hold brake_torque at the output)");
      net.Connect(port("pob_command" + n, "y"), port("pob" + n, "f_normalized"));
      net.Connect(port("rotor" + n, "flange_b"), port("pob" + n, "flange_a"));
    } else {
      // Always in operation: the input `active` reads 1 (a connected constant, so that the
      // network has every input connected, as a Modelica model must).
      add("Constant", part("active" + n), scalars({{"k", 1.0}}), "motor " + n + " in operation");
      net.Connect(port("active" + n, "y"), port("control" + n, "active"));
    }
  }
  // Differential and PDU gearbox. The gearbox efficiency is applied in the motors' eta_m.
  add("IdealGear", part("gear"), scalars({{"ratio", ratio}}), "PDU gearbox");
  if (n_m == 2) {
    add("IdealPlanetary", part("differential"), scalars({{"ratio", 1.0}}), "speed-summing differential");
    net.Connect(port("rotor1", "flange_b"), port("differential", "sun"));
    net.Connect(port("rotor2", "flange_b"), port("differential", "ring"));
    net.Connect(port("differential", "carrier"), port("gear", "flange_a"));
  } else {
    net.Connect(port("rotor1", "flange_b"), port("gear", "flange_a"));
  }
  add("Inertia", part("output"), scalars({{"J", Value(pdu, "gear_inertia")}}), "differential and gears at the output");
  net.Connect(port("gear", "flange_b"), port("output", "flange_a"));
  // Output angle and speed (the FPPU and the speed reported as "<pdu>.w").
  add("SpeedSensor", id, {}, pdu.description + " (output speed)");
  add("AngleSensor", part("angle"), {}, "output angle (FPPU)");
  net.Connect(port("output", "flange_a"), id + ".flange");
  net.Connect(port("output", "flange_a"), port("angle", "flange"));

  PduPorts ports;
  ports.flange_left = port("output", "flange_b");
  ports.flange_right = port("output", "flange_a");
  ports.w_ref = port("w_ref", "u");
  ports.phi = port("angle", "phi");
  ports.w = id + ".w";
  if (with_stop) ports.stop = port("stop", "u");
  return ports;
}

}  // namespace highlift::model::detail
