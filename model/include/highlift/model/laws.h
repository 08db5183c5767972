// Physical laws of the component types that more than one analysis evaluates, each written once
// and templated on its scalar: double (simulation, sizing at nominal values), the interval of the
// enclosures (interval.h) and the symbolic scalar of the constraint propagator (symbolic.h). A
// law uses only +, -, *, /, exp, BySign and construction from a double, so any scalar with those
// operations serves.
// Symbols as in the paper and the Modelica Standard Library; SI units throughout.
#pragma once

#include <cmath>
#include <numbers>

#include "highlift/model/interval.h"
#include "highlift/model/symbolic.h"

namespace highlift::model {

/// Polar second moment of area of a tube [m^4]: Ip = pi/32 (D^4 - d^4) with d = D - 2 t,
/// factored as pi/8 (D^2 + d^2)(D - t) t so every factor is positive (tighter intervals).
template <class T>
T TubePolarMoment(const T& D, const T& t) {
  const T d = D - T(2.0) * t;
  return T(std::numbers::pi / 8.0) * (D * D + d * d) * (D - t) * t;
}

/// Torsional stiffness of a tube [N*m/rad]: c = G Ip / L.
template <class T>
T ShaftStiffness(const T& G, const T& D, const T& t, const T& L) {
  return G * TubePolarMoment(D, t) / L;
}

/// Polar mass moment of inertia of a tube [kg*m^2]: J = rho Ip L.
template <class T>
T ShaftInertia(const T& rho, const T& D, const T& t, const T& L) {
  return rho * TubePolarMoment(D, t) * L;
}

/// Mass per length of a tube [kg/m]: m_l = rho pi/4 (D^2 - d^2) = rho pi (D - t) t.
/// Example: Ti 50 x 2.0 mm, rho = 4420 kg/m^3: 1.33 kg/m.
template <class T>
T ShaftMassPerLength(const T& rho, const T& D, const T& t) {
  return rho * T(std::numbers::pi) * (D - t) * t;
}

/// Mass of a tube [kg]: m = rho pi (D - t) t L.
template <class T>
T ShaftMass(const T& rho, const T& D, const T& t, const T& L) {
  return ShaftMassPerLength(rho, D, t) * L;
}

/// Torque capacity of a tube at the allowable shear stress tau_allow [Pa] at its outer fibre
/// [N*m]: tau = tau_allow Ip / (D/2). Example: Ti 50 x 2.0 mm at 550 MPa: 3.83 kN*m.
template <class T>
T ShaftTorqueCapacity(const T& tau_allow, const T& D, const T& t) {
  return tau_allow * TubePolarMoment(D, t) / (D * T(0.5));
}

/// Stribeck friction, the paper's equation (3), at speed magnitude w_abs >= 0 [rad/s]:
/// tau = tau_Coulomb + d_vis w + tau_Stribeck exp(-f_exp w)  [N*m]; opposes the motion.
template <class T>
T StribeckTorque(const T& tau_Coulomb, const T& d_vis, const T& tau_Stribeck, const T& f_exp, const T& w_abs) {
  using std::exp;
  return tau_Coulomb + d_vis * w_abs + tau_Stribeck * exp(-(f_exp * w_abs));
}

/// Input torque of a gear stage carrying output torque tau_out (positive = opposing the motion,
/// power flows input -> output) with ratio = w_in / w_out:
///   opposing (tau_out >= 0): tau_in = tau_out / (ratio eta_opposing)
///   aiding   (tau_out <  0): tau_in = tau_out eta_aiding / ratio
/// The load-dependent loss is the paper's equation (4) expressed as an efficiency.
template <class T>
T GearInputTorque(const T& tau_out, const T& ratio, const T& eta_opposing, const T& eta_aiding) {
  return BySign(
      tau_out, [&](const T& x) { return x / (ratio * eta_opposing); },
      [&](const T& x) { return x * eta_aiding / ratio; }, "GearInputTorque");
}

/// Torque capacity of a tube at its allowable shear stress [N*m]: tau = tau_allow 2 Ip / D, with
/// Ip its polar moment (TubePolarMoment).
template <class T>
T TubeTorqueCapacity(const T& tau_allow, const T& D, const T& Ip) {
  return tau_allow * T(2.0) * Ip / D;
}

/// Shear stress at the surface of a tube carrying torque tau [Pa]: tau D / (2 Ip).
template <class T>
T TubeShearStress(const T& tau, const T& D, const T& Ip) {
  return tau * D / (T(2.0) * Ip);
}

/// Efficiency of a gear train of `meshes` equal meshes of efficiency eta_mesh: eta = eta_mesh^n.
inline double GearTrainEfficiency(double eta_mesh, double meshes) { return std::pow(eta_mesh, meshes); }

}  // namespace highlift::model
