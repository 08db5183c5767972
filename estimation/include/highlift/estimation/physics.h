// Physics-based estimates of drive-system parameters. Each law is written once, templated on
// its scalar, so it serves double in the estimator and interval types in the propagator
// (anything with + - * / and, where noted, exp and log found by argument-dependent lookup).
// Everything is SI: lengths in m, torques in N*m, stiffness in N*m/rad, inertia in kg*m^2,
// moduli and stresses in Pa, densities in kg/m^3. Symbols as in the paper and the Modelica
// Standard Library: G shear modulus, D outer and d inner diameter, L length, rho density,
// J inertia, c stiffness, ratio = input speed / output speed.
#pragma once

#include <cmath>

namespace highlift::estimation {

namespace detail {
inline constexpr double kPi = 3.14159265358979323846;
}

/// Polar second moment of area of a tube, I_p = pi/32 (D^4 - d^4) [m^4].
/// D outer diameter [m], d inner diameter [m].
template <class T>
T TubePolarMoment(const T& D, const T& d) {
  return T(detail::kPi / 32.0) * (D * D * D * D - d * d * d * d);
}

/// Torsional stiffness of a tube, c = G I_p / L = G pi/32 (D^4 - d^4) / L [N*m/rad].
/// G shear modulus [Pa], D outer and d inner diameter [m], L length [m].
/// Example: Ti 50 x 2.0 mm (G = 44 GPa), L = 4 m: c = 1914 N*m/rad.
template <class T>
T ShaftStiffness(const T& G, const T& D, const T& d, const T& L) {
  return G * TubePolarMoment(D, d) / L;
}

/// Rotational inertia of a tube about its axis, J = rho I_p L [kg*m^2].
/// rho density [kg/m^3], D, d diameters [m], L length [m].
template <class T>
T ShaftInertia(const T& rho, const T& D, const T& d, const T& L) {
  return rho * TubePolarMoment(D, d) * L;
}

/// Mass per length of a tube, m_l = rho pi/4 (D^2 - d^2) [kg/m].
/// Example: Ti 50 x 2.0 mm, rho = 4420 kg/m^3: 1.33 kg/m.
template <class T>
T ShaftMassPerLength(const T& rho, const T& D, const T& d) {
  return rho * T(detail::kPi / 4.0) * (D * D - d * d);
}

/// Mass of a tube, m = rho pi/4 (D^2 - d^2) L [kg].
template <class T>
T ShaftMass(const T& rho, const T& D, const T& d, const T& L) {
  return ShaftMassPerLength(rho, D, d) * L;
}

/// Torque capacity of a tube at the allowable shear stress at its outer fibre,
/// tau_max = tau_allow I_p / (D/2) = tau_allow pi/16 (D^4 - d^4)/D [N*m].
/// tau_allow allowable shear stress [Pa]. Example: Ti 50 x 2.0 mm at 550 MPa: 3.83 kN*m.
template <class T>
T ShaftTorqueCapacity(const T& tau_allow, const T& D, const T& d) {
  return tau_allow * T(detail::kPi / 16.0) * (D * D * D * D - d * d * d * d) / D;
}

/// Inertia on the output side of a gear seen from its input, J_in = J_out / ratio^2 [kg*m^2]
/// (kinetic energy is conserved: J_in w_in^2 = J_out w_out^2, w_in = ratio w_out).
template <class T>
T InertiaAtInput(const T& J_out, const T& ratio) {
  return J_out / (ratio * ratio);
}

/// Inertia on the input side of a gear seen from its output, J_out = J_in ratio^2 [kg*m^2].
template <class T>
T InertiaAtOutput(const T& J_in, const T& ratio) {
  return J_in * ratio * ratio;
}

/// A flap panel moving along its track, seen as an inertia at the actuator input:
/// the panel of mass m [kg] travels a stroke s [m] while the actuator output turns through
/// phi_travel [rad], so its speed is v = (s/phi_travel) w_out and, with w_in = ratio w_out,
/// J = m (s / phi_travel)^2 / ratio^2 [kg*m^2]. Example: 1200 kg, 2.5 m over 2.2 rad,
/// station ratio 400: 9.7e-3 kg*m^2 at the shaft (domain.md s3).
template <class T>
T FlapInertiaAtInput(const T& m, const T& s, const T& phi_travel, const T& ratio) {
  const T lever = s / phi_travel;
  return m * lever * lever / (ratio * ratio);
}

/// Reference values of the gear scaling laws below (domain.md s3/s6, tag E).
struct GearScaling {
  /// Input inertia of a geared actuator or gearbox of input torque rating tau_in_ref [N*m].
  double inertia_reference = 1e-3;                 // kg*m^2, domain.md s6: GRA input J about 1e-3
  double inertia_floor = 3e-4;  // kg*m^2: input shaft, bearings and no-back brake of even a small unit
  double input_torque_reference = 20e3 / 200 / 0.85;  // N*m: 20 kN*m, 200:1, eta 0.85 (s3)
  /// Mass of a gearbox or actuator of output torque rating tau_out_ref.
  double mass_reference = 20.0;                    // kg, estimate for a 20 kN*m GRA (1 kN*m/kg)
  double output_torque_reference = 20e3;           // N*m
  double mass_exponent = 0.8;  // housing overhead makes mass grow slower than torque (volume ~ T)
};

/// Gearbox input inertia from its input torque rating: geometrically similar gears at equal
/// stress have volume ~ tau, radius ~ tau^(1/3), so their J ~ m r^2 ~ tau^(5/3); the input
/// shaft, bearings and brake add a floor J_0:
/// J_in = J_0 + (J_ref - J_0) (tau_in / tau_in_ref)^(5/3) [kg*m^2]. tau_in [N*m]. Uses exp, log.
/// With the defaults: 1e-3 kg*m^2 for a 20 kN*m, 200:1 GRA; 3.5e-4 for 6 kN*m, 300:1 (s4).
template <class T>
T GearboxInertiaFromTorque(const T& tau_in, const GearScaling& k = {}) {
  using std::exp;
  using std::log;
  return T(k.inertia_floor) + T(k.inertia_reference - k.inertia_floor) *
                                  exp(T(5.0 / 3.0) * log(tau_in / T(k.input_torque_reference)));
}

/// Gearbox or actuator mass from its output torque rating:
/// m = m_ref (tau_out / tau_out_ref)^0.8 [kg]. tau_out [N*m]. Uses exp and log.
template <class T>
T GearboxMassFromTorque(const T& tau_out, const GearScaling& k = {}) {
  using std::exp;
  using std::log;
  return T(k.mass_reference) * exp(T(k.mass_exponent) * log(tau_out / T(k.output_torque_reference)));
}

/// Geared actuator input inertia from its output torque rating tau_out [N*m], ratio and
/// efficiency eta: the input stage carries tau_in = tau_out / (ratio eta).
template <class T>
T ActuatorInputInertia(const T& tau_out, const T& ratio, const T& eta, const GearScaling& k = {}) {
  return GearboxInertiaFromTorque(tau_out / (ratio * eta), k);
}

/// PDU inertia at its output: n motors of rotor inertia J_m [kg*m^2] through the PDU ratio
/// (motor speed / output speed) plus the gears referred to the output J_g:
/// J = n J_m ratio^2 + J_g [kg*m^2]. Example: 2 x 3e-4 x 20^2 + 0.02 = 0.26 kg*m^2 (s3).
template <class T>
T PduOutputInertia(const T& J_m, const T& n, const T& ratio, const T& J_g) {
  return n * InertiaAtOutput(J_m, ratio) + J_g;
}

/// Drag of bearings and joints per length of shaft: tau_d = tau_each / spacing [N*m/m], with
/// tau_each the drag of one bearing [N*m] and spacing the distance between bearings [m].
/// Example: 0.1 N*m every 0.5 m: 0.2 N*m/m (domain.md s3: 0.2-0.3 N*m per metre).
template <class T>
T BearingDragPerLength(const T& tau_each, const T& spacing) {
  return tau_each / spacing;
}

}  // namespace highlift::estimation
