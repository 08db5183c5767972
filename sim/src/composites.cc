// Flattening of composite element types into their parts.
#include "composites.h"

#include "highlift/core/error.h"

namespace highlift::sim::detail {
namespace {

constexpr int kMaxDepth = 8;

std::optional<Composite> Expand(const NetworkElement& e) {
  if (auto c = ExpandBrakeComposite(e)) return c;
  if (auto c = ExpandGearComposite(e)) return c;
  if (auto c = ExpandDriveComposite(e)) return c;
  if (auto c = ExpandHydraulicComposite(e)) return c;
  if (auto c = ExpandMslComposite(e)) return c;
  return std::nullopt;
}

// One level of expansion: nullopt when no element of the network is a composite (nothing is
// copied then).
std::optional<Network> FlattenOnce(const Network& network,
                                   std::map<std::string, std::vector<std::string>>& alias) {  // "composite.port" -> inner ports
  std::vector<std::optional<Composite>> composites;
  composites.reserve(network.elements().size());
  bool expanded = false;
  for (const NetworkElement& e : network.elements()) {
    composites.push_back(Expand(e));
    expanded = expanded || composites.back().has_value();
  }
  if (!expanded) return std::nullopt;
  Network out;
  for (std::size_t i = 0; i < composites.size(); ++i) {
    const NetworkElement& e = network.elements()[i];
    const std::optional<Composite>& c = composites[i];
    if (!c) {
      out.Adopt(e);
      continue;
    }
    for (const NetworkElement& part : c->inner.elements()) {
      if (part.id != e.id && part.id.rfind(e.id + ".", 0) != 0)
        throw InputError("element '" + e.id + "' (" + e.type + "): part '" + part.id +
                         "' must be named '" + e.id + "' or '" + e.id + ".<part>'");
      out.Adopt(part);
    }
    for (const NetworkConnection& k : c->inner.connections()) out.Adopt(k);
    for (const auto& [port, inner] : c->ports) alias[e.id + "." + port] = inner;
  }
  auto resolve = [&](const PortRef& p) -> std::vector<std::string> {
    const std::string name = p.ToString();
    const NetworkElement* owner = network.Find(p.component);
    auto it = alias.find(name);
    if (it != alias.end()) return it->second;
    if (out.Find(p.component) == nullptr)
      throw InputError("element '" + p.component + "' (" + (owner ? owner->type : "?") +
                       "): port '" + p.port + "' is connected but the composite has no part for it");
    return {name};
  };
  for (const NetworkConnection& k : network.connections()) {
    const auto a = resolve(k.a), b = resolve(k.b);
    // A signal input of a composite may feed several parts: connect each to the one source.
    for (const auto& x : a)
      for (const auto& y : b) out.Connect(x, y);
  }
  return out;
}

}  // namespace

Network FlattenComposites(const Network& network, std::map<std::string, std::vector<std::string>>* ports) {
  std::optional<Network> current;  // the last level; none: the network given
  for (int depth = 0; depth < kMaxDepth; ++depth) {
    std::map<std::string, std::vector<std::string>> alias;
    std::optional<Network> next = FlattenOnce(current ? *current : network, alias);
    if (!next) return current ? std::move(*current) : network;
    if (ports != nullptr) {
      // The ports of earlier levels that led to a composite of this level go on to its parts.
      for (auto& [outer, inner] : *ports) {
        std::vector<std::string> resolved;
        for (const auto& p : inner) {
          auto it = alias.find(p);
          if (it == alias.end()) resolved.push_back(p);
          else resolved.insert(resolved.end(), it->second.begin(), it->second.end());
        }
        inner = std::move(resolved);
      }
      for (auto& [outer, inner] : alias) ports->emplace(outer, inner);
    }
    current = std::move(next);
  }
  throw InputError("composite elements nest deeper than " + std::to_string(kMaxDepth) +
                   " levels; a composite type probably contains itself");
}

}  // namespace highlift::sim::detail
