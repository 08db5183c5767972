#include "highlift/model/symbolic.h"

#include <cmath>
#include <cstdio>

namespace highlift::model {

Sign Sign::OfRange(double lo, double hi) {
  if (!(lo <= hi)) return Unknown();
  std::uint8_t bits = 0;
  if (lo < 0) bits |= kNegative;
  if (lo <= 0 && hi >= 0) bits |= kZero;
  if (hi > 0) bits |= kPositive;
  return Sign(bits);
}

std::string Sign::Name() const {
  switch (bits_) {
    case 0: return "unknown";
    case kPositive: return "positive";
    case kZero | kPositive: return "non-negative";
    case kNegative: return "negative";
    case kNegative | kZero: return "non-positive";
    case kZero: return "zero";
    case kNegative | kPositive: return "non-zero";
    default: return "either";
  }
}

namespace symbolic {

enum class Kind { kConst, kVar, kMissing, kAdd, kSub, kMul, kDiv, kNeg, kPow, kExp, kSqrt, kAbs, kMin, kMax };

struct Node {
  Kind kind = Kind::kConst;
  double value = 0.0;  // kConst
  int n = 0;           // kPow
  std::string name;    // kVar: the variable; kMissing: the parameter
  Sign sign;
  std::shared_ptr<const Node> a, b;
};

namespace {

using Ptr = std::shared_ptr<const Node>;

Ptr Make(Kind kind, Sign sign, Ptr a = nullptr, Ptr b = nullptr, int n = 0) {
  auto node = std::make_shared<Node>();
  node->kind = kind;
  node->sign = sign;
  node->a = std::move(a);
  node->b = std::move(b);
  node->n = n;
  return node;
}

constexpr std::uint8_t N = Sign::kNegative, Z = Sign::kZero, P = Sign::kPositive;

/// The signs of a sum (or, with b negated, of a difference).
Sign SumSign(Sign a, Sign b) {
  if (!a.known() || !b.known()) return Sign::Unknown();
  std::uint8_t bits = 0;
  if (a.may_be_negative() || b.may_be_negative()) bits |= N;
  if (a.may_be_positive() || b.may_be_positive()) bits |= P;
  if ((a.may_be_zero() && b.may_be_zero()) || (a.may_be_negative() && b.may_be_positive()) ||
      (a.may_be_positive() && b.may_be_negative()))
    bits |= Z;
  return Sign(bits);
}
Sign Negated(Sign a) {
  std::uint8_t bits = a.bits() & Z;
  if (a.may_be_negative()) bits |= P;
  if (a.may_be_positive()) bits |= N;
  return Sign(bits);
}
Sign ProductSign(Sign a, Sign b) {
  if (!a.known() || !b.known()) return Sign::Unknown();
  std::uint8_t bits = 0;
  if ((a.may_be_negative() && b.may_be_positive()) || (a.may_be_positive() && b.may_be_negative())) bits |= N;
  if ((a.may_be_positive() && b.may_be_positive()) || (a.may_be_negative() && b.may_be_negative())) bits |= P;
  if (a.may_be_zero() || b.may_be_zero()) bits |= Z;
  return Sign(bits);
}
Sign PowSign(Sign a, int n) {
  if (!a.known() || n % 2 != 0) return a;
  std::uint8_t bits = a.bits() & Z;
  if (a.may_be_negative() || a.may_be_positive()) bits |= P;
  return Sign(bits);
}
Sign MinSign(Sign a, Sign b) {
  if (!a.known() || !b.known()) return Sign::Unknown();
  std::uint8_t bits = 0;
  if (a.may_be_negative() || b.may_be_negative()) bits |= N;
  if (a.may_be_positive() && b.may_be_positive()) bits |= P;
  if ((a.may_be_zero() && (b.may_be_zero() || b.may_be_positive())) ||
      (b.may_be_zero() && (a.may_be_zero() || a.may_be_positive())))
    bits |= Z;
  return Sign(bits);
}
Sign MaxSign(Sign a, Sign b) { return Negated(MinSign(Negated(a), Negated(b))); }

bool IsConst(const Ptr& p, double v) { return p->kind == Kind::kConst && p->value == v; }

bool SameNode(const Node& a, const Node& b) {
  if (&a == &b) return true;
  if (a.kind != b.kind) return false;
  switch (a.kind) {
    case Kind::kConst: return a.value == b.value;
    case Kind::kVar:
    case Kind::kMissing: return a.name == b.name;
    case Kind::kPow: return a.n == b.n && SameNode(*a.a, *b.a);
    default:
      if (!SameNode(*a.a, *b.a)) return false;
      return a.b == nullptr ? b.b == nullptr : b.b != nullptr && SameNode(*a.b, *b.b);
  }
}
bool SameTree(const Ptr& a, const Ptr& b) { return SameNode(*a, *b); }

Ptr Constant(double v) {
  HIGHLIFT_CHECK(std::isfinite(v), "a symbolic constant must be finite");
  auto node = Make(Kind::kConst, Sign::Of(v));
  std::const_pointer_cast<Node>(node)->value = v == 0.0 ? 0.0 : v;  // no -0
  return node;
}

Ptr Neg(const Ptr& a);
/// True when the negation of `a` can be pushed into it without a unary minus node.
bool CheapNegation(const Ptr& a) {
  switch (a->kind) {
    case Kind::kConst:
    case Kind::kNeg: return true;
    case Kind::kMul:
    case Kind::kDiv: return CheapNegation(a->a);
    case Kind::kAdd:
    case Kind::kSub: return CheapNegation(a->a) && CheapNegation(a->b);
    default: return false;
  }
}
Ptr Mul(const Ptr& a, const Ptr& b);
Ptr Div(const Ptr& a, const Ptr& b);
Ptr Add(const Ptr& a, const Ptr& b);
Ptr Sub(const Ptr& a, const Ptr& b);
Ptr Pow(const Ptr& a, int n);

Ptr Neg(const Ptr& a) {
  if (a->kind == Kind::kMissing) return a;
  if (a->kind == Kind::kConst) return Constant(-a->value);
  if (a->kind == Kind::kNeg) return a->a;
  if (CheapNegation(a)) {
    if (a->kind == Kind::kMul) return Mul(Neg(a->a), a->b);
    if (a->kind == Kind::kDiv) return Div(Neg(a->a), a->b);
    if (a->kind == Kind::kAdd) return Add(Neg(a->a), Neg(a->b));
    if (a->kind == Kind::kSub) return Sub(Neg(a->a), Neg(a->b));
  }
  return Make(Kind::kNeg, Negated(a->sign), a);
}

Ptr Add(const Ptr& a, const Ptr& b) {
  if (a->kind == Kind::kMissing) return a;
  if (b->kind == Kind::kMissing) return b;
  if (IsConst(a, 0.0)) return b;
  if (IsConst(b, 0.0)) return a;
  return Make(Kind::kAdd, SumSign(a->sign, b->sign), a, b);
}
Ptr Sub(const Ptr& a, const Ptr& b) {
  if (a->kind == Kind::kMissing) return a;
  if (b->kind == Kind::kMissing) return b;
  if (IsConst(b, 0.0)) return a;
  if (IsConst(a, 0.0)) return Neg(b);
  return Make(Kind::kSub, SumSign(a->sign, Negated(b->sign)), a, b);
}
Ptr Mul(const Ptr& a, const Ptr& b) {
  if (IsConst(a, 0.0) || IsConst(b, 0.0)) return Constant(0.0);  // also when the other is missing
  if (a->kind == Kind::kMissing) return a;
  if (b->kind == Kind::kMissing) return b;
  if (IsConst(a, 1.0)) return b;
  if (IsConst(b, 1.0)) return a;
  if (SameTree(a, b)) return Pow(a, 2);
  if (a->kind == Kind::kPow && SameTree(a->a, b)) return Pow(b, a->n + 1);
  // (l * x) * x = l * x^2 and (l * x^n) * x = l * x^(n+1): the motors' inertia n J_m i i.
  if (a->kind == Kind::kMul) {
    const Ptr& r = a->b;
    if (SameTree(r, b)) return Mul(a->a, Pow(b, 2));
    if (r->kind == Kind::kPow && SameTree(r->a, b)) return Mul(a->a, Pow(b, r->n + 1));
  }
  return Make(Kind::kMul, ProductSign(a->sign, b->sign), a, b);
}
Ptr Div(const Ptr& a, const Ptr& b) {
  HIGHLIFT_CHECK(!IsConst(b, 0.0), "symbolic division by the constant 0");
  if (IsConst(a, 0.0)) return a;  // the laws divide by ratios, efficiencies, lengths: never zero
  if (a->kind == Kind::kMissing) return a;
  if (b->kind == Kind::kMissing) return b;
  if (IsConst(b, 1.0)) return a;
  return Make(Kind::kDiv, ProductSign(a->sign, b->sign), a, b);
}
Ptr Pow(const Ptr& a, int n) {
  if (a->kind == Kind::kMissing) return a;
  if (n == 0) return Constant(1.0);
  if (n == 1 || IsConst(a, 1.0) || IsConst(a, 0.0)) return a;
  HIGHLIFT_CHECK(n > 1, "symbolic powers take an exponent >= 0 (divide instead)");
  return Make(Kind::kPow, PowSign(a->sign, n), a, nullptr, n);
}
Ptr Function(Kind kind, const Ptr& a, Sign sign) {
  if (a->kind == Kind::kMissing) return a;
  return Make(kind, sign, a);
}
Ptr MinMax(Kind kind, const Ptr& a, const Ptr& b) {
  if (a->kind == Kind::kMissing) return a;
  if (b->kind == Kind::kMissing) return b;
  if (a->kind == Kind::kConst && b->kind == Kind::kConst)  // exact
    return Constant(kind == Kind::kMin ? std::min(a->value, b->value) : std::max(a->value, b->value));
  return Make(kind, kind == Kind::kMin ? MinSign(a->sign, b->sign) : MaxSign(a->sign, b->sign), a, b);
}

// Rendering: the precedence levels of icsp/parser.h's grammar.
constexpr int kSumLevel = 1, kProductLevel = 2, kUnaryLevel = 3, kPowerLevel = 4, kPrimaryLevel = 5;

int Level(const Node& e) {
  switch (e.kind) {
    case Kind::kAdd:
    case Kind::kSub: return kSumLevel;
    case Kind::kMul:
    case Kind::kDiv: return kProductLevel;
    case Kind::kNeg: return kUnaryLevel;
    case Kind::kPow: return kPowerLevel;
    default: return kPrimaryLevel;
  }
}

using Names = std::vector<std::pair<const Node*, const std::string*>>;
void Render(const Node& e, const Names& names, std::string& out);
/// The variable that names `e`, or nullptr.
const std::string* NameOf(const Node& e, const Names& names) {
  for (const auto& [tree, name] : names)
    if (e.kind == tree->kind && SameNode(e, *tree)) return name;
  return nullptr;
}
/// `e` as an operand that needs at least `level`; a unary minus is always parenthesized.
void Operand(const Node& e, int level, const Names& names, std::string& out) {
  const bool parens = !NameOf(e, names) && (Level(e) < level || e.kind == Kind::kNeg);
  if (parens) out += '(';
  Render(e, names, out);
  if (parens) out += ')';
}
void Binary(const Node& e, const char* op, int level, const Names& names, std::string& out) {
  Operand(*e.a, level, names, out);
  out += op;
  Operand(*e.b, level + 1, names, out);  // the right operand of the same level keeps the tree's shape
}
void Call(const char* name, const Node& e, const Names& names, std::string& out) {
  out += name;
  out += '(';
  Render(*e.a, names, out);
  if (e.b) {
    out += ", ";
    Render(*e.b, names, out);
  }
  out += ')';
}

void Render(const Node& e, const Names& names, std::string& out) {
  if (const std::string* name = NameOf(e, names)) {
    out += *name;
    return;
  }
  switch (e.kind) {
    case Kind::kConst: {
      char buf[40];
      std::snprintf(buf, sizeof buf, e.value < 0 ? "(%.17g)" : "%.17g", e.value);  // round-trips exactly
      out += buf;
      return;
    }
    case Kind::kVar: out += e.name; return;
    case Kind::kMissing: HIGHLIFT_CHECK(false, "rendering a missing value ('" + e.name + "')"); return;
    case Kind::kAdd: Binary(e, " + ", kSumLevel, names, out); return;
    case Kind::kSub: Binary(e, " - ", kSumLevel, names, out); return;
    case Kind::kMul: Binary(e, " * ", kProductLevel, names, out); return;
    case Kind::kDiv: Binary(e, " / ", kProductLevel, names, out); return;
    case Kind::kNeg:
      out += '-';
      Operand(*e.a, kPowerLevel, names, out);
      return;
    case Kind::kPow:
      Operand(*e.a, kPrimaryLevel, names, out);
      out += '^' + std::to_string(e.n);
      return;
    case Kind::kExp: Call("exp", e, names, out); return;
    case Kind::kSqrt: Call("sqrt", e, names, out); return;
    case Kind::kAbs: Call("abs", e, names, out); return;
    case Kind::kMin: Call("min", e, names, out); return;
    case Kind::kMax: Call("max", e, names, out); return;
  }
}

}  // namespace
}  // namespace symbolic

using symbolic::Kind;

Sym::Sym(double value) : node_(symbolic::Constant(value)) {}

Sym Sym::Variable(std::string name, Sign sign) {
  auto node = symbolic::Make(Kind::kVar, sign);
  std::const_pointer_cast<symbolic::Node>(node)->name = std::move(name);
  return Sym(std::move(node));
}
Sym Sym::Missing(std::string what) {
  auto node = symbolic::Make(Kind::kMissing, Sign::Unknown());
  std::const_pointer_cast<symbolic::Node>(node)->name = std::move(what);
  return Sym(std::move(node));
}

Sign Sym::sign() const { return node_->sign; }
bool Sym::missing() const { return node_->kind == Kind::kMissing; }
const std::string& Sym::missing_what() const {
  static const std::string kNone;
  return missing() ? node_->name : kNone;
}
bool Sym::constant(double* value) const {
  if (node_->kind != Kind::kConst) return false;
  if (value) *value = node_->value;
  return true;
}
bool Sym::variable(std::string* name) const {
  if (node_->kind != Kind::kVar) return false;
  if (name) *name = node_->name;
  return true;
}
std::string Sym::Text() const { return Text({}); }
std::string Sym::Text(const Names& names) const {
  symbolic::Names nodes;
  for (const auto& [tree, name] : names) nodes.push_back({tree.node_.get(), &name});
  std::string out;
  symbolic::Render(*node_, nodes, out);
  return out;
}
bool Sym::Same(const Sym& other) const { return symbolic::SameTree(node_, other.node_); }

Sym operator+(const Sym& a, const Sym& b) { return Sym(symbolic::Add(a.node_, b.node_)); }
Sym operator-(const Sym& a, const Sym& b) { return Sym(symbolic::Sub(a.node_, b.node_)); }
Sym operator*(const Sym& a, const Sym& b) { return Sym(symbolic::Mul(a.node_, b.node_)); }
Sym operator/(const Sym& a, const Sym& b) { return Sym(symbolic::Div(a.node_, b.node_)); }
Sym operator-(const Sym& a) { return Sym(symbolic::Neg(a.node_)); }
Sym exp(const Sym& x) { return Sym(symbolic::Function(Kind::kExp, x.node_, Sign::Positive())); }
Sym sqrt(const Sym& x) {
  const Sign s = x.sign();
  const bool positive = s.known() && !s.may_be_zero() && !s.may_be_negative();
  return Sym(symbolic::Function(Kind::kSqrt, x.node_, positive ? Sign::Positive() : Sign::NonNegative()));
}
Sym abs(const Sym& x) {
  const Sign s = x.sign();
  if (s.known() && !s.may_be_negative()) return x;
  return Sym(symbolic::Function(Kind::kAbs, x.node_, symbolic::PowSign(s, 2)));
}
Sym pow(const Sym& x, int n) { return Sym(symbolic::Pow(x.node_, n)); }
Sym min(const Sym& a, const Sym& b) { return Sym(symbolic::MinMax(Kind::kMin, a.node_, b.node_)); }
Sym max(const Sym& a, const Sym& b) { return Sym(symbolic::MinMax(Kind::kMax, a.node_, b.node_)); }

}  // namespace highlift::model
