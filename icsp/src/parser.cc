#include "highlift/icsp/parser.h"

#include <algorithm>
#include <cctype>
#include <cfenv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "highlift/core/units.h"

namespace highlift::icsp {

double ConstantToSI(double value, std::string_view unit) {
  const UnitConversion u = ParseUnit(unit);
  return u.scale * value + u.offset;
}

namespace {
/// A unit's factor or offset as an interval: integers (1, 1000, 1e9, 60) are exact; any other
/// factor is the unit system's double result for a real number (1e-3, pi/30, 0.0254), taken as
/// known to two ulps either way.
Interval EncloseFactor(double f) {
  if (f == std::floor(f) && std::fabs(f) < 0x1p53) return Interval(f, f, true);
  double lo = f, hi = f;
  for (int k = 0; k < 2; ++k) {
    lo = std::nextafter(lo, -kInf);
    hi = std::nextafter(hi, kInf);
  }
  return Interval(lo, hi, true);
}
/// The decimal text as the tightest interval of doubles around it (a point when it is exact).
/// The C library's strtod rounds in the current rounding mode.
Interval EncloseDecimal(const std::string& text) {
  const int mode = std::fegetround();
  std::fesetround(FE_DOWNWARD);
  const double lo = std::strtod(text.c_str(), nullptr);
  std::fesetround(FE_UPWARD);
  const double hi = std::strtod(text.c_str(), nullptr);
  std::fesetround(mode);
  return Interval(lo, hi, true);
}
}  // namespace

Interval ConstantToSI(const Interval& value, std::string_view unit) {
  const UnitConversion u = ParseUnit(unit);
  if (u.scale == 1.0 && u.offset == 0.0) return value;
  return value * EncloseFactor(u.scale) + EncloseFactor(u.offset);
}

std::vector<std::string> ClosestNames(std::string_view name, const std::vector<std::string>& candidates,
                                      std::size_t max_results) {
  auto distance = [](std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      std::size_t diag = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j) {
        const std::size_t up = row[j];
        const std::size_t cost = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                                         std::tolower(static_cast<unsigned char>(b[j - 1])) ? 0 : 1;
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + cost});
        diag = up;
      }
    }
    return row[b.size()];
  };
  std::vector<std::pair<std::size_t, std::string>> scored;
  const std::size_t limit = std::max<std::size_t>(2, name.size() / 3);
  for (const auto& c : candidates) {
    const std::size_t d = distance(name, c);
    if (d <= limit) scored.push_back({d, c});
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  for (std::size_t i = 0; i < scored.size() && i < max_results; ++i) out.push_back(scored[i].second);
  return out;
}

namespace {

enum class Tok { kNumber, kName, kUnit, kPlus, kMinus, kStar, kSlash, kCaret, kLParen, kRParen,
                 kLBracket, kRBracket, kComma, kEq, kLe, kGe, kEnd };

struct Token {
  Tok kind = Tok::kEnd;
  std::size_t pos = 0;   // 0-based offset
  std::size_t len = 0;
  double number = 0.0;   // round to nearest
  Interval enclosure;    // the decimal number as an interval of doubles
  std::string text;
};

bool IsNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool IsNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }

/// An expression node with its physical dimension, when known: a constant with a unit, a
/// parameter with a unit, and what the operators make of them. A bare number or a parameter
/// without a unit has no known dimension and matches anything.
struct Typed {
  ExprId id;
  std::optional<Dimension> dimension;
  std::size_t pos = 0;  ///< where the expression starts (for messages)
  std::size_t len = 1;
  int height = 1;       ///< longest operand chain below this node (a + b + c: 3)
};

std::string DimensionText(const Dimension& d) {
  const std::string name = DescribeDimension(d);
  const std::string exponents = d.ToString();
  return name == exponents ? "dimension " + exponents : "a " + name + " (" + exponents + ")";
}

