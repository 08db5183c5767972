// ballscrew_actuator: a linear ballscrew actuator (actuator.h); its travel in input-side angle
// is stroke / lead.
#include "actuator.h"

namespace highlift::model::components {
namespace {

class BallscrewActuatorModel final : public ActuatorModel {
 public:
  BallscrewActuatorModel() : ActuatorModel("ballscrew_actuator") {}
  double TravelAngle(const Component& c) const override {
    const auto stroke = Value(c, "stroke");
    if (!stroke)
      throw InputError("component '" + c.id + "' (" + c.type + "): a load against position needs the 'stroke': give it",
                       c.where);
    return *stroke / Require(c, "lead");
  }
  /// The screw's turns over the stroke (lead in m/rad), the angle its ratio multiplies.
  Sym OutputTravel(const ParameterReader<Sym>& p) const override { return p("stroke") / p("lead"); }

  template <class T>
  Lumped<T> Law(const ParameterReader<T>& p) const {
    Lumped<T> out = DefaultLumped(p);
    out.J = p("input_inertia");
    return out;
  }
  HIGHLIFT_LUMPED_LAW
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(BallscrewActuator, BallscrewActuatorModel)
