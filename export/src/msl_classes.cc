// The list of MSL 4.0.0 names we use (see msl_classes.h). Each entry: full path, kind,
// modifiable names (parameters first, then variables that take start/fixed modifiers), and
// connectors as "name:kind" with kind r (rotational), t (translational), ri/ro (Real in/out),
// bi/bo (Boolean in/out), io (Integer out), h (heat port).
//
// Parameter names follow MSL 4.0.0 (Modelica/Mechanics/Rotational, Modelica/Blocks); when a
// class is added here, take its names from the 4.0.0 sources, not from 4.1.
#include "msl_classes.h"

#include <algorithm>
#include <sstream>

#include "highlift/core/error.h"

namespace highlift::msl {
namespace {

struct Entry {
  const char* path;
  const char* kind;
  const char* modifiers;
  const char* connectors;
};

// Shared modifier lists.
#define HL_COMPLIANT "phi_rel tau phi_rel0"
#define HL_RELATIVE "stateSelect phi_nominal phi_rel w_rel a_rel tau"
#define HL_HEAT "useHeatPort lossPower"
#define HL_FRICTION "w_small mode startForward startBackward locked free tau0 tau0_max sa"
#define HL_TWO_SUPPORT "flange_a:r flange_b:r support:r"
#define HL_ONE_SUPPORT "flange:r support:r"
#define HL_REAL_ATTRIBUTES "start fixed min max nominal unit displayUnit quantity stateSelect"

const Entry kEntries[] = {
    // ---- Rotational components ---------------------------------------------------------------
    {"Modelica.Mechanics.Rotational.Components.Inertia", "model", "J stateSelect phi w a",
     "flange_a:r flange_b:r"},
    {"Modelica.Mechanics.Rotational.Components.Spring", "model", "c " HL_COMPLIANT,
     "flange_a:r flange_b:r"},
    {"Modelica.Mechanics.Rotational.Components.Damper", "model", "d " HL_RELATIVE " " HL_HEAT,
     "flange_a:r flange_b:r heatPort:h"},
    {"Modelica.Mechanics.Rotational.Components.SpringDamper", "model",
     "c d phi_rel0 " HL_RELATIVE " " HL_HEAT, "flange_a:r flange_b:r heatPort:h"},
    {"Modelica.Mechanics.Rotational.Components.ElastoBacklash", "model",
     "c d b phi_rel0 " HL_RELATIVE " " HL_HEAT, "flange_a:r flange_b:r heatPort:h"},
    {"Modelica.Mechanics.Rotational.Components.ElastoBacklash2", "model",
     "c d b phi_rel0 " HL_RELATIVE " " HL_HEAT, "flange_a:r flange_b:r heatPort:h"},
    {"Modelica.Mechanics.Rotational.Components.IdealGear", "model", "ratio useSupport phi_a phi_b",
     HL_TWO_SUPPORT},
    {"Modelica.Mechanics.Rotational.Components.IdealPlanetary", "model", "ratio",
     "sun:r carrier:r ring:r"},
    {"Modelica.Mechanics.Rotational.Components.LossyGear", "model",
     "ratio lossTable useSupport " HL_HEAT " phi_a phi_b w_a a_a tau_loss mode",
     HL_TWO_SUPPORT " heatPort:h"},
    {"Modelica.Mechanics.Rotational.Components.Fixed", "model", "phi0", "flange:r"},
    {"Modelica.Mechanics.Rotational.Components.AngleToTorqueAdaptor", "model", "use_w use_a",
     "flange:r phi:ri w:ri a:ri tau:ro"},
    {"Modelica.Mechanics.Rotational.Components.TorqueToAngleAdaptor", "model", "use_w use_a",
     "flange:r tau:ri phi:ro w:ro a:ro"},
    {"Modelica.Mechanics.Rotational.Components.Gearbox", "model",
     "ratio lossTable c d b stateSelect useSupport " HL_HEAT " phi_rel w_rel a_rel", HL_TWO_SUPPORT " heatPort:h"},
    {"Modelica.Mechanics.Rotational.Components.Disc", "model", "deltaPhi phi", "flange_a:r flange_b:r"},
    {"Modelica.Mechanics.Rotational.Components.InitializeFlange", "model",
     "use_phi_start use_w_start use_a_start stateSelect phi_flange w_flange",
     "flange:r phi_start:ri w_start:ri a_start:ri"},
    {"Modelica.Mechanics.Rotational.Components.RelativeStates", "model", "stateSelect phi_rel w_rel a_rel",
     "flange_a:r flange_b:r"},
    {"Modelica.Mechanics.Rotational.Components.IdealGearR2T", "model", "ratio useSupportR useSupportT",
     "flangeR:r flangeT:t supportR:r supportT:t"},
    {"Modelica.Mechanics.Rotational.Components.IdealRollingWheel", "model", "radius useSupportR useSupportT",
     "flangeR:r flangeT:t supportR:r supportT:t"},
    {"Modelica.Mechanics.Rotational.Components.BearingFriction", "model",
     "tau_pos peak useSupport " HL_HEAT " " HL_FRICTION " phi w a tau", HL_TWO_SUPPORT " heatPort:h"},
    {"Modelica.Mechanics.Rotational.Components.Brake", "model",
     "mu_pos peak cgeo fn_max useSupport " HL_HEAT " " HL_FRICTION " phi w a tau fn",
     HL_TWO_SUPPORT " f_normalized:ri heatPort:h"},
    {"Modelica.Mechanics.Rotational.Components.Clutch", "model",
     "mu_pos peak cgeo fn_max " HL_RELATIVE " " HL_HEAT " " HL_FRICTION " fn",
     "flange_a:r flange_b:r f_normalized:ri heatPort:h"},
    {"Modelica.Mechanics.Rotational.Components.OneWayClutch", "model",
     "mu_pos peak cgeo fn_max " HL_RELATIVE " " HL_HEAT " " HL_FRICTION " fn stuck",
     "flange_a:r flange_b:r f_normalized:ri heatPort:h"},
    // ---- Rotational sources ------------------------------------------------------------------
    {"Modelica.Mechanics.Rotational.Sources.Torque", "model", "useSupport phi", HL_ONE_SUPPORT " tau:ri"},
    {"Modelica.Mechanics.Rotational.Sources.Torque2", "model", "", "flange_a:r flange_b:r tau:ri"},
    {"Modelica.Mechanics.Rotational.Sources.Speed", "model", "exact f_crit useSupport phi w a",
     HL_ONE_SUPPORT " w_ref:ri"},
    {"Modelica.Mechanics.Rotational.Sources.Position", "model", "exact f_crit useSupport phi w a",
     HL_ONE_SUPPORT " phi_ref:ri"},
    {"Modelica.Mechanics.Rotational.Sources.Accelerate", "model", "useSupport phi w a",
     HL_ONE_SUPPORT " a_ref:ri"},
    {"Modelica.Mechanics.Rotational.Sources.Move", "model", "useSupport phi", HL_ONE_SUPPORT " u:ri"},
    {"Modelica.Mechanics.Rotational.Sources.ConstantTorque", "model",
     "tau_constant useSupport phi w tau", HL_ONE_SUPPORT},
    {"Modelica.Mechanics.Rotational.Sources.ConstantSpeed", "model", "w_fixed useSupport phi w tau",
     HL_ONE_SUPPORT},
    {"Modelica.Mechanics.Rotational.Sources.TorqueStep", "model",
     "stepTorque offsetTorque startTime useSupport phi w tau", HL_ONE_SUPPORT},
    {"Modelica.Mechanics.Rotational.Sources.LinearSpeedDependentTorque", "model",
     "tau_nominal TorqueDirection w_nominal useSupport phi w tau", HL_ONE_SUPPORT},
    {"Modelica.Mechanics.Rotational.Sources.QuadraticSpeedDependentTorque", "model",
     "tau_nominal TorqueDirection w_nominal useSupport phi w tau", HL_ONE_SUPPORT},
    // Sources.InverseSpeedDependentTorque is not in 4.0.0 (it appears in 4.1.0): the element type
    // exports as HighLift.Sources.InverseSpeedDependentTorque.
    {"Modelica.Mechanics.Rotational.Sources.SignTorque", "model",
     "tau_nominal reg w0 useSupport phi w tau", HL_ONE_SUPPORT},
    {"Modelica.Mechanics.Rotational.Sources.EddyCurrentTorque", "model",
     "tau_nominal w_nominal TRef alpha20 T useSupport " HL_HEAT " phi w tau", HL_ONE_SUPPORT " heatPort:h"},
    // ---- Rotational sensors ------------------------------------------------------------------
    {"Modelica.Mechanics.Rotational.Sensors.AngleSensor", "model", "", "flange:r phi:ro"},
    {"Modelica.Mechanics.Rotational.Sensors.SpeedSensor", "model", "", "flange:r w:ro"},
    {"Modelica.Mechanics.Rotational.Sensors.TorqueSensor", "model", "", "flange_a:r flange_b:r tau:ro"},
    {"Modelica.Mechanics.Rotational.Sensors.AccSensor", "model", "", "flange:r a:ro"},
    {"Modelica.Mechanics.Rotational.Sensors.RelAccSensor", "model", "", "flange_a:r flange_b:r a_rel:ro"},
    {"Modelica.Mechanics.Rotational.Sensors.RelAngleSensor", "model", "", "flange_a:r flange_b:r phi_rel:ro"},
    {"Modelica.Mechanics.Rotational.Sensors.RelSpeedSensor", "model", "", "flange_a:r flange_b:r w_rel:ro"},
    {"Modelica.Mechanics.Rotational.Sensors.PowerSensor", "model", "", "flange_a:r flange_b:r power:ro"},
    {"Modelica.Mechanics.Rotational.Sensors.MultiSensor", "model", "",
     "flange_a:r flange_b:r power:ro w:ro tau:ro"},
    // ---- Rotational interfaces (connectors and partial models the library extends) -----------
    {"Modelica.Mechanics.Rotational.Interfaces.Flange_a", "connector", "phi tau", ""},
    {"Modelica.Mechanics.Rotational.Interfaces.Flange_b", "connector", "phi tau", ""},
    {"Modelica.Mechanics.Rotational.Interfaces.Support", "connector", "phi tau", ""},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialTwoFlanges", "partial", "", "flange_a:r flange_b:r"},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialCompliant", "partial", HL_COMPLIANT,
     "flange_a:r flange_b:r"},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialCompliantWithRelativeStates", "partial",
     HL_RELATIVE, "flange_a:r flange_b:r"},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialTwoFlangesAndSupport", "partial", "useSupport",
     HL_TWO_SUPPORT " internalSupport:r"},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialOneFlangeAndSupport", "partial", "useSupport",
     HL_ONE_SUPPORT " internalSupport:r"},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialElementaryTwoFlangesAndSupport2", "partial",
     "useSupport", HL_TWO_SUPPORT},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialElementaryOneFlangeAndSupport2", "partial",
     "useSupport", HL_ONE_SUPPORT},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialTorque", "partial", "useSupport phi",
     HL_ONE_SUPPORT},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialFriction", "partial", HL_FRICTION, ""},
    {"Modelica.Mechanics.Rotational.Icons.Gear", "partial", "", ""},
    {"Modelica.Mechanics.Rotational.Icons.Gearbox", "partial", "", ""},
    {"Modelica.Mechanics.Rotational.Icons.Clutch", "partial", "", ""},
    // ---- Translational -----------------------------------------------------------------------
    {"Modelica.Mechanics.Translational.Interfaces.Flange_a", "connector", "s f", ""},
    {"Modelica.Mechanics.Translational.Interfaces.Flange_b", "connector", "s f", ""},
    {"Modelica.Mechanics.Translational.Interfaces.Support", "connector", "s f", ""},
    {"Modelica.Mechanics.Translational.Components.Mass", "model", "m L stateSelect s v a",
     "flange_a:t flange_b:t"},
    {"Modelica.Mechanics.Translational.Components.Fixed", "model", "s0", "flange:t"},
    {"Modelica.Mechanics.Translational.Components.Spring", "model", "c s_rel0 s_rel f", "flange_a:t flange_b:t"},
    {"Modelica.Mechanics.Translational.Components.Damper", "model",
     "d stateSelect s_nominal s_rel v_rel a_rel f useHeatPort lossPower", "flange_a:t flange_b:t heatPort:h"},
    {"Modelica.Mechanics.Translational.Components.SpringDamper", "model",
     "c d s_rel0 stateSelect s_nominal s_rel v_rel a_rel f useHeatPort lossPower",
     "flange_a:t flange_b:t heatPort:h"},
    {"Modelica.Mechanics.Translational.Sensors.PositionSensor", "model", "", "flange:t s:ro"},
    {"Modelica.Mechanics.Translational.Sensors.SpeedSensor", "model", "", "flange:t v:ro"},
    {"Modelica.Mechanics.Translational.Sources.Force", "model", "useSupport s", "flange:t support:t f:ri"},
    // ---- Thermal -----------------------------------------------------------------------------
    {"Modelica.Thermal.HeatTransfer.Interfaces.HeatPort_a", "connector", "T Q_flow", ""},
    {"Modelica.Thermal.HeatTransfer.Interfaces.PartialElementaryConditionalHeatPortWithoutT",
     "partial", HL_HEAT, "heatPort:h"},
    {"Modelica.Thermal.HeatTransfer.Components.HeatCapacitor", "model", "C T der_T", "port:h"},
    // ---- Blocks ------------------------------------------------------------------------------
    {"Modelica.Blocks.Interfaces.RealInput", "connector", HL_REAL_ATTRIBUTES, ""},
    {"Modelica.Blocks.Interfaces.RealOutput", "connector", HL_REAL_ATTRIBUTES, ""},
    {"Modelica.Blocks.Interfaces.BooleanInput", "connector", "start fixed quantity", ""},
    {"Modelica.Blocks.Interfaces.BooleanOutput", "connector", "start fixed quantity", ""},
    {"Modelica.Blocks.Interfaces.IntegerOutput", "connector", "start fixed min max quantity", ""},
    {"Modelica.Blocks.Interfaces.SISO", "partial", "u y", "u:ri y:ro"},
    {"Modelica.Blocks.Icons.Block", "partial", "", ""},
    {"Modelica.Blocks.Icons.BooleanBlock", "partial", "", ""},
    {"Modelica.Blocks.Sources.Constant", "block", "k y", "y:ro"},
    {"Modelica.Blocks.Sources.Step", "block", "height offset startTime y", "y:ro"},
    {"Modelica.Blocks.Sources.Ramp", "block", "height duration offset startTime y", "y:ro"},
    {"Modelica.Blocks.Sources.Sine", "block", "amplitude f phase offset startTime y", "y:ro"},
    {"Modelica.Blocks.Sources.Cosine", "block", "amplitude f phase offset startTime y", "y:ro"},
    {"Modelica.Blocks.Sources.Pulse", "block", "amplitude width period nperiod offset startTime y",
     "y:ro"},
    {"Modelica.Blocks.Sources.TimeTable", "block", "table offset startTime shiftTime timeScale y",
     "y:ro"},
    {"Modelica.Blocks.Sources.BooleanStep", "block", "startTime startValue y", "y:bo"},
    {"Modelica.Blocks.Sources.BooleanConstant", "block", "k y", "y:bo"},
    {"Modelica.Blocks.Sources.CombiTimeTable", "block",
     "tableOnFile table tableName fileName verboseRead columns smoothness extrapolation timeScale "
     "offset startTime shiftTime timeEvents verboseExtrapolation y",
     "y:ro"},
    {"Modelica.Blocks.Tables.CombiTable1Ds", "block",
     "tableOnFile table tableName fileName verboseRead columns smoothness extrapolation "
     "verboseExtrapolation u y",
     "u:ri y:ro"},
    {"Modelica.Blocks.Math.Gain", "block", "k u y", "u:ri y:ro"},
    {"Modelica.Blocks.Math.Product", "block", "u1 u2 y", "u1:ri u2:ri y:ro"},
    {"Modelica.Blocks.Math.Feedback", "block", "u1 u2 y", "u1:ri u2:ri y:ro"},
    {"Modelica.Blocks.Math.Add", "block", "k1 k2 u1 u2 y", "u1:ri u2:ri y:ro"},
    {"Modelica.Blocks.Math.BooleanToReal", "block", "realTrue realFalse u y", "u:bi y:ro"},
    {"Modelica.Blocks.Nonlinear.Limiter", "block", "uMax uMin strict homotopyType u y", "u:ri y:ro"},
    // use_reset/use_set and their conditional connectors reset, set: MSL 4.0.0 (since 3.2.3).
    {"Modelica.Blocks.Continuous.Integrator", "block", "k use_reset use_set initType y_start u y",
     "u:ri y:ro reset:bi set:ri"},
    {"Modelica.Blocks.Continuous.FirstOrder", "block", "k T initType y_start u y", "u:ri y:ro"},
    {"Modelica.Blocks.Types.Smoothness", "enum", "", ""},
    {"Modelica.Blocks.Types.Smoothness.LinearSegments", "constant", "", ""},
    {"Modelica.Blocks.Types.Smoothness.ContinuousDerivative", "constant", "", ""},
    {"Modelica.Blocks.Types.Smoothness.ConstantSegments", "constant", "", ""},
    {"Modelica.Blocks.Types.Extrapolation", "enum", "", ""},
    {"Modelica.Blocks.Types.Extrapolation.HoldLastPoint", "constant", "", ""},
    {"Modelica.Blocks.Types.Extrapolation.LastTwoPoints", "constant", "", ""},
    {"Modelica.Blocks.Types.Extrapolation.Periodic", "constant", "", ""},
    {"Modelica.Blocks.Types.Extrapolation.NoExtrapolation", "constant", "", ""},
    {"Modelica.Blocks.Types.TimeEvents", "enum", "", ""},
    {"Modelica.Blocks.Types.TimeEvents.Always", "constant", "", ""},
    {"Modelica.Blocks.Types.TimeEvents.AtDiscontinuities", "constant", "", ""},
    {"Modelica.Blocks.Types.TimeEvents.NoTimeEvents", "constant", "", ""},
    {"Modelica.Blocks.Types.Init.InitialOutput", "constant", "", ""},
    {"Modelica.Blocks.Types.Init.NoInit", "constant", "", ""},
    {"Modelica.Blocks.Types.Regularization.Exp", "constant", "", ""},
    // ---- Icons, constants, functions ---------------------------------------------------------
    {"Modelica.Icons.Package", "partial", "", ""},
    {"Modelica.Icons.InterfacesPackage", "partial", "", ""},
    {"Modelica.Icons.ExamplesPackage", "partial", "", ""},
    {"Modelica.Icons.SourcesPackage", "partial", "", ""},
    {"Modelica.Icons.Example", "partial", "", ""},
    {"Modelica.Icons.Information", "partial", "", ""},
    {"Modelica.Icons.BasesPackage", "partial", "", ""},
    {"Modelica.Icons.UtilitiesPackage", "partial", "", ""},
    {"Modelica.Constants.pi", "constant", "", ""},
    {"Modelica.Constants.inf", "constant", "", ""},
    {"Modelica.Constants.eps", "constant", "", ""},
    {"Modelica.Constants.small", "constant", "", ""},
    {"Modelica.Math.Vectors.interpolate", "function", "", ""},
    {"Modelica.Math.exp", "function", "", ""},
    {"Modelica.Math.tanh", "function", "", ""},
    {"Modelica", "package", "version", ""},
    {"Modelica.Units.SI", "package", "", ""},
    {"Modelica.Utilities.Files.loadResource", "function", "", ""},
    {"Modelica.Units.NonSI.AngularVelocity_rpm", "type", "", ""},
    {"Modelica.Units.Conversions.from_rpm", "function", "", ""},
};

