// Element networks (MSL element types) to a Modelica model that uses the MSL classes directly,
// with the project's instance names and parameter names, so that a Modelica tool reproduces
// the MSL reference results.
#include <algorithm>
#include <set>
#include <sstream>

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
                          "IdealGearR2T", "IdealRollingWheel", "Disc", "InitializeFlange", "Gearbox",
                          "AngleToTorqueAdaptor", "TorqueToAngleAdaptor"})
      m[c] = rotational + "Components." + c;
    for (const char* c : {"Torque", "Torque2", "ConstantTorque", "TorqueStep", "LinearSpeedDependentTorque",
                          "QuadraticSpeedDependentTorque", "SignTorque",
                          "EddyCurrentTorque", "Speed", "Position", "ConstantSpeed", "Accelerate", "Move"})
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
    // MSL 4.1.0 has it, 4.0.0 not: the HighLift class of the same name and parameters.
    m["InverseSpeedDependentTorque"] = "HighLift.Sources.InverseSpeedDependentTorque";
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

/// The text of a HighLift class file of the embedded library ("HighLift.Mechanical.Jam" ->
/// HighLift/Mechanical/Jam.mo), empty when there is none.
std::string_view HighLiftClassText(const std::string& cls) {
  std::string path = cls;
  std::replace(path.begin(), path.end(), '.', '/');
  path += ".mo";
  for (const auto& [file, text] : EmbeddedLibrary())
    if (file == path) return text;
  return {};
}

/// True when a line of the class text that contains `marker` declares `name` (the word after
/// the type, followed by a blank, '=', '(', ';' or a comment).
bool Declares(std::string_view text, std::string_view marker, const std::string& name) {
  std::size_t line_start = 0;
  while (line_start < text.size()) {
    std::size_t line_end = text.find('\n', line_start);
    if (line_end == std::string_view::npos) line_end = text.size();
    const std::string_view line = text.substr(line_start, line_end - line_start);
    if (const auto at = line.find(marker); at != std::string_view::npos) {
      for (std::size_t pos = line.find(name, at + marker.size()); pos != std::string_view::npos;
           pos = line.find(name, pos + 1)) {
        const char before = line[pos - 1];
        const char after = pos + name.size() < line.size() ? line[pos + name.size()] : ';';
        if ((before == ' ' || before == '\t') && std::string_view(" =(;\"").find(after) != std::string_view::npos)
          return true;
      }
    }
    line_start = line_end + 1;
  }
  return false;
}

bool HighLiftDeclaresParameter(const std::string& cls, const std::string& name) {
  return Declares(HighLiftClassText(cls), "parameter ", name);
}

bool HighLiftDeclaresBooleanConnector(const std::string& cls, const std::string& port) {
  const std::string_view text = HighLiftClassText(cls);
  return Declares(text, "Modelica.Blocks.Interfaces.BooleanInput", port) ||
         Declares(text, "Modelica.Blocks.Interfaces.BooleanOutput", port);
}

