// The symbolic scalar of the component laws: model::Sym. A law templated on its scalar (laws.h,
// ComponentModel's LumpedAtInput and InputTorque) instantiated with Sym does not compute a number
// but builds the expression of the law, the way a Ceres cost functor instantiated with Jet
// builds derivatives. The constraint propagator (icsp) reads every component law this way: it
// hands the law its variables (ParameterReader<Sym>) and renders the result as text of its
// constraint language (icsp/parser.h), so each law is written once for double, Interval and the
// propagator.
//
//   const Sym c = ShaftStiffness(Sym::Variable("s.G", Sign::Positive()), ...);
//   c.Text()   // "s.G * (0.39269908169872414 * (s.D^2 + ...) * ...) / s.L"
//
// Every Sym carries the signs its value can take. Constants know theirs; a variable has the sign
// its creator declares (icsp: from the parameter's domain or declaration, and from the law of a
// derived variable); +, -, *, /, exp, ... combine them. BySign (interval.h), where a law changes
// at zero (opposing and aiding efficiencies), picks its branch by the sign; a value that may take
// either sign gets the exact split f_pos(max(x, 0)) + f_neg(min(x, 0)) - f_pos(0), and a value
// whose sign nobody declared is an InternalError naming the law.
//
// A parameter that has no value is Sym::Missing(name): anything computed from it is missing too
// (except 0 * x = 0), so the caller leaves out the law that needs it.
//
// The expression is simplified only by exact identities (x + 0, 1 * x, x / 1, 0 * x, -(-x),
// x * x = x^2, x^n * x = x^(n+1), (-c) * x = -(c * x)); constants are never folded by floating
// point operations (the propagator encloses each constant as written).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "highlift/model/interval.h"

namespace highlift::model {

/// The signs a value can take: a subset of {negative, zero, positive}. The empty set means
/// nothing is known (no declaration), which is not the same as "either sign" (all three).
class Sign {
 public:
  static constexpr std::uint8_t kNegative = 1, kZero = 2, kPositive = 4;
  constexpr Sign() = default;
  constexpr explicit Sign(std::uint8_t bits) : bits_(bits) {}
  static constexpr Sign Unknown() { return Sign(0); }
  static constexpr Sign Positive() { return Sign(kPositive); }
  static constexpr Sign NonNegative() { return Sign(kZero | kPositive); }
  static constexpr Sign Negative() { return Sign(kNegative); }
  static constexpr Sign NonPositive() { return Sign(kNegative | kZero); }
  static constexpr Sign Either() { return Sign(kNegative | kZero | kPositive); }
  static Sign Of(double v) { return Sign(v > 0 ? kPositive : v < 0 ? kNegative : kZero); }
  /// The signs of the values of [lo, hi]; Unknown for an empty or NaN interval.
  static Sign OfRange(double lo, double hi);

  constexpr bool known() const { return bits_ != 0; }
  constexpr bool may_be_negative() const { return bits_ & kNegative; }
  constexpr bool may_be_zero() const { return bits_ & kZero; }
  constexpr bool may_be_positive() const { return bits_ & kPositive; }
  constexpr std::uint8_t bits() const { return bits_; }
  constexpr bool operator==(const Sign&) const = default;
  /// "positive", "non-negative", ..., "unknown".
  std::string Name() const;

 private:
  std::uint8_t bits_ = 0;
};

namespace symbolic {
struct Node;
}

class Sym {
 public:
  /// A constant (implicit, so the laws' T(0.5) and T(x) work as for double).
  Sym(double value);  // NOLINT(google-explicit-constructor)
  Sym() : Sym(0.0) {}
  /// A variable of the constraint language, e.g. "shaft_l1.outer_diameter", whose value has the
  /// signs `sign` (Unknown: not declared).
  static Sym Variable(std::string name, Sign sign);
  /// The value of a parameter that has none (`what` names it in messages).
  static Sym Missing(std::string what);

  Sign sign() const;
  bool missing() const;
  /// The first missing parameter it was computed from (empty when it is not missing).
  const std::string& missing_what() const;
  /// True for a constant; `*value` its value.
  bool constant(double* value = nullptr) const;
  /// True for a variable; `*name` its name.
  bool variable(std::string* name = nullptr) const;
  /// The text in the constraint language (icsp/parser.h); InternalError when missing().
  std::string Text() const;
  /// Named subexpressions: a subexpression that is the same tree as one of `names` is written as
  /// the variable named beside it (icsp's derived variables such as a shaft's polar moment).
  using Names = std::vector<std::pair<Sym, std::string>>;
  std::string Text(const Names& names) const;
  /// Structural equality (the same expression tree).
  bool Same(const Sym& other) const;

  Sym& operator+=(const Sym& b) { return *this = *this + b; }
  Sym& operator-=(const Sym& b) { return *this = *this - b; }
  Sym& operator*=(const Sym& b) { return *this = *this * b; }

  friend Sym operator+(const Sym& a, const Sym& b);
  friend Sym operator-(const Sym& a, const Sym& b);
  friend Sym operator*(const Sym& a, const Sym& b);
  friend Sym operator/(const Sym& a, const Sym& b);
  friend Sym operator-(const Sym& a);
  friend Sym exp(const Sym& x);
  friend Sym sqrt(const Sym& x);
  friend Sym abs(const Sym& x);
  friend Sym pow(const Sym& x, int n);
  friend Sym min(const Sym& a, const Sym& b);
  friend Sym max(const Sym& a, const Sym& b);

 private:
  explicit Sym(std::shared_ptr<const symbolic::Node> node) : node_(std::move(node)) {}
  std::shared_ptr<const symbolic::Node> node_;
};

/// BySign for the symbolic scalar (see the double and Interval versions in interval.h): the
/// branch of x's sign; the exact split f_pos(max(x, 0)) + f_neg(min(x, 0)) - f_pos(0) when x may
/// take either sign (the laws are continuous at zero); InternalError naming `law` when x's sign
/// is not known.
template <class Pos, class Neg>
Sym BySign(const Sym& x, Pos f_pos, Neg f_neg, std::string_view law = {}) {
  if (x.missing()) return x;
  const Sign s = x.sign();
  if (!s.known()) {
    HIGHLIFT_CHECK(false, "the law '" + std::string(law.empty() ? "BySign" : law) +
                              "' changes at zero and needs the sign of its argument, which is not known (" +
                              x.Text() + "): declare the sign of its variables");
  }
  if (!s.may_be_negative()) return f_pos(x);
  if (!s.may_be_positive()) return f_neg(x);
  return f_pos(max(x, Sym(0.0))) + f_neg(min(x, Sym(0.0))) - f_pos(Sym(0.0));
}

}  // namespace highlift::model
