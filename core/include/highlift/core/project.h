// A drive-system project: the component graph (structure), the parameter values and domains,
// requirements, load cases, scenarios and settings. Structure and values are kept apart: the
// graph says what is connected; Parameter holds what is known about a value.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "highlift/core/catalogue.h"
#include "highlift/core/domain.h"
#include "highlift/core/error.h"

namespace highlift {

/// What is known about one parameter of one component, in SI.
struct Parameter {
  std::optional<double> nominal;  ///< point value when known
  Domain domain;                  ///< interval domain (contains nominal when both are set)
  Provenance provenance = Provenance::kDefault;
  std::string note;               ///< where it came from, e.g. "domain.md s3 (E)", "db part GRA-200"
  std::string database_part;      ///< designation of a database part this value refers to, if any
  bool design = false;            ///< a design variable of `highlift optimize` ("design": true)
  SourceLocation where;           ///< where it was given in the project file (empty if not given)
};

/// One instance of a catalogue component type (or, in an element network, of an element type).
struct Component {
  std::string id;                 ///< unique in the project, e.g. "shaft_l3", "wtb_left"
  std::string type;               ///< catalogue type name
  std::string description;
  std::map<std::string, Parameter> parameters;  ///< every scalar/integer/boolean parameter, by name
  std::map<std::string, std::vector<std::vector<double>>> tables;  ///< table parameters (SI)
  std::map<std::string, std::string> texts;     ///< text parameters
  std::map<std::string, std::string> labels;    ///< free metadata: "side": "left", "station": "3"
  SourceLocation where;
};

/// A connection of two ports: "component.port".
struct PortRef {
  std::string component;
  std::string port;
  std::string ToString() const { return component + "." + port; }
  friend bool operator==(const PortRef&, const PortRef&) = default;
  friend auto operator<=>(const PortRef&, const PortRef&) = default;
};

struct Connection {
  PortRef a;
  PortRef b;
  SourceLocation where;
};

/// A requirement: an inequality or equation over named quantities, in the icsp constraint
/// language, e.g. "wtb_left.static_capacity >= 1.5 * peak.rupture_wtb.wtb_left".
struct Requirement {
  std::string id;
  std::string expression;
  std::string description;
  SourceLocation where;
};

/// A signal given as a table against time or against flap position (linear interpolation).
struct Table {
  std::string abscissa = "time";      ///< "time" [s] or "position" [0..1 of full travel]
  std::vector<double> x;              ///< SI
  std::vector<double> y;              ///< SI
};

/// A load case: airload per actuator and the PDU speed profile.
struct LoadCase {
  std::string name;
  std::string description;
  std::string direction = "extend";   ///< "extend" or "retract"
  std::map<std::string, Table> actuator_loads;  ///< by actuator component id; output torque [N*m]
  std::optional<Table> pdu_speed;     ///< PDU output speed [rad/s] against time
  std::map<std::string, double> values;  ///< further named scalars in SI
  SourceLocation where;
};

/// The PDU speed command of a load case as table rows {time, speed}, the simulator's and the
/// Modelica export's: the `pdu_speed` profile signed by the direction (retract negative); a
/// single point becomes a constant (two rows); no load case or no profile gives 0.
std::vector<std::vector<double>> SpeedCommandRows(const LoadCase* load_case);

/// The failure kind of a jam scenario and sizing case (Scenario::kind, the peak cases' kind), and
/// the project file's key of its event: written once here. Not the catalogue type "jam" (the
/// ground stop a jam scenario adds), which only its own file names.
inline const std::string kJamKind = "jam";

/// A failure or operating scenario run by the simulator and the peak-load analysis.
struct Scenario {
  std::string name;
  std::string kind;                   ///< "extension", "jam", "rupture"
  std::string description;
  std::string load_case;              ///< name of the load case driving it
  double stop_time = 10.0;            ///< s
  std::optional<double> output_interval;        ///< s, overrides Settings::output_interval
  std::optional<std::string> jam_component;     ///< kind == "jam": the jammed component id
  std::optional<double> jam_time;               ///< s
  std::optional<std::string> rupture_component; ///< kind == "rupture": the disconnector or shaft id
  std::optional<double> rupture_time;           ///< s
  std::string wtb_trigger = "monitor";          ///< "monitor" or "time"
  std::optional<double> wtb_time;               ///< s, when wtb_trigger == "time"
  std::map<std::string, double> values;         ///< further named scalars in SI
  SourceLocation where;
};

/// The run of an element network, as a Modelica `experiment` annotation (StartTime,
/// StopTime, Interval, Tolerance); a scenario, when one is chosen, takes precedence.
struct Experiment {
  double start_time = 0.0;                ///< s
  double stop_time = 1.0;                 ///< s
  std::optional<double> interval;         ///< s, output interval (absent: settings)
  std::optional<double> tolerance;        ///< relative tolerance (absent: settings)
  SourceLocation where;
};

/// Project-wide settings with documented defaults.
struct Settings {
  int shaft_elements = 4;             ///< sub-elements per shaft segment in full-resolution models
  double relative_tolerance = 1e-6;   ///< simulator
  /// Simulator absolute tolerance per unit nominal value (a state's absolute tolerance is this
  /// times its nominal value); absent: the simulator's default (SimulationOptions).
  std::optional<double> absolute_tolerance;
  double output_interval = 1e-3;      ///< s, simulator output step
  /// Simulator start: "given" (the start values) or "steady_state" (every inertia starts with
  /// a = 0, free speeds and twists solved; sim::StartKind).
  std::string initial = "given";
  /// s, stiffness-proportional structural damping beta of the elastic elements of a
  /// transmission that give no damping of their own (d = beta*c): the damping ratio of a mode at
  /// w rad/s is beta*w/2. 4e-4 s: 1.6 % at the 13 Hz first mode of the A380-class example.
  double structural_damping = 4e-4;
  std::map<std::string, double> values;
};

struct Project {
  std::string name;
  std::string description;
  std::vector<std::string> sources;   ///< where the numbers come from (domain.md tags)
  std::vector<Component> components;  ///< drive-system components (catalogue types)
  std::vector<Connection> connections;
  std::vector<Component> elements;    ///< element-level network (element types), may be empty
  std::vector<Connection> element_connections;
  std::vector<Requirement> requirements;
  std::vector<LoadCase> load_cases;
  std::vector<Scenario> scenarios;
  std::optional<Experiment> experiment;  ///< element networks: the Modelica experiment
  Settings settings;
  std::string file;                   ///< path it was loaded from, if any

  const Component* FindComponent(std::string_view id) const;
  Component* FindComponent(std::string_view id);
  const Scenario* FindScenario(std::string_view name) const;
  const LoadCase* FindLoadCase(std::string_view name) const;
};

/// The first difference between two projects, as a readable sentence ("components[2]
/// 'shaft_l1': parameter 'length': nominal 3 vs 3.5"), or "" when they are equal. Source
/// locations (`where`) and `Project::file` are not compared: a project loaded from a file and
/// the same project saved and loaded again are equal. Used by the round-trip tests.
std::string DescribeDifference(const Project& a, const Project& b);

}  // namespace highlift
