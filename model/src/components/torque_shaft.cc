// torque_shaft: a tube segment of the transmission, ports a and b. Stiffness given or from the
// tube law c = G Ip / L; inertia given, from the linear density or J = rho Ip L; damping given or
// the structural damping beta*c; drag per length (its bearings and joints) at its two ends.
// Full resolution: shaft_elements spring-dampers "<id>.e1".."<id>.eN" between the inertias
// "<id>.m0".."<id>.mN"; reduced resolution: a member of a lumped chain. Its torque capacity is at
// the lesser of the allowable shear stress and the tube's torsional buckling stress (laws.h
// TubeBucklingStress: NASA SP-8007 s. 4.1.4, Timoshenko & Gere s. 11.12).
#include <algorithm>
#include <string>
#include <type_traits>

#include "declaration.h"
#include "highlift/model/drive_network.h"
#include "highlift/model/laws.h"

namespace highlift::model::components {

// The declaration: ports, parameters (units, defaults, domains, sources) and roles.
ComponentTypeSpec TorqueShaftDeclaration() {
  ComponentTypeSpec t;
  t.name = "torque_shaft";
  t.display_name = "torque shaft";
  t.description =
      "Torque shaft segment: a tube (length, outer diameter, wall thickness, material) or given "
      "directly by stiffness and inertia. c = G*pi/32*(D^4 - d^4)/L, J = rho*pi/32*(D^4 - d^4)*L. "
      "Torque capacity min(tau_allow, tau_cr)*2*Ip/D, tau_cr the elastic torsional buckling stress of the tube "
      "(NASA SP-8007 s. 4.1.4: long or moderate length, E = 2*G*(1 + nu), knock-down gamma).";
  t.ports = {Flange("a", "flange nearer the PDU"), Flange("b", "flange farther from the PDU")};
  auto& ps = t.parameters;
  ps.push_back(Param("length", "L", Length(), "m", "length of the segment")
                   .Valid(0.01, 100)
                   .Source("none: given per segment (domain.md s3 lists 1.5-4 m)"));
  ps.push_back(Param("outer_diameter", "D", Length(), "mm", "outer diameter of the tube")
                   .Nominal(50)
                   .Default(38, 60)
                   .Valid(5, 500)
                   .Source("domain.md s3 (E): 50 mm inboard, 45 mm outboard; s4: 38 mm"));
  ps.push_back(Param("wall_thickness", "t", Length(), "mm", "wall thickness of the tube")
                   .Nominal(2.0)
                   .Default(1.4, 2.1)
                   .Valid(0.1, 100)
                   .Source("domain.md s3 (E): 2.0 mm inboard, 1.8 mm outboard, +-0.1 mm"));
  ps.push_back(Param("shear_modulus", "G", Pressure(), "GPa", "shear modulus of the tube material")
                   .Nominal(44)
                   .Default(43, 51)
                   .Valid(1, 300)
                   .Source("domain.md s6 (P-low): Ti-6Al-4V G 44 [43, 51] GPa"));
  ps.push_back(Param("density", "rho", Density(), "kg/m^3", "density of the tube material")
                   .Nominal(4420)
                   .Valid(100, 30000)
                   .Source("domain.md s1 (P): Ti-6Al-4V 4420 kg/m3"));
  ps.push_back(Param("allowable_shear_stress", "tau_allow", Pressure(), "MPa", "allowable (ultimate) shear stress of the material")
                   .Nominal(550)
                   .Default(500, 600)
                   .Valid(1, 5000)
                   .Source("domain.md s6 (E): Ti-6Al-4V ultimate shear about 550 MPa"));
  ps.push_back(Param("poisson_ratio", "nu", Dimensionless(), "1", "Poisson's ratio of the tube material (its torsional buckling, E = 2 G (1 + nu))")
                   .Nominal(0.33)
                   .Default(0.31, 0.34)
                   .Valid(0, 0.5)
                   .Source("(E): Ti-6Al-4V 0.31-0.34 (handbook values; with G 44 GPa, E = 2 G (1 + nu) = 115-118 GPa)"));
  ps.push_back(Param("buckling_knockdown", "gamma", Dimensionless(), "1",
                     "imperfection knock-down on the tube's elastic torsional buckling stress (correlation factor)")
                   .Nominal(0.67)
                   .Valid(0.05, 1)
                   .Source("NASA SP-8007 (1968) s. 4.1.4 (P): correlation factor 0.67 for cylinders in torsion"));
  ps.push_back(OptionalStiffness("torsional stiffness of the whole segment; overrides the tube geometry",
                                 ReferenceSide::kShaft, "none: from the tube geometry unless given"));
  ps.push_back(Param("inertia", "J", dimensions::Inertia(), "kg*m^2", "inertia of the whole segment; overrides the tube geometry")
                   .Valid(0, 1e3)
                   .Optional()
                   .Source("none: from the tube geometry unless given")
                   .Side(ReferenceSide::kShaft));
  ps.push_back(Param("linear_density", "m_l", LinearDensity(), "kg/m", "mass per length (for a composite tube whose density is not known)")
                   .Valid(0, 1e3)
                   .Optional()
                   .Source("domain.md s1 (P): Ti 1.2 kg/m, CFRP 0.28 kg/m"));
  ps.push_back(Param("damping", "d", RotationalDamping(), "N*m*s/rad", "structural damping of the segment")
                   .Valid(0, 1e6)
                   .Optional()
                   .Source("none")
                   .Side(ReferenceSide::kShaft));
  ps.push_back(Param("drag_per_length", "tau_d", TorquePerLength(), "N*m/m",
                     "drag torque of the bearings and joints along the segment, per metre of shaft")
                   .Nominal(0.25)
                   .Default(0.1, 0.5)
                   .Valid(0, 100)
                   .Source("domain.md s3 (E): 0.2-0.3 N m per metre, domain [0.1, 0.5]")
                   .Side(ReferenceSide::kShaft));
  ps.push_back(SpanPosition());
  t.relations = {{"wall_thickness", "outer_diameter", 2.0, "the radius", "equal: a solid shaft"}};
  t.roles = {.chain_member = true, .rupturable = true, .segment = true};
  return t;
}

namespace {

struct ShaftValues {
  double c = 0;     // N*m/rad, whole segment
  double J = 0;     // kg*m^2, whole segment
  double d = 0;     // N*m*s/rad
  double drag = 0;  // N*m, Coulomb drag of the whole segment
};

/// `beta`: the project's structural damping (d = beta*c when the shaft gives no damping).
ShaftValues ShaftData(const Component& s, double beta) {
  ShaftValues data;
  const double L = Require(s, "length");
  const auto D = Value(s, "outer_diameter");
  const auto t = Value(s, "wall_thickness");
  const bool tube = D && t && *D > 0 && *t > 0;
  if (auto c = Value(s, "stiffness")) {
    data.c = *c;
  } else {
    if (!tube)
      throw InputError("component '" + s.id + "' (" + s.type + "): neither 'stiffness' nor a tube "
                       "geometry ('outer_diameter', 'wall_thickness') is given: give one of them",
                       s.where);
    data.c = ShaftStiffness(Require(s, "shear_modulus"), *D, std::min(*t, *D / 2), L);
  }
  if (auto J = Value(s, "inertia")) {
    data.J = *J;
  } else if (auto m_l = Value(s, "linear_density"); m_l && D && t) {
    const double d_in = std::max(0.0, *D - 2 * *t);
    data.J = *m_l * L * (*D * *D + d_in * d_in) / 8;
  } else {
    data.J = tube ? ShaftInertia(Require(s, "density"), *D, std::min(*t, *D / 2), L) : 0.0;
  }
  data.d = ValueOr(s, "damping", beta * data.c);
  data.drag = ValueOr(s, "drag_per_length", 0.0) * L;
  return data;
}

class TorqueShaftModel final : public NamedModel {
 public:
  TorqueShaftModel() : NamedModel("torque_shaft") {}

