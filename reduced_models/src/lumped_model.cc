#include "highlift/reduced_models/lumped_model.h"

#include <numeric>
#include <utility>

#include "highlift/core/error.h"
#include "highlift/core/message_number.h"

namespace highlift::reduced_models {
namespace {

/// Union-find over point indices, to reject cycles (the modal solver assumes a forest).
struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int Find(int i) { return parent[i] == i ? i : parent[i] = Find(parent[i]); }
  bool Unite(int a, int b) {
    a = Find(a);
    b = Find(b);
    if (a == b) return false;
    parent[a] = b;
    return true;
  }
};

void CheckTransmission(const Transmission& t) {
  DisjointSets sets(t.points.size());
  for (const auto& link : t.links) {
    const int n = static_cast<int>(t.points.size());
    HIGHLIFT_CHECK(link.a >= 0 && link.a < n && link.b >= 0 && link.b < n,
                   "transmission link '" + link.name + "' refers to a point that does not exist");
    if (!(link.c > 0.0))
      throw InputError("link '" + link.name + "': stiffness c = " + FormatMessageNumber(link.c) +
                       " N*m/rad must be > 0; give the component a positive stiffness or its "
                       "geometry and material");
    if (link.J < 0.0)
      throw InputError("link '" + link.name + "': inertia J must be >= 0");
    if (!sets.Unite(link.a, link.b))
      throw InputError("link '" + link.name + "' closes a loop in the transmission; the reduced "
                       "models need a tree (a shaft line may branch only at gearboxes)");
  }
  for (const auto& p : t.points)
    if (p.J < 0.0) throw InputError("point '" + p.name + "': inertia J must be >= 0");
}

/// A section: the chain of links between two kept points through points that are merged away.
struct Section {
  int from = 0, to = 0;                 // kept points
  std::vector<int> links;               // in order from `from`
  std::vector<int> inner_points;        // in order
};

std::vector<Section> FindSections(const Transmission& t, std::vector<bool>* kept) {
  const std::size_t n = t.points.size();
  std::vector<std::vector<int>> incident(n);
  for (std::size_t i = 0; i < t.links.size(); ++i) {
    incident[t.links[i].a].push_back(static_cast<int>(i));
    incident[t.links[i].b].push_back(static_cast<int>(i));
  }
  kept->assign(n, false);
  for (std::size_t p = 0; p < n; ++p) (*kept)[p] = t.points[p].accumulate || incident[p].size() != 2;
  std::vector<bool> used(t.links.size(), false);
  std::vector<Section> sections;
  for (std::size_t p = 0; p < n; ++p) {
    if (!(*kept)[p]) continue;
    for (int start : incident[p]) {
      if (used[start]) continue;
      Section s;
      s.from = static_cast<int>(p);
      int at = static_cast<int>(p);
      int link = start;
      while (true) {
        used[link] = true;
        s.links.push_back(link);
        const int next = t.links[link].a == at ? t.links[link].b : t.links[link].a;
        if ((*kept)[next]) {
          s.to = next;
          break;
        }
        s.inner_points.push_back(next);
        link = incident[next][0] == link ? incident[next][1] : incident[next][0];
        at = next;
      }
      sections.push_back(std::move(s));
    }
  }
  return sections;
}

LumpedModel BuildFull(const Transmission& t, int n) {
  LumpedModel m;
  for (std::size_t p = 0; p < t.points.size(); ++p)
    m.AddNode(t.points[p].name, t.points[p].J, static_cast<int>(p));
  for (std::size_t i = 0; i < t.links.size(); ++i) {
    const auto& link = t.links[i];
    const int li = static_cast<int>(i);
    if (link.J == 0.0 || n == 1) {
      m.nodes[link.a].J += 0.5 * link.J;
      m.nodes[link.b].J += 0.5 * link.J;
      m.AddSpring(link.a, link.b, link.c, link.name, li);
      continue;
    }
    const double j_element = link.J / n;
    m.nodes[link.a].J += 0.5 * j_element;
    m.nodes[link.b].J += 0.5 * j_element;
    int previous = link.a;
    for (int k = 1; k < n; ++k) {
      const int node = m.AddNode(link.name + "#" + std::to_string(k), j_element);
      m.AddSpring(previous, node, n * link.c, link.name + "#" + std::to_string(k), li);
      previous = node;
    }
    m.AddSpring(previous, link.b, n * link.c, link.name + "#" + std::to_string(n), li);
  }
  return m;
}

LumpedModel BuildReduced(const Transmission& t, bool two_masses) {
  std::vector<bool> kept;
  const std::vector<Section> sections = FindSections(t, &kept);
  LumpedModel m;
  std::vector<int> node_of(t.points.size(), -1);
  for (std::size_t p = 0; p < t.points.size(); ++p)
    if (kept[p]) node_of[p] = m.AddNode(t.points[p].name, t.points[p].J, static_cast<int>(p));
  for (const Section& s : sections) {
    // Compliance coordinate along the section: 0 at `from`, F at `to`.
    double F = 0.0;
    for (int l : s.links) F += 1.0 / t.links[l].c;
    const int a = node_of[s.from], b = node_of[s.to];
    std::string name = t.links[s.links.front()].name;
    if (s.links.size() > 1) name += ".." + t.links[s.links.back()].name;
    const int link_id = s.links.size() == 1 ? s.links.front() : -1;
    double own_J = 0.0;
    for (int l : s.links) own_J += t.links[l].J;
    for (int p : s.inner_points) own_J += t.points[p].J;
    if (!two_masses || own_J == 0.0) {
      // Lever rule: an inertia at compliance position s goes (1 - s/F) to `from`, s/F to `to`.
      double position = 0.0;
      for (std::size_t k = 0; k < s.links.size(); ++k) {
        const auto& link = t.links[s.links[k]];
        const double centre = (position + 0.5 / link.c) / F;
        m.nodes[a].J += (1.0 - centre) * link.J;
        m.nodes[b].J += centre * link.J;
        position += 1.0 / link.c;
        if (k < s.inner_points.size()) {
          const double at = position / F;
          const double J = t.points[s.inner_points[k]].J;
          m.nodes[a].J += (1.0 - at) * J;
          m.nodes[b].J += at * J;
        }
      }
      m.AddSpring(a, b, 1.0 / F, name, link_id);
    } else {
      // Neumann: two masses of own_J/2 at 1/4 and 3/4 of the section's compliance.
      const int m1 = m.AddNode(name + "#1", 0.5 * own_J);
      const int m2 = m.AddNode(name + "#2", 0.5 * own_J);
      m.AddSpring(a, m1, 4.0 / F, name + "#1", link_id);
      m.AddSpring(m1, m2, 2.0 / F, name + "#2", link_id);
      m.AddSpring(m2, b, 4.0 / F, name + "#3", link_id);
    }
  }
  return m;
}

}  // namespace

