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

/// Critical shear stress of a thin-walled tube in torsion, elastic buckling [Pa], with G the
/// shear modulus [Pa], nu Poisson's ratio, gamma the imperfection knock-down (correlation factor),
/// D, t, L [m]. E = 2 G (1 + nu), r = (D - t)/2 the mean radius:
///   long tube (length independent):  tau_long = gamma sqrt(2)/6 E (t/r)^(3/2) / (1 - nu^2)^(3/4)
///   moderate length:                 tau_mod  = 0.747 gamma^(3/4) E (t/r)^(5/4) (r/L)^(1/2) / (1 - nu^2)^(5/8)
/// and the larger of the two (tau_mod falls as L^(-1/2) toward tau_long, which it meets near
/// SP-8007's regime boundary Z = 78 (r/t)^2 (1 - nu^2), Z = L^2/(r t) (1 - nu^2)^(1/2)).
/// Sources: NASA SP-8007 (rev. 1968), "Buckling of thin-walled circular cylinders", s. 4.1.4
/// torsion: the moderate-length formula and the correlation factor gamma = 0.67; the long-tube
/// constant sqrt(2)/6 = 0.236 is the exact one of Timoshenko & Gere, Theory of Elastic Stability
/// (1961) s. 11.12 (Donnell's simplified shell equations give 0.272, 15 % higher; EN 1993-1-6
/// Annex D gives 0.25 E (t/r)^(3/2), the same for nu = 0.3, and 0.75 E (t/r)^(5/4) (r/L)^(1/2)
/// at moderate length). Elastic only: no plasticity reduction, so a thick tube (D/t below ~15)
/// gets a stress above the material's allowable, which then governs.
/// Example: Ti-6Al-4V (G 44 GPa, nu 0.33), gamma 0.67, 38 x 1.5 mm, L 1.4 m: 475 MPa (long).
/// Monotone: grows with G, nu (0 <= nu < 1), gamma, t (t < D) and falls with D and L; on
/// intervals every factor is enclosed from below and above (the natural extension is exact in
/// t / r = 2 t / (D - t)).
template <class T>
T TubeBucklingStress(const T& G, const T& nu, const T& gamma, const T& D, const T& t, const T& L) {
  using std::max;
  using std::sqrt;
  const T r = (D - t) * T(0.5);
  const T E = T(2.0) * G * (T(1.0) + nu);
  const T q = T(1.0) - nu * nu;         // 1 - nu^2
  const T q4 = sqrt(sqrt(q));           // (1 - nu^2)^(1/4)
  const T s = t / r;                    // t/r
  const T s4 = sqrt(sqrt(s));           // (t/r)^(1/4)
  const T tau_long = gamma * T(std::numbers::sqrt2 / 6.0) * E * s * sqrt(s) / (sqrt(q) * q4);
  const T tau_mod = T(0.747) * sqrt(gamma) * sqrt(sqrt(gamma)) * E * s * s4 * sqrt(r / L) / (sqrt(q) * sqrt(q4));
  return max(tau_long, tau_mod);
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

/// Torque capacity of a tube at the lesser of its allowable shear stress and its torsional
/// buckling stress (TubeBucklingStress) [N*m]: min(tau_allow, tau_cr) 2 Ip / D.
template <class T>
T TubeTorqueCapacityWithBuckling(const T& tau_allow, const T& tau_cr, const T& D, const T& Ip) {
  using std::min;
  return TubeTorqueCapacity(min(tau_allow, tau_cr), D, Ip);
}

/// Shear stress at the surface of a tube carrying torque tau [Pa]: tau D / (2 Ip).
template <class T>
T TubeShearStress(const T& tau, const T& D, const T& Ip) {
  return tau * D / (T(2.0) * Ip);
}

/// Efficiency of a gear train of `meshes` equal meshes of efficiency eta_mesh: eta = eta_mesh^n.
inline double GearTrainEfficiency(double eta_mesh, double meshes) { return std::pow(eta_mesh, meshes); }

}  // namespace highlift::model
