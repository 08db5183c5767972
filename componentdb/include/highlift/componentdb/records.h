// The content of the component database as plain values: parts with their parameters, and
// materials with their properties. Values keep the unit they were given in (for display and an
// exact export round trip) beside their SI value (for queries and estimation).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "highlift/core/domain.h"

namespace highlift::componentdb {

/// How much a value can be trusted (domain.md): published, published in a weak source, or an
/// engineering estimate (the centre of an interval, not the truth).
enum class Tag { kPublished, kPublishedLow, kEstimate };
/// "P", "P-low", "E".
std::string ToString(Tag tag);
/// Inverse of ToString; nullopt for anything else.
std::optional<Tag> TagFromString(const std::string& text);

/// One value of a part parameter or material property: a point value, an interval, or both
/// (a nominal value inside an interval).
struct Quantity {
  std::string name;             ///< catalogue parameter name, or material property name
  std::optional<double> value;  ///< nominal value in `unit`, when known
  std::optional<double> lo;     ///< lower bound in `unit` (with hi), when an interval is known
  std::optional<double> hi;     ///< upper bound in `unit`
  std::string unit;             ///< unit as given, e.g. "kN*m", "kg*m^2", "1"
  std::optional<double> value_si;  ///< nominal value in SI
  Domain domain_si;             ///< [lo, hi] in SI; a point [v, v] when only a value is given
  Tag tag = Tag::kEstimate;
  std::string source;           ///< where the number comes from, or how it was derived
  std::string origin;           ///< where it was read, e.g. "parts.csv row 14"; not compared, not stored

  /// The value to use where one number is needed: the nominal value, else the interval midpoint.
  double Representative() const;
  friend bool operator==(const Quantity& a, const Quantity& b);
};

/// A part: one existing (or plausible, tagged E) component of a catalogue type.
struct Part {
  std::string type;          ///< catalogue type name (JSON "type" of the component)
  std::string designation;   ///< unique name, e.g. "GRA-200-A380C"
  std::string program;       ///< aircraft program or class, e.g. "A380-class flap"
  std::string supplier;      ///< supplier where known, else empty
  std::string note;
  std::vector<Quantity> parameters;
  std::string origin;        ///< where it was read, e.g. "parts.csv row 14"; not compared, not stored

  const Quantity* Find(const std::string& parameter) const;
  friend bool operator==(const Part& a, const Part& b);
};

/// A material: shear modulus [Pa], density [kg/m^3] and allowable shear stress [Pa].
struct Material {
  std::string name;          ///< unique, e.g. "Ti-6Al-4V"
  std::string note;
  std::vector<Quantity> properties;  ///< "shear_modulus", "density", "allowable_shear_stress"
  std::string origin;        ///< where it was read; not compared, not stored

  const Quantity* Find(const std::string& property) const;
  friend bool operator==(const Material& a, const Material& b);
};

/// The material property names with their SI dimensions are fixed: these three, all required.
const std::vector<std::string>& MaterialPropertyNames();

/// A set of records to import or that were exported.
struct Records {
  std::vector<Part> parts;
  std::vector<Material> materials;
  friend bool operator==(const Records&, const Records&) = default;
};

}  // namespace highlift::componentdb
