// The gearboxes (angle_gearbox.cc, branch_gearbox.cc): a gear stage of `meshes` meshes of
// efficiency eta_mesh, optional stiffness and backlash, Stribeck friction and inertia.
#pragma once

#include "component_util.h"
#include "gear_scaling.h"
#include "highlift/model/laws.h"

namespace highlift::model::components {

/// The element parameters of a gearbox (GeneralRotationalElement / BranchGearbox).
inline Scalars GearboxScalars(const Component& c, ExpansionContext& x) {
  CheckBacklash(c);
  const auto stiffness = Value(c, "stiffness");
  Scalars s = x.Regularised(Stribeck(c));
  s["ratio"] = Require(c, "ratio");
  s["elastic"] = stiffness ? 1 : 0;
  if (stiffness) {
    s["c"] = *stiffness;
    s["d"] = x.beta() * *stiffness;
    s["b"] = ValueOr(c, "backlash", 0.0);
  }
  s["J"] = Require(c, "inertia");
  s["eta_GE"] = GearTrainEfficiency(Require(c, "eta_mesh"), ValueOr(c, "meshes", 1.0));
  return s;
}

/// The gearboxes' estimation law: the inertia by gear scaling at a torque rating (input side).
/// Dormant until the catalogue declares a parameter "torque_rating" for them: a law whose input
/// the type does not have does not apply.
inline std::vector<EstimationLaw> GearboxEstimationLaws() {
  return {EstimateParameter("inertia", {FromParameter("torque_rating")},
                            "physics: gear scaling J = 3e-4 + 7e-4 (tau_in / 117.6 N m)^(5/3) kg m2 (domain.md s6)",
                            [](const auto& v) { return GearboxInertiaFromTorque(v[0]); })};
}

}  // namespace highlift::model::components
