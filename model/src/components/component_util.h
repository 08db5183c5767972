// Helpers shared by the component models: reading a component's parameter values in SI.
#pragma once

#include <limits>
#include <optional>
#include <string>

#include "highlift/core/error.h"
#include "highlift/model/component_model.h"
#include "highlift/model/laws.h"

namespace highlift::model::components {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The value of an optional parameter for the drive model: its nominal value, else the middle of
/// a domain the project gives (not a catalogue default), the rule of the reduced models
/// (reduced_models NominalValue) and of the reports, so that the simulation and `peak` read the
/// same value: an A320-class slat's load_inertia given only as [1e-4, 2e-3] kg*m^2 counts as
/// 1.05e-3 in both (it was 0 in the simulation, which then stopped the jammed actuator's input
/// alone). A required parameter still needs a value (Require).
inline std::optional<double> Value(const Component& c, const std::string& name) {
  auto it = c.parameters.find(name);
  if (it == c.parameters.end()) return std::nullopt;
  const Parameter& p = it->second;
  if (p.nominal) return p.nominal;
  if (p.provenance != Provenance::kDefault && p.domain.bounded() && !p.domain.empty()) return p.domain.mid();
  return std::nullopt;
}

inline double ValueOr(const Component& c, const std::string& name, double fallback) {
  return Value(c, name).value_or(fallback);
}

/// The nominal value; InputError naming the component, the parameter and the remedy otherwise.
double Require(const Component& c, const std::string& name);

/// The Stribeck friction parameters the component gives, by element parameter name (tau_C,
/// d_vis, tau_S, f_exp).
Scalars Stribeck(const Component& c);

/// InputError "a backlash needs a stiffness" when the component gives a backlash without one.
void CheckBacklash(const Component& c);

/// A chain member with its inertia, its Coulomb drag and, when it gives a stiffness, that
/// stiffness with the structural damping beta*c in series.
inline ChainMember RigidOrElasticMember(const Component& c, double beta) {
  ChainMember m{Require(c, "inertia"), ValueOr(c, "coulomb_torque", 0.0), Value(c, "stiffness"), std::nullopt};
  if (m.c && beta > 0) m.d = beta * *m.c;
  return m;
}

/// The Stribeck friction of a component at its input speed (coulomb_torque, viscous_coefficient,
/// stribeck_torque, stribeck_decay).
template <class T>
T StribeckOf(const ParameterReader<T>& p, const T& w) {
  return StribeckTorque(p("coulomb_torque"), p("viscous_coefficient"), p("stribeck_torque"), p("stribeck_decay"), w);
}

/// Efficiency of a gear train of `meshes` (default 1) meshes of efficiency eta_mesh.
template <class T>
T MeshEfficiency(const ParameterReader<T>& p) {
  const int meshes = p.Has("meshes") ? static_cast<int>(p.Nominal("meshes")) : 1;
  T eta(1.0);
  for (int i = 0; i < meshes; ++i) eta = eta * p("eta_mesh");
  return eta;
}

/// Helper base: the type name as constructor argument (its roles are in its declaration).
class NamedModel : public ComponentModel {
 public:
  explicit NamedModel(std::string_view type) : type_(type) {}
  std::string_view type() const override { return type_; }

 private:
  std::string_view type_;
};

/// Two-flange components (ports a and b) that are one element `c.id` with flanges a/b.
inline void MapAB(const Component& c, ExpansionContext& x) {
  x.MapPort(c, "a", c.id + ".flange_a");
  x.MapPort(c, "b", c.id + ".flange_b");
}

/// Speed law of a gear stage: parameter "ratio" = speed at port `fast` / speed at the others.
inline PortRatio GearSpeedRatio(std::string_view fast, std::string_view from, std::string_view to) {
  if (from == fast && to != fast) return {"ratio", -1};
  if (to == fast && from != fast) return {"ratio", 1};
  return {};
}

}  // namespace highlift::model::components

/// Registration: defines the accessor of one component model (listed in registry.cc).
#define HIGHLIFT_REGISTER_COMPONENT(Name, ModelClass)                     \
  namespace highlift::model::components {                                 \
  const ComponentModel& Name##Component() {                                 \
    static const ModelClass model;                                        \
    return model;                                                         \
  }                                                                       \
  }