class Parser {
 public:
  Parser(Network& net, std::string_view text, const std::string& context, const SourceLocation& where,
         NameResolver resolve, bool check_dimensions)
      : net_(net), text_(text), context_(context), where_(where), resolve_(std::move(resolve)),
        check_dimensions_(check_dimensions) {
    Lex();
  }

  ParsedConstraint Constraint() {
    ParsedConstraint pc;
    const Typed lhs = Expr();
    const Token& t = Peek();
    if (t.kind == Tok::kEq) pc.relation = Relation::kEqual;
    else if (t.kind == Tok::kLe) pc.relation = Relation::kLessEqual;
    else if (t.kind == Tok::kGe) pc.relation = Relation::kGreaterEqual;
    else Fail(t, "expected '==', '<=' or '>=' here", "write a relation such as 'a <= b'");
    const Token& relation = t;
    ++at_;
    const Typed rhs = Expr();
    ExpectEnd();
    Same(lhs, rhs, relation, "compares");
    pc.lhs = lhs.id;
    pc.rhs = rhs.id;
    return pc;
  }

  ExprId ExpressionOnly() {
    ExprId e = Expr().id;
    ExpectEnd();
    return e;
  }

 private:
  /// Nesting limit: parentheses, unary signs, powers and function calls each nest one level
  /// (counted in Factor, which every nesting passes); the parser recurses once per level.
  static constexpr int kMaxDepth = 200;
  static constexpr int kMaxHeight = 5000;  ///< operands chained in one expression tree
  struct DepthGuard {
    Parser& p;
    DepthGuard(Parser& parser, const Token& at) : p(parser) {
      if (++p.depth_ > kMaxDepth)
        p.Fail(at, "the expression is nested more than " + std::to_string(kMaxDepth) + " levels deep",
               "simplify it (remove redundant parentheses, signs or nested functions)");
    }
    ~DepthGuard() { --p.depth_; }
  };

  /// The two sides of + - min max or a relation must have the same dimension when both are known.
  void Same(const Typed& a, const Typed& b, const Token& op, const std::string& verb) {
    if (!check_dimensions_ || !a.dimension || !b.dimension || *a.dimension == *b.dimension) return;
    Fail(op, "'" + std::string(text_.substr(op.pos, op.len)) + "' " + verb + " " + DimensionText(*a.dimension) +
                 " with " + DimensionText(*b.dimension),
         "give both sides the same kind of quantity (check the units of the constants)");
  }
  static std::optional<Dimension> Product(const Typed& a, const Typed& b, bool divide) {
    if (!a.dimension || !b.dimension) return std::nullopt;
    return divide ? *a.dimension / *b.dimension : *a.dimension * *b.dimension;
  }
  /// The node with its dimension, text span and height; `a`, `b` are its operands.
  Typed Make(ExprId id, std::optional<Dimension> d, std::size_t pos, std::size_t end, const Typed* a = nullptr,
             const Typed* b = nullptr) {
    const int height = 1 + std::max(a ? a->height : 0, b ? b->height : 0);
    // Later walks of the expression (text, evaluation, explanations) recurse once per level: a
    // chain of 10^5 sums would overflow their stack.
    if (height > kMaxHeight)
      Fail(pos, end > pos ? end - pos : 1,
           "the expression is a chain of more than " + std::to_string(kMaxHeight) + " operations",
           "split it into several requirements");
    return Typed{id, d, pos, end > pos ? end - pos : 1, height};
  }
  std::size_t End() const { return at_ > 0 ? tokens_[at_ - 1].pos + tokens_[at_ - 1].len : 0; }