  /// The segment at its own speed: stiffness given or the tube law; inertia given, from the
  /// linear density (thin tube, mean radius) or the tube law.
  template <class T>
  Lumped<T> Law(const ParameterReader<T>& p) const {
    Lumped<T> out;
    out.c = p.Has("stiffness") ? p("stiffness")
                               : ShaftStiffness(p("shear_modulus"), p("outer_diameter"), p("wall_thickness"), p("length"));
    if (p.Has("inertia")) {
      out.J = p("inertia");
    } else if (p.Has("linear_density")) {
      const T r = (p("outer_diameter") - p("wall_thickness")) * T(0.5);
      out.J = p("linear_density") * p("length") * r * r;
    } else {
      out.J = ShaftInertia(p("density"), p("outer_diameter"), p("wall_thickness"), p("length"));
    }
    return out;
  }
  HIGHLIFT_LUMPED_LAW

  /// Steady state: its drag per length over its length adds to what it passes on.
  template <class T>
  T SteadyLaw(const ParameterReader<T>& p, const SteadyFlow<T>& in) const {
    return in.through + in.friction * p("drag_per_length") * p("length");
  }
  HIGHLIFT_STEADY_LAW

  /// Its torque capacity at the lesser of the allowable shear stress and the torsional buckling
  /// stress of the tube (laws.h TubeBucklingStress: elastic shell buckling, long or moderate
  /// length, with the knock-down gamma), min(tau_allow, tau_cr) 2 Ip / D, against the operating
  /// torque and the peak loads alike. At a point it is named after the stress that governs.
  template <class T>
  std::optional<Allowable<T>> PeakLaw(const ParameterReader<T>& p) const {
    const T D = p("outer_diameter"), t = p("wall_thickness");
    const T tau_allow = p("allowable_shear_stress");
    const T tau_cr =
        TubeBucklingStress(p("shear_modulus"), p("poisson_ratio"), p("buckling_knockdown"), D, t, p("length"));
    std::string name = "torque capacity";
    if constexpr (std::is_same_v<T, double>) {
      if (tau_cr < tau_allow) name = "torque capacity (torsional buckling)";
    }
    return Allowable<T>{name, TubeTorqueCapacityWithBuckling(tau_allow, tau_cr, D, TubePolarMoment(D, t))};
  }
  HIGHLIFT_PEAK_ALLOWABLE_LAW
  std::optional<Allowable<Interval>> SteadyAllowable(const ParameterReader<Interval>& p) const override {
    auto a = PeakLaw(p);
    a->name = "torque capacity at the allowable shear stress or the torsional buckling stress, the lesser";
    return a;
  }

