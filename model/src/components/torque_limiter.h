// The torque limiters (system_torque_limiter.cc, station_torque_limiter.cc): one
// HighLift.Mechanical.TorqueLimiter element, ports input and output.
#pragma once

#include "component_util.h"

namespace highlift::model::components {

class TorqueLimiterModel : public NamedModel {
 public:
  explicit TorqueLimiterModel(std::string_view type) : NamedModel(type) {}

  std::vector<std::string> PowerPorts() const override { return {"output"}; }

  /// In the lumped models the normal-operation stiffness c1 (the paper's figure 4).
  template <class T>
  Lumped<T> Law(const ParameterReader<T>& p) const {
    Lumped<T> out = DefaultLumped(p);
    out.c = p("stiffness_normal");
    return out;
  }
  HIGHLIFT_LUMPED_LAW

  void Expand(const Component& c, ExpansionContext& x) const override {
    const double tau1_ext = Require(c, "lockout_torque_extend");
    const double tau1_ret = Require(c, "lockout_torque_retract");
    const double tau2 = Require(c, "end_stop_torque");
    if (!(tau2 > tau1_ext && tau2 > tau1_ret))
      throw InputError("component '" + c.id + "' (" + c.type + "): 'end_stop_torque' = " + std::to_string(tau2) +
                           " N*m must exceed both lock-out torques (" + std::to_string(tau1_ext) + ", " +
                           std::to_string(tau1_ret) + " N*m): raise it or lower the lock-out torques",
                       c.where);
    // The retract end stop keeps the extend ratio tau2/tau1.
    x.Add("TorqueLimiter", c.id,
          {{"tau1_ext", tau1_ext},
           {"tau1_ret", tau1_ret},
           {"tau2_ext", tau2},
           {"tau2_ret", tau2 * tau1_ret / tau1_ext},
           {"c1", Require(c, "stiffness_normal")},
           {"d", x.beta() * Require(c, "stiffness_normal")},  // structural damping of the balls and ramps
           {"c2", Require(c, "stiffness_lockout")},
           {"c3", Require(c, "stiffness_end_stop")},
           {"tauB_max", Require(c, "max_brake_torque")},
           {"J", Require(c, "inertia")}},
          c.id);
    x.MapPort(c, "input", c.id + ".flange_a");
    x.MapPort(c, "output", c.id + ".flange_b");
  }

  std::vector<FitRule> FitRules() const override { return {{"inertia", "lockout_torque_extend"}}; }
};

}  // namespace highlift::model::components