int Transmission::AddPoint(std::string name, double J, bool accumulate, std::string component) {
  points.push_back({std::move(name), J, accumulate, std::move(component)});
  return static_cast<int>(points.size()) - 1;
}

int Transmission::AddLink(int a, int b, double c, double J, std::string name, std::string component) {
  links.push_back({a, b, c, J, std::move(name), std::move(component)});
  return static_cast<int>(links.size()) - 1;
}

int Transmission::FindPoint(std::string_view name) const {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].name == name) return static_cast<int>(i);
  return -1;
}

double Transmission::TotalInertia() const {
  double sum = 0.0;
  for (const auto& p : points) sum += p.J;
  for (const auto& l : links) sum += l.J;
  return sum;
}

int LumpedModel::AddNode(std::string name, double J, int point) {
  nodes.push_back({std::move(name), J, point});
  return static_cast<int>(nodes.size()) - 1;
}

int LumpedModel::AddSpring(int a, int b, double c, std::string name, int link) {
  springs.push_back({a, b, c, link, std::move(name)});
  return static_cast<int>(springs.size()) - 1;
}

double LumpedModel::TotalInertia() const {
  double sum = 0.0;
  for (const auto& n : nodes) sum += n.J;
  return sum;
}

int LumpedModel::NodeOfPoint(int point) const {
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].point == point) return static_cast<int>(i);
  return -1;
}

std::string ToString(Reduction r) {
  switch (r) {
    case Reduction::kFullResolution: return "full";
    case Reduction::kAccumulated: return "accumulated";
    case Reduction::kTwoMassesPerSection: return "two_masses";
  }
  return "?";
}

bool ReductionFromString(std::string_view s, Reduction* r) {
  for (Reduction candidate : {Reduction::kFullResolution, Reduction::kAccumulated,
                              Reduction::kTwoMassesPerSection})
    if (ToString(candidate) == s) {
      *r = candidate;
      return true;
    }
  return false;
}

LumpedModel BuildLumpedModel(const Transmission& transmission, Reduction reduction,
                             int elements_per_link) {
  if (elements_per_link < 1)
    throw InputError("shaft_elements = " + std::to_string(elements_per_link) +
                     " must be >= 1 (sub-elements per shaft segment in full-resolution models)");
  CheckTransmission(transmission);
  switch (reduction) {
    case Reduction::kFullResolution: return BuildFull(transmission, elements_per_link);
    case Reduction::kAccumulated: return BuildReduced(transmission, false);
    case Reduction::kTwoMassesPerSection: return BuildReduced(transmission, true);
  }
  HIGHLIFT_CHECK(false, "unknown reduction rule");
  return {};
}

}  // namespace highlift::reduced_models