// Modelica.Units.SI types we use (all take the type attributes as modifiers).
const char* const kSiTypes[] = {
    "AbsolutePressure", "Angle", "AngularAcceleration", "AngularFrequency", "AngularVelocity",
    "Area", "BulkModulus", "Density", "Diameter", "Distance", "Efficiency", "Energy", "Force",
    "Frequency", "Inertia", "Length", "Mass", "ModulusOfElasticity", "Position", "Power", "Pressure",
    "RotationalDampingConstant", "RotationalSpringConstant", "ShearModulus", "Temperature", "Time",
    "Torque", "TranslationalDampingConstant", "Velocity", "Volume", "VolumeFlowRate",
};
constexpr const char* kTypeAttributes =
    "start fixed min max nominal unit displayUnit quantity stateSelect";

std::vector<std::string> Words(const char* text) {
  std::vector<std::string> words;
  std::istringstream in(text);
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

ConnectorKind KindFromTag(const std::string& tag) {
  if (tag == "r") return ConnectorKind::kRotational;
  if (tag == "t") return ConnectorKind::kTranslational;
  if (tag == "ri") return ConnectorKind::kRealInput;
  if (tag == "ro") return ConnectorKind::kRealOutput;
  if (tag == "bi") return ConnectorKind::kBooleanInput;
  if (tag == "bo") return ConnectorKind::kBooleanOutput;
  if (tag == "io") return ConnectorKind::kIntegerOutput;
  if (tag == "h") return ConnectorKind::kHeat;
  HIGHLIFT_CHECK(false, "msl_classes.cc: unknown connector tag '" + tag + "'");
  return ConnectorKind::kRotational;
}

std::vector<MslClass> Build() {
  std::vector<MslClass> classes;
  for (const Entry& e : kEntries) {
    MslClass c{e.path, e.kind, Words(e.modifiers), {}};
    for (const std::string& word : Words(e.connectors)) {
      const auto colon = word.find(':');
      HIGHLIFT_CHECK(colon != std::string::npos, "msl_classes.cc: connector without kind: " + word);
      c.connectors.push_back({word.substr(0, colon), KindFromTag(word.substr(colon + 1))});
    }
    classes.push_back(std::move(c));
  }
  for (const char* type : kSiTypes)
    classes.push_back({std::string("Modelica.Units.SI.") + type, "type", Words(kTypeAttributes), {}});
  std::sort(classes.begin(), classes.end(),
            [](const MslClass& a, const MslClass& b) { return a.path < b.path; });
  for (std::size_t i = 1; i < classes.size(); ++i)
    HIGHLIFT_CHECK(classes[i - 1].path != classes[i].path,
                   "msl_classes.cc: duplicate entry " + classes[i].path);
  return classes;
}

}  // namespace

