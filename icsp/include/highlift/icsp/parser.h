// The constraint language.
//
//   constraint := expr ("==" | "<=" | ">=") expr
//   expr       := ["+"|"-"] term {("+"|"-") term}
//   term       := factor {("*"|"/") factor}
//   factor     := "-" factor | primary ["^" factor]          (right-associative power)
//   primary    := number [unit] | "[" number "," number "]" [unit] | name
//               | function "(" expr {"," expr} ")" | "(" expr ")"
//   function   := sqrt exp log abs min max sin cos
//
// Names are parameters such as `wtb_left.static_limit_torque` (letters, digits, '_' and '.').
// A constant may carry a unit written right after it: `2 mm`, `550 N*m`, `[43, 51] GPa`,
// `242 rpm`; it is converted to SI. Constants are enclosed: a decimal that no double represents
// (0.1) becomes the interval of the two doubles around it, and a unit conversion rounds outward,
// so a point that satisfies the constraint as written is never cut off. A unit is one word of letters, digits and `* / ^`, so write
// spaces around an operator that follows a unit (`2 mm * x`). Exponents that are constants give
// x^n (integer) or x^p (real, x >= 0); other exponents give exp(y * log(x)).
// Errors throw InputError with the column and a caret line under the offending text.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "highlift/core/error.h"
#include "highlift/icsp/network.h"

namespace highlift::icsp {

/// Looks up a name; returns an id with value -1 when unknown. The default uses
/// Network::FindVariable.
using NameResolver = std::function<VariableId(std::string_view name)>;

struct ParsedConstraint {
  ExprId lhs;
  Relation relation = Relation::kEqual;
  ExprId rhs;
};

/// Parses `text` into expression nodes of `network`. `context` names the text in messages
/// (e.g. "requirement 'R3'"); `where` is attached to the InputError (file, JSON pointer).
/// Input errors, never crashes or violated constraints: nesting deeper than 200 levels, division
/// by the constant 0, log() or sqrt() of a constant outside their domain and, with
/// `check_dimensions`, sides of + - min max or the relation with different dimensions (`X >=
/// 145 kg` with X a torque; dimensions come from the constants' units and the variables' units,
/// a bare number matches anything). AddConstraintText checks dimensions for requirements.
ParsedConstraint ParseConstraint(Network& network, std::string_view text, const std::string& context,
                                 const SourceLocation& where = {}, NameResolver resolve = {},
                                 bool check_dimensions = false);
/// Parses one expression (no relation).
ExprId ParseExpression(Network& network, std::string_view text, const std::string& context,
                       const SourceLocation& where = {}, NameResolver resolve = {});
/// Parses and adds `lhs OP rhs` as (lhs - rhs) OP 0.
ConstraintId AddConstraintText(Network& network, std::string_view text, ConstraintInfo info,
                               const SourceLocation& where = {}, NameResolver resolve = {});

/// `value` given in `unit` converted to SI (the one place where the parser meets units).
/// Throws InputError naming the unit when it is not understood.
double ConstantToSI(double value, std::string_view unit);
/// The same for an enclosure, outward: the result encloses the conversion of every value in
/// `value`. Integer factors (1000, 1e9, 60) are exact; other factors (1e-3, pi/30) are the unit
/// system's doubles and are taken as known to two ulps.
Interval ConstantToSI(const Interval& value, std::string_view unit);

/// Closest names to `name` (edit distance), at most `max_results`, for "did you mean".
std::vector<std::string> ClosestNames(std::string_view name, const std::vector<std::string>& candidates,
                                      std::size_t max_results = 3);

}  // namespace highlift::icsp
