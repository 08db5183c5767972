// Internal: the builders of element type declarations (ports, scalar, flag, integer and table
// parameters), shared by the files that declare the element types of one family:
// element_types.cc (MSL), element_types_brakes.cc, element_types_gears.cc,
// element_types_drive.cc and element_types_hydraulic.cc (the HighLift library).
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "highlift/core/catalogue.h"

namespace highlift::element_types {

constexpr double kInf = std::numeric_limits<double>::infinity();

inline Dimension Temperature() {
  Dimension d;
  d.exponents[4] = 1;
  return d;
}
inline Dimension HeatCapacity() { return dimensions::Energy() / Temperature(); }
inline Dimension PerKelvin() { return Dimension{} / Temperature(); }

inline PortSpec Flange(std::string name, std::string description, bool required = true) {
  return {std::move(name), PortKind::kFlange, required, std::move(description), false, {}};
}
inline PortSpec Signal(std::string name, std::string description, bool required = true) {
  return {std::move(name), PortKind::kSignal, required, std::move(description), false, {}};
}
inline PortSpec SignalOutput(std::string name, std::string description) {
  return {std::move(name), PortKind::kSignal, false, std::move(description), true, {}};
}
inline PortSpec Support() {
  return Flange("support",
                "housing flange; grounded (phi = 0) when left unconnected (MSL useSupport=false)",
                false);
}

inline ParameterSpec Scalar(std::string name, Dimension dimension, std::string unit,
                     std::optional<double> nominal, Domain valid, std::string description) {
  ParameterSpec p;
  p.kind = ParameterKind::kScalar;
  p.name = name;
  p.symbol = std::move(name);
  p.dimension = dimension;
  p.unit = std::move(unit);
  p.nominal = nominal;
  p.default_domain = nominal ? Domain::Point(*nominal) : valid;
  p.valid_range = valid;
  p.description = std::move(description);
  p.source = "Modelica Standard Library 4.0.0";
  return p;
}
/// An optional initial value: given means fixed (MSL start value with fixed=true).
inline ParameterSpec Start(std::string name, Dimension dimension, std::string unit,
                    std::string description) {
  ParameterSpec p = Scalar(std::move(name), dimension, std::move(unit), std::nullopt,
                           Domain::Whole(), std::move(description));
  p.optional = true;
  return p;
}
/// An optional nominal value of a state (MSL `nominal`): scales the solver's absolute tolerance
/// of that state (absolute_tolerance * nominal); absent means 1.
inline ParameterSpec Nominal(std::string name, Dimension dimension, std::string unit,
                             std::string description) {
  ParameterSpec p = Scalar(std::move(name), dimension, std::move(unit), std::nullopt,
                           {std::nextafter(0.0, 1.0), kInf}, std::move(description));
  p.optional = true;
  return p;
}
inline ParameterSpec Flag(std::string name, bool nominal, std::string description) {
  ParameterSpec p = Scalar(std::move(name), {}, "1", nominal ? 1.0 : 0.0, {0, 1},
                           std::move(description));
  p.kind = ParameterKind::kBoolean;
  return p;
}
inline ParameterSpec Integer(std::string name, double nominal, Domain valid, std::string description) {
  ParameterSpec p = Scalar(std::move(name), {}, "1", nominal, valid, std::move(description));
  p.kind = ParameterKind::kInteger;
  return p;
}
inline ParameterSpec TableParameter(std::string name, std::string description) {
  ParameterSpec p;
  p.kind = ParameterKind::kTable;
  p.name = name;
  p.symbol = std::move(name);
  p.unit = "SI";
  p.description = std::move(description);
  p.source = "Modelica Standard Library 4.0.0";
  return p;
}

inline ComponentTypeSpec Type(std::string name, std::string description, std::vector<PortSpec> ports,
                       std::vector<ParameterSpec> parameters) {
  ComponentTypeSpec t;
  t.display_name = name;
  t.name = std::move(name);
  t.description = std::move(description);
  t.ports = std::move(ports);
  t.parameters = std::move(parameters);
  return t;
}

/// The element types of the HighLift library, by family (each file appends its own).
void AppendBrakeTypes(std::vector<ComponentTypeSpec>& types);
void AppendGearTypes(std::vector<ComponentTypeSpec>& types);
void AppendDriveTypes(std::vector<ComponentTypeSpec>& types);
void AppendHydraulicTypes(std::vector<ComponentTypeSpec>& types);
/// Modelica.Mechanics.Translational and the rotational-translational gears (MSL).
void AppendTranslationalTypes(std::vector<ComponentTypeSpec>& types);

}  // namespace highlift::element_types
