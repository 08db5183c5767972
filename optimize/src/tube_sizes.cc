// The table constraint of `optimize --tube-sizes` (tube_sizes.h, docs/optimize.md).
#include "tube_sizes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "highlift/core/error.h"

namespace highlift::optimize::detail {

using icsp::Interval;

namespace {

/// v lies in x, with a relative slack of 1e-9 for the rounding of units (a domain given as
/// "45 mm" and a size given as 45 mm are the same number after the same conversion, but a
/// propagated bound may be rounded outwards or inwards by an ulp).
bool In(double v, const Interval& x) {
  const double slack = 1e-9 * std::fabs(v);
  return v >= x.lower() - slack && v <= x.upper() + slack;
}

/// log-distance of v from the interval x (0 inside).
double Away(double v, const Interval& x) {
  if (v < x.lower() && x.lower() > 0) return std::log(x.lower() / v);
  if (v > x.upper() && x.upper() > 0) return std::log(v / x.upper());
  return 0.0;
}

std::string Mm(double si) {
  std::ostringstream o;
  o << si * 1e3;
  return o.str();
}

std::string Range(const Interval& x) { return "[" + Mm(x.lower()) + ", " + Mm(x.upper()) + "] mm"; }

bool Same(double a, double b) { return std::fabs(a - b) <= 1e-12 * std::max(std::fabs(a), std::fabs(b)); }

}  // namespace

TubeConstraint::TubeConstraint(const componentdb::TubeSizeTable& table, const Project& project,
                               const std::vector<std::string>& design_names,
                               const std::vector<Interval>& design_domains,
                               const std::function<Interval(const std::string&)>& domain_of)
    : table_name_(table.name) {
  const std::string option = "--tube-sizes " + table.name;
  auto index = [&](const std::string& name) {
    const auto it = std::find(design_names.begin(), design_names.end(), name);
    return it == design_names.end() ? -1 : static_cast<int>(it - design_names.begin());
  };
  for (const Component& c : project.components) {
    if (c.type != "torque_shaft") continue;
    TubeShaft s;
    s.component = c.id;
    s.diameter = index(c.id + ".outer_diameter");
    s.wall = index(c.id + ".wall_thickness");
    if (s.diameter < 0 && s.wall < 0) continue;
    const Interval Dd = s.diameter >= 0 ? design_domains[s.diameter] : domain_of(c.id + ".outer_diameter");
    const Interval td = s.wall >= 0 ? design_domains[s.wall] : domain_of(c.id + ".wall_thickness");
    for (const componentdb::TubeSize& z : table.sizes) {
      if (!In(z.outer_diameter, Dd) || !In(z.wall_thickness, td)) continue;
      s.designations.push_back(z.designation);
      s.D.push_back(s.diameter >= 0 ? std::clamp(z.outer_diameter, Dd.lower(), Dd.upper()) : z.outer_diameter);
      s.t.push_back(s.wall >= 0 ? std::clamp(z.wall_thickness, td.lower(), td.upper()) : z.wall_thickness);
    }
    if (s.designations.empty()) {
      // The nearest sizes to the domains (by the larger log-distance of D and t).
      std::vector<std::pair<double, std::size_t>> near;
      for (std::size_t k = 0; k < table.sizes.size(); ++k)
        near.push_back({std::max(Away(table.sizes[k].outer_diameter, Dd), Away(table.sizes[k].wall_thickness, td)), k});
      std::stable_sort(near.begin(), near.end());
      // One per distinct value of what lies outside the domains (sizes that differ only inside them
      // are equally near).
      std::string list;
      std::vector<std::pair<double, double>> listed;
      for (std::size_t k = 0; k < near.size() && listed.size() < 3; ++k) {
        const componentdb::TubeSize& z = table.sizes[near[k].second];
        const std::pair<double, double> key{Away(z.outer_diameter, Dd) > 0 ? z.outer_diameter : -1.0,
                                            Away(z.wall_thickness, td) > 0 ? z.wall_thickness : -1.0};
        if (std::find(listed.begin(), listed.end(), key) != listed.end()) continue;
        listed.push_back(key);
        list += (list.empty() ? "" : ", ") + z.designation + " (D " + Mm(z.outer_diameter) + " mm, t " +
                Mm(z.wall_thickness) + " mm)";
      }
      throw InputError(option + ": no size of the table fits shaft '" + c.id + "': outer_diameter " + Range(Dd) +
                       (s.diameter >= 0 ? " (design variable)" : "") + ", wall_thickness " + Range(td) +
                       (s.wall >= 0 ? " (design variable)" : "") + "; the nearest of its " +
                       std::to_string(table.sizes.size()) + " sizes are " + list +
                       ". Widen the shaft's domains (\"min\", \"max\") to include a size, or give a table with "
                       "such sizes (--tube-sizes FILE)");
    }
    shafts_.push_back(std::move(s));
  }
  if (shafts_.empty())
    throw InputError(option + ": no torque shaft has its outer_diameter or wall_thickness as a design variable, so "
                     "the table restricts nothing; mark them \"design\": true in the project or name them with "
                     "--design (e.g. --design shaft_l1.outer_diameter,shaft_l1.wall_thickness), or leave out "
                     "--tube-sizes");
}

bool TubeConstraint::Contract(std::vector<Interval>& d, bool& changed) const {
  changed = false;
  const double inf = std::numeric_limits<double>::infinity();
  for (const TubeShaft& s : shafts_) {
    double dlo = inf, dhi = -inf, tlo = inf, thi = -inf;
    bool any = false;
    for (std::size_t k = 0; k < s.D.size(); ++k) {
      if ((s.diameter >= 0 && !In(s.D[k], d[s.diameter])) || (s.wall >= 0 && !In(s.t[k], d[s.wall]))) continue;
      any = true;
      dlo = std::min(dlo, s.D[k]), dhi = std::max(dhi, s.D[k]);
      tlo = std::min(tlo, s.t[k]), thi = std::max(thi, s.t[k]);
    }
    if (!any) return false;
    // x in {sizes} and x in box  =>  x in hull(sizes inside the box)
    auto narrow = [&](int i, double lo, double hi) {
      if (i < 0) return;
      if (d[i].lower() == lo && d[i].upper() == hi) return;
      d[i] = Interval(lo, hi);
      changed = true;
    };
    narrow(s.diameter, dlo, dhi);
    narrow(s.wall, tlo, thi);
  }
  return true;
}

TubeConstraint::Snapped TubeConstraint::Snap(const std::vector<double>& x, const std::vector<Interval>& d) const {
  // Per mode (nearest, up, down): x with each shaft at its size.
  std::vector<std::vector<double>> out(3, x);
  for (const TubeShaft& s : shafts_) {
    std::vector<std::size_t> inside;
    for (std::size_t k = 0; k < s.D.size(); ++k)
      if ((s.diameter < 0 || In(s.D[k], d[s.diameter])) && (s.wall < 0 || In(s.t[k], d[s.wall]))) inside.push_back(k);
    if (inside.empty())
      for (std::size_t k = 0; k < s.D.size(); ++k) inside.push_back(k);
    const double xD = s.diameter >= 0 ? x[s.diameter] : 0.0, xt = s.wall >= 0 ? x[s.wall] : 0.0;
    auto sq = [](double a) { return a * a; };
    auto distance = [&](std::size_t k) {
      return (s.diameter >= 0 ? sq(std::log(s.D[k] / xD)) : 0.0) + (s.wall >= 0 ? sq(std::log(s.t[k] / xt)) : 0.0);
    };
    auto at_least = [&](std::size_t k) {
      return (s.diameter < 0 || s.D[k] >= xD * (1 - 1e-12)) && (s.wall < 0 || s.t[k] >= xt * (1 - 1e-12));
    };
    auto at_most = [&](std::size_t k) {
      return (s.diameter < 0 || s.D[k] <= xD * (1 + 1e-12)) && (s.wall < 0 || s.t[k] <= xt * (1 + 1e-12));
    };
    std::size_t nearest = inside.front(), up = nearest, down = nearest;
    double dn = distance(nearest), du = std::numeric_limits<double>::infinity(), dd = du;
    for (std::size_t k : inside) {
      const double e = distance(k);
      if (e < dn) dn = e, nearest = k;
      if (at_least(k) && e < du) du = e, up = k;
      if (at_most(k) && e < dd) dd = e, down = k;
    }
    if (!std::isfinite(du)) up = nearest;
    if (!std::isfinite(dd)) down = nearest;
    const std::size_t chosen[3] = {nearest, up, down};
    for (int m = 0; m < 3; ++m) {
      if (s.diameter >= 0) out[m][s.diameter] = s.D[chosen[m]];
      if (s.wall >= 0) out[m][s.wall] = s.t[chosen[m]];
    }
  }
  return {std::move(out[0]), std::move(out[1]), std::move(out[2])};
}

std::vector<std::pair<std::string, std::string>> TubeConstraint::Sizes(const std::vector<double>& x) const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const TubeShaft& s : shafts_) {
    std::string names;
    for (std::size_t k = 0; k < s.D.size(); ++k)
      if ((s.diameter < 0 || Same(s.D[k], x[s.diameter])) && (s.wall < 0 || Same(s.t[k], x[s.wall])))
        names += (names.empty() ? "" : " or ") + s.designations[k];
    out.push_back({s.component, names});
  }
  return out;
}

}  // namespace highlift::optimize::detail