const std::vector<MslClass>& Classes() {
  static const std::vector<MslClass> classes = Build();
  return classes;
}

const MslClass* Find(std::string_view path) {
  const auto& classes = Classes();
  auto it = std::lower_bound(classes.begin(), classes.end(), path,
                             [](const MslClass& c, std::string_view p) { return c.path < p; });
  if (it != classes.end() && it->path == path) return &*it;
  return nullptr;
}

bool ConnectorClassKind(std::string_view path, ConnectorKind& kind) {
  static const std::pair<std::string_view, ConnectorKind> kConnectors[] = {
      {"Modelica.Mechanics.Rotational.Interfaces.Flange_a", ConnectorKind::kRotational},
      {"Modelica.Mechanics.Rotational.Interfaces.Flange_b", ConnectorKind::kRotational},
      {"Modelica.Mechanics.Rotational.Interfaces.Support", ConnectorKind::kRotational},
      {"Modelica.Mechanics.Translational.Interfaces.Flange_a", ConnectorKind::kTranslational},
      {"Modelica.Mechanics.Translational.Interfaces.Flange_b", ConnectorKind::kTranslational},
      {"Modelica.Mechanics.Translational.Interfaces.Support", ConnectorKind::kTranslational},
      {"Modelica.Blocks.Interfaces.RealInput", ConnectorKind::kRealInput},
      {"Modelica.Blocks.Interfaces.RealOutput", ConnectorKind::kRealOutput},
      {"Modelica.Blocks.Interfaces.BooleanInput", ConnectorKind::kBooleanInput},
      {"Modelica.Blocks.Interfaces.BooleanOutput", ConnectorKind::kBooleanOutput},
      {"Modelica.Blocks.Interfaces.IntegerOutput", ConnectorKind::kIntegerOutput},
      {"Modelica.Thermal.HeatTransfer.Interfaces.HeatPort_a", ConnectorKind::kHeat},
      {"HighLift.Hydraulics.Interfaces.Port", ConnectorKind::kHydraulic},
  };
  for (const auto& [p, k] : kConnectors) {
    if (p == path) {
      kind = k;
      return true;
    }
  }
  return false;
}