/// True when the MSL class declares `name` itself (Integrator.y_start is a parameter, not the
/// start value of a variable y_start), or the HighLift class declares a parameter `name`
/// (DifferentialCylinder.s_start, Volume.p_start).
bool HasModifier(const std::string& cls, const std::string& name) {
  if (cls.rfind("HighLift.", 0) == 0) return HighLiftDeclaresParameter(cls, name);
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

// Integer parameters of the element types that are enumerations of Modelica.Blocks.Types.
std::string EnumerationValue(const std::string& parameter, double value, const std::string& what) {
  static const std::map<std::string, std::pair<std::string, std::vector<std::string>>> enumerations = {
      {"extrapolation", {"Extrapolation", {"HoldLastPoint", "LastTwoPoints", "Periodic", "NoExtrapolation"}}},
      {"smoothness", {"Smoothness", {"LinearSegments", "ContinuousDerivative", "ConstantSegments"}}},
      {"timeEvents", {"TimeEvents", {"Always", "AtDiscontinuities", "NoTimeEvents"}}}};
  auto it = enumerations.find(parameter);
  if (it == enumerations.end()) return {};
  const auto index = static_cast<long long>(value);
  if (index < 1 || index > static_cast<long long>(it->second.second.size()))
    throw InputError(what + " = " + FormatInteger(value) + " is no value of Modelica.Blocks.Types." +
                     it->second.first);
  return "Modelica.Blocks.Types." + it->second.first + "." + it->second.second[index - 1];
}

// Element types whose Modelica class reads its table from a text file when asked
// (Modelica.Blocks.Sources.CombiTimeTable, Modelica.Blocks.Tables.CombiTable1Ds: tableOnFile,
// tableName, fileName).
bool ReadsTableFromFile(const std::string& type) { return type == "CombiTimeTable" || type == "CombiTable1Ds"; }

// Output ports that are vectors in the Modelica class (one table column): port -> "y[1]".
std::string ModelicaPort(const std::string& type, const std::string& port) {
  if ((type == "CombiTimeTable" || type == "CombiTable1Ds") && port == "y") return "y[1]";
  return port;
}

/// Boolean connectors of the HighLift classes (declared Modelica.Blocks.Interfaces.BooleanInput
/// or BooleanOutput in the library). The element network carries every signal as a Real (0/1
/// for a Boolean); where a Real source of the network meets a Boolean connector in Modelica the
/// writer picks the Boolean counterpart of the source block (below).
bool IsBooleanConnector(const std::string& cls, const std::string& port) {
  return cls.rfind("HighLift.", 0) == 0 && HighLiftDeclaresBooleanConnector(cls, port);
}

}  // namespace

