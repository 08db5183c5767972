// The physical laws of the reduced models, each written once and templated on its scalar so the
// same body serves double (point values) and detail::Interval (guaranteed enclosures).
// Symbols as in the paper and the Modelica Standard Library; SI units throughout.
#pragma once

#include <cmath>
#include <numbers>

#include "highlift/model/laws.h"
#include "interval.h"

namespace highlift::reduced_models::detail {

using std::exp;
using std::sqrt;

// The tube, friction and gear laws are the component types', written once in the model layer
// (highlift/model/laws.h).
using model::GearInputTorque;
using model::ShaftInertia;
using model::ShaftMass;
using model::ShaftStiffness;
using model::StribeckTorque;
using model::TubePolarMoment;

/// Peak torque of a single-DOF oscillator J*, c* stopped suddenly from speed w_max, the paper's
/// equation (1): 1/2 J* w^2 = 1/2 tau^2 / c*  =>  tau_max = w_max sqrt(c* J*).
template <class T>
T PeakTorque(const T& w_max, const T& c_star, const T& J_star) {
  return w_max * sqrt(c_star * J_star);
}

}  // namespace highlift::reduced_models::detail
