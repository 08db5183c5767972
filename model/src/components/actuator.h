// The actuators (geared_rotary_actuator.cc, ballscrew_actuator.cc): one
// HighLift.Mechanical.GearedRotaryActuator between port input and the surface (element port
// flange_b, where the load case's airload acts), ratio = w_input / w_output; with a jam element
// on its output when the scenario jams it.
#pragma once

#include "component_util.h"
#include "declaration.h"
#include "highlift/core/text_table.h"
#include "highlift/model/drive_network.h"

namespace highlift::model::components {

constexpr double kJamStiffness = 1e5;  // N*m/rad referred to the actuator input

class ActuatorModel : public NamedModel {
 public:
  explicit ActuatorModel(std::string_view type) : NamedModel(type) {}

  PortRatio SpeedRatioLaw(std::string_view from, std::string_view to) const override {
    return GearSpeedRatio("input", from, to);
  }
  std::vector<std::string> PowerPorts() const override { return {}; }

  /// Steady state: the airload through the gear stage with its opposing and aiding
  /// efficiencies, plus its Stribeck friction.
  template <class T>
  T SteadyLaw(const ParameterReader<T>& p, const SteadyFlow<T>& in) const {
    return GearInputTorque(in.load, p("ratio"), p("eta_opposing"), p("eta_aiding")) + in.friction * StribeckOf(p, in.w);
  }
  HIGHLIFT_STEADY_LAW

  /// The travel at the input flange: the output travel (OutputTravel of the type) times the ratio.
  Sym InputTravel(const ParameterReader<Sym>& p) const override { return OutputTravel(p) * p("ratio"); }
  /// The output angle over the full travel, rad, as the propagator reads it.
  virtual Sym OutputTravel(const ParameterReader<Sym>& p) const = 0;

  void Expand(const Component& c, ExpansionContext& x) const override {
    const double ratio = Require(c, "ratio");
    Scalars s = x.Regularised(Stribeck(c));
    s["ratio"] = ratio;
    s["eta_op"] = Require(c, "eta_opposing");
    s["eta_ai"] = Require(c, "eta_aiding");
    s["J_in"] = Require(c, "input_inertia");
    if (auto J_load = Value(c, "load_inertia")) s["J_load"] = *J_load;
    if (auto phi = Value(c, "eta_settle_angle")) s["phi_eta"] = *phi;
    if (auto w = Value(c, "eta_speed_threshold")) s["w_eta"] = *w;
    CheckBacklash(c);
    if (auto stiffness = Value(c, "stiffness")) {
      s["elastic"] = 1;
      s["c"] = *stiffness;
      s["d"] = x.beta() * *stiffness;
      s["b"] = ValueOr(c, "backlash", 0.0);
    }
    x.Add("GearedRotaryActuator", c.id, s, c.id);
    x.model().own_element_torque.insert(c.id);
    x.MapPort(c, "input", c.id + ".flange_a");
    // A jam of this actuator: its output is tied to the structure at the scenario's time.
    const Scenario* scenario = x.scenario();
    if (scenario && scenario->jam_component == c.id) {
      const std::string jam = c.id + ".jam";
      const double c_jam = kJamStiffness * ratio * ratio;
      x.Add("Jam", jam, {{"c", c_jam}, {"d", x.beta() * c_jam}, {"t_jam", *scenario->jam_time}}, c.id, {},
            "jam of " + c.id + " (stiffness " + FormatNumber(kJamStiffness) + " N*m/rad at the input)");
      x.Connect(c.id + ".flange_b", jam + ".flange");
    }
  }
};

}  // namespace highlift::model::components
