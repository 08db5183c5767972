// The hydraulic power drive unit as a sub-network of hydraulic and mechanical elements.
//
// A pdu component whose text parameter `drive` is "hydraulic" is built here into
// elements of the HighLift.Hydraulics family: a supply (PressureSource, Tank), per motor a
// ServoValve positioning a DifferentialCylinder that sets the displacement of a
// VariableDisplacementMotor, a speed loop on the commanded speed, the two motors summed by a
// differential and the PDU gearbox to the two transmission outputs.
#pragma once

#include <optional>
#include <string>

#include "highlift/core/project.h"
#include "highlift/model/component_model.h"
#include "highlift/model/network.h"

namespace highlift::model::detail {

/// The ports of an added hydraulic PDU, each "element.port" in the network it was added to.
struct PduPorts {
  std::string flange_left;   ///< output flange to the left transmission
  std::string flange_right;  ///< output flange to the right transmission
  std::string w_ref;         ///< signal input: commanded PDU output speed, rad/s
  std::string phi;           ///< signal output: PDU output angle, rad
  std::string w;             ///< signal output: PDU output speed, rad/s
  std::string stop;          ///< signal input: shutdown command (> 0.5), when requested
};

/// True when the pdu component asks for the hydraulic drive (text parameter `drive` =
/// "hydraulic"; absent or "speed_controlled" is the speed-controlled PDU). Throws InputError
/// naming the component for any other value.
bool IsHydraulicPdu(const Component& pdu);

/// Adds the elements of the hydraulic PDU of component `pdu` (ids "<pdu.id>.<part>") to `net`
/// and returns its ports. `motor_lost_time` (s; a scenario's value `motor_lost_time`): from
/// then on the last motor is lost (displacement commanded to 0, its pressure-off brake
/// applied); empty: every motor runs throughout. `with_stop`: the PDU gets the shutdown input
/// PduPorts::stop (> 0.5, latched by its source, the monitor's wing-tip brake command): every
/// motor's displacement is commanded to 0 and its pressure-off brake applied. Throws InputError
/// naming the component and parameter for invalid parameters.
PduPorts AddHydraulicPdu(Network& net, const Component& pdu,
                         std::optional<double> motor_lost_time = std::nullopt, bool with_stop = false);

}  // namespace highlift::model::detail

namespace highlift::model {

/// True when the PDU's stall torque follows from its motors: a hydraulic drive (`drive` =
/// "hydraulic") that gives `motor_displacement`. Then the simulated drive stalls at
/// HydraulicStallTorque, whatever the parameter `stall_torque` says, and every analysis reads
/// that law (PduStallTorque). Throws InputError for a `drive` that is no drive kind.
template <class T>
bool StallTorqueFromMotors(const Component& pdu, const ParameterReader<T>& p) {
  return detail::IsHydraulicPdu(pdu) && p.Has("motor_displacement");
}

/// The output torque of the hydraulic drive at stall: every motor at full displacement on the
/// supply pressure against the return pressure, through the PDU gear with the motors' and the
/// gearbox's efficiencies, n_m V_m (p_s - p_r) i eta_m eta (V_m per radian in SI;
/// docs/hydraulics.md). The sizing rule of AddHydraulicPdu is this law solved for V_m.
template <class T>
T HydraulicStallTorque(const T& n_m, const T& V_m, const T& p_s, const T& p_r, const T& ratio, const T& eta_m,
                       const T& eta) {
  return n_m * V_m * (p_s - p_r) * ratio * eta_m * eta;
}

/// The PDU's stall torque at its output as the jam analyses read it (the static torque the
/// drive puts into a jam, `peak`, `size`, `check`): the hydraulic law when StallTorqueFromMotors,
/// else the parameter `stall_torque`.
template <class T>
T PduStallTorque(const Component& pdu, const ParameterReader<T>& p) {
  if (!StallTorqueFromMotors(pdu, p)) return p("stall_torque");
  return HydraulicStallTorque<T>(T(p.Nominal("motor_count")), p("motor_displacement"), p("supply_pressure"),
                                 p("return_pressure"), p("ratio"), p("motor_mechanical_efficiency"), p("efficiency"));
}

/// True when PduStallTorque has every parameter it reads.
template <class T>
bool HasPduStallTorque(const Component& pdu, const ParameterReader<T>& p) {
  if (!StallTorqueFromMotors(pdu, p)) return p.Has("stall_torque");
  for (const char* name : {"motor_count", "supply_pressure", "return_pressure", "ratio", "motor_mechanical_efficiency",
                           "efficiency"})
    if (!p.Has(name)) return false;
  return true;
}

}  // namespace highlift::model
