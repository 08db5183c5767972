#include "span_layout.h"

#include <cmath>
#include <deque>
#include <map>

#include "highlift/core/catalogue.h"

namespace highlift::report {
namespace {

std::optional<double> Nominal(const Component& c, const std::string& name) {
  auto it = c.parameters.find(name);
  if (it == c.parameters.end()) return std::nullopt;
  return it->second.nominal;
}

/// A segment's length along the drive line (torque shafts); 0 for the others.
double Length(const Component& c) { return RolesOf(c.type).segment ? Nominal(c, "length").value_or(0.0) : 0.0; }

/// True when the flange `port` of `c` branches off the drive line to a station: a geared flange
/// of a type whose drive line passes through it (a branch gearbox's branch).
bool StationBranch(const Component& c, const std::string& port) {
  const ComponentTypeSpec* type = FindComponentType(c.type);
  const PortSpec* spec = type ? type->FindPort(port) : nullptr;
  return spec && !spec->speed_ratio.empty() && type->FindPort("through") != nullptr;
}

/// Outboard direction: -1 on the left wing.
double Outboard(const Component& c, double x) {
  auto side = c.labels.find("side");
  if (side != c.labels.end()) return side->second == "left" ? -1.0 : 1.0;
  return x < 0 ? -1.0 : 1.0;
}

}  // namespace

SpanLayout LayOutAlongSpan(const Project& project) {
  const std::size_t n = project.components.size();
  SpanLayout out;
  out.x.assign(n, NAN);
  out.lane.assign(n, 0);
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < n; ++i) index[project.components[i].id] = static_cast<int>(i);
  // Flange neighbours, with the port of the component each connection leaves from.
  std::vector<std::vector<std::pair<int, std::string>>> next(n);
  for (const Connection& c : project.connections) {
    auto a = index.find(c.a.component), b = index.find(c.b.component);
    if (a == index.end() || b == index.end()) continue;
    next[a->second].push_back({b->second, c.a.port});
    next[b->second].push_back({a->second, c.b.port});
    out.edges.push_back({a->second, b->second});
  }
  // Walk from the PDU: the distance along the drive line (to shaft midpoints) and the lane.
  std::vector<double> distance(n, NAN);
  std::deque<int> queue;
  for (std::size_t i = 0; i < n; ++i)
    if (RolesOf(project.components[i].type).drive_unit) {
      distance[i] = 0;
      queue.push_back(static_cast<int>(i));
    }
  while (!queue.empty()) {
    const int from = queue.front();
    queue.pop_front();
    const Component& parent = project.components[from];
    for (const auto& [to, port] : next[from]) {
      if (!std::isnan(distance[to])) continue;
      const Component& child = project.components[to];
      int lane = out.lane[from];
      if (lane > 0) ++lane;
      else if (StationBranch(parent, port)) lane = 1;
      out.lane[to] = lane;
      distance[to] = distance[from] + (lane > 0 ? 0.0 : (Length(parent) + Length(child)) / 2);
      queue.push_back(to);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Component& c = project.components[i];
    if (RolesOf(c.type).tip_sensor) out.lane[i] = -1;
    if (auto given = Nominal(c, "span_position")) {
      out.x[i] = *given;
    } else if (!std::isnan(distance[i])) {
      out.x[i] = Outboard(c, 0.0) * distance[i];
      out.from_lengths = true;
    }
  }
  return out;
}

std::optional<double> SpanLayout::NodePosition(const Project& project, const std::string& node, int elements) const {
  auto at = [&](const std::string& id) -> const Component* {
    for (std::size_t i = 0; i < project.components.size(); ++i)
      if (project.components[i].id == id && lane[i] == 0 && !std::isnan(x[i])) return &project.components[i];
    return nullptr;
  };
  auto position = [&](const Component* c) { return x[c - project.components.data()]; };
  // A shaft's end: its midpoint -/+ half its length, outboard.
  auto end = [&](const Component* c, double fraction) {
    const double mid = position(c);
    return mid + Outboard(*c, mid) * Length(*c) * (fraction - 0.5);
  };
  if (const std::size_t dots = node.find(".."); dots != std::string::npos) {
    const Component* a = at(node.substr(0, dots));
    const Component* b = at(node.substr(dots + 2));
    if (!a || !b) return std::nullopt;
    return (position(a) + position(b)) / 2;
  }
  if (const std::size_t hash = node.find('#'); hash != std::string::npos) {
    const Component* c = at(node.substr(0, hash));
    const std::string k = node.substr(hash + 1);
    if (!c || elements <= 0 || k.empty() || k.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    return end(c, std::stod(k) / elements);
  }
  if (const std::size_t slash = node.find('/'); slash != std::string::npos) {
    const Component* c = at(node.substr(0, slash));
    if (!c) return std::nullopt;
    return end(c, node.substr(slash + 1) == "a" ? 0.0 : 1.0);
  }
  const Component* c = at(node);
  if (!c) return std::nullopt;
  return position(c);
}

}  // namespace highlift::report
