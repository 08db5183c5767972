#include "highlift/core/graph.h"

#include <algorithm>
#include <deque>
#include <set>

namespace highlift {

namespace {
const std::vector<GraphEdge> kNoEdges;

bool IsGearbox(const std::string& type) { return type == "angle_gearbox" || type == "branch_gearbox"; }

// Speed of `port` relative to the speed of the "input" port of a gearbox.
double RelativeToInput(const Component& c, std::string_view port, bool* known) {
  if (!IsGearbox(c.type)) return 1.0;
  const bool geared = (c.type == "angle_gearbox" && port == "output") || (c.type == "branch_gearbox" && port == "branch");
  if (!geared) return 1.0;
  auto it = c.parameters.find("ratio");
  if (it == c.parameters.end() || !it->second.nominal || *it->second.nominal == 0.0) {
    if (known) *known = false;
    return 1.0;
  }
  return 1.0 / *it->second.nominal;
}
}  // namespace

double PortSpeedFactor(const Component& component, std::string_view from_port, std::string_view to_port, bool* known) {
  if (known) *known = true;
  return RelativeToInput(component, to_port, known) / RelativeToInput(component, from_port, known);
}

ComponentGraph::ComponentGraph(const Project& project) {
  Build(project.components, project.connections);
  for (const auto& c : project.components) {
    if (c.type == "pdu") {
      pdu_ = c.id;
      break;
    }
  }
  Walk();
}

ComponentGraph ComponentGraph::Elements(const Project& project) {
  ComponentGraph g;
  g.Build(project.elements, project.element_connections);
  return g;
}

void ComponentGraph::Build(const std::vector<Component>& components, const std::vector<Connection>& connections) {
  components_ = &components;
  for (const auto& c : components) {
    by_id_.emplace(c.id, &c);
    edges_[c.id];
  }
  for (std::size_t i = 0; i < connections.size(); ++i) {
    const Connection& k = connections[i];
    edges_[k.a.component].push_back({k.a.port, k.b, i});
    edges_[k.b.component].push_back({k.b.port, k.a, i});
  }
}

void ComponentGraph::Walk() {
  if (pdu_.empty()) return;
  PowerPath root;
  root.components = {pdu_};
  root.entry_ports = {""};
  paths_[pdu_] = root;
  order_.push_back(pdu_);
  std::deque<std::string> queue = {pdu_};
  while (!queue.empty()) {
    const std::string id = queue.front();
    queue.pop_front();
    const PowerPath& here = paths_.at(id);
    const Component* component = by_id_.at(id);
    for (const GraphEdge& e : Neighbours(id)) {
      const std::string& next = e.neighbour.component;
      if (paths_.count(next) || !by_id_.count(next)) continue;
      PowerPath path = here;
      bool known = true;
      // leaving `id` by e.port
      if (id != pdu_) path.speed_ratio *= PortSpeedFactor(*component, here.entry_port, e.port, &known);
      if (!known) path.ratio_unknown = true;
      path.components.push_back(next);
      path.entry_ports.push_back(e.neighbour.port);
      path.entry_port = e.neighbour.port;
      if (id == pdu_) path.pdu_port = e.port;
      const Component* n = by_id_.at(next);
      path.reversed = IsGearbox(n->type) && e.neighbour.port != "input";
      paths_[next] = std::move(path);
      order_.push_back(next);
      queue.push_back(next);
    }
  }
}

const std::vector<GraphEdge>& ComponentGraph::Neighbours(std::string_view id) const {
  auto it = edges_.find(id);
  return it == edges_.end() ? kNoEdges : it->second;
}

std::optional<PortRef> ComponentGraph::ConnectedTo(const PortRef& port) const {
  for (const GraphEdge& e : Neighbours(port.component))
    if (e.port == port.port) return e.neighbour;
  return std::nullopt;
}

const PowerPath* ComponentGraph::PathTo(std::string_view id) const {
  auto it = paths_.find(id);
  return it == paths_.end() ? nullptr : &it->second;
}

std::optional<double> ComponentGraph::SpeedRatio(std::string_view id) const {
  const PowerPath* p = PathTo(id);
  if (!p) return std::nullopt;
  return p->speed_ratio;
}

std::optional<double> ComponentGraph::SpeedRatioAtPort(std::string_view id, std::string_view port) const {
  const PowerPath* p = PathTo(id);
  if (!p) return std::nullopt;
  if (id == pdu_) return 1.0;
  return p->speed_ratio * PortSpeedFactor(*by_id_.at(std::string(id)), p->entry_port, port);
}

std::vector<std::vector<std::string>> ComponentGraph::Islands() const {
  std::vector<std::vector<std::string>> islands;
  std::set<std::string> seen;
  auto flood = [&](const std::string& start) {
    std::vector<std::string> island;
    std::deque<std::string> queue = {start};
    seen.insert(start);
    while (!queue.empty()) {
      const std::string id = queue.front();
      queue.pop_front();
      island.push_back(id);
      for (const GraphEdge& e : Neighbours(id)) {
        const std::string& next = e.neighbour.component;
        if (!by_id_.count(next) || seen.count(next)) continue;
        seen.insert(next);
        queue.push_back(next);
      }
    }
    // project order
    std::vector<std::string> ordered;
    for (const auto& c : *components_)
      if (std::find(island.begin(), island.end(), c.id) != island.end()) ordered.push_back(c.id);
    islands.push_back(std::move(ordered));
  };
  if (!pdu_.empty()) flood(pdu_);
  for (const auto& c : *components_)
    if (!seen.count(c.id)) flood(c.id);
  return islands;
}

}  // namespace highlift
