// The component graph of a project: which port is connected to which, and how each component is
// reached from the PDU (the power path). Other modules use it to walk the transmission: the
// reduced models lump inertias and stiffnesses along the path, the estimator and the `info`
// command reflect inertias to the PDU with the speed ratios, the simulator builds its network.
//
//   ComponentGraph graph(project);                  // drive-system components and connections
//   for (const auto& id : graph.ReachOrder()) {     // breadth-first from the PDU
//     const PowerPath& path = *graph.PathTo(id);
//     double J_at_pdu = J * path.speed_ratio * path.speed_ratio;   // inertia reflected to the PDU
//   }
//
// Speed ratios follow the gear-ratio convention of docs/project-format.md: `ratio` = input speed
// / output speed (branch gearbox: input speed / branch speed; input to through is 1:1), so the
// speed at a component's entry flange is the PDU output speed times the product of 1/ratio over
// the gearboxes passed on the way. Missing or unknown ratios count as 1 and are flagged.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "highlift/core/project.h"

namespace highlift {

/// One connection seen from a component: its own port and the port at the other end.
struct GraphEdge {
  std::string port;      ///< port of this component
  PortRef neighbour;     ///< the other end of the connection
  std::size_t connection = 0;  ///< index into Project::connections (or element_connections)
};

/// How a component is reached from the PDU. Constant size (the whole route is
/// ComponentGraph::Route), so a graph of n components takes memory linear in n.
struct PowerPath {
  std::string previous;                 ///< the component before this one on the route ("" for the PDU)
  std::size_t depth = 0;                ///< components between the PDU and this one, plus one (0 for the PDU)
  std::string entry_port;               ///< port by which this component is entered ("" for the PDU)
  std::string pdu_port;                 ///< PDU output the path leaves by ("left", "right"; "" for the PDU)
  /// Speed of this component's entry flange / PDU output speed (product of 1/ratio along the path).
  double speed_ratio = 1.0;
  /// True when a gear ratio on the path (not of this component itself) had no nominal value.
  bool ratio_unknown = false;
  /// True when this component is a gearbox entered by another port than "input".
  bool reversed = false;
};

/// Refers to the project it was built from: keep the project alive (and unchanged) while using it.
class ComponentGraph {
 public:
  /// The graph of the drive-system components (`project.components`, `project.connections`).
  explicit ComponentGraph(const Project& project);
  /// The graph of the element network (`project.elements`, `project.element_connections`); no
  /// PDU, so PathTo() is empty.
  static ComponentGraph Elements(const Project& project);

  /// Connections of component `id` (empty for an unknown id). Connections naming unknown
  /// components are kept (validation reports them).
  const std::vector<GraphEdge>& Neighbours(std::string_view id) const;
  /// The port at the other end of `port`, if it is connected (the first, if connected twice).
  std::optional<PortRef> ConnectedTo(const PortRef& port) const;
  /// Id of the PDU (the first component whose type is the drive unit), or "" if there is none.
  const std::string& pdu() const { return pdu_; }
  /// Components reachable from the PDU, breadth-first, the PDU first.
  const std::vector<std::string>& ReachOrder() const { return order_; }
  /// The path from the PDU to `id`, or nullopt if `id` is not reachable.
  const PowerPath* PathTo(std::string_view id) const;
  /// Speed ratio of component `id`'s entry flange relative to the PDU output (see PowerPath).
  std::optional<double> SpeedRatio(std::string_view id) const;
  /// Speed of the flange `port` of a reachable component / PDU output speed: applies the
  /// component's own ratio (e.g. a GRA "input" -> its output speed is SpeedRatioAtPort(id,"input")/ratio).
  std::optional<double> SpeedRatioAtPort(std::string_view id, std::string_view port) const;
  /// Ids from the PDU (first) to `id` (last); empty when `id` is not reachable.
  std::vector<std::string> Route(std::string_view id) const;
  /// Connected groups of components (each sorted by order in the project), the PDU's first.
  std::vector<std::vector<std::string>> Islands() const;
  /// Connections that close a loop in the drive-system graph (indices into Project::connections,
  /// in project order): the walk from the PDU met a component it had already reached. A drive
  /// transmission is a tree; validation reports each as an error. Connections on a flange that
  /// is connected twice are left out (validation reports the double connection).
  const std::vector<std::size_t>& LoopConnections() const { return loop_connections_; }

 private:
  ComponentGraph() = default;
  void Build(const std::vector<Component>& components, const std::vector<Connection>& connections);
  void Walk();

  const std::vector<Component>* components_ = nullptr;
  std::map<std::string, std::vector<GraphEdge>, std::less<>> edges_;
  std::map<std::string, const Component*, std::less<>> by_id_;
  std::string pdu_;
  std::vector<std::string> order_;
  std::map<std::string, PowerPath, std::less<>> paths_;
  std::vector<std::size_t> loop_connections_;
  std::map<PortRef, int> port_uses_;  ///< connections per flange
};

/// "connection a.x - b.y closes a loop in the transmission ('pdu' -> ... -> 'pdu'); ..." for
/// one of graph.LoopConnections().
std::string DescribeLoop(const ComponentGraph& graph, const Project& project, std::size_t connection);

/// Speed factor from entering `component` by `from_port` to leaving by `to_port`: 1 for rigid
/// components, 1/ratio from "input" to "output"/"branch", ratio the other way. `known` is set to
/// false when the ratio has no nominal value (the factor then assumes 1).
double PortSpeedFactor(const Component& component, std::string_view from_port, std::string_view to_port,
                       bool* known = nullptr);

}  // namespace highlift
