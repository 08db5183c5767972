// Builders of a component type's declaration (its ComponentTypeSpec: ports, parameters with units,
// defaults, domains and sources), used by the Declaration() function in each type's file.
// Numbers are written in the display unit and converted to SI.
//
// Sources (the `source` of each parameter): "domain.md s3 (E)" etc. refer to sections and tags
// of ../shared/reference/domain.md; "paper fig. 4" etc. to highlift_paper.txt; "estimate" marks a
// catalogue estimate with its reasoning, to be treated as the centre of an interval.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "component_util.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/units.h"

namespace highlift::model::components {

using namespace highlift::dimensions;


// Builder of a ParameterSpec; numbers are in the display unit.
class Param {
 public:
  Param(std::string name, std::string symbol, Dimension dimension, std::string unit, std::string description) {
    spec_.name = std::move(name);
    spec_.symbol = std::move(symbol);
    spec_.dimension = dimension;
    spec_.unit = std::move(unit);
    spec_.description = std::move(description);
  }
  static Param Integer(std::string name, std::string symbol, std::string description) {
    Param p(std::move(name), std::move(symbol), Dimensionless(), "1", std::move(description));
    p.spec_.kind = ParameterKind::kInteger;
    return p;
  }
  static Param Text(std::string name, std::string description) {
    Param p(std::move(name), "", Dimensionless(), "", std::move(description));
    p.spec_.kind = ParameterKind::kText;
    return p;
  }
  Param& Nominal(double v) {
    nominal_ = v;
    return *this;
  }
  Param& Default(double lo, double hi) {
    default_ = Domain{lo, hi};
    return *this;
  }
  Param& Valid(double lo, double hi) {
    valid_ = Domain{lo, hi};
    return *this;
  }
  Param& Source(std::string s) {
    spec_.source = std::move(s);
    return *this;
  }
  Param& Optional() {
    spec_.optional = true;
    return *this;
  }
  Param& Side(ReferenceSide side) {  // the gear side the value counts on
    spec_.referred_to = side;
    return *this;
  }
  operator ParameterSpec() const {  // NOLINT: implicit by design, for the declaration lists
    ParameterSpec s = spec_;
    const std::string unit = spec_.kind == ParameterKind::kText ? "1" : spec_.unit;
    auto si = [&](double v) { return std::isinf(v) ? v : ToSI(v, unit, spec_.dimension); };
    auto si_domain = [&](const Domain& d) { return Domain{si(d.lo), si(d.hi)}; };
    s.valid_range = si_domain(valid_);
    if (nominal_) s.nominal = si(*nominal_);
    if (default_) {
      s.default_domain = si_domain(*default_);
    } else if (s.nominal) {
      s.default_domain = Domain::Point(*s.nominal);
    } else {
      s.default_domain = s.valid_range;
    }
    return s;
  }

