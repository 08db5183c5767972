// The element laws: one class per MSL element type over small shared bases (TwoFlange for the
// relative quantities, Compliant for relative-twist states, Friction for the MSL stick/slip
// state machine, TorqueSource for the torque sources, SignalBlock for Modelica.Blocks sources).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "highlift/core/error.h"
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {

double Interpolate(const Table& table, int column, double x) {
  return InterpolatePoints(
      table.size(), [&](std::size_t i) { return table[i][0]; }, [&](std::size_t i) { return table[i][column]; }, x);
}


using namespace msl;  // the MSL laws of msl_elements.h

std::unique_ptr<Element> MakeElement(const NetworkElement& e) {
  const std::string& t = e.type;
  std::unique_ptr<Element> el;
  if (t == "Fixed") el = std::make_unique<Fixed>(e);
  else if (t == "Inertia") el = std::make_unique<Inertia>(e);
  else if (t == "Spring") el = std::make_unique<Spring>(e);
  else if (t == "Damper") el = std::make_unique<Damper>(e);
  else if (t == "SpringDamper") el = std::make_unique<SpringDamper>(e);
  else if (t == "ElastoBacklash") el = std::make_unique<ElastoBacklash>(e);
  else if (t == "ElastoBacklash2") el = std::make_unique<ElastoBacklash2>(e);
  else if (t == "IdealGear") el = std::make_unique<IdealGear>(e);
  else if (t == "IdealPlanetary") el = std::make_unique<IdealPlanetary>(e);
  else if (t == "LossyGear") el = std::make_unique<LossyGear>(e);
  else if (t == "BearingFriction") el = std::make_unique<BearingFriction>(e);
  else if (t == "Brake") el = std::make_unique<Brake>(e);
  else if (t == "Clutch") el = std::make_unique<Clutch>(e, false);
  else if (t == "OneWayClutch") el = std::make_unique<Clutch>(e, true);
  else if (t == "Torque") el = std::make_unique<TorqueInput>();
  else if (t == "ConstantTorque") el = std::make_unique<ConstantTorque>(e);
  else if (t == "TorqueStep") el = std::make_unique<TorqueStep>(e);
  else if (t == "LinearSpeedDependentTorque") el = std::make_unique<SpeedDependentTorque>(e, false);
  else if (t == "QuadraticSpeedDependentTorque") el = std::make_unique<SpeedDependentTorque>(e, true);
  else if (t == "SignTorque") el = std::make_unique<SignTorque>(e);
  else if (t == "EddyCurrentTorque") el = std::make_unique<EddyCurrentTorque>(e);
  else if (t == "Constant") el = std::make_unique<Constant>(e);
  else if (t == "Step") el = std::make_unique<Step>(e);
  else if (t == "Ramp") el = std::make_unique<Ramp>(e);
  else if (t == "Sine") el = std::make_unique<Sine>(e);
  else if (t == "Pulse") el = std::make_unique<Pulse>(e);
  else if (t == "TimeTable") el = std::make_unique<TimeTable>(e);
  else if (t == "Product") el = std::make_unique<Product>();
  else if (t == "Feedback") el = std::make_unique<Feedback>();
  else if ((el = MakeMoreMslElement(e))) {
  } else if ((el = MakeExtraMslElement(e))) {
  } else if ((el = MakeBrakeElement(e))) {
  } else if ((el = MakeGearElement(e))) {
  } else if ((el = MakeDriveElement(e))) {
  } else if ((el = MakeHydraulicElement(e))) {
  } else
    throw InputError("element '" + e.id + "': type '" + t +
                     "' has no simulation law; use one of the element types listed by "
                     "`highlift info --elements`");
  el->id = e.id;
  el->type = e.type;
  return el;
}

/// Fixed flanges are ground nodes at phi0: exposed for the model builder.
double FixedAngle(const Element& element) {
  return static_cast<const Fixed&>(element).phi0;
}

}  // namespace highlift::sim::detail