  void Expand(const Component& c, ExpansionContext& x) const override {
    const ShaftValues data = ShaftData(c, x.beta());
    const int n = x.shaft_elements();
    const Scenario* scenario = x.scenario();
    const bool ruptured = scenario && scenario->rupture_component == c.id;
    const int broken = ruptured ? (n + 1) / 2 : 0;  // the spring-damper replaced by a Disconnector
    std::vector<std::string> masses;
    for (int i = 0; i <= n; ++i) {
      const double share = (i == 0 || i == n) ? 0.5 / n : 1.0 / n;
      const std::string mass = c.id + ".m" + std::to_string(i);
      // The drag of the segment (its bearings and joints) acts at its two ends, half at each, as
      // in the reduced model: interior masses without Coulomb friction avoid stick/slip events
      // of every sub-element while the shaft starts and stops.
      if (data.drag > 0 && (i == 0 || i == n))
        x.Add("LossyInertia", mass, x.Regularised({{"J", data.J * share}, {"tau_C", data.drag * 0.5}}), c.id);
      else
        x.Add("Inertia", mass, {{"J", data.J * share}}, c.id);
      masses.push_back(mass);
      if (i == 0) continue;
      const std::string spring = c.id + ".e" + std::to_string(i);
      Scalars s = {{"c", data.c * n}, {"d", data.d * n}};
      if (i == broken) {
        s["t_disconnect"] = *scenario->rupture_time;
        x.Add("Disconnector", spring, s, c.id, {}, "rupture of " + c.id);
      } else {
        x.Add("SpringDamper", spring, s, c.id);
      }
      x.Connect(masses[i - 1] + ".flange_b", spring + ".flange_a");
      x.Connect(spring + ".flange_b", mass + ".flange_a");
    }
    x.MapPort(c, "a", masses.front() + ".flange_a");
    x.MapPort(c, "b", masses.back() + ".flange_b");
    x.model().derived.push_back({c.id + ".tau", c.id + ".e1.tau", -1.0});
    x.model().torque_sign[c.id] = -1.0;  // peak torques as the derived column
  }