  /// The value of a constant subexpression (numbers, signs and + - * / of numbers), if it is one.
  std::optional<Interval> ConstantValue(ExprId e, int depth = 0) const {
    if (depth > kMaxDepth) return std::nullopt;
    const ExprNode& n = net_.node(e);
    switch (n.op) {
      case Op::kConst: return n.value;
      case Op::kNeg: {
        const auto a = ConstantValue(ExprId{n.a}, depth + 1);
        if (a) return -*a;
        return std::nullopt;
      }
      case Op::kAdd:
      case Op::kSub:
      case Op::kMul: {
        const auto a = ConstantValue(ExprId{n.a}, depth + 1);
        const auto b = ConstantValue(ExprId{n.b}, depth + 1);
        if (!a || !b) return std::nullopt;
        return n.op == Op::kAdd ? *a + *b : n.op == Op::kSub ? *a - *b : *a * *b;
      }
      default: return std::nullopt;
    }
  }

  [[noreturn]] void Fail(std::size_t pos, std::size_t len, const std::string& problem, const std::string& remedy) {
    std::string msg = context_ + ": " + problem + " at column " + std::to_string(pos + 1) + "\n  " +
                      std::string(text_) + "\n  " + std::string(pos, ' ') + "^" +
                      std::string(len > 1 ? len - 1 : 0, '~');
    if (!remedy.empty()) msg += "\n" + remedy;
    SourceLocation w = where_;
    if (w.line == 0) w.column = static_cast<int>(pos + 1);
    throw InputError(msg, w);
  }
  [[noreturn]] void Fail(const Token& t, const std::string& problem, const std::string& remedy) {
    Fail(t.pos, std::max<std::size_t>(t.len, 1), problem, remedy);
  }

