#include "highlift/core/graph.h"

#include <algorithm>
#include <deque>
#include <set>

#include "highlift/core/catalogue.h"

namespace highlift {

namespace {
const std::vector<GraphEdge> kNoEdges;

// Speed of `port` relative to the speed of the flange "input", by the type's declaration: a
// geared flange (PortSpec::speed_ratio) turns 1/ratio as fast.
double RelativeToInput(const Component& c, std::string_view port, bool* known) {
  const ComponentTypeSpec* type = FindComponentType(c.type);
  const PortSpec* spec = type ? type->FindPort(port) : nullptr;
  if (!spec || spec->speed_ratio.empty()) return 1.0;
  auto it = c.parameters.find(spec->speed_ratio);
  if (it == c.parameters.end() || !it->second.nominal || *it->second.nominal == 0.0) {
    if (known) *known = false;
    return 1.0;
  }
  return 1.0 / *it->second.nominal;
}

bool Geared(const Component& c) {
  const ComponentTypeSpec* type = FindComponentType(c.type);
  return type && type->GearedPort() != nullptr;
}

bool DriveUnit(const Component& c) {
  const ComponentTypeSpec* type = FindComponentType(c.type);
  return type && type->roles.drive_unit;
}
}  // namespace

double PortSpeedFactor(const Component& component, std::string_view from_port, std::string_view to_port, bool* known) {
  if (known) *known = true;
  return RelativeToInput(component, to_port, known) / RelativeToInput(component, from_port, known);
}

ComponentGraph::ComponentGraph(const Project& project) {
  Build(project.components, project.connections);
  for (const auto& c : project.components) {
    if (DriveUnit(c)) {
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
    ++port_uses_[k.a];
    ++port_uses_[k.b];
  }
}

void ComponentGraph::Walk() {
  if (pdu_.empty()) return;
  paths_[pdu_] = PowerPath{};
  order_.push_back(pdu_);
  // The connection by which each reached component was entered (none for the PDU).
  std::map<std::string, std::size_t, std::less<>> entered_by;
  std::set<std::size_t> loops;
  std::deque<std::string> queue = {pdu_};
  while (!queue.empty()) {
    const std::string id = queue.front();
    queue.pop_front();
    const PowerPath& here = paths_.at(id);
    const Component* component = by_id_.at(id);
    const auto entry = entered_by.find(id);
    for (const GraphEdge& e : Neighbours(id)) {
      const std::string& next = e.neighbour.component;
      if (!by_id_.count(next)) continue;
      if (paths_.count(next)) {
        // reached before by another connection: this one closes a loop (unless a flange on it
        // is connected twice, which validation reports as such)
        const bool doubled = port_uses_.at(PortRef{id, e.port}) > 1 || port_uses_.at(e.neighbour) > 1;
        if (!doubled && (entry == entered_by.end() || entry->second != e.connection)) {
          const auto next_entry = entered_by.find(next);
          if (next_entry == entered_by.end() || next_entry->second != e.connection) loops.insert(e.connection);
        }
        continue;
      }
      PowerPath path;
      bool known = true;
      path.speed_ratio = here.speed_ratio;
      path.ratio_unknown = here.ratio_unknown;
      path.pdu_port = here.pdu_port;
      // leaving `id` by e.port
      if (id != pdu_) path.speed_ratio *= PortSpeedFactor(*component, here.entry_port, e.port, &known);
      if (!known) path.ratio_unknown = true;
      path.previous = id;
      path.depth = here.depth + 1;
      path.entry_port = e.neighbour.port;
      if (id == pdu_) path.pdu_port = e.port;
      const Component* n = by_id_.at(next);
      path.reversed = Geared(*n) && e.neighbour.port != "input";
      paths_[next] = std::move(path);
      entered_by[next] = e.connection;
      order_.push_back(next);
      queue.push_back(next);
    }
  }
  loop_connections_.assign(loops.begin(), loops.end());
}

std::vector<std::string> ComponentGraph::Route(std::string_view id) const {
  std::vector<std::string> route;
  const PowerPath* p = PathTo(id);
  if (p == nullptr) return route;
  route.emplace_back(id);
  while (!p->previous.empty()) {
    route.push_back(p->previous);
    p = PathTo(p->previous);
  }
  std::reverse(route.begin(), route.end());
  return route;
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

std::string DescribeLoop(const ComponentGraph& graph, const Project& project, std::size_t connection) {
  const Connection& k = project.connections.at(connection);
  const std::vector<std::string> a = graph.Route(k.a.component), b = graph.Route(k.b.component);
  std::size_t common = 0;  // shared start of both routes from the PDU
  while (common < a.size() && common < b.size() && a[common] == b[common]) ++common;
  std::vector<std::string> loop;
  if (common > 0) loop.push_back(a[common - 1]);
  for (std::size_t i = common; i < a.size(); ++i) loop.push_back(a[i]);
  for (std::size_t i = b.size(); i-- > common;) loop.push_back(b[i]);
  if (common > 0) loop.push_back(a[common - 1]);
  std::string route;
  for (std::size_t i = 0; i < loop.size() && i < 16; ++i) route += (i ? " -> '" : "'") + loop[i] + "'";
  if (loop.size() > 16) route += " -> ... (" + std::to_string(loop.size()) + " in all)";
  return "connection " + k.a.ToString() + " - " + k.b.ToString() + " closes a loop in the transmission (" + route +
         "); a drive system is a tree from the PDU (it branches at gearboxes and never joins again): remove one "
         "connection of the loop";
}

std::vector<std::vector<std::string>> ComponentGraph::Islands() const {
  // Flood fill from the PDU, then from each component not yet reached; every island is listed in
  // project order. O(n log n): one pass to number the islands, one to list them.
  std::map<std::string, std::size_t, std::less<>> island_of;
  std::size_t count = 0;
  auto flood = [&](const std::string& start) {
    std::deque<std::string> queue = {start};
    island_of.emplace(start, count);
    while (!queue.empty()) {
      const std::string id = queue.front();
      queue.pop_front();
      for (const GraphEdge& e : Neighbours(id)) {
        const std::string& next = e.neighbour.component;
        if (!by_id_.count(next) || island_of.count(next)) continue;
        island_of.emplace(next, count);
        queue.push_back(next);
      }
    }
    ++count;
  };
  if (!pdu_.empty()) flood(pdu_);
  for (const auto& c : *components_)
    if (!island_of.count(c.id)) flood(c.id);
  std::vector<std::vector<std::string>> islands(count);
  for (const auto& c : *components_) islands[island_of.at(c.id)].push_back(c.id);
  return islands;
}

}  // namespace highlift
