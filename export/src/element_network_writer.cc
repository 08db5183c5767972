// Element networks (MSL element types) to a Modelica model that uses the MSL classes directly,
// with the project's instance names and parameter names, so that a Modelica tool reproduces
// the MSL reference results.
#include <algorithm>
#include <set>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/export/modelica_check.h"
#include "model_writer.h"
#include "writers.h"

namespace highlift::modelica_detail {
namespace {

// Element type -> Modelica class.
const std::map<std::string, std::string>& ClassOfElementType() {
  static const std::map<std::string, std::string> classes = [] {
    std::map<std::string, std::string> m;
    const std::string rotational = "Modelica.Mechanics.Rotational.";
    for (const char* c : {"Fixed", "Inertia", "Spring", "Damper", "SpringDamper", "ElastoBacklash",
                          "ElastoBacklash2", "IdealGear", "IdealPlanetary", "LossyGear",
                          "BearingFriction", "Brake", "Clutch", "OneWayClutch", "RelativeStates",
                          "IdealGearR2T", "IdealRollingWheel"})
      m[c] = rotational + "Components." + c;
    for (const char* c : {"Torque", "ConstantTorque", "TorqueStep", "LinearSpeedDependentTorque",
                          "QuadraticSpeedDependentTorque", "SignTorque", "EddyCurrentTorque", "Speed",
                          "Position", "ConstantSpeed", "Accelerate", "Move"})
      m[c] = rotational + "Sources." + c;
    for (const char* c : {"AngleSensor", "SpeedSensor", "AccSensor", "TorqueSensor", "RelAngleSensor",
                          "RelSpeedSensor", "RelAccSensor", "PowerSensor", "MultiSensor"})
      m[c] = rotational + "Sensors." + c;
    for (const char* c : {"Constant", "Step", "Ramp", "Sine", "Cosine", "Pulse", "TimeTable"})
      m[c] = std::string("Modelica.Blocks.Sources.") + c;
    for (const char* c : {"Product", "Feedback", "Gain", "Add"})
      m[c] = std::string("Modelica.Blocks.Math.") + c;
    // k and y_start are parameters of the MSL class; its default initType InitialState gives
    // y = y_start at the start, as the simulator's Integrator.
    m["Integrator"] = "Modelica.Blocks.Continuous.Integrator";
    for (const char* c : {"ShaftBrake", "NonlinearSpring", "TorqueLimiter", "LossyInertia",
                          "StribeckFriction", "GeneralRotationalElement", "GearedRotaryActuator",
                          "BranchGearbox", "WingTipBrake", "Disconnector", "Jam"})
      m[c] = std::string("HighLift.Mechanical.") + c;
    for (const char* c : {"BrakeActuation", "Monitoring"}) m[c] = std::string("HighLift.Control.") + c;
    m["PDU"] = "HighLift.Drives.PDU";
    for (const char* c : {"PressureSource", "Tank", "TurbulentResistance", "ServoValve",
                          "DifferentialCylinder", "VariableDisplacementMotor", "Volume",
                          "MotorSpeedControl"})
      m[c] = std::string("HighLift.Hydraulics.") + c;
    const std::string translational = "Modelica.Mechanics.Translational.";
    for (const char* c : {"Mass", "Fixed", "Spring", "Damper", "SpringDamper"})
      m[std::string(c) == "Mass" ? c : std::string("Translational.") + c] = translational + "Components." + c;
    m["Translational.Force"] = translational + "Sources.Force";
    for (const char* c : {"PositionSensor", "SpeedSensor"})
      m[std::string("Translational.") + c] = translational + "Sensors." + c;
    m["CombiTimeTable"] = "Modelica.Blocks.Sources.CombiTimeTable";
    m["CombiTable1Ds"] = "Modelica.Blocks.Tables.CombiTable1Ds";
    return m;
  }();
  return classes;
}

/// True when the MSL class declares `name` itself (Integrator.y_start is a parameter, not the
/// start value of a variable y_start).
bool HasModifier(const std::string& cls, const std::string& name) {
  if (cls.rfind("Modelica.", 0) != 0) return false;
  const auto known = MslModifiers(cls);
  return std::find(known.begin(), known.end(), name) != known.end();
}

std::string FormatInteger(double value) { return std::to_string(static_cast<long long>(value)); }

// Conditional inputs whose switch is a parameter of the Modelica class but not of the element
// type (the simulator enables the input by its connection): element type, input, switch.
struct ConditionalInput {
  const char* type;
  const char* input;
  const char* parameter;
};
constexpr ConditionalInput kConditionalInputs[] = {{"PDU", "stop", "useStopInput"}};

// Parameters of EddyCurrentTorque that belong to the heat capacitor we add beside it.
bool IsHeatCapacitorParameter(const std::string& name) {
  return name == "C_heatPort" || name == "T_heatPort_start";
}

}  // namespace

ModelOutput WriteElementNetwork(const Project& project, const std::string& model_name,
                                const ModelicaExportOptions& options) {
  ModelOutput out;
  const Scenario* scenario = SelectScenario(project, options);
  if (scenario) out.scenario = scenario->name;

  IdentifierMap ids({model_name, "Modelica", "HighLift", "time"});
  for (const auto& e : project.elements) ids.Add(e.id);

  // Which ports are connected (support flanges switch useSupport on).
  std::set<std::pair<std::string, std::string>> connected;
  for (const auto& c : project.element_connections) {
    connected.insert({c.a.component, c.a.port});
    connected.insert({c.b.component, c.b.port});
  }

  ModelWriter writer(model_name);
  std::vector<std::pair<std::string, std::string>> extra_connects;
  std::vector<std::string> initial_equations;
  for (const auto& e : project.elements) {
    const auto cls = ClassOfElementType().find(e.type);
    if (cls == ClassOfElementType().end())
      throw InputError("element '" + e.id + "': element type '" + e.type +
                           "' has no Modelica class in the exporter (export/src/"
                           "element_network_writer.cc); use a type listed by 'highlift info --elements'",
                       e.where);
    const ComponentTypeSpec* spec = FindElementType(e.type);
    Instance inst{cls->second, ids.Get(e.id), {}, e.description};
    bool heat_port = false;
    if (spec) {
      for (const ParameterSpec& p : spec->parameters) {
        if (p.kind == ParameterKind::kTable) {
          auto t = e.tables.find(p.name);
          if (t == e.tables.end()) continue;  // MSL default table
          inst.modifiers.push_back({p.name, FormatMatrix(t->second, "element '" + e.id + "' table '" + p.name + "'"), {}});
          continue;
        }
        if (p.kind == ParameterKind::kText) continue;
        auto it = e.parameters.find(p.name);
        if (it == e.parameters.end()) continue;
        const Parameter& value = it->second;
        if (value.provenance == Provenance::kDefault) {
          if (!value.nominal && !p.optional)
            throw InputError("element '" + e.id + "' (" + e.type + "): parameter '" + p.name +
                                 "' has no value and no default: give it in the project file",
                             e.where);
          continue;  // the MSL default applies
        }
        if (IsHeatCapacitorParameter(p.name)) continue;
        const double v = RequireValue(e, p.name);
        const std::string what = "element '" + e.id + "' parameter '" + p.name + "'";
        const bool start_flag = p.name.size() > 6 && p.name.substr(p.name.size() - 6) == "_fixed" &&
                                !HasModifier(cls->second, p.name);
        if (p.kind == ParameterKind::kBoolean && start_flag) {
          continue;  // phi_fixed = false: the `fixed` attribute of phi_start's modifier
        } else if (p.kind == ParameterKind::kBoolean) {
          if (p.name == "useHeatPort") heat_port = v != 0.0;
          inst.modifiers.push_back({p.name, v != 0.0 ? "true" : "false", {}});
        } else if (p.kind == ParameterKind::kInteger) {
          inst.modifiers.push_back({p.name, FormatInteger(v), {}});
        } else if (p.name.size() > 6 && p.name.substr(p.name.size() - 6) == "_start" &&
                   !HasModifier(cls->second, p.name)) {
          // Initial values: MSL start values with fixed=true; a speed the class has no
          // variable for (Spring: w_rel) becomes an initial equation on the derivative.
          const std::string variable = p.name.substr(0, p.name.size() - 6);
          const auto known = MslModifiers(cls->second);
          const bool msl = cls->second.rfind("Modelica.", 0) == 0;
          auto fixed_flag = e.parameters.find(variable + "_fixed");
          const bool fixed = fixed_flag == e.parameters.end() || !fixed_flag->second.nominal ||
                             *fixed_flag->second.nominal != 0.0;
          if (!msl || std::find(known.begin(), known.end(), variable) != known.end()) {
            inst.modifiers.push_back(
                {variable, "", {{"start", FormatModelicaReal(v, what)}, {"fixed", fixed ? "true" : "false"}}});
          } else if (variable == "w_rel" || variable == "w" || variable == "v_rel" || variable == "v") {
            const std::string position = variable == "w" ? ".phi" : variable == "w_rel" ? ".phi_rel"
                                         : variable == "v" ? ".s" : ".s_rel";
            initial_equations.push_back("der(" + inst.name + position + ") = " + FormatModelicaReal(v, what) + ";");
          } else {
            throw InputError("element '" + e.id + "' (" + e.type + "): initial value '" + p.name +
                                 "' has no variable in " + cls->second + "; leave it out",
                             e.where);
          }
        } else if (p.name.size() > 8 && p.name.substr(p.name.size() - 8) == "_nominal" &&
                   !HasModifier(cls->second, p.name)) {
          // A nominal value the class has no parameter for: the attribute of the variable
          // (Inertia: phi(nominal = ...); Spring: phi_rel(nominal = ...)).
          std::string variable = p.name.substr(0, p.name.size() - 8);
          const auto known = MslModifiers(cls->second);
          if (std::find(known.begin(), known.end(), variable) == known.end()) variable += "_rel";
          inst.modifiers.push_back({variable, "", {{"nominal", FormatModelicaReal(v, what)}}});
        } else {
          inst.modifiers.push_back({p.name, FormatModelicaReal(v, what), {}});
        }
      }
    }
    // A connected support switches its useSupport on (useSupportR, useSupportT of the
    // rotational-translational gears).
    for (const char* support : {"support", "supportR", "supportT"})
      if (connected.count({e.id, support}))
        inst.modifiers.push_back({std::string("useS") + (support + 1), "true", {}});
    for (const ConditionalInput& input : kConditionalInputs)
      if (e.type == input.type && connected.count({e.id, input.input}))
        inst.modifiers.push_back({input.parameter, "true", {}});
    writer.AddInstance(inst);
    if (heat_port) {
      // The heat port of the eddy current brake goes into a lumped heat capacitor.
      const std::string cap = ids.Add(e.id + "_heatCapacitor");
      double C = 1.0, T0 = 293.15;
      if (auto it = e.parameters.find("C_heatPort"); it != e.parameters.end() && it->second.nominal)
        C = *it->second.nominal;
      if (auto it = e.parameters.find("T_heatPort_start"); it != e.parameters.end() && it->second.nominal)
        T0 = *it->second.nominal;
      writer.AddInstance({"Modelica.Thermal.HeatTransfer.Components.HeatCapacitor", cap,
                          {{"C", FormatModelicaReal(C, "C_heatPort"), {}},
                           {"T", "", {{"start", FormatModelicaReal(T0, "T_heatPort_start")}, {"fixed", "true"}}}},
                          "heat capacity on the heat port of " + e.id});
      extra_connects.emplace_back(ids.Get(e.id) + ".heatPort", cap + ".port");
    }
  }
  for (const auto& c : project.element_connections) {
    if (!ids.Contains(c.a.component) || !ids.Contains(c.b.component))
      throw InputError("element connection " + c.a.ToString() + " - " + c.b.ToString() +
                           ": refers to an unknown element; connect elements listed under 'elements'",
                       c.where);
    writer.AddConnect(ids.Get(c.a.component) + "." + c.a.port, ids.Get(c.b.component) + "." + c.b.port);
  }
  for (auto& [a, b] : extra_connects) writer.AddConnect(a, b);
  for (auto& e : initial_equations) writer.AddInitialEquation(std::move(e));

  Experiment experiment;
  experiment.tolerance = project.settings.relative_tolerance;
  experiment.interval = project.settings.output_interval;
  if (scenario) {
    experiment.stop_time = scenario->stop_time;
    if (scenario->output_interval) experiment.interval = *scenario->output_interval;  // as `highlift simulate`
  } else if (project.experiment) {  // the project's own experiment annotation
    experiment.stop_time = project.experiment->stop_time;
    if (project.experiment->interval) experiment.interval = *project.experiment->interval;
    if (project.experiment->tolerance) experiment.tolerance = *project.experiment->tolerance;
  } else if (auto it = project.settings.values.find("stop_time"); it != project.settings.values.end()) {
    experiment.stop_time = it->second;
  }
  writer.SetExperiment(experiment);
  writer.SetDescription(project.name);
  std::string doc = "<html>\n<p>Element network of the highlift project <strong>" + HtmlEscape(project.name) +
                    "</strong>, exported by <code>highlift export</code>. Every element is the Modelica "
                    "Standard Library 4.0.0 class of its element type, with the project's instance "
                    "names and parameters.</p>\n";
  if (!project.description.empty()) doc += "<p>" + HtmlEscape(project.description) + "</p>\n";
  const auto renamed = ids.Renamed();
  if (!renamed.empty()) {
    doc += "<p>Renamed to valid Modelica identifiers:</p>\n<ul>\n";
    for (const auto& [from, to] : renamed) doc += "<li>" + HtmlEscape(from) + " &rarr; " + to + "</li>\n";
    doc += "</ul>\n";
  }
  writer.SetDocumentation(doc + "</html>");
  out.text = writer.Render();
  out.renamed = renamed;
  out.instances = writer.instance_count();
  out.connects = writer.connect_count();
  return out;
}

}  // namespace highlift::modelica_detail
