// Physical dimensions and quantities. Everything inside highlift is SI; units appear only at the
// edges (project files, reports). Angles are dimensionless (rad), so an angular velocity is 1/s
// and a torsional stiffness (N*m/rad) has the dimension of a torque.
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace highlift {

/// Exponents of the SI base dimensions: m, kg, s, A, K, mol, cd.
struct Dimension {
  std::array<int, 7> exponents{};

  friend bool operator==(const Dimension&, const Dimension&) = default;
  Dimension operator*(const Dimension& o) const;
  Dimension operator/(const Dimension& o) const;
  Dimension pow(int n) const;
  /// "kg*m^2*s^-2"; "1" for dimensionless.
  std::string ToString() const;
};

/// Named dimensions used by the catalogue. Each has a canonical SI unit for display.
namespace dimensions {
Dimension Dimensionless();      // 1 (also angles, ratios, efficiencies)
Dimension Length();             // m
Dimension Mass();               // kg
Dimension Time();               // s
Dimension AngularVelocity();    // rad/s = 1/s
Dimension AngularAcceleration();  // rad/s^2
Dimension Torque();             // N*m (also torsional stiffness N*m/rad)
Dimension RotationalDamping();  // N*m*s/rad
Dimension Inertia();            // kg*m^2
Dimension Force();              // N
Dimension Pressure();           // Pa (also shear modulus, stress)
Dimension Density();            // kg/m^3
Dimension LinearDensity();      // kg/m
Dimension TorquePerLength();    // N*m/m = N
Dimension Power();              // W
Dimension Area();               // m^2
Dimension Volume();             // m^3 (also displacement per radian)
Dimension VolumeFlowRate();     // m^3/s
Dimension Energy();             // J
}  // namespace dimensions

/// Human name of a dimension when it is one of the named ones ("torque", "length"), else its
/// exponent form. Used in messages such as "expected a torque (N*m), got a length (m)".
std::string DescribeDimension(const Dimension& d);

/// A unit converted to SI: value_si = scale * value + offset (offset only for temperatures).
struct UnitConversion {
  double scale = 1.0;
  double offset = 0.0;
  Dimension dimension;
};

/// Parses a unit expression ("mm", "N*m/rad", "rpm", "psi", "kg/m", "kg m2", "GPa", "deg").
/// Uses UDUNITS-2. Throws InputError naming the unit when it is not understood.
UnitConversion ParseUnit(std::string_view unit);

/// Converts `value` given in `unit` to SI, checking the dimension. Throws InputError with the
/// expected dimension when it does not match ("expected a torque (N*m), got a length (mm)").
double ToSI(double value, std::string_view unit, const Dimension& expected);

/// Converts an SI value to `unit` (for reports). Throws InputError on a dimension mismatch.
double FromSI(double value_si, std::string_view unit, const Dimension& expected);

}  // namespace highlift