  void Lex() {
    std::size_t i = 0;
    const std::size_t n = text_.size();
    bool after_number = false;  // a word right after a constant is its unit
    while (i < n) {
      const char c = text_[i];
      if (std::isspace(static_cast<unsigned char>(c))) {
        ++i;
        continue;
      }
      Token t;
      t.pos = i;
      const bool unit_allowed = after_number;
      after_number = false;
      if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < n && std::isdigit(static_cast<unsigned char>(text_[i + 1])))) {
        // digits [. digits] [(e|E) [+|-] digits]: a decimal number (no hex, inf or nan forms)
        std::size_t j = i;
        while (j < n && std::isdigit(static_cast<unsigned char>(text_[j]))) ++j;
        if (j < n && text_[j] == '.') {
          ++j;
          while (j < n && std::isdigit(static_cast<unsigned char>(text_[j]))) ++j;
        }
        if (j < n && (text_[j] == 'e' || text_[j] == 'E')) {
          std::size_t k = j + 1;
          if (k < n && (text_[k] == '+' || text_[k] == '-')) ++k;
          if (k < n && std::isdigit(static_cast<unsigned char>(text_[k]))) {
            while (k < n && std::isdigit(static_cast<unsigned char>(text_[k]))) ++k;
            j = k;
          }
        }
        const std::string digits(text_.substr(i, j - i));
        t.number = std::strtod(digits.c_str(), nullptr);
        t.enclosure = EncloseDecimal(digits);
        t.len = j - i;
        t.kind = Tok::kNumber;
        if (!std::isfinite(t.number)) Fail(i, t.len, "number '" + digits + "' is out of range", "");
        i = j;
        after_number = true;  // a word right after it is its unit ("2 mm", also "2mm")
        tokens_.push_back(t);
        continue;
      }
      if (c == ']') {
        t.kind = Tok::kRBracket;
        t.len = 1;
        ++i;
        tokens_.push_back(t);
        after_number = true;  // "[43, 51] GPa"
        continue;
      }
      if (IsNameStart(c)) {
        std::size_t j = i;
        if (unit_allowed) {
          while (j < n && (IsNameChar(text_[j]) || text_[j] == '*' || text_[j] == '/' || text_[j] == '^' ||
                           (text_[j] == '-' && j > i && text_[j - 1] == '^'))) {
            ++j;
          }
          t.kind = Tok::kUnit;
        } else {
          while (j < n && IsNameChar(text_[j])) ++j;
          t.kind = Tok::kName;
        }
        t.len = j - i;
        t.text = std::string(text_.substr(i, t.len));
        i = j;
        tokens_.push_back(t);
        continue;
      }
      t.len = 1;
      switch (c) {
        case '+': t.kind = Tok::kPlus; break;
        case '-': t.kind = Tok::kMinus; break;
        case '*': t.kind = Tok::kStar; break;
        case '/': t.kind = Tok::kSlash; break;
        case '^': t.kind = Tok::kCaret; break;
        case '(': t.kind = Tok::kLParen; break;
        case ')': t.kind = Tok::kRParen; break;
        case '[': t.kind = Tok::kLBracket; break;
        case ',': t.kind = Tok::kComma; break;
        case '=':
        case '<':
        case '>': {
          const bool two = i + 1 < n && text_[i + 1] == '=';
          if (c == '=') t.kind = Tok::kEq;
          else if (c == '<') t.kind = Tok::kLe;
          else t.kind = Tok::kGe;
          if (!two && c != '=') {
            Fail(i, 1, std::string("strict relation '") + c + "' is not supported",
                 std::string("write '") + c + "=' (interval domains are closed)");
          }
          t.len = two ? 2 : 1;
          break;
        }
        default:
          Fail(i, 1, std::string("unexpected character '") + c + "'",
               "use numbers, parameter names, + - * / ^, sqrt exp log abs min max sin cos and == <= >=");
      }
      i += t.len;
      tokens_.push_back(t);
    }
    Token end;
    end.kind = Tok::kEnd;
    end.pos = n;
    end.len = 1;
    tokens_.push_back(end);
  }

  const Token& Peek() const { return tokens_[at_]; }
  const Token& Next() { return tokens_[at_++]; }
  void Expect(Tok kind, const char* what) {
    const Token& t = Peek();
    if (t.kind != kind) {
      Fail(t, std::string("expected ") + what + (t.kind == Tok::kEnd ? " before the end" : " here"), "");
    }
    ++at_;
  }
  void ExpectEnd() {
    const Token& t = Peek();
    if (t.kind != Tok::kEnd) {
      Fail(t, "unexpected text after the end of the expression",
           t.kind == Tok::kEq || t.kind == Tok::kLe || t.kind == Tok::kGe
               ? "a constraint has exactly one relation"
               : "check for a missing operator");
    }
  }

  Typed Expr() {
    const std::size_t start = Peek().pos;
    Typed e;
    if (Peek().kind == Tok::kMinus) {
      ++at_;
      const Typed t = Term();
      e = Make(net_.Unary(Op::kNeg, t.id), t.dimension, start, End(), &t);
    } else {
      if (Peek().kind == Tok::kPlus) ++at_;
      e = Term();
    }
    while (Peek().kind == Tok::kPlus || Peek().kind == Tok::kMinus) {
      const Token& op = Next();
      const bool plus = op.kind == Tok::kPlus;
      const Typed r = Term();
      Same(e, r, op, plus ? "adds" : "subtracts");
      e = Make(plus ? net_.Add(e.id, r.id) : net_.Sub(e.id, r.id), e.dimension ? e.dimension : r.dimension, start,
               End(), &e, &r);
    }
    return e;
  }

  Typed Term() {
    const std::size_t start = Peek().pos;
    Typed e = Factor();
    while (Peek().kind == Tok::kStar || Peek().kind == Tok::kSlash) {
      const bool mul = Next().kind == Tok::kStar;
      const Typed r = Factor();
      if (!mul) {
        const auto divisor = ConstantValue(r.id);
        if (divisor && divisor->lower() == 0.0 && divisor->upper() == 0.0)
          Fail(r.pos, r.len, "division by zero", "the divisor is the constant 0; check the expression");
      }
      e = Make(mul ? net_.Mul(e.id, r.id) : net_.Div(e.id, r.id), Product(e, r, !mul), start, End(), &e, &r);
    }
    return e;
  }

  Typed Factor() {
    const DepthGuard guard(*this, Peek());
    const std::size_t start = Peek().pos;
    if (Peek().kind == Tok::kMinus) {
      ++at_;
      const Typed f = Factor();
      return Make(net_.Unary(Op::kNeg, f.id), f.dimension, start, End(), &f);
    }
    const Typed typed_base = Primary();
    if (Peek().kind != Tok::kCaret) return typed_base;
    const ExprId base = typed_base.id;
    ++at_;
    const Token& exp_tok = Peek();
    const Typed typed_exponent = Factor();
    const ExprId exponent = typed_exponent.id;
    if (check_dimensions_ && typed_exponent.dimension && *typed_exponent.dimension != Dimension{})
      Fail(typed_exponent.pos, typed_exponent.len,
           "the exponent is " + DimensionText(*typed_exponent.dimension) + ", not a number",
           "an exponent has no unit");
    const ExprNode& en = net_.node(exponent);
    // A constant exponent is the double nearest the number written (x^0.3 is x^fl(0.3)).
    std::optional<double> constant;
    auto nearest = [&](int node) -> std::optional<double> {
      const auto it = nearest_.find(node);
      if (it != nearest_.end()) return it->second;
      const ExprNode& c = net_.node(ExprId{node});
      if (c.op == Op::kConst && c.value.lower() == c.value.upper()) return c.value.lower();
      return std::nullopt;
    };
    if (en.op == Op::kConst) constant = nearest(exponent.value);
    if (en.op == Op::kNeg && net_.node(ExprId{en.a}).op == Op::kConst) {
      if (const auto v = nearest(en.a)) constant = -*v;
    }
    const std::size_t end = End();
    if (constant) {
      const double p = *constant;
      if (!std::isfinite(p)) Fail(exp_tok, "the exponent is not finite", "");
      if (p == std::floor(p) && std::fabs(p) <= 64) {
        std::optional<Dimension> d;
        if (typed_base.dimension) d = typed_base.dimension->pow(static_cast<int>(p));
        return Make(net_.PowInt(base, static_cast<int>(p)), d, start, end, &typed_base);
      }
      return Make(net_.PowReal(base, p), std::nullopt, start, end, &typed_base);
    }
    const Typed log_base = Make(net_.Unary(Op::kLog, base), std::nullopt, start, end, &typed_base);
    const Typed product = Make(net_.Mul(exponent, log_base.id), std::nullopt, start, end, &typed_exponent, &log_base);
    return Make(net_.Unary(Op::kExp, product.id), std::nullopt, start, end, &product);
  }

  /// A number with an optional sign, enclosed.
  Interval SignedNumber() {
    bool neg = false;
    if (Peek().kind == Tok::kMinus) {
      neg = true;
      ++at_;
    }
    const Token& t = Peek();
    if (t.kind != Tok::kNumber) Fail(t, "expected a number here", "an interval constant is written [lo, hi]");
    ++at_;
    return neg ? -t.enclosure : t.enclosure;
  }

  /// The constant converted to SI when a unit follows (outward: the result encloses the exact
  /// conversion of the decimal value).
  Interval ApplyUnit(const Interval& value, std::optional<Dimension>* dimension = nullptr) {
    if (Peek().kind != Tok::kUnit) return value;
    const Token& u = Next();
    try {
      const Interval si = ConstantToSI(value, u.text);
      if (dimension) *dimension = ParseUnit(u.text).dimension;
      return si;
    } catch (const InputError& e) {
      Fail(u, "unknown unit '" + u.text + "'",
           "write a unit such as mm, N*m, N*m/rad, kg*m^2, rpm or GPa, with spaces around any "
           "operator that follows it (" + e.message() + ")");
    }
  }

  Typed Primary() {
    const Token& t = Peek();
    switch (t.kind) {
      case Tok::kNumber: {
        ++at_;
        if (Peek().kind == Tok::kUnit) {
          std::optional<Dimension> d;
          const Interval value = ApplyUnit(t.enclosure, &d);
          return Make(net_.Const(value), d, t.pos, End());
        }
        const ExprId e = net_.Const(t.enclosure);
        nearest_[e.value] = t.number;
        return Make(e, std::nullopt, t.pos, End());
      }
      case Tok::kLBracket: {
        ++at_;
        const Interval lo = SignedNumber();
        Expect(Tok::kComma, "','");
        const Interval hi = SignedNumber();
        const Token& close = Peek();
        Expect(Tok::kRBracket, "']'");
        if (!(lo.lower() <= hi.upper())) {
          Fail(t.pos, close.pos + 1 - t.pos, "interval constant has lo > hi", "write [lo, hi] with lo <= hi");
        }
        std::optional<Dimension> d;
        const Interval value = ApplyUnit(Interval(lo.lower(), hi.upper(), true), &d);
        return Make(net_.Const(value), d, t.pos, End());
      }
      case Tok::kLParen: {
        ++at_;
        const Typed e = Expr();
        Expect(Tok::kRParen, "')'");
        Typed inner = e;
        inner.pos = t.pos;
        inner.len = End() - t.pos;
        return inner;
      }
      case Tok::kName: {
        ++at_;
        if (Peek().kind == Tok::kLParen) return Call(t);
        VariableId v = resolve_ ? resolve_(t.text) : net_.FindVariable(t.text);
        if (v.value < 0) {
          const auto close = ClosestNames(t.text, net_.VariableNames());
          std::string remedy = "use a parameter name of the project (component.parameter)";
          if (!close.empty()) {
            remedy = "did you mean ";
            for (std::size_t i = 0; i < close.size(); ++i) remedy += (i ? ", '" : "'") + close[i] + "'";
            remedy += "?";
          }
          Fail(t, "unknown parameter '" + t.text + "'", remedy);
        }
        return Make(net_.Var(v), VariableDimension(v), t.pos, End());
      }
      case Tok::kUnit:
        Fail(t, "a unit '" + t.text + "' must follow a number", "");
      case Tok::kEnd:
        Fail(t, "expression ends too early", "complete the expression");
      default:
        Fail(t, "expected a number, a parameter, a function or '(' here", "");
    }
  }

  std::optional<Dimension> VariableDimension(VariableId v) const {
    if (!check_dimensions_) return std::nullopt;
    const std::string& unit = net_.variable(v).unit;
    if (unit.empty()) return std::nullopt;
    try {
      return ParseUnit(unit).dimension;
    } catch (const InputError&) {
      return std::nullopt;
    }
  }

  Typed Call(const Token& name) {
    static const std::vector<std::string> kUnary = {"sqrt", "exp", "log", "abs", "sin", "cos"};
    static const std::vector<std::string> kBinary = {"min", "max"};
    const bool unary = std::find(kUnary.begin(), kUnary.end(), name.text) != kUnary.end();
    const bool binary = std::find(kBinary.begin(), kBinary.end(), name.text) != kBinary.end();
    if (!unary && !binary) {
      std::vector<std::string> all = kUnary;
      all.insert(all.end(), kBinary.begin(), kBinary.end());
      const auto close = ClosestNames(name.text, all, 1);
      Fail(name, "unknown function '" + name.text + "'",
           close.empty() ? "functions are sqrt exp log abs min max sin cos" : "did you mean '" + close[0] + "'?");
    }
    Expect(Tok::kLParen, "'('");
    std::vector<Typed> args{Expr()};
    while (Peek().kind == Tok::kComma) {
      const Token& comma = Next();
      args.push_back(Expr());
      if (binary) Same(args.front(), args.back(), comma, "mixes");
    }
    const Token& close = Peek();
    Expect(Tok::kRParen, "')'");
    const std::size_t end = End();
    if (unary && args.size() != 1) {
      Fail(name.pos, close.pos + 1 - name.pos, name.text + "() takes one argument, got " + std::to_string(args.size()), "");
    }
    if (binary) {
      if (args.size() < 2) Fail(name.pos, close.pos + 1 - name.pos, name.text + "() takes at least two arguments", "");
      Typed e = args[0];
      for (std::size_t i = 1; i < args.size(); ++i)
        e = Make(net_.Binary(name.text == "min" ? Op::kMin : Op::kMax, e.id, args[i].id),
                 e.dimension ? e.dimension : args[i].dimension, name.pos, end, &e, &args[i]);
      return e;
    }
    static const Op kOps[] = {Op::kSqrt, Op::kExp, Op::kLog, Op::kAbs, Op::kSin, Op::kCos};
    const auto idx = std::find(kUnary.begin(), kUnary.end(), name.text) - kUnary.begin();
    const Op op = kOps[idx];
    const Typed& arg = args[0];
    // A constant argument outside the function's domain is a mistake in the text, not a
    // violated requirement: log(-1), log(0), sqrt(-4).
    if (const auto value = ConstantValue(arg.id)) {
      if (op == Op::kLog && !(value->upper() > 0))
        Fail(arg.pos, arg.len, "log() of the constant " + FormatConstant(*value) + ", which is not positive",
             "log is defined for positive arguments only");
      if (op == Op::kSqrt && !(value->upper() >= 0))
        Fail(arg.pos, arg.len, "sqrt() of the negative constant " + FormatConstant(*value),
             "sqrt is defined for arguments >= 0 only");
    }
    std::optional<Dimension> d;
    if (op == Op::kAbs) d = arg.dimension;
    if (op == Op::kSqrt && arg.dimension) {
      Dimension half;
      bool even = true;
      for (std::size_t i = 0; i < half.exponents.size(); ++i) {
        even = even && arg.dimension->exponents[i] % 2 == 0;
        half.exponents[i] = arg.dimension->exponents[i] / 2;
      }
      if (even) d = half;
    }
    if (check_dimensions_ && (op == Op::kExp || op == Op::kLog) && arg.dimension && *arg.dimension != Dimension{})
      Fail(arg.pos, arg.len, name.text + "() of " + DimensionText(*arg.dimension),
           "take " + name.text + "() of a ratio of quantities, which has no unit");
    return Make(net_.Unary(op, arg.id), d, name.pos, end, &arg);
  }

  static std::string FormatConstant(const Interval& v) {
    std::ostringstream s;
    s.precision(6);
    if (v.lower() == v.upper()) s << v.lower();
    else s << "[" << v.lower() << ", " << v.upper() << "]";
    return s.str();
  }

  Network& net_;
  std::string_view text_;
  const std::string& context_;
  SourceLocation where_;
  NameResolver resolve_;
  std::vector<Token> tokens_;
  std::size_t at_ = 0;
  std::unordered_map<int, double> nearest_;  ///< constant node of a number -> its nearest double
  bool check_dimensions_ = false;
  int depth_ = 0;
};

}  // namespace

ParsedConstraint ParseConstraint(Network& network, std::string_view text, const std::string& context,
                                 const SourceLocation& where, NameResolver resolve, bool check_dimensions) {
  Parser p(network, text, context, where, std::move(resolve), check_dimensions);
  return p.Constraint();
}

ExprId ParseExpression(Network& network, std::string_view text, const std::string& context,
                       const SourceLocation& where, NameResolver resolve) {
  Parser p(network, text, context, where, std::move(resolve), false);
  return p.ExpressionOnly();
}

ConstraintId AddConstraintText(Network& network, std::string_view text, ConstraintInfo info,
                               const SourceLocation& where, NameResolver resolve) {
  const std::string context = (info.role == ConstraintRole::kRequirement ? "requirement '" : "constraint '") +
                              info.label + "'";
  // Requirements are the user's text: their units are checked (physics constraints are ours).
  const ParsedConstraint pc =
      ParseConstraint(network, text, context, where, std::move(resolve), info.role == ConstraintRole::kRequirement);
  if (info.source.empty()) info.source = std::string(text);
  return network.AddConstraint(pc.lhs, pc.relation, pc.rhs, std::move(info));
}

}  // namespace highlift::icsp
