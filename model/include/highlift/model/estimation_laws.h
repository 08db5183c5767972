// Estimation laws of the component types (`highlift estimate`): what a type can say about its
// own parameters from its other parameters, from quantities given as component labels and from
// constant ranges, and which of its parameters the database fits against a rating. Each type
// declares them in its own file (ComponentModel::EstimationLaws and FitRules); the estimator
// evaluates them without knowing the type.
//
// A law is written once as a generic lambda over its inputs, `[](const auto& v) {...}` with v[i]
// the i-th input, and instantiated for double (the nominal value) and Interval (the domain,
// outward rounded) by EstimateParameter / DeriveQuantity:
//
//   EstimateParameter("stiffness", {FromParameter("shear_modulus"), ...}, "physics: c = G Ip / L",
//                     [](const auto& v) { return ShaftStiffness(v[0], v[1], v[2], v[3]); });
#pragma once

#include <functional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "highlift/core/units.h"
#include "highlift/model/interval.h"

namespace highlift::model {

/// One input of an estimation law.
struct LawInput {
  enum class Kind {
    kParameter,  ///< a parameter of the component: its domain and nominal value
    kLabel,      ///< a component label holding a quantity with a unit ("1200 kg"); without the
                 ///< label the law does not apply
    kConstant,   ///< a constant range with a nominal value (a range from domain.md)
  };
  Kind kind = Kind::kParameter;
  std::string name;      ///< parameter or label name (a constant: empty)
  Dimension dimension;   ///< a label: the dimension of its quantity
  Interval range;        ///< a constant: its range, SI
  double nominal = 0.0;  ///< a constant: its nominal value, SI
};

inline LawInput FromParameter(std::string name) { return {LawInput::Kind::kParameter, std::move(name), {}, {}, 0.0}; }
inline LawInput FromLabel(std::string name, Dimension dimension) {
  return {LawInput::Kind::kLabel, std::move(name), dimension, {}, 0.0};
}
inline LawInput FromConstant(double lo, double nominal, double hi) {
  return {LawInput::Kind::kConstant, {}, {}, Interval(lo, hi), nominal};
}

/// One estimation law: a parameter of the component (stored with provenance "estimated") or a
/// derived quantity (reported, not stored) from `inputs`, in their order.
struct EstimationLaw {
  std::string output;  ///< the parameter, or the name of the derived quantity
  bool derived = false;
  std::string unit;    ///< a derived quantity: its SI unit ("kg"); a parameter: empty (the catalogue's)
  std::vector<LawInput> inputs;
  std::string note;    ///< the law as reports show it
  std::function<double(std::span<const double>)> nominal;         ///< the law at nominal values
  std::function<Interval(std::span<const Interval>)> enclosure;  ///< the same law on domains
};

/// A parameter fitted against a rating over the database parts of the component's type
/// (estimation/fit.h): log parameter = log a + b log rating.
struct FitRule {
  std::string parameter;
  std::string rating;
};

namespace detail {
template <class Law>
EstimationLaw WrapLaw(std::string output, bool derived, std::string unit, std::vector<LawInput> inputs,
                      std::string note, Law law) {
  EstimationLaw out{std::move(output), derived, std::move(unit), std::move(inputs), std::move(note), {}, {}};
  out.nominal = [law](std::span<const double> v) -> double { return law(v); };
  out.enclosure = [law](std::span<const Interval> v) -> Interval { return law(v); };
  return out;
}
}  // namespace detail

/// A law monotone in each input (signs[i] = +1: increasing in input i, -1: decreasing) on the
/// interval inputs v for which where(v) holds: there its exact range, the law at the two extreme
/// corners, each evaluated on point intervals (outward rounded); elsewhere, and for double, the
/// law itself. On a box the law would overestimate when an input occurs more than once.
template <class Law, class Where>
auto MonotoneLaw(std::vector<int> signs, Where where, Law law) {
  return [signs, where, law](const auto& v) {
    if constexpr (std::is_same_v<std::decay_t<decltype(v[0])>, Interval>) {
      if (where(v)) {
        std::vector<Interval> lo, hi;
        for (std::size_t i = 0; i < v.size(); ++i) {
          lo.emplace_back(signs.at(i) > 0 ? v[i].lo : v[i].hi);
          hi.emplace_back(signs.at(i) > 0 ? v[i].hi : v[i].lo);
        }
        return Interval(law(std::span<const Interval>(lo)).lo, law(std::span<const Interval>(hi)).hi);
      }
    }
    return law(v);
  };
}

/// A law that estimates parameter `parameter` of the component.
template <class Law>
EstimationLaw EstimateParameter(std::string parameter, std::vector<LawInput> inputs, std::string note, Law law) {
  return detail::WrapLaw(std::move(parameter), false, {}, std::move(inputs), std::move(note), law);
}

/// A law for a quantity reported beside the parameters (a shaft's mass), in SI unit `unit`.
template <class Law>
EstimationLaw DeriveQuantity(std::string name, std::string unit, std::vector<LawInput> inputs, std::string note,
                             Law law) {
  return detail::WrapLaw(std::move(name), true, std::move(unit), std::move(inputs), std::move(note), law);
}

}  // namespace highlift::model
