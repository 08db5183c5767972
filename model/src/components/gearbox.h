// The gearboxes (angle_gearbox.cc, branch_gearbox.cc): a gear stage of `meshes` meshes of
// efficiency eta_mesh, optional stiffness and backlash, Stribeck friction and inertia.
#pragma once

#include "component_util.h"
#include "declaration.h"
#include "gear_scaling.h"
#include "highlift/model/laws.h"

namespace highlift::model::components {

inline void AddGearbox(std::vector<ParameterSpec>& ps, const std::string& ratio_meaning, double ratio,
                double ratio_lo, double ratio_hi, const std::string& ratio_source, double J, const std::string& J_source) {
  ps.push_back(Param("ratio", "ratio", Dimensionless(), "1", ratio_meaning)
                   .Nominal(ratio)
                   .Default(ratio_lo, ratio_hi)
                   .Valid(0.01, 100)
                   .Source(ratio_source));
  ps.push_back(Efficiency("eta_mesh", "eta", 0.97, 0.96, 0.98, "efficiency per gear mesh",
                          "domain.md s6 (E): 0.96-0.98 per mesh"));
  ps.push_back(Param::Integer("meshes", "n_mesh", "number of gear meshes in the power path")
                   .Nominal(1)
                   .Valid(1, 10)
                   .Source("estimate: one bevel mesh"));
  // The input flange is on the transmission shaft (root gearbox, station down-drive).
  ps.push_back(Inertia(J, 0.5 * J, 2 * J, "inertia referred to the input", J_source, ReferenceSide::kShaft));
  ps.push_back(Backlash("total backlash referred to the input", ReferenceSide::kShaft));
  ps.push_back(OptionalStiffness("torsional stiffness referred to the input", ReferenceSide::kShaft));
  AddStribeck(ps, 0.1, 0.05, 0.2, "estimate: like a steady bearing, domain.md s6 (E) 0.05-0.2 N m", ReferenceSide::kShaft);
}

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

/// Steady state of a branch gearbox: the through shaft 1:1, the branch a gear stage (eta =
/// eta_mesh^meshes both ways), plus its Stribeck friction.
template <class T>
T BranchGearboxInputTorque(const ParameterReader<T>& p, const SteadyFlow<T>& in) {
  const T eta = MeshEfficiency(p);
  return in.through + GearInputTorque(in.branch, p("ratio"), eta, eta) + in.friction * StribeckOf(p, in.w);
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
