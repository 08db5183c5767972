// The table constraint of `optimize --tube-sizes`: each torque shaft whose outer diameter and/or
// wall thickness are design variables is one of the table's sizes (docs/optimize.md, "Tube sizes").
// Internal to optimize: the branch and bound contracts its boxes with Contract and snaps its
// candidate designs with Snap.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "highlift/componentdb/tube_sizes.h"
#include "highlift/core/project.h"
#include "highlift/icsp/interval.h"

namespace highlift::optimize::detail {

/// One shaft restricted to the table: the sizes its domains admit, with their values (SI).
struct TubeShaft {
  std::string component;
  int diameter = -1, wall = -1;     ///< positions in the design vector (-1: not a design variable)
  std::vector<std::string> designations;
  std::vector<double> D, t;         ///< the admitted sizes, clamped into the design domains
};

class TubeConstraint {
 public:
  /// `design_names` and `design_domains`: the design variables ("component.parameter") and their
  /// domains (SI); `domain_of` gives the domain of any other parameter (a shaft's D or t that is not
  /// a design variable). Throws InputError when no torque shaft of `project` has its D or t as a
  /// design variable, or when a shaft's domains admit no size of the table (naming the shaft, its
  /// domains and the nearest sizes).
  TubeConstraint(const componentdb::TubeSizeTable& table, const Project& project,
                 const std::vector<std::string>& design_names, const std::vector<icsp::Interval>& design_domains,
                 const std::function<icsp::Interval(const std::string&)>& domain_of);

  /// The table constraint on a box of design variables: each shaft's (D, t) contracted to the hull
  /// of the sizes inside it (a set operation: every size of the box stays in it). Returns false
  /// when a shaft has no size left (no design of the box is made of the table's sizes); `changed`
  /// says whether an interval narrowed.
  bool Contract(std::vector<icsp::Interval>& d, bool& changed) const;

  /// Designs made of the table's sizes near `x` inside the box `d` (each shaft's sizes inside it;
  /// all of its sizes when none is): every shaft at its nearest size (by |log D/D_x| and
  /// |log t/t_x|), at its nearest size that is at least as large in D and t ("up"; the nearest when
  /// there is none), and at its nearest that is at most as large ("down"; likewise).
  struct Snapped {
    std::vector<double> nearest, up, down;
  };
  Snapped Snap(const std::vector<double>& x, const std::vector<icsp::Interval>& d) const;

  /// Each shaft's size at `x` ("" when x is not one of its sizes), by component.
  std::vector<std::pair<std::string, std::string>> Sizes(const std::vector<double>& x) const;

  const std::vector<TubeShaft>& shafts() const { return shafts_; }
  const std::string& table_name() const { return table_name_; }

 private:
  std::vector<TubeShaft> shafts_;
  std::string table_name_;
};

}  // namespace highlift::optimize::detail
