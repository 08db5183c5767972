// ballscrew_actuator: a linear ballscrew actuator (actuator.h); its travel in input-side angle
// is stroke / lead.
#include "actuator.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec BallscrewActuatorDeclaration() {
  ComponentTypeSpec t;
  t.name = "ballscrew_actuator";
  t.display_name = "ballscrew actuator";
  t.description = "Ballscrew actuator: input gear and a ball screw turning rotation into stroke.";
  t.ports = {Flange("input", "input flange from the station gearbox or limiter")};
  auto& ps = t.parameters;
  ps.push_back(Param("ratio", "ratio", Dimensionless(), "1", "input gear ratio, input speed / screw speed")
                   .Nominal(1)
                   .Default(1, 3)
                   .Valid(0.01, 1000)
                   .Source("estimate"));
  ps.push_back(Param("lead", "l", Length(), "mm/rev", "screw lead, stroke per screw revolution")
                   .Nominal(10)
                   .Default(5, 20)
                   .Valid(0.1, 1000)
                   .Source("estimate"));
  ps.push_back(Efficiency("eta_opposing", "eta_op", 0.90, 0.85, 0.95, "efficiency driving against an opposing load",
                          "estimate: ball screws are more efficient than planetary GRAs"));
  ps.push_back(AidingEfficiency("eta_aiding", "eta_ai", 0.80, 0.70, 0.90, "efficiency with an aiding (back-driving) load", "estimate"));
  ps.push_back(Param("input_inertia", "J_in", dimensions::Inertia(), "kg*m^2", "inertia referred to the input")
                   .Nominal(5e-4)
                   .Default(2e-4, 1e-3)
                   .Valid(0, 100)
                   .Source("estimate")
                   .Side(ReferenceSide::kActuatorInput));
  ps.push_back(Param("output_force_rating", "F_max", Force(), "kN", "rated output force")
                   .Valid(0, 1e4)
                   .Optional()
                   .Source("none")
                   .Side(ReferenceSide::kActuatorOutput));
  ps.push_back(Param("stroke", "s", Length(), "mm", "stroke for full travel")
                   .Valid(0, 1e5)
                   .Optional()
                   .Source("none"));
  ps.push_back(Backlash("total backlash referred to the input", ReferenceSide::kActuatorInput));
  AddStribeck(ps, 0.2, 0.1, 0.4, "estimate: about twice a steady bearing", ReferenceSide::kActuatorInput);
  ps.push_back(SpanPosition());
  t.roles = {.actuator = true, .jammable = true, .lumps_inertia = true};
  return t;
}

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
