// Gear scaling (domain.md s3/s6, tag E): the inertia of a gear train estimated from the torque
// it is rated for, shared by the estimation laws of the geared actuator
// (geared_rotary_actuator.cc) and of the gearboxes (gearbox.h).
#pragma once

#include <cmath>

namespace highlift::model::components {

/// Reference values of the gear scaling law below.
struct GearScaling {
  double inertia_reference = 1e-3;  ///< kg*m^2, domain.md s6: GRA input J about 1e-3
  double inertia_floor = 3e-4;      ///< kg*m^2: input shaft, bearings and no-back brake of even a small unit
  double input_torque_reference = 20e3 / 200 / 0.85;  ///< N*m: 20 kN*m, 200:1, eta 0.85 (s3)
};

/// Gearbox input inertia from its input torque rating tau_in [N*m]: geometrically similar gears
/// at equal stress have volume ~ tau, radius ~ tau^(1/3), so their J ~ m r^2 ~ tau^(5/3); the
/// input shaft, bearings and brake add a floor J_0:
///   J_in = J_0 + (J_ref - J_0) (tau_in / tau_in_ref)^(5/3)  [kg*m^2].
/// With the defaults: 1e-3 kg*m^2 for a 20 kN*m, 200:1 GRA; 3.5e-4 for 6 kN*m, 300:1 (s4).
template <class T>
T GearboxInertiaFromTorque(const T& tau_in, const GearScaling& k = {}) {
  using std::exp;
  using std::log;
  return T(k.inertia_floor) +
         T(k.inertia_reference - k.inertia_floor) * exp(T(5.0 / 3.0) * log(tau_in / T(k.input_torque_reference)));
}

}  // namespace highlift::model::components
