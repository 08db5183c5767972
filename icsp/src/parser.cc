#include "highlift/icsp/parser.h"

#include <algorithm>
#include <cctype>
#include <cfenv>
#include <cmath>
#include <cstdlib>
#include <optional>
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

class Parser {
 public:
  Parser(Network& net, std::string_view text, const std::string& context, const SourceLocation& where,
         NameResolver resolve)
      : net_(net), text_(text), context_(context), where_(where), resolve_(std::move(resolve)) {
    Lex();
  }

  ParsedConstraint Constraint() {
    ParsedConstraint pc;
    pc.lhs = Expr();
    const Token& t = Peek();
    if (t.kind == Tok::kEq) pc.relation = Relation::kEqual;
    else if (t.kind == Tok::kLe) pc.relation = Relation::kLessEqual;
    else if (t.kind == Tok::kGe) pc.relation = Relation::kGreaterEqual;
    else Fail(t, "expected '==', '<=' or '>=' here", "write a relation such as 'a <= b'");
    ++at_;
    pc.rhs = Expr();
    ExpectEnd();
    return pc;
  }

  ExprId ExpressionOnly() {
    ExprId e = Expr();
    ExpectEnd();
    return e;
  }

 private:
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

  ExprId Expr() {
    ExprId e;
    if (Peek().kind == Tok::kMinus) {
      ++at_;
      e = net_.Unary(Op::kNeg, Term());
    } else {
      if (Peek().kind == Tok::kPlus) ++at_;
      e = Term();
    }
    while (Peek().kind == Tok::kPlus || Peek().kind == Tok::kMinus) {
      const bool plus = Next().kind == Tok::kPlus;
      ExprId r = Term();
      e = plus ? net_.Add(e, r) : net_.Sub(e, r);
    }
    return e;
  }

  ExprId Term() {
    ExprId e = Factor();
    while (Peek().kind == Tok::kStar || Peek().kind == Tok::kSlash) {
      const bool mul = Next().kind == Tok::kStar;
      ExprId r = Factor();
      e = mul ? net_.Mul(e, r) : net_.Div(e, r);
    }
    return e;
  }

  ExprId Factor() {
    if (Peek().kind == Tok::kMinus) {
      ++at_;
      return net_.Unary(Op::kNeg, Factor());
    }
    ExprId base = Primary();
    if (Peek().kind != Tok::kCaret) return base;
    ++at_;
    const Token& exp_tok = Peek();
    ExprId exponent = Factor();
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
    if (constant) {
      const double p = *constant;
      if (!std::isfinite(p)) Fail(exp_tok, "the exponent is not finite", "");
      if (p == std::floor(p) && std::fabs(p) <= 64) return net_.PowInt(base, static_cast<int>(p));
      return net_.PowReal(base, p);
    }
    return net_.Unary(Op::kExp, net_.Mul(exponent, net_.Unary(Op::kLog, base)));
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
  Interval ApplyUnit(const Interval& value) {
    if (Peek().kind != Tok::kUnit) return value;
    const Token& u = Next();
    try {
      return ConstantToSI(value, u.text);
    } catch (const InputError& e) {
      Fail(u, "unknown unit '" + u.text + "'",
           "write a unit such as mm, N*m, N*m/rad, kg*m^2, rpm or GPa, with spaces around any "
           "operator that follows it (" + e.message() + ")");
    }
  }

  ExprId Primary() {
    const Token& t = Peek();
    switch (t.kind) {
      case Tok::kNumber: {
        ++at_;
        if (Peek().kind == Tok::kUnit) return net_.Const(ApplyUnit(t.enclosure));
        const ExprId e = net_.Const(t.enclosure);
        nearest_[e.value] = t.number;
        return e;
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
        return net_.Const(ApplyUnit(Interval(lo.lower(), hi.upper(), true)));
      }
      case Tok::kLParen: {
        ++at_;
        ExprId e = Expr();
        Expect(Tok::kRParen, "')'");
        return e;
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
        return net_.Var(v);
      }
      case Tok::kUnit:
        Fail(t, "a unit '" + t.text + "' must follow a number", "");
      case Tok::kEnd:
        Fail(t, "expression ends too early", "complete the expression");
      default:
        Fail(t, "expected a number, a parameter, a function or '(' here", "");
    }
  }

  ExprId Call(const Token& name) {
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
    std::vector<ExprId> args{Expr()};
    while (Peek().kind == Tok::kComma) {
      ++at_;
      args.push_back(Expr());
    }
    const Token& close = Peek();
    Expect(Tok::kRParen, "')'");
    if (unary && args.size() != 1) {
      Fail(name.pos, close.pos + 1 - name.pos, name.text + "() takes one argument, got " + std::to_string(args.size()), "");
    }
    if (binary) {
      if (args.size() < 2) Fail(name.pos, close.pos + 1 - name.pos, name.text + "() takes at least two arguments", "");
      ExprId e = args[0];
      for (std::size_t i = 1; i < args.size(); ++i) e = net_.Binary(name.text == "min" ? Op::kMin : Op::kMax, e, args[i]);
      return e;
    }
    static const Op kOps[] = {Op::kSqrt, Op::kExp, Op::kLog, Op::kAbs, Op::kSin, Op::kCos};
    const auto idx = std::find(kUnary.begin(), kUnary.end(), name.text) - kUnary.begin();
    return net_.Unary(kOps[idx], args[0]);
  }

  Network& net_;
  std::string_view text_;
  const std::string& context_;
  SourceLocation where_;
  NameResolver resolve_;
  std::vector<Token> tokens_;
  std::size_t at_ = 0;
  std::unordered_map<int, double> nearest_;  ///< constant node of a number -> its nearest double
};

}  // namespace

ParsedConstraint ParseConstraint(Network& network, std::string_view text, const std::string& context,
                                 const SourceLocation& where, NameResolver resolve) {
  Parser p(network, text, context, where, std::move(resolve));
  return p.Constraint();
}

ExprId ParseExpression(Network& network, std::string_view text, const std::string& context,
                       const SourceLocation& where, NameResolver resolve) {
  Parser p(network, text, context, where, std::move(resolve));
  return p.ExpressionOnly();
}

ConstraintId AddConstraintText(Network& network, std::string_view text, ConstraintInfo info,
                               const SourceLocation& where, NameResolver resolve) {
  const std::string context = (info.role == ConstraintRole::kRequirement ? "requirement '" : "constraint '") +
                              info.label + "'";
  const ParsedConstraint pc = ParseConstraint(network, text, context, where, std::move(resolve));
  if (info.source.empty()) info.source = std::string(text);
  return network.AddConstraint(pc.lhs, pc.relation, pc.rhs, std::move(info));
}

}  // namespace highlift::icsp
