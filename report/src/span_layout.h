// Where each component sits along the span and in which lane of the drawing: the components'
// span_position where the project gives it, else the distance from the PDU along the drive
// line (shaft lengths), negative on the left wing.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "highlift/core/project.h"

namespace highlift::report {

struct SpanLayout {
  std::vector<double> x;     ///< m, per component (project order); NaN when not reached
  std::vector<int> lane;     ///< 0 the drive line, 1, 2, ... down a station's branch, -1 sensors
  std::vector<std::pair<int, int>> edges;  ///< connected components (flange connections)
  bool from_lengths = false; ///< some positions were computed from shaft lengths

  /// Span position of a node of a lumped model with `elements` sub-elements per shaft: a
  /// component ("tgb_l1"), a shaft end ("shaft_l1/b"), a sub-element node ("shaft_l1#2") or a
  /// lumped section ("shaft_l2a..shaft_l2b"); nullopt for a node off the drive line (lane != 0)
  /// or not found.
  std::optional<double> NodePosition(const Project& project, const std::string& node, int elements) const;

  std::vector<int> elements_of_shaft;  ///< unused
};

SpanLayout LayOutAlongSpan(const Project& project);

}  // namespace highlift::report
