// Single-DOF reduction of the part of a transmission in focus, and the paper's equation (1).
//
// J* is the total (reflected) inertia of the moving part: everything that turns at the drive
// speed before the stop, so 1/2 J* w^2 is the whole kinetic energy that the stop must absorb.
// c* = J* w1^2, with w1 the first eigenfrequency of the part with the stop clamped, so the
// oscillator has the part's first eigenfrequency (dynamic similarity, paper section 3). Then
//   tau_max = w_max sqrt(c* J*) = w_max w1 J*                                      (1)
// which is the energy balance of the oscillator. The share of J* that the first mode carries
// (its effective modal inertia, (phi1' M 1)^2 for a mass-normalised phi1) is reported: the
// closer to 1, the closer (1) is to the multi-DOF peak; below 1, (1) is conservative for the
// first mode because it puts all the kinetic energy into it.
#pragma once

#include <vector>

#include "highlift/reduced_models/lumped_model.h"

namespace highlift::reduced_models {

struct SingleDof {
  double J_star = 0.0;            ///< kg*m^2, total inertia of the moving part
  double c_star = 0.0;            ///< N*m/rad, J* w1^2
  double omega = 0.0;             ///< rad/s, first eigenfrequency of the part with the stop clamped
  double first_mode_share = 0.0;  ///< effective modal inertia of mode 1 / J*, in (0, 1]
};

/// Reduces `model` with `stops` clamped (a jammed station, an engaged brake). Every free node
/// must be held by a stop through springs: otherwise InputError (the part would run away).
SingleDof ReduceToSingleDof(const LumpedModel& model, const std::vector<int>& stops);

/// Equation (1): tau_max = w_max sqrt(c* J*) [N*m].
double PeakTorque(double w_max, const SingleDof& oscillator);

/// The speed reached by the back-driven outboard part after a shaft rupture when the wing-tip
/// brake engages. The part starts at w0 in the direction the airload aids, accelerates at
/// alpha = (tau_aiding - tau_drag) / J until the monitor trips, on overspeed
/// (w >= overspeed_factor * w_reference) or on asymmetry (0.5 alpha t^2 >= asymmetry_threshold,
/// the lag or lead against the still-driven side), whichever is first; then after the monitor
/// latency and the brake's engagement latency and half its rise time to full torque:
///   w_max = w0 + alpha (t_detect + t_latency)
/// w_max rises with w0, tau_aiding, the thresholds and the latencies and falls with tau_drag and
/// J, which gives interval enclosures from two evaluations.
struct RuptureInput {
  double w0 = 0.0;                   ///< rad/s, speed at the rupture
  double J = 0.0;                    ///< kg*m^2, inertia of the outboard part (reflected)
  double tau_aiding = 0.0;           ///< N*m, back-driving torque of the airload at the shaft (>= 0)
  double tau_drag = 0.0;             ///< N*m, friction of the outboard part at the shaft (>= 0)
  double w_reference = 0.0;          ///< rad/s, maximum shaft speed the overspeed refers to
  double overspeed_factor = 1.3;     ///< 1, overspeed trip at this multiple of w_reference
  double asymmetry_threshold = 0.0;  ///< rad of shaft rotation; 0 disables the asymmetry trigger
  double latency = 0.1;              ///< s, monitor + brake engagement latency + half the rise time
};
struct RuptureSpeed {
  double w_max = 0.0;                ///< rad/s
  double alpha = 0.0;                ///< rad/s^2, back-drive acceleration (0 when friction holds)
  double t_detect = 0.0;             ///< s, from the rupture to the trip
  const char* trigger = "none";      ///< "overspeed", "asymmetry" or "none" (friction holds)
};
RuptureSpeed ComputeRuptureSpeed(const RuptureInput& input);

}  // namespace highlift::reduced_models
