// geared_rotary_actuator: a rotary actuator at a flap or slat station (actuator.h); its travel
// is the output angle travel_angle.
#include "actuator.h"

namespace highlift::model::components {
namespace {

class GearedRotaryActuatorModel final : public ActuatorModel {
 public:
  GearedRotaryActuatorModel() : ActuatorModel("geared_rotary_actuator") {}
  double TravelAngle(const Component& c) const override { return Require(c, "travel_angle"); }
  Sym OutputTravel(const ParameterReader<Sym>& p) const override { return p("travel_angle"); }

  /// Input side plus the surface's inertia referred to the input.
  template <class T>
  Lumped<T> Law(const ParameterReader<T>& p) const {
    Lumped<T> out = DefaultLumped(p);
    out.J = p("input_inertia") + p("load_inertia");
    return out;
  }
  HIGHLIFT_LUMPED_LAW

  /// Against the peak loads at its input: its rated output torque / ratio.
  template <class T>
  std::optional<Allowable<T>> PeakLaw(const ParameterReader<T>& p) const {
    if (!p.Has("output_torque_rating")) return std::nullopt;
    return Allowable<T>{"rated output torque / ratio", p("output_torque_rating") / p("ratio")};
  }
  HIGHLIFT_PEAK_ALLOWABLE_LAW
  /// In the steady state its rated output torque against its output load.
  std::optional<Allowable<Interval>> SteadyAllowable(const ParameterReader<Interval>& p) const override {
    if (!p.Has("output_torque_rating")) return std::nullopt;
    return Allowable<Interval>{"rated output torque", p("output_torque_rating"), true};
  }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(GearedRotaryActuator, GearedRotaryActuatorModel)
