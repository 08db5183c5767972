// The structure of an interval constraint network: variables (names, units, initial domains),
// an expression DAG with hash-consing (a subexpression used by several constraints is one node),
// and constraints g OP 0 with OP in {==, <=, >=}, or monotone black-box constraints
// y = f(x1..xn). The values (current domains) live in a Box, apart from the structure, so one
// network serves many studies (check, trade-off slices, explanations).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "highlift/icsp/interval.h"

namespace highlift::icsp {

/// Index of a variable in a Network (and of its domain in a Box).
struct VariableId {
  int value = -1;
  friend bool operator==(VariableId, VariableId) = default;
};
/// Index of an expression node in a Network.
struct ExprId {
  int value = -1;
  friend bool operator==(ExprId, ExprId) = default;
};
/// Index of a constraint in a Network.
struct ConstraintId {
  int value = -1;
  friend bool operator==(ConstraintId, ConstraintId) = default;
};

/// Current domains, one per variable, indexed by VariableId::value.
using Box = std::vector<Interval>;

enum class Op : std::uint8_t {
  kVar, kConst, kAdd, kSub, kMul, kDiv, kNeg, kSqr, kPowInt, kPowReal, kSqrt, kExp, kLog, kAbs,
  kMin, kMax, kSin, kCos
};
/// "+", "sqrt", ... (for messages and printing).
std::string ToString(Op op);

enum class Relation : std::uint8_t { kEqual, kLessEqual, kGreaterEqual };
/// "==", "<=", ">=".
std::string ToString(Relation r);

/// Physics constraints are the model (always kept); requirements are what the engineer asks for
/// and are what an explanation of infeasibility names.
enum class ConstraintRole : std::uint8_t { kPhysics, kRequirement };
std::string ToString(ConstraintRole r);

/// Monotonicity of a black-box function in one argument.
enum class Monotonicity : std::uint8_t { kIncreasing, kDecreasing };

/// What a constraint means to an engineer.
struct ConstraintInfo {
  std::string label;        ///< short identifier, e.g. "R3" or "shaft_l1.stiffness"
  std::string description;  ///< one line in words, e.g. "tube stiffness c = G*Ip/L"
  ConstraintRole role = ConstraintRole::kPhysics;
  std::string source = {};  ///< the constraint as written, with its units (AddConstraintText
                            ///< fills it); explanations quote it
};

struct VariableInfo {
  std::string name;         ///< e.g. "wtb_left.static_limit_torque"
  std::string unit;         ///< display unit (values are SI); may be empty
  Interval initial;         ///< initial domain (SI)
  std::string provenance;   ///< "user", "default", ... (free text for reports)
};

struct ExprNode {
  Op op = Op::kConst;
  int a = -1;          ///< first operand node (or variable index for kVar)
  int b = -1;          ///< second operand node
  int n = 0;           ///< integer exponent (kPowInt)
  double p = 0.0;      ///< real exponent (kPowReal)
  Interval value;      ///< constant (kConst)
};

/// y = f(x1..xn) with f monotone in each argument; enclosed by evaluating f at the corners.
struct MonotoneFunction {
  std::function<double(std::span<const double>)> f;
  std::vector<Monotonicity> monotonicity;  ///< one per argument
  double relative_error = 1e-12;           ///< |computed f - true f| <= this * |f| (widening)
  int bisection_steps = 40;                ///< per bound in the backward projection
};

struct Constraint {
  enum class Kind : std::uint8_t { kExpression, kMonotone };
  Kind kind = Kind::kExpression;
  int root = -1;                           ///< kExpression: node of g in g OP 0
  Relation relation = Relation::kEqual;
  int monotone = -1;                       ///< kMonotone: index into monotone functions
  int topo_begin = 0, topo_end = 0;        ///< nodes in topological order (children first)
  int vars_begin = 0, vars_end = 0;        ///< variables in its scope
  ConstraintInfo info;
};

class Network {
 public:
  /// Adds a variable; names must be unique and non-empty. Throws InputError otherwise.
  VariableId AddVariable(std::string name, Interval initial, std::string unit = "",
                         std::string provenance = "");
  /// Reserves memory for the given numbers of variables, expression nodes and constraints.
  void Reserve(int variables, int nodes, int constraints);
  /// The variable named `name`, or an id with value -1.
  VariableId FindVariable(std::string_view name) const;
  int num_variables() const { return static_cast<int>(variables_.size()); }
  const VariableInfo& variable(VariableId v) const { return variables_[v.value]; }
  void SetInitial(VariableId v, Interval initial) { variables_[v.value].initial = initial; }
  /// The initial domains of all variables.
  Box InitialBox() const;
  /// All variable names (for suggestions).
  std::vector<std::string> VariableNames() const;

