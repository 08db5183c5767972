// The gearboxes (angle_gearbox.cc, branch_gearbox.cc): a gear stage of `meshes` meshes of
// efficiency eta_mesh, optional stiffness and backlash, Stribeck friction and inertia.
#pragma once

#include "component_util.h"
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

}  // namespace highlift::model::components