  ChainMember Chain(const Component& c, double beta) const override {
    const ShaftValues data = ShaftData(c, beta);
    return {data.J, data.drag, data.c, data.d, true};
  }

  /// The tube laws (laws.h) on the tube as given (d = D - 2t inside each law), on intervals with
  /// their exact range: each grows with D and, while t <= D/2, with t (inputs 1 and 2); the drag
  /// per length from a label "bearing_spacing" and a bearing drag of 0.05-0.2 N*m each
  /// (domain.md s6, E).
  std::vector<EstimationLaw> EstimationLaws() const override {
    const LawInput G = FromParameter("shear_modulus"), rho = FromParameter("density"),
                   D = FromParameter("outer_diameter"), t = FromParameter("wall_thickness"), L = FromParameter("length"),
                   tau = FromParameter("allowable_shear_stress"), nu = FromParameter("poisson_ratio"),
                   gamma = FromParameter("buckling_knockdown");
    const auto tube = [](const auto& v) { return v[2].lo >= 0.0 && v[1].lo >= 2.0 * v[2].hi; };
    return {
        EstimateParameter("stiffness", {G, D, t, L}, "physics: c = G pi/32 (D^4 - d^4)/L, d = D - 2t",
                          MonotoneLaw({1, 1, 1, -1}, tube,
                                      [](const auto& v) { return ShaftStiffness(v[0], v[1], v[2], v[3]); })),
        EstimateParameter("inertia", {rho, D, t, L}, "physics: J = rho pi/32 (D^4 - d^4) L",
                          MonotoneLaw({1, 1, 1, 1}, tube, [](const auto& v) { return ShaftInertia(v[0], v[1], v[2], v[3]); })),
        EstimateParameter("linear_density", {rho, D, t}, "physics: m_l = rho pi/4 (D^2 - d^2)",
                          MonotoneLaw({1, 1, 1}, tube, [](const auto& v) { return ShaftMassPerLength(v[0], v[1], v[2]); })),
        EstimateParameter("drag_per_length", {FromConstant(0.05, 0.1, 0.2), FromLabel("bearing_spacing", dimensions::Length())},
                          "physics: bearing drag 0.05-0.2 N m each (domain.md s6) / bearing_spacing label",
                          [](const auto& v) { return v[0] / v[1]; }),
        DeriveQuantity("torque_capacity", "N*m", {tau, D, t, G, nu, gamma, L},
                       "min(tau_allow, tau_cr) pi/16 (D^4 - d^4)/D, tau_cr the torsional buckling stress (laws.h)",
                       MonotoneLaw({1, 1, 1, 1, 1, 1, -1}, tube, [](const auto& v) {
                         return TubeTorqueCapacityWithBuckling(v[0], TubeBucklingStress(v[3], v[4], v[5], v[1], v[2], v[6]),
                                                               v[1], TubePolarMoment(v[1], v[2]));
                       })),
        DeriveQuantity("mass", "kg", {rho, D, t, L}, "rho pi/4 (D^2 - d^2) L",
                       MonotoneLaw({1, 1, 1, 1}, tube, [](const auto& v) { return ShaftMass(v[0], v[1], v[2], v[3]); }))};
  }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(TorqueShaft, TorqueShaftModel)
