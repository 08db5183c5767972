// Lumped torsional models of a transmission and the rules that build them.
//
// A Transmission is the physical description: concentrated inertias (PDU, gearboxes, stations,
// brakes) joined by links (shaft segments with distributed stiffness and inertia, or massless
// springs). A LumpedModel is what the modal analysis solves: rigid inertias joined by massless
// springs. Everything is reflected to one reference speed (the PDU output shaft): a value at a
// place turning at w_local = n * w_ref enters as J n^2, c n^2 (kinetic and strain energy are
// preserved). Reduction rules (see docs/reduced_models.md for their first-mode errors):
//   kFullResolution       every distributed link split into n sub-elements (n springs of n c,
//                         inertia J/n per interior node, J/(2n) to each end point);
//   kAccumulated          inertias accumulated at the accumulation points (PDU, gearboxes,
//                         stations, brakes, branch points) with one series spring per section;
//   kTwoMassesPerSection  Neumann's rule: each section between accumulation points carries its
//                         own inertia on two masses at 1/4 and 3/4 of its compliance.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace highlift::reduced_models {

/// Reflects an inertia or a stiffness at a place turning at speed_ratio = w_local / w_ref.
inline double Reflect(double value, double speed_ratio) { return value * speed_ratio * speed_ratio; }

struct Transmission {
  struct Point {
    std::string name;        ///< e.g. "gbx_l1", or "shaft_l1/b" for a joint between links
    double J = 0.0;          ///< kg*m^2, reflected concentrated inertia (>= 0)
    bool accumulate = true;  ///< an accumulation point (kept by the reduced rules)
    std::string component;   ///< component id, if any
  };
  struct Link {
    int a = 0;               ///< point index
    int b = 0;               ///< point index
    double c = 0.0;          ///< N*m/rad, reflected stiffness (> 0)
    double J = 0.0;          ///< kg*m^2, reflected distributed inertia (0 for a massless spring)
    std::string name;        ///< e.g. "shaft_l1"
    std::string component;
  };
  std::vector<Point> points;
  std::vector<Link> links;

  int AddPoint(std::string name, double J, bool accumulate = true, std::string component = {});
  int AddLink(int a, int b, double c, double J, std::string name, std::string component = {});
  int FindPoint(std::string_view name) const;  ///< -1 when absent
  double TotalInertia() const;                 ///< sum of all concentrated and distributed J
};

struct LumpedModel {
  static constexpr int kGround = -1;
  struct Node {
    std::string name;
    double J = 0.0;          ///< kg*m^2 (> 0 for the modal analysis)
    int point = -1;          ///< the Transmission point it stands for, -1 for an interior node
  };
  struct Spring {
    int a = 0;               ///< node index
    int b = kGround;         ///< node index or kGround
    double c = 0.0;          ///< N*m/rad
    int link = -1;           ///< the Transmission link it belongs to, -1 for a merged section
    std::string name;
  };
  std::vector<Node> nodes;
  std::vector<Spring> springs;

  int AddNode(std::string name, double J, int point = -1);
  int AddSpring(int a, int b, double c, std::string name, int link = -1);
  double TotalInertia() const;
  /// The node standing for transmission point `point`, -1 if it was merged away.
  int NodeOfPoint(int point) const;
};

enum class Reduction { kFullResolution, kAccumulated, kTwoMassesPerSection };
/// "full", "accumulated", "two_masses"; and back (nullopt-like: returns false on unknown).
std::string ToString(Reduction r);
bool ReductionFromString(std::string_view s, Reduction* r);

/// Builds the lumped model of `transmission` by rule `reduction`; `elements_per_link` is n of
/// the full-resolution rule (>= 1). Total inertia is preserved by every rule. Throws
/// InputError when a link has c <= 0 or the links contain a cycle.
LumpedModel BuildLumpedModel(const Transmission& transmission, Reduction reduction,
                             int elements_per_link = 4);

}  // namespace highlift::reduced_models
