// The maintained list of Modelica Standard Library 4.0.0 names the exporter and the HighLift
// library may use: classes with their parameters/modifiable variables and connectors, unit
// types, functions and constants. The structural checker rejects any other `Modelica.` name.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace highlift::msl {

/// Physical domain of a connector, so that connect() between two kinds can be checked.
enum class ConnectorKind {
  kRotational,     // Rotational Flange_a/Flange_b/Support
  kTranslational,  // Translational Flange_a/Flange_b/Support
  kRealInput,
  kRealOutput,
  kBooleanInput,
  kBooleanOutput,
  kIntegerOutput,
  kHeat,           // HeatPort
  kHydraulic,      // HighLift.Hydraulics.Interfaces.Port (library only)
};

struct Connector {
  std::string name;
  ConnectorKind kind;
};

struct MslClass {
  std::string path;                    // full name, "Modelica.Mechanics.Rotational.Components.Inertia"
  std::string kind;                    // "model", "block", "partial", "connector", "type",
                                       // "function", "constant", "package", "record", "enum"
  std::vector<std::string> modifiers;  // parameters and variables a modifier may name
  std::vector<Connector> connectors;
};

/// Every listed name, sorted by path.
const std::vector<MslClass>& Classes();
/// The entry for `path`, or nullptr.
const MslClass* Find(std::string_view path);

/// True when a connector class path (e.g. "Modelica.Blocks.Interfaces.RealInput") is a
/// connector type; sets `kind`.
bool ConnectorClassKind(std::string_view path, ConnectorKind& kind);

/// Parameters of an MSL 4.0.0 class that have no default (declared with a `start` value only,
/// such as Inertia.J or Gain.k): an instance must give them. Empty for a class without any or
/// one not in the list.
std::vector<std::string> RequiredParameters(std::string_view path);

/// A connector that exists only when a Boolean parameter is true (`Flange_a support if
/// useSupport`): the connector, the parameter and its default.
struct ConditionalConnector {
  std::string connector;
  std::string parameter;
  bool default_value = false;
};
std::vector<ConditionalConnector> ConditionalConnectors(std::string_view path);

/// "rotational flange", "Real input", ... for messages.
std::string ToString(ConnectorKind kind);

/// True when two connector kinds may be connected (equal physical domain; a Real output may
/// drive a Real input, two inputs of an enclosing class may be joined).
bool Compatible(ConnectorKind a, ConnectorKind b);

}  // namespace highlift::msl
