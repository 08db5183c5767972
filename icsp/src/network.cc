#include "highlift/icsp/network.h"

#include <bit>
#include <cstdio>

#include "highlift/core/error.h"

namespace highlift::icsp {

std::string ToString(const Interval& x, int significant) {
  if (IsEmpty(x)) return "[empty]";
  char buf[96];
  // + 0.0 turns -0 into 0 for display.
  std::snprintf(buf, sizeof buf, "[%.*g, %.*g]", significant, x.lower() + 0.0, significant, x.upper() + 0.0);
  return buf;
}

std::string ToString(Op op) {
  switch (op) {
    case Op::kVar: return "var";
    case Op::kConst: return "const";
    case Op::kAdd: return "+";
    case Op::kSub: return "-";
    case Op::kMul: return "*";
    case Op::kDiv: return "/";
    case Op::kNeg: return "neg";
    case Op::kSqr: return "sqr";
    case Op::kPowInt: return "^";
    case Op::kPowReal: return "^";
    case Op::kSqrt: return "sqrt";
    case Op::kExp: return "exp";
    case Op::kLog: return "log";
    case Op::kAbs: return "abs";
    case Op::kMin: return "min";
    case Op::kMax: return "max";
    case Op::kSin: return "sin";
    case Op::kCos: return "cos";
  }
  return "?";
}

std::string ToString(Relation r) {
  switch (r) {
    case Relation::kEqual: return "==";
    case Relation::kLessEqual: return "<=";
    case Relation::kGreaterEqual: return ">=";
  }
  return "?";
}

std::string ToString(ConstraintRole r) {
  return r == ConstraintRole::kPhysics ? "physics" : "requirement";
}

VariableId Network::AddVariable(std::string name, Interval initial, std::string unit,
                                std::string provenance) {
  if (name.empty()) throw InputError("icsp: a variable needs a non-empty name");
  if (variable_index_.count(name) != 0) {
    throw InputError("icsp: variable '" + name + "' is declared twice; give each variable a unique name");
  }
  const int id = static_cast<int>(variables_.size());
  variable_index_.emplace(name, id);
  variables_.push_back({std::move(name), std::move(unit), initial, std::move(provenance)});
  adjacency_.emplace_back();
  return VariableId{id};
}

VariableId Network::FindVariable(std::string_view name) const {
  auto it = variable_index_.find(std::string(name));
  return it == variable_index_.end() ? VariableId{} : VariableId{it->second};
}

Box Network::InitialBox() const {
  Box box;
  box.reserve(variables_.size());
  for (const auto& v : variables_) box.push_back(v.initial);
  return box;
}

std::vector<std::string> Network::VariableNames() const {
  std::vector<std::string> names;
  names.reserve(variables_.size());
  for (const auto& v : variables_) names.push_back(v.name);
  return names;
}

std::size_t Network::KeyHash::operator()(const ExprNode& n) const {
  // splitmix64 finalizer per field: cheap and well mixed (identifiers are small consecutive
  // integers, which a plain combine would cluster).
  auto fmix = [](std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  std::uint64_t h = fmix(static_cast<std::uint64_t>(n.op) + 0x9E3779B97F4A7C15ull);
  h = fmix(h ^ (static_cast<std::uint64_t>(static_cast<std::uint32_t>(n.a)) |
                (static_cast<std::uint64_t>(static_cast<std::uint32_t>(n.b)) << 32)));
  h = fmix(h ^ static_cast<std::uint32_t>(n.n) ^ std::bit_cast<std::uint64_t>(n.p));
  if (n.op == Op::kConst) {
    h = fmix(h ^ std::bit_cast<std::uint64_t>(n.value.lower()));
    h = fmix(h ^ std::bit_cast<std::uint64_t>(n.value.upper()));
  }
  return static_cast<std::size_t>(h);
}

bool Network::KeyEqual::operator()(const ExprNode& x, const ExprNode& y) const {
  if (x.op != y.op || x.a != y.a || x.b != y.b || x.n != y.n ||
      std::bit_cast<std::uint64_t>(x.p) != std::bit_cast<std::uint64_t>(y.p)) {
    return false;
  }
  if (x.op != Op::kConst) return true;
  return std::bit_cast<std::uint64_t>(x.value.lower()) == std::bit_cast<std::uint64_t>(y.value.lower()) &&
         std::bit_cast<std::uint64_t>(x.value.upper()) == std::bit_cast<std::uint64_t>(y.value.upper());
}

ExprId Network::Intern(const ExprNode& node) {
  if ((nodes_.size() + 1) * 2 > interned_.size()) {
    // Grow and re-insert: linear probing over a power-of-two table at most half full.
    std::vector<int> table(std::max<std::size_t>(1024, interned_.size() * 2), -1);
    const std::size_t mask = table.size() - 1;
    for (std::size_t id = 0; id < nodes_.size(); ++id) {
      std::size_t i = KeyHash{}(nodes_[id]) & mask;
      while (table[i] >= 0) i = (i + 1) & mask;
      table[i] = static_cast<int>(id);
    }
    interned_.swap(table);
  }
  const std::size_t mask = interned_.size() - 1;
  std::size_t i = KeyHash{}(node) & mask;
  while (true) {
    const int id = interned_[i];
    if (id < 0) {
      interned_[i] = static_cast<int>(nodes_.size());
      nodes_.push_back(node);
      return ExprId{interned_[i]};
    }
    if (KeyEqual{}(nodes_[id], node)) return ExprId{id};
    i = (i + 1) & mask;
  }
}

void Network::Reserve(int variables, int nodes, int constraints) {
  variables_.reserve(variables);
  variable_index_.reserve(variables);
  adjacency_.reserve(variables);
  nodes_.reserve(nodes);
  constraints_.reserve(constraints);
  topo_.reserve(nodes);
  scope_.reserve(static_cast<std::size_t>(constraints) * 3);
}

ExprId Network::Var(VariableId v) {
  HIGHLIFT_CHECK(v.value >= 0 && v.value < num_variables(), "icsp: variable id out of range");
  ExprNode n;
  n.op = Op::kVar;
  n.a = v.value;
  return Intern(n);
}

ExprId Network::Const(double value) { return Const(Interval(value, value, true)); }

ExprId Network::Const(Interval value) {
  ExprNode n;
  n.op = Op::kConst;
  n.value = value;
  return Intern(n);
}

ExprId Network::Unary(Op op, ExprId a) {
  HIGHLIFT_CHECK(a.value >= 0 && a.value < num_nodes(), "icsp: operand out of range");
  ExprNode n;
  n.op = op;
  n.a = a.value;
  return Intern(n);
}

ExprId Network::Binary(Op op, ExprId a, ExprId b) {
  HIGHLIFT_CHECK(a.value >= 0 && a.value < num_nodes() && b.value >= 0 && b.value < num_nodes(),
                 "icsp: operand out of range");
  ExprNode n;
  n.op = op;
  n.a = a.value;
  n.b = b.value;
  return Intern(n);
}

ExprId Network::PowInt(ExprId a, int exponent) {
  if (exponent == 2) return Unary(Op::kSqr, a);
  ExprNode n;
  n.op = Op::kPowInt;
  n.a = a.value;
  n.n = exponent;
  return Intern(n);
}

ExprId Network::PowReal(ExprId a, double p) {
  ExprNode n;
  n.op = Op::kPowReal;
  n.a = a.value;
  n.p = p;
  return Intern(n);
}

ExprId Network::Replace(ExprId e, const std::unordered_map<int, ExprId>& replacements) {
  HIGHLIFT_CHECK(e.value >= 0 && e.value < num_nodes(), "icsp: expression id out of range");
  if (replacements.empty()) return e;
  // Post-order over the DAG below e (each node once), operands rebuilt before their parents.
  std::unordered_map<int, ExprId> done;
  std::vector<std::pair<int, bool>> stack{{e.value, false}};
  while (!stack.empty()) {
    const auto [id, expanded] = stack.back();
    stack.pop_back();
    if (done.count(id)) continue;
    if (const auto it = replacements.find(id); it != replacements.end()) {
      done.emplace(id, it->second);
      continue;
    }
    const ExprNode n = nodes_[id];
    const bool leaf = n.op == Op::kVar || n.op == Op::kConst;
    const bool binary = !leaf && n.b >= 0;
    if (leaf) {
      done.emplace(id, ExprId{id});
      continue;
    }
    if (!expanded) {
      stack.push_back({id, true});
      stack.push_back({n.a, false});
      if (binary) stack.push_back({n.b, false});
      continue;
    }
    ExprNode m = n;
    m.a = done.at(n.a).value;
    if (binary) m.b = done.at(n.b).value;
    done.emplace(id, (m.a == n.a && m.b == n.b) ? ExprId{id} : Intern(m));
  }
  return done.at(e.value);
}

void Network::IndexConstraint(Constraint& c, std::vector<int> vars_of_monotone) {
  const int id = static_cast<int>(constraints_.size());
  if (visit_stamp_.size() < nodes_.size()) visit_stamp_.resize(nodes_.size() * 2 + 16, 0);
  ++stamp_;
  c.topo_begin = static_cast<int>(topo_.size());
  c.vars_begin = static_cast<int>(scope_.size());
  if (c.kind == Constraint::Kind::kExpression) {
    // Iterative post-order DFS (operands first); each DAG node once.
    std::vector<std::pair<int, int>> stack{{c.root, 0}};
    visit_stamp_[c.root] = stamp_;
    while (!stack.empty()) {
      auto& [node, state] = stack.back();
      const ExprNode& n = nodes_[node];
      const int child = state == 0 ? (n.op == Op::kVar || n.op == Op::kConst ? -1 : n.a)
                        : state == 1 ? n.b
                                     : -1;
      if (state < 2) {
        ++state;
        if (child >= 0 && visit_stamp_[child] != stamp_) {
          visit_stamp_[child] = stamp_;
          stack.push_back({child, 0});
        }
        continue;
      }
      topo_.push_back(node);
      if (n.op == Op::kVar) scope_.push_back(n.a);
      stack.pop_back();
    }
  } else {
    for (int v : vars_of_monotone) scope_.push_back(v);
  }
  c.topo_end = static_cast<int>(topo_.size());
  c.vars_end = static_cast<int>(scope_.size());
  for (int k = c.vars_begin; k < c.vars_end; ++k) adjacency_[scope_[k]].push_back(id);
  constraints_.push_back(std::move(c));
}

ConstraintId Network::AddConstraint(ExprId g, Relation relation, ConstraintInfo info) {
  HIGHLIFT_CHECK(g.value >= 0 && g.value < num_nodes(), "icsp: constraint expression out of range");
  Constraint c;
  c.kind = Constraint::Kind::kExpression;
  c.root = g.value;
  c.relation = relation;
  c.info = std::move(info);
  IndexConstraint(c, {});
  return ConstraintId{num_constraints() - 1};
}

ConstraintId Network::AddConstraint(ExprId lhs, Relation relation, ExprId rhs, ConstraintInfo info) {
  return AddConstraint(Sub(lhs, rhs), relation, std::move(info));
}

ConstraintId Network::AddMonotone(VariableId y, std::vector<VariableId> args, MonotoneFunction f,
                                  ConstraintInfo info) {
  if (f.monotonicity.size() != args.size()) {
    throw InputError("icsp: monotone constraint '" + info.label + "' has " +
                     std::to_string(args.size()) + " arguments but " +
                     std::to_string(f.monotonicity.size()) +
                     " monotonicity declarations; give one per argument");
  }
  if (!f.f) throw InputError("icsp: monotone constraint '" + info.label + "' has no function");
  std::vector<int> vars{y.value};
  for (VariableId a : args) {
    if (a == y) {
      throw InputError("icsp: monotone constraint '" + info.label +
                       "' uses its result as an argument; y = f(x) needs y outside x");
    }
    vars.push_back(a.value);
  }
  for (std::size_t i = 0; i < vars.size(); ++i) {
    for (std::size_t j = i + 1; j < vars.size(); ++j) {
      if (vars[i] == vars[j]) {
        throw InputError("icsp: monotone constraint '" + info.label + "' lists variable '" +
                         variables_[vars[i]].name + "' twice; pass each argument once");
      }
    }
  }
  Constraint c;
  c.kind = Constraint::Kind::kMonotone;
  c.monotone = static_cast<int>(monotone_.size());
  c.info = std::move(info);
  monotone_.push_back(std::move(f));
  IndexConstraint(c, vars);  // scope: y, then the arguments in order
  return ConstraintId{num_constraints() - 1};
}

std::span<const int> Network::ScopeOf(ConstraintId c) const {
  const Constraint& k = constraints_[c.value];
  return {scope_.data() + k.vars_begin, static_cast<std::size_t>(k.vars_end - k.vars_begin)};
}

std::span<const int> Network::TopoOf(ConstraintId c) const {
  const Constraint& k = constraints_[c.value];
  return {topo_.data() + k.topo_begin, static_cast<std::size_t>(k.topo_end - k.topo_begin)};
}

namespace {
int Precedence(Op op) {
  switch (op) {
    case Op::kAdd:
    case Op::kSub: return 1;
    case Op::kMul:
    case Op::kDiv: return 2;
    case Op::kNeg: return 3;
    case Op::kPowInt:
    case Op::kPowReal:
    case Op::kSqr: return 4;
    default: return 5;
  }
}
std::string Number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}
}  // namespace

void Network::PrintExpr(int node, int parent_precedence, std::string& out) const {
  const ExprNode& n = nodes_[node];
  const int prec = Precedence(n.op);
  const bool paren = prec < parent_precedence;
  if (paren) out += "(";
  switch (n.op) {
    case Op::kVar: out += variables_[n.a].name; break;
    case Op::kConst:
      // An enclosed decimal (0.1 is [0.09999999999999999, 0.1]) prints as the number.
      if (n.value.lower() == n.value.upper() || Number(n.value.lower()) == Number(n.value.upper())) {
        out += Number(n.value.lower());
      } else {
        out += "[" + Number(n.value.lower()) + ", " + Number(n.value.upper()) + "]";
      }
      break;
    case Op::kAdd:
    case Op::kSub:
    case Op::kMul:
    case Op::kDiv:
      PrintExpr(n.a, prec, out);
      out += " " + ToString(n.op) + " ";
      PrintExpr(n.b, prec + 1, out);
      break;
    case Op::kNeg:
      out += "-";
      PrintExpr(n.a, prec + 1, out);
      break;
    case Op::kSqr:
      PrintExpr(n.a, prec + 1, out);
      out += "^2";
      break;
    case Op::kPowInt:
      PrintExpr(n.a, prec + 1, out);
      out += "^" + std::to_string(n.n);
      break;
    case Op::kPowReal:
      PrintExpr(n.a, prec + 1, out);
      out += "^" + Number(n.p);
      break;
    case Op::kMin:
    case Op::kMax:
      out += ToString(n.op) + "(";
      PrintExpr(n.a, 0, out);
      out += ", ";
      PrintExpr(n.b, 0, out);
      out += ")";
      break;
    default:
      out += ToString(n.op) + "(";
      PrintExpr(n.a, 0, out);
      out += ")";
      break;
  }
  if (paren) out += ")";
}

std::string Network::ExprText(ExprId e) const {
  std::string out;
  PrintExpr(e.value, 0, out);
  return out;
}

std::string Network::ConstraintText(ConstraintId id) const {
  const Constraint& c = constraints_[id.value];
  if (c.kind == Constraint::Kind::kMonotone) {
    auto scope = ScopeOf(id);
    std::string out = variables_[scope[0]].name + " == f(";
    for (std::size_t k = 1; k < scope.size(); ++k) {
      if (k > 1) out += ", ";
      out += variables_[scope[k]].name;
    }
    return out + ")";
  }
  const ExprNode& root = nodes_[c.root];
  std::string out;
  if (root.op == Op::kSub) {  // print lhs OP rhs
    PrintExpr(root.a, 0, out);
    out += " " + ToString(c.relation) + " ";
    PrintExpr(root.b, 0, out);
  } else {
    PrintExpr(c.root, 0, out);
    out += " " + ToString(c.relation) + " 0";
  }
  return out;
}

}  // namespace highlift::icsp
