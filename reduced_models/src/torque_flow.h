// Steady-state torque flow on the component tree, templated on the scalar. Torques are positive
// when they resist the commanded motion; every component's input-flange torque is
//   tau_in = law(tau_out) + drag(|w_in|)
// with gear stages by GearInputTorque (opposing / aiding efficiencies), drag by the Stribeck law
// (paper eq. 3) or the shaft's drag per length, summed up to the PDU.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "graph_model.h"

namespace highlift::reduced_models::detail {

template <class T>
struct Flow {
  std::vector<T> tau_in;   ///< N*m at each node's input flange, at its own speed
  std::vector<T> w_in;     ///< rad/s at each node's input flange
  std::vector<T> n;        ///< speed ratio w_in / w_pdu
};

template <class T>
T PowInt(const T& x, int k) {
  T r(1.0);
  for (int i = 0; i < k; ++i) r = r * x;
  return r;
}

template <class T>
T StribeckOf(const Component& c, const ParameterMode& mode, const T& w_abs) {
  return StribeckTorque(Read<T>(c, "coulomb_torque", mode), Read<T>(c, "viscous_coefficient", mode),
                        Read<T>(c, "stribeck_torque", mode), Read<T>(c, "stribeck_decay", mode), w_abs);
}

template <class T>
T MeshEfficiency(const Component& c, const ParameterMode& mode) {
  const int meshes = HasValue(c, "meshes") ? static_cast<int>(NominalValue(c, "meshes")) : 1;
  return PowInt(Read<T>(c, "eta_mesh", mode), meshes);
}

/// `loads`: actuator id -> output torque (positive opposing the motion). `w_pdu` >= 0 (an interval
/// when the PDU speed is uncertain).
template <class T>
Flow<T> SolveFlow(const Graph& g, const ParameterMode& mode, const std::map<std::string, double>& loads,
                  const T& w_pdu, bool friction = true) {
  Flow<T> f;
  const std::size_t count = g.nodes.size();
  f.n = SpeedRatios<T>(g, mode);
  f.w_in.resize(count);
  f.tau_in.assign(count, T(0.0));
  for (std::size_t i = 0; i < count; ++i) f.w_in[i] = f.n[i] * w_pdu;
  const T on(friction ? 1.0 : 0.0);
  for (std::size_t k = count; k-- > 0;) {
    const Component& c = *g.nodes[k].component;
    T through(0.0), branch(0.0);
    for (int child : g.nodes[k].children)
      (g.nodes[child].parent_port == "branch" ? branch : through) += f.tau_in[child];
    const T w = f.w_in[k];
    T tau(0.0);
    if (c.type == "torque_shaft") {
      tau = through + on * Read<T>(c, "drag_per_length", mode) * Read<T>(c, "length", mode);
    } else if (c.type == "steady_bearing") {
      tau = through + on * StribeckOf<T>(c, mode, w);
    } else if (c.type == "universal_joint") {
      const T eta = Read<T>(c, "efficiency", mode);
      tau = GearInputTorque(through, T(1.0), eta, eta);
    } else if (c.type == "angle_gearbox") {
      const T eta = MeshEfficiency<T>(c, mode);
      tau = GearInputTorque(through, Read<T>(c, "ratio", mode), eta, eta) + on * StribeckOf<T>(c, mode, w);
    } else if (c.type == "branch_gearbox") {
      const T eta = MeshEfficiency<T>(c, mode);
      tau = through + GearInputTorque(branch, Read<T>(c, "ratio", mode), eta, eta) + on * StribeckOf<T>(c, mode, w);
    } else if (c.type == "geared_rotary_actuator" || c.type == "ballscrew_actuator") {
      auto it = loads.find(c.id);
      const T load(it == loads.end() ? 0.0 : it->second);
      tau = GearInputTorque(load, Read<T>(c, "ratio", mode), Read<T>(c, "eta_opposing", mode),
                            Read<T>(c, "eta_aiding", mode)) +
            on * StribeckOf<T>(c, mode, w);
    } else {
      // PDU output (both sides), limiters, brakes, sensors, disconnectors: torque passes through.
      tau = through;
    }
    f.tau_in[k] = tau;
  }
  return f;
}

}  // namespace highlift::reduced_models::detail