  // Expression building; identical subexpressions are one node.
  ExprId Var(VariableId v);
  ExprId Const(double value);
  ExprId Const(Interval value);
  ExprId Unary(Op op, ExprId a);
  ExprId Binary(Op op, ExprId a, ExprId b);
  ExprId PowInt(ExprId a, int n);
  ExprId PowReal(ExprId a, double p);
  ExprId Add(ExprId a, ExprId b) { return Binary(Op::kAdd, a, b); }
  ExprId Sub(ExprId a, ExprId b) { return Binary(Op::kSub, a, b); }
  ExprId Mul(ExprId a, ExprId b) { return Binary(Op::kMul, a, b); }
  ExprId Div(ExprId a, ExprId b) { return Binary(Op::kDiv, a, b); }
  ExprId Sqrt(ExprId a) { return Unary(Op::kSqrt, a); }
  int num_nodes() const { return static_cast<int>(nodes_.size()); }
  const ExprNode& node(ExprId e) const { return nodes_[e.value]; }
  /// `e` with every node that is a key of `replacements` replaced by its value, the rest rebuilt
  /// (hash-consed, so an unchanged subexpression is the same node). Sound only when each value
  /// equals its key for every point of the network's solutions (an exact identity, e.g. a
  /// polynomial and the derived variable that names it); the drive-system network uses it so that
  /// a requirement written in a tube's D and t reads the tube's polar moment.
  ExprId Replace(ExprId e, const std::unordered_map<int, ExprId>& replacements);

  /// Adds g OP 0.
  ConstraintId AddConstraint(ExprId g, Relation relation, ConstraintInfo info);
  /// Adds lhs OP rhs as (lhs - rhs) OP 0.
  ConstraintId AddConstraint(ExprId lhs, Relation relation, ExprId rhs, ConstraintInfo info);
  /// Adds y = f(args) with f monotone in each argument (see MonotoneFunction).
  ConstraintId AddMonotone(VariableId y, std::vector<VariableId> args, MonotoneFunction f,
                           ConstraintInfo info);
  int num_constraints() const { return static_cast<int>(constraints_.size()); }
  const Constraint& constraint(ConstraintId c) const { return constraints_[c.value]; }
  /// Variables in the scope of a constraint.
  std::span<const int> ScopeOf(ConstraintId c) const;
  /// Constraints whose scope holds v.
  std::span<const int> ConstraintsOf(VariableId v) const { return adjacency_[v.value]; }
  /// Nodes of an expression constraint in topological order (operands first).
  std::span<const int> TopoOf(ConstraintId c) const;
  const MonotoneFunction& monotone(int index) const { return monotone_[index]; }
  int num_monotone() const { return static_cast<int>(monotone_.size()); }

  /// g OP 0 as text with variable names, e.g. "tau - 1 * sqrt(c * J) == 0"; for a monotone
  /// constraint "y = f(x1, x2)".
  std::string ConstraintText(ConstraintId c) const;
  std::string ExprText(ExprId e) const;

 private:
  struct KeyHash {
    std::size_t operator()(const ExprNode& n) const;
  };
  struct KeyEqual {
    bool operator()(const ExprNode& x, const ExprNode& y) const;
  };
  ExprId Intern(const ExprNode& node);
  void IndexConstraint(Constraint& c, std::vector<int> vars_of_monotone);
  void PrintExpr(int node, int parent_precedence, std::string& out) const;

  std::vector<VariableInfo> variables_;
  std::unordered_map<std::string, int> variable_index_;
  std::vector<ExprNode> nodes_;
  std::vector<int> interned_;               ///< open-addressing hash table of node ids (-1: free)
  std::vector<Constraint> constraints_;
  std::vector<int> topo_;                   ///< concatenated topological orders
  std::vector<int> scope_;                  ///< concatenated scopes
  std::vector<std::vector<int>> adjacency_; ///< variable -> constraints
  std::vector<MonotoneFunction> monotone_;
  std::vector<int> visit_stamp_;            ///< scratch for topological sorting
  int stamp_ = 0;
};

}  // namespace highlift::icsp