 private:
  ParameterSpec spec_;
  std::optional<double> nominal_;
  std::optional<Domain> default_;
  Domain valid_{0.0, kInfinity};
};

inline PortSpec Flange(std::string name, std::string description, bool required = true) {
  return PortSpec{std::move(name), PortKind::kFlange, required, std::move(description), false, {}};
}

/// A gear's flange turning 1/ratio as fast as its flange "input".
inline PortSpec GearedFlange(std::string name, std::string description, bool required = true) {
  PortSpec p = Flange(std::move(name), std::move(description), required);
  p.speed_ratio = "ratio";
  return p;
}

inline ParameterSpec SpanPosition() {
  return Param("span_position", "x", Length(), "m",
               "position along the span from the aircraft centre line (stations, reports)")
      .Valid(-100, 100)
      .Optional()
      .Source("domain.md s3 (E) gives x per node");
}

inline ParameterSpec Inertia(double nominal, double lo, double hi, std::string description, std::string source,
                      ReferenceSide side) {
  return Param("inertia", "J", dimensions::Inertia(), "kg*m^2", std::move(description))
      .Nominal(nominal)
      .Default(lo, hi)
      .Valid(0, 1e3)
      .Source(std::move(source))
      .Side(side);
}

inline ParameterSpec OptionalStiffness(std::string description, ReferenceSide side,
                                std::string source = "none: rigid unless given") {
  return Param("stiffness", "c", Torque(), "N*m/rad", std::move(description))
      .Valid(0, 1e9)
      .Optional()
      .Source(std::move(source))
      .Side(side);
}

inline ParameterSpec Backlash(std::string description, ReferenceSide side) {
  return Param("backlash", "b", Dimensionless(), "deg", std::move(description))
      .Nominal(0)
      .Default(0, 0.5)
      .Valid(0, 30)
      .Source("estimate: 0 (ideal); up to 0.5 deg for worn splines")
      .Side(side);
}

// Stribeck friction of the paper's eq. (3): tau = tau_C + d_vis*|w| + tau_S*exp(-f_exp*|w|).
// domain.md s6: T_brk = tau_C + tau_S = 1.2-1.5 x tau_C, w_brk 0.05-0.2 rad/s (f_exp = 1/w_brk).
inline void AddStribeck(std::vector<ParameterSpec>& ps, double tau_C, double tau_C_lo, double tau_C_hi,
                 const std::string& tau_C_source, ReferenceSide side) {
  ps.push_back(Param("coulomb_torque", "tau_C", Torque(), "N*m", "Coulomb friction (drag) torque, paper eq. (3)")
                   .Nominal(tau_C)
                   .Default(tau_C_lo, tau_C_hi)
                   .Valid(0, 1e4)
                   .Source(tau_C_source)
                   .Side(side));
  ps.push_back(Param("viscous_coefficient", "d_vis", RotationalDamping(), "N*m*s/rad",
                     "viscous friction coefficient, paper eq. (3)")
                   .Nominal(1e-4 * tau_C / 0.1)
                   .Default(0, 1e-3 * tau_C / 0.1)
                   .Valid(0, 1e3)
                   .Source("estimate: small; viscous drag at 25 rad/s below 3 % of tau_C")
                   .Side(side));
  ps.push_back(Param("stribeck_torque", "tau_S", Torque(), "N*m",
                     "Stribeck (break-away excess) torque at standstill, paper eq. (3)")
                   .Nominal(0.35 * tau_C)
                   .Default(0.2 * tau_C, 0.5 * tau_C)
                   .Valid(0, 1e4)
                   .Source("domain.md s6 (E): T_brk 1.2-1.5 x T_C")
                   .Side(side));
  ps.push_back(Param("stribeck_decay", "f_exp", Time(), "s/rad", "decay of the Stribeck torque with speed, paper eq. (3)")
                   .Nominal(10)
                   .Default(5, 20)
                   .Valid(0, 1e4)
                   .Source("domain.md s6 (E): w_brk 0.05-0.2 rad/s, f_exp = 1/w_brk")
                   .Side(side));
}

// An efficiency in the driving direction: the input torque is the output torque divided by it
// (tau_in = tau_out / (i eta)), so 0, a part that passes no power however hard it is driven,
// has no steady state. Valid from 0.01: no gear, joint or motor of a drive transmits less than
// 1 % of its power (real ones 0.6 to 0.99).
inline ParameterSpec Efficiency(std::string name, std::string symbol, double nominal, double lo, double hi,
                         std::string description, std::string source) {
  return Param(std::move(name), std::move(symbol), Dimensionless(), "1", std::move(description))
      .Nominal(nominal)
      .Default(lo, hi)
      .Valid(0.01, 1)
      .Source(std::move(source));
}

// The efficiency with an aiding (back-driving) load: the torque passed on is multiplied by it,
// and 0 is a self-locking actuator that an aiding load cannot back-drive.
inline ParameterSpec AidingEfficiency(std::string name, std::string symbol, double nominal, double lo, double hi,
                               std::string description, std::string source) {
  ParameterSpec p = Efficiency(std::move(name), std::move(symbol), nominal, lo, hi, std::move(description),
                               std::move(source));
  p.valid_range = Domain{0, 1};
  return p;
}

}  // namespace highlift::model::components