ModelOutput WriteNetworkModel(const NetworkModel& network, const std::string& model_name) {
  const auto& elements = *network.elements;
  const auto& connections = *network.connections;
  IdentifierMap ids({model_name, "Modelica", "HighLift", "time"});
  std::map<std::string, const model::NetworkElement*> by_id;
  // Ids that are identifiers already keep them; the others (shaft_l1.m1, Real, ...) then take
  // their sanitised name, or, where an id of the first kind holds it, the next free one. So a
  // project id equal to a generated name ("shaft_l1_m1") is never renamed, whatever the order.
  for (const bool valid : {true, false})
    for (const auto& e : elements)
      if (IsModelicaIdentifier(e.id) == valid) ids.Add(e.id);
  for (const auto& e : elements) by_id[e.id] = &e;
  auto class_of = [&](const model::NetworkElement& e) -> const std::string& {
    const auto cls = ClassOfElementType().find(e.type);
    if (cls == ClassOfElementType().end())
      throw InputError("element '" + e.id + "': element type '" + e.type +
                       "' has no Modelica class in the exporter (export/src/"
                       "element_network_writer.cc); use a type listed by 'highlift info --elements'");
    return cls->second;
  };

  // Which ports are connected (support flanges switch useSupport on), and which signal outputs
  // feed a Boolean connector or are fed by one.
  std::set<std::pair<std::string, std::string>> connected, feeds_boolean, fed_by_boolean;
  for (const auto& c : connections) {
    connected.insert({c.a.component, c.a.port});
    connected.insert({c.b.component, c.b.port});
    for (const auto& [x, y] : {std::pair{&c.a, &c.b}, std::pair{&c.b, &c.a}}) {
      auto other = by_id.find(y->component);
      if (other == by_id.end() || !IsBooleanConnector(class_of(*other->second), y->port)) continue;
      feeds_boolean.insert({x->component, x->port});
      fed_by_boolean.insert({x->component, x->port});
    }
  }
  // A Real source of the network in front of Boolean inputs, or a unit gain behind a Boolean
  // output, is written as its Boolean counterpart.
  auto boolean_counterpart = [&](const model::NetworkElement& e) -> std::string {
    const auto& s = e.parameters.scalars;
    auto value = [&](const char* name) {
      auto it = s.find(name);
      return it == s.end() ? 0.0 : it->second;
    };
    if (e.type == "Step" && feeds_boolean.count({e.id, "y"}) && value("height") == 1 && value("offset") == 0)
      return "Modelica.Blocks.Sources.BooleanStep";
    if (e.type == "Gain" && fed_by_boolean.count({e.id, "u"}) && value("k") == 1)
      return "Modelica.Blocks.Math.BooleanToReal";
    return {};
  };

  // The start: an Inertia (Mass) gets phi(start, fixed) and w(start, fixed) (s and v), any
  // other flange initial equations on its angle and its derivative.
  std::map<std::string, std::vector<Modifier>> start_modifiers;
  std::vector<std::string> start_equations;
  if (network.start != nullptr) {
    for (const model::FlangeStart& f : network.start->flanges) {
      auto owner = by_id.find(f.flange.component);
      if (owner == by_id.end())
        throw InternalError("start value for flange '" + f.flange.ToString() + "', which is in no element");
      const std::string& type = owner->second->type;
      const bool translational = type == "Mass" || type.rfind("Translational.", 0) == 0;
      const std::string what = "start of " + f.flange.ToString();
      if (type == "Inertia" || type == "Mass") {
        auto& mods = start_modifiers[f.flange.component];
        if (f.phi) mods.push_back({translational ? "s" : "phi", "", {{"start", FormatModelicaReal(*f.phi, what)}, {"fixed", "true"}}});
        if (f.w) mods.push_back({translational ? "v" : "w", "", {{"start", FormatModelicaReal(*f.w, what)}, {"fixed", "true"}}});
        continue;
      }
      const std::string angle = ids.Get(f.flange.component) + "." + ModelicaPort(type, f.flange.port) +
                                (translational ? ".s" : ".phi");
      if (f.phi) start_equations.push_back(angle + " = " + FormatModelicaReal(*f.phi, what) + ";");
      if (f.w) start_equations.push_back("der(" + angle + ") = " + FormatModelicaReal(*f.w, what) + ";");
    }
  }

  ModelWriter writer(model_name);
  std::ostringstream table_file;
  writer.SetWithin(kModelsPackage);
  std::vector<std::pair<std::string, std::string>> extra_connects;
  std::vector<std::string> initial_equations;
  for (const auto& e : elements) {
    const std::string& cls = class_of(e);
    const ComponentTypeSpec* spec = e.spec ? e.spec : FindElementType(e.type);
    const std::string name = ids.Get(e.id);
    if (const std::string boolean = boolean_counterpart(e); !boolean.empty()) {
      Instance inst{boolean, name, {}, e.description};
      if (e.type == "Step")  // BooleanStep: false before startTime, true from then on
        inst.modifiers.push_back({"startTime", FormatModelicaReal(e.parameters.scalars.at("startTime")), {}});
      writer.AddInstance(inst);
      continue;
    }
    Instance inst{cls, name, {}, e.description};
    bool heat_port = false;
    auto given = [&](const std::string& parameter) {
      auto it = e.given.find(parameter);
      return it != e.given.end() && it->second;
    };
    if (spec) {
      for (const ParameterSpec& p : spec->parameters) {
        const std::string what = "element '" + e.id + "' parameter '" + p.name + "'";
        if (p.kind == ParameterKind::kTable) {
          auto t = e.parameters.tables.find(p.name);
          if (t == e.parameters.tables.end()) continue;  // MSL default table
          // Only the MSL table blocks read a table from a file (tableOnFile); any other
          // table parameter (a Brake's mu_pos) stays a matrix modifier.
          if (network.tables_in_file && ReadsTableFromFile(e.type)) {
            const auto& rows = t->second;
            table_file << "double " << name << "(" << rows.size() << "," << (rows.empty() ? 0 : rows[0].size()) << ")\n";
            for (const auto& row : rows) {
              for (std::size_t i = 0; i < row.size(); ++i) table_file << (i ? " " : "") << FormatModelicaReal(row[i], name);
              table_file << "\n";
            }
            inst.modifiers.push_back({"tableOnFile", "true", {}});
            inst.modifiers.push_back({"tableName", "\"" + EscapeModelicaString(name) + "\"", {}});
            inst.modifiers.push_back(
                {"fileName", "Modelica.Utilities.Files.loadResource(\"modelica://" + std::string(kModelsFolder) + "/" +
                                     model_name + ".txt\")", {}});
          } else {
            inst.modifiers.push_back({p.name, FormatMatrix(t->second, "element '" + e.id + "' table '" + p.name + "'"), {}});
          }
          continue;
        }
        if (p.kind == ParameterKind::kText) continue;
        if (!given(p.name)) continue;  // the class default, which is the element type's default
        if (IsHeatCapacitorParameter(p.name)) continue;
        auto it = e.parameters.scalars.find(p.name);
        if (it == e.parameters.scalars.end()) continue;
        const double v = it->second;
        const bool start_flag = p.name.size() > 6 && p.name.substr(p.name.size() - 6) == "_fixed" &&
                                !HasModifier(cls, p.name);
        if (p.kind == ParameterKind::kBoolean && start_flag) {
          continue;  // phi_fixed = false: the `fixed` attribute of phi_start's modifier
        } else if (p.kind == ParameterKind::kBoolean) {
          if (p.name == "useHeatPort") heat_port = v != 0.0;
          inst.modifiers.push_back({p.name, v != 0.0 ? "true" : "false", {}});
        } else if (p.kind == ParameterKind::kInteger) {
          const std::string enumeration = EnumerationValue(p.name, v, what);
          inst.modifiers.push_back({p.name, enumeration.empty() ? FormatInteger(v) : enumeration, {}});
        } else if (p.name.size() > 6 && p.name.substr(p.name.size() - 6) == "_start" && !HasModifier(cls, p.name)) {
          // Initial values: MSL start values with fixed=true; a speed the class has no
          // variable for (Spring: w_rel) becomes an initial equation on the derivative.
          const std::string variable = p.name.substr(0, p.name.size() - 6);
          const auto known = MslModifiers(cls);
          const bool msl = cls.rfind("Modelica.", 0) == 0;
          auto fixed_flag = e.parameters.scalars.find(variable + "_fixed");
          const bool fixed = fixed_flag == e.parameters.scalars.end() || fixed_flag->second != 0.0;
          if (!msl || std::find(known.begin(), known.end(), variable) != known.end()) {
            inst.modifiers.push_back(
                {variable, "", {{"start", FormatModelicaReal(v, what)}, {"fixed", fixed ? "true" : "false"}}});
          } else if (variable == "w_rel" || variable == "w" || variable == "v_rel" || variable == "v") {
            const std::string position = variable == "w" ? ".phi" : variable == "w_rel" ? ".phi_rel"
                                         : variable == "v" ? ".s" : ".s_rel";
            initial_equations.push_back("der(" + inst.name + position + ") = " + FormatModelicaReal(v, what) + ";");
          } else {
            throw InputError("element '" + e.id + "' (" + e.type + "): initial value '" + p.name +
                             "' has no variable in " + cls + "; leave it out");
          }
        } else if (p.name.size() > 8 && p.name.substr(p.name.size() - 8) == "_nominal" &&
                   !HasModifier(cls, p.name)) {
          // A nominal value the class has no parameter for: the attribute of the variable
          // (Inertia: phi(nominal = ...); Spring: phi_rel(nominal = ...)).
          std::string variable = p.name.substr(0, p.name.size() - 8);
          const auto known = MslModifiers(cls);
          if (std::find(known.begin(), known.end(), variable) == known.end()) variable += "_rel";
          inst.modifiers.push_back({variable, "", {{"nominal", FormatModelicaReal(v, what)}}});
        } else {
          inst.modifiers.push_back({p.name, FormatModelicaReal(v, what), {}});
        }
      }
    }
    if (auto it = start_modifiers.find(e.id); it != start_modifiers.end()) {
      for (const Modifier& m : it->second) {
        const bool taken = std::any_of(inst.modifiers.begin(), inst.modifiers.end(),
                                       [&](const Modifier& x) { return x.name == m.name; });
        HIGHLIFT_CHECK(!taken, "element '" + e.id + "': a start value of " + m.name + " given twice");
        inst.modifiers.push_back(m);
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
      if (auto it = e.parameters.scalars.find("C_heatPort"); it != e.parameters.scalars.end() && given("C_heatPort"))
        C = it->second;
      if (auto it = e.parameters.scalars.find("T_heatPort_start");
          it != e.parameters.scalars.end() && given("T_heatPort_start"))
        T0 = it->second;
      writer.AddInstance({"Modelica.Thermal.HeatTransfer.Components.HeatCapacitor", cap,
                          {{"C", FormatModelicaReal(C, "C_heatPort"), {}},
                           {"T", "", {{"start", FormatModelicaReal(T0, "T_heatPort_start")}, {"fixed", "true"}}}},
                          "heat capacity on the heat port of " + e.id});
      extra_connects.emplace_back(ids.Get(e.id) + ".heatPort", cap + ".port");
    }
  }
  for (const auto& c : connections) {
    auto end = [&](const PortRef& p) { return ids.Get(p.component) + "." + ModelicaPort(by_id.at(p.component)->type, p.port); };
    writer.AddConnect(end(c.a), end(c.b));
  }
  for (auto& [a, b] : extra_connects) writer.AddConnect(a, b);
  for (auto& e : initial_equations) writer.AddInitialEquation(std::move(e));
  for (auto& e : start_equations) writer.AddInitialEquation(std::move(e));

  writer.SetExperiment(network.experiment);
  writer.SetDescription(network.description);
  ModelOutput out;
  out.renamed = ids.Renamed();
  if (network.documentation) writer.SetDocumentation(network.documentation(out.renamed));
  out.text = writer.Render();
  out.instances = writer.instance_count();
  out.connects = writer.connect_count();
  if (network.tables_in_file)
    out.extra_files.push_back({std::string(kModelsFolder) + "/" + model_name + ".txt", "#1\n" + table_file.str()});
  if (network.start != nullptr) out.start = network.start->summary;
  return out;
}

ModelOutput WriteElementNetwork(const Project& project, const std::string& model_name,
                                const ModelicaExportOptions& options) {
  // The project's elements as network elements: the parameters given in the project file are
  // written, the defaults are the classes' own.
  std::vector<model::NetworkElement> elements;
  std::set<std::string> ids;
  for (const auto& e : project.elements) {
    if (!ClassOfElementType().count(e.type))
      throw InputError("element '" + e.id + "': element type '" + e.type +
                           "' has no Modelica class in the exporter (export/src/"
                           "element_network_writer.cc); use a type listed by 'highlift info --elements'",
                       e.where);
    model::NetworkElement x;
    x.id = e.id;
    x.type = e.type;
    x.spec = FindElementType(e.type);
    x.description = e.description;
    ids.insert(e.id);
    if (x.spec) {
      for (const ParameterSpec& p : x.spec->parameters) {
        if (p.kind == ParameterKind::kTable) {
          if (auto t = e.tables.find(p.name); t != e.tables.end()) x.parameters.tables[p.name] = t->second;
          continue;
        }
        if (p.kind == ParameterKind::kText) continue;
        auto it = e.parameters.find(p.name);
        if (it == e.parameters.end()) continue;
        if (it->second.provenance == Provenance::kDefault) {
          if (!it->second.nominal && !p.optional)
            throw InputError("element '" + e.id + "' (" + e.type + "): parameter '" + p.name +
                                 "' has no value and no default: give it in the project file",
                             e.where);
          continue;  // the MSL default applies
        }
        x.parameters.scalars[p.name] = RequireValue(e, p.name);
        x.given[p.name] = true;
      }
    }
    elements.push_back(std::move(x));
  }
  std::vector<model::NetworkConnection> connections;
  for (const auto& c : project.element_connections) {
    if (!ids.count(c.a.component) || !ids.count(c.b.component))
      throw InputError("element connection " + c.a.ToString() + " - " + c.b.ToString() +
                           ": refers to an unknown element; connect elements listed under 'elements'",
                       c.where);
    connections.push_back({c.a, c.b});
  }

  NetworkModel network;
  network.elements = &elements;
  network.connections = &connections;
  network.description = project.name;
  const Scenario* scenario = SelectScenario(project, options);
  Experiment& experiment = network.experiment;
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
  network.documentation = [&](const std::map<std::string, std::string>& renamed) {
    std::string doc = "<html>\n<p>Element network of the highlift project <strong>" + HtmlEscape(project.name) +
                      "</strong>, exported by <code>highlift export</code>. Every element is the Modelica "
                      "Standard Library 4.0.0 class of its element type, with the project's instance "
                      "names and parameters.</p>\n";
    if (!project.description.empty()) doc += "<p>" + HtmlEscape(project.description) + "</p>\n";
    if (!renamed.empty()) {
      doc += "<p>Renamed to valid Modelica identifiers:</p>\n<ul>\n";
      for (const auto& [from, to] : renamed) doc += "<li>" + HtmlEscape(from) + " &rarr; " + to + "</li>\n";
      doc += "</ul>\n";
    }
    return doc + "</html>";
  };
  ModelOutput out = WriteNetworkModel(network, model_name);
  if (scenario) out.scenario = scenario->name;
  return out;
}

}  // namespace highlift::modelica_detail