namespace {

// Parameters without a default (a `start` value only) in MSL 4.0.0, per class we instantiate;
// taken from the 4.0.0 sources (e.g. Inertia: `parameter SI.Inertia J(min=0, start=1)`,
// Gain: `parameter Real k(start=1, unit="1")`). Parameters with a default are not listed.
struct Required {
  const char* path;
  const char* parameters;
};
const Required kRequired[] = {
    {"Modelica.Mechanics.Rotational.Components.Inertia", "J"},
    {"Modelica.Mechanics.Rotational.Components.Spring", "c"},
    {"Modelica.Mechanics.Rotational.Components.Damper", "d"},
    {"Modelica.Mechanics.Rotational.Components.SpringDamper", "c d"},
    {"Modelica.Mechanics.Rotational.Components.ElastoBacklash", "c d"},
    {"Modelica.Mechanics.Rotational.Components.ElastoBacklash2", "c d"},
    {"Modelica.Mechanics.Rotational.Components.IdealGear", "ratio"},
    {"Modelica.Mechanics.Rotational.Components.IdealPlanetary", "ratio"},
    {"Modelica.Mechanics.Rotational.Components.LossyGear", "ratio"},
    {"Modelica.Mechanics.Rotational.Components.IdealGearR2T", "ratio"},
    {"Modelica.Mechanics.Rotational.Components.IdealRollingWheel", "radius"},
    {"Modelica.Mechanics.Rotational.Components.Brake", "fn_max"},
    {"Modelica.Mechanics.Rotational.Components.Clutch", "fn_max"},
    {"Modelica.Mechanics.Rotational.Components.OneWayClutch", "fn_max"},
    {"Modelica.Mechanics.Rotational.Sources.ConstantTorque", "tau_constant"},
    {"Modelica.Mechanics.Rotational.Sources.ConstantSpeed", "w_fixed"},
    {"Modelica.Mechanics.Rotational.Sources.TorqueStep", "stepTorque offsetTorque"},
    {"Modelica.Mechanics.Rotational.Sources.LinearSpeedDependentTorque", "tau_nominal w_nominal"},
    {"Modelica.Mechanics.Rotational.Sources.QuadraticSpeedDependentTorque", "tau_nominal w_nominal"},
    {"Modelica.Mechanics.Rotational.Sources.SignTorque", "tau_nominal"},
    {"Modelica.Mechanics.Rotational.Sources.EddyCurrentTorque", "tau_max w_max"},
    {"Modelica.Mechanics.Translational.Components.Mass", "m"},
    {"Modelica.Mechanics.Translational.Components.Spring", "c"},
    {"Modelica.Mechanics.Translational.Components.Damper", "d"},
    {"Modelica.Mechanics.Translational.Components.SpringDamper", "c d"},
    {"Modelica.Thermal.HeatTransfer.Components.HeatCapacitor", "C"},
    {"Modelica.Blocks.Sources.Constant", "k"},
    {"Modelica.Blocks.Sources.Ramp", "duration"},
    {"Modelica.Blocks.Sources.Sine", "f"},
    {"Modelica.Blocks.Sources.Cosine", "f"},
    {"Modelica.Blocks.Sources.Pulse", "width period"},
    {"Modelica.Blocks.Math.Gain", "k"},
    {"Modelica.Blocks.Nonlinear.Limiter", "uMax"},
    {"Modelica.Blocks.Continuous.FirstOrder", "T"},
};

// Conditional connectors: class, connector, switch, its default.
struct Conditional {
  const char* path;
  const char* connector;
  const char* parameter;
  bool default_value;
};
const Conditional kConditional[] = {
    {"Modelica.Mechanics.Rotational.Components.IdealGear", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Components.LossyGear", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Components.LossyGear", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Rotational.Components.Gearbox", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Components.AngleToTorqueAdaptor", "a", "use_a", true},
    {"Modelica.Mechanics.Rotational.Components.TorqueToAngleAdaptor", "w", "use_w", true},
    {"Modelica.Mechanics.Rotational.Components.TorqueToAngleAdaptor", "a", "use_a", true},
    {"Modelica.Mechanics.Rotational.Components.Gearbox", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Rotational.Components.IdealGearR2T", "supportR", "useSupportR", false},
    {"Modelica.Mechanics.Rotational.Components.IdealGearR2T", "supportT", "useSupportT", false},
    {"Modelica.Mechanics.Rotational.Components.IdealRollingWheel", "supportR", "useSupportR", false},
    {"Modelica.Mechanics.Rotational.Components.IdealRollingWheel", "supportT", "useSupportT", false},
    {"Modelica.Mechanics.Rotational.Components.Damper", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Rotational.Components.SpringDamper", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Rotational.Components.ElastoBacklash", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Rotational.Components.ElastoBacklash2", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Rotational.Components.BearingFriction", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Components.BearingFriction", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Rotational.Components.Brake", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Components.Brake", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Rotational.Components.Clutch", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Rotational.Components.OneWayClutch", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Rotational.Components.InitializeFlange", "phi_start", "use_phi_start", true},
    {"Modelica.Mechanics.Rotational.Components.InitializeFlange", "w_start", "use_w_start", true},
    {"Modelica.Mechanics.Rotational.Components.InitializeFlange", "a_start", "use_a_start", true},
    {"Modelica.Mechanics.Rotational.Sources.Torque", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.Speed", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.Position", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.Accelerate", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.Move", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.ConstantTorque", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.ConstantSpeed", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.TorqueStep", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.LinearSpeedDependentTorque", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.QuadraticSpeedDependentTorque", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.SignTorque", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.EddyCurrentTorque", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Sources.EddyCurrentTorque", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Translational.Components.Damper", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Translational.Components.SpringDamper", "heatPort", "useHeatPort", false},
    {"Modelica.Mechanics.Translational.Sources.Force", "support", "useSupport", false},
    {"Modelica.Blocks.Continuous.Integrator", "reset", "use_reset", false},
    {"Modelica.Blocks.Continuous.Integrator", "set", "use_set", false},  // if use_reset and use_set
    // The partial classes the HighLift classes extend.
    {"Modelica.Mechanics.Rotational.Interfaces.PartialTwoFlangesAndSupport", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialOneFlangeAndSupport", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialElementaryTwoFlangesAndSupport2", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialElementaryOneFlangeAndSupport2", "support", "useSupport", false},
    {"Modelica.Mechanics.Rotational.Interfaces.PartialTorque", "support", "useSupport", false},
    {"Modelica.Thermal.HeatTransfer.Interfaces.PartialElementaryConditionalHeatPortWithoutT", "heatPort", "useHeatPort",
     false},
};

}  // namespace

std::vector<std::string> RequiredParameters(std::string_view path) {
  std::vector<std::string> out;
  for (const Required& r : kRequired) {
    if (path != r.path) continue;
    std::istringstream names(r.parameters);
    for (std::string n; names >> n;) out.push_back(n);
  }
  return out;
}

std::vector<ConditionalConnector> ConditionalConnectors(std::string_view path) {
  std::vector<ConditionalConnector> out;
  for (const Conditional& c : kConditional)
    if (path == c.path) out.push_back({c.connector, c.parameter, c.default_value});
  return out;
}

std::string ToString(ConnectorKind kind) {
  switch (kind) {
    case ConnectorKind::kRotational: return "rotational flange";
    case ConnectorKind::kTranslational: return "translational flange";
    case ConnectorKind::kRealInput: return "Real input";
    case ConnectorKind::kRealOutput: return "Real output";
    case ConnectorKind::kBooleanInput: return "Boolean input";
    case ConnectorKind::kBooleanOutput: return "Boolean output";
    case ConnectorKind::kIntegerOutput: return "Integer output";
    case ConnectorKind::kHeat: return "heat port";
    case ConnectorKind::kHydraulic: return "hydraulic port";
  }
  return "connector";
}

bool Compatible(ConnectorKind a, ConnectorKind b) {
  auto signal = [](ConnectorKind k, ConnectorKind in, ConnectorKind out) { return k == in || k == out; };
  if (signal(a, ConnectorKind::kRealInput, ConnectorKind::kRealOutput))
    return signal(b, ConnectorKind::kRealInput, ConnectorKind::kRealOutput);
  if (signal(a, ConnectorKind::kBooleanInput, ConnectorKind::kBooleanOutput))
    return signal(b, ConnectorKind::kBooleanInput, ConnectorKind::kBooleanOutput);
  return a == b;
}

}  // namespace highlift::msl
