// Steady-state torque flow on the component tree, templated on the scalar. Torques are positive
// when they resist the commanded motion; every component's input-flange torque is its type's
// steady-state law (ComponentModel::InputTorque: gear stages by GearInputTorque with opposing /
// aiding efficiencies, drag by the Stribeck law or the shaft's drag per length), summed up to the
// PDU.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "graph_model.h"

namespace highlift::reduced_models::detail {

/// The same value to the bit (an Interval: both bounds).
inline bool SameValue(double a, double b) { return a == b; }
inline bool SameValue(const Interval& a, const Interval& b) { return a.lo == b.lo && a.hi == b.hi; }

template <class T>
struct Flow {
  std::vector<T> tau_in;   ///< N*m at each node's input flange, at its own speed
  std::vector<T> w_in;     ///< rad/s at each node's input flange
  std::vector<T> n;        ///< speed ratio w_in / w_pdu
};

/// `loads`: actuator id -> output torque (positive opposing the motion). `w_pdu` >= 0 (an interval
/// when the PDU speed is uncertain).
///
/// `nominal` (a mode of one parameter only, ParameterMode::kOne): the same flow in the nominal
/// mode, with the same `loads`, `w_pdu` and `friction`. A node whose component is not the
/// parameter's, whose speed is the same and whose children's torques are the same takes the
/// nominal torque: its law would do the same operations on the same values.
///
/// `ratios`: SpeedRatios<T>(g, mode) when the caller has them (they are not computed again).
template <class T>
Flow<T> SolveFlow(const Graph& g, const ParameterMode& mode, const std::map<std::string, double>& loads,
                  const T& w_pdu, bool friction = true, const Flow<T>* nominal = nullptr,
                  const std::vector<T>* ratios = nullptr) {
  Flow<T> f;
  const std::size_t count = g.nodes.size();
  f.n = ratios != nullptr ? *ratios : SpeedRatios<T>(g, mode);
  f.w_in.resize(count);
  f.tau_in.assign(count, T(0.0));
  for (std::size_t i = 0; i < count; ++i) f.w_in[i] = f.n[i] * w_pdu;
  const T on(friction ? 1.0 : 0.0);
  if (mode.kind != ParameterMode::kOne || (nominal != nullptr && nominal->tau_in.size() != count)) nominal = nullptr;
  std::vector<char> changed(nominal != nullptr ? count : 0, 0);
  for (std::size_t k = count; k-- > 0;) {
    const Component& c = *g.nodes[k].component;
    if (nominal != nullptr) {
      bool same = c.id != mode.component && SameValue(f.w_in[k], nominal->w_in[k]);
      for (int child : g.nodes[k].children) same = same && !changed[child];
      if (same) {
        f.tau_in[k] = nominal->tau_in[k];
        continue;
      }
      changed[k] = 1;
    }
    T through(0.0), branch(0.0);
    for (int child : g.nodes[k].children)
      (g.nodes[child].parent_port == "branch" ? branch : through) += f.tau_in[child];
    const T w = f.w_in[k];
    // The component's steady-state law (model/src/components/<type>.cc); torque passes
    // through a type without one (PDU output, limiters, brakes, sensors, disconnectors).
    auto load = loads.find(c.id);
    const model::SteadyFlow<T> in{through, branch, T(load == loads.end() ? 0.0 : load->second), w, on};
    const model::ComponentModel* m = g.nodes[k].model;
    const T tau = m ? m->InputTorque(ModeReader<T>(c, mode), in) : through;
    f.tau_in[k] = tau;
  }
  return f;
}

}  // namespace highlift::reduced_models::detail
