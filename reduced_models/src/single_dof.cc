#include "highlift/reduced_models/single_dof.h"

#include <cmath>
#include <limits>

#include "highlift/core/error.h"
#include "highlift/reduced_models/modal.h"
#include "laws.h"

namespace highlift::reduced_models {

SingleDof ReduceToSingleDof(const LumpedModel& model, const std::vector<int>& stops) {
  ModalOptions options;
  options.clamped = stops;
  options.mode_shapes = 1;
  const ModalResult modes = ComputeModes(model, options);
  if (modes.omega.empty())
    throw InputError("the part of the transmission in focus has no inertia that can move: every component of it is "
                     "held rigidly by the stop (the jammed actuator or the wing-tip brake); a single-DOF peak needs an "
                     "inertia beyond a compliance (a shaft) from the stop");
  if (modes.rigid_body_modes > 0)
    throw InputError("part of the transmission in focus is not held by the stop (a rigid-body mode "
                     "remains); connect it to the stop or leave it out of the part in focus");
  std::vector<bool> is_stop(model.nodes.size(), false);
  for (int s : stops) is_stop[s] = true;
  SingleDof result;
  double participation = 0.0;
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    if (is_stop[i]) continue;
    result.J_star += model.nodes[i].J;
    participation += modes.shapes(static_cast<Eigen::Index>(i), 0) * model.nodes[i].J;
  }
  result.omega = modes.omega[0];
  result.c_star = result.J_star * result.omega * result.omega;
  result.first_mode_share = participation * participation / result.J_star;
  return result;
}

double PeakTorque(double w_max, const SingleDof& oscillator) {
  return detail::PeakTorque(w_max, oscillator.c_star, oscillator.J_star);
}

RuptureSpeed ComputeRuptureSpeed(const RuptureInput& in) {
  HIGHLIFT_CHECK(in.J > 0.0, "rupture: outboard inertia must be positive");
  RuptureSpeed r;
  r.alpha = std::max(0.0, (in.tau_aiding - in.tau_drag) / in.J);
  if (r.alpha == 0.0) {
    r.w_max = in.w0;
    return r;
  }
  double t_overspeed = std::numeric_limits<double>::infinity();
  if (in.w_reference > 0.0) t_overspeed = std::max(0.0, in.overspeed_factor * in.w_reference - in.w0) / r.alpha;
  double t_asymmetry = std::numeric_limits<double>::infinity();
  if (in.asymmetry_threshold > 0.0) t_asymmetry = std::sqrt(2.0 * in.asymmetry_threshold / r.alpha);
  if (!std::isfinite(t_overspeed) && !std::isfinite(t_asymmetry))
    throw InputError("rupture: no monitor trigger is defined (no overspeed reference speed and no "
                     "asymmetry threshold); give the position sensor an asymmetry_threshold or the PDU "
                     "a max_output_speed");
  r.trigger = t_overspeed <= t_asymmetry ? "overspeed" : "asymmetry";
  r.t_detect = std::min(t_overspeed, t_asymmetry);
  r.w_max = in.w0 + r.alpha * (r.t_detect + in.latency);
  return r;
}

}  // namespace highlift::reduced_models
