// The drive-system network of the example projects, through the library and through the CLI.
#include "highlift/icsp/drive_system.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

#include "common/run_cli.h"
#include "highlift/core/project_io.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/sizing.h"
#include "optimize/one_tube_chain.h"

namespace highlift::icsp {
namespace {

const std::string kFlaps = std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps.json";
const std::string kInfeasible = std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps_infeasible.json";

Interval Final(const CheckResult& r, const std::string& name) {
  for (const auto& p : r.parameters) {
    if (p.name == name) return p.final;
  }
  ADD_FAILURE() << "no quantity " << name;
  return Empty();
}

/// The domain of `name` in a box.
Interval In(const DriveSystemNetwork& net, const Box& box, const std::string& name) {
  const VariableId v = net.network.FindVariable(name);
  if (v.value < 0) {
    ADD_FAILURE() << "no quantity " << name;
    return Empty();
  }
  return box[v.value];
}

/// Propagates the physics alone (no requirement narrows anything) from `box`.
PropagationReport PropagatePhysics(const DriveSystemNetwork& net, Box& box) {
  std::vector<char> physics(static_cast<std::size_t>(net.network.num_constraints()), 0);
  for (int c = 0; c < net.network.num_constraints(); ++c)
    physics[c] = net.network.constraint(ConstraintId{c}).info.role == ConstraintRole::kPhysics;
  return Propagator(net.network).Propagate(box, physics);
}

/// The box with every parameter at its nominal value.
Box NominalBox(const DriveSystemNetwork& net) {
  Box box = net.network.InitialBox();
  for (const auto& [v, value] : net.nominal) box[v] = Interval(value, value);
  return box;
}

TEST(DriveSystem, FlapProjectMeetsItsRequirementsAndDerivesThePhysics) {
  const Project project = LoadProject(kFlaps);
  const DriveSystemNetwork net = BuildDriveSystemNetwork(project);
  EXPECT_GT(net.physics_constraints, 100);
  EXPECT_EQ(net.requirement_constraints, static_cast<int>(project.requirements.size()));
  const CheckResult r = CheckDriveSystem(net);
  ASSERT_TRUE(r.feasible) << r.report.BriefReport();
  EXPECT_EQ(r.report.status, Status::kFixedPoint);
  // Station input torque: 20 kN*m / (i_act eta_opp) / (i_branch eta_mesh), 60.64 N*m at the
  // nominal efficiencies 0.85 and 0.97; the bounds come from the efficiency domains.
  const Interval station = Final(r, "tgb_l1.station_torque");
  EXPECT_LE(station.lower(), 20000.0 / (200 * 0.85) / (2 * 0.97));
  EXPECT_GE(station.upper(), 20000.0 / (200 * 0.85) / (2 * 0.97));
  const Interval eta_opp = Final(r, "gra_l1.eta_opposing"), eta_mesh = Final(r, "tgb_l1.eta_mesh");
  EXPECT_NEAR(station.lower(), 20000.0 / (200 * eta_opp.upper()) / (2 * eta_mesh.upper()), 1e-9);
  EXPECT_NEAR(station.upper(), 20000.0 / (200 * eta_opp.lower()) / (2 * eta_mesh.lower()), 1e-9);
  // Tube stiffness c = G Ip / L of a 50 x 2 mm tube, 2 m long, G = 44 GPa (domain of G may be wider).
  const Interval c = Final(r, "shaft_l0a.c");
  const double ip = M_PI / 32 * (std::pow(0.05, 4) - std::pow(0.046, 4));
  EXPECT_LE(c.lower(), 44e9 * ip / 2.0 * 1.0000001);
  EXPECT_GE(c.upper(), 44e9 * ip / 2.0 * 0.9999999);
  // Equation (1) at the jam of station 1 is positive and finite.
  const Interval peak = Final(r, "peak.jam_l1.torque");
  EXPECT_GT(peak.lower(), 0.0);
  EXPECT_TRUE(std::isfinite(peak.upper()));
}

TEST(DriveSystem, ExtensionTimeIncludesTheRampsOfTheSpeedProfile) {
  // tools/gen_examples.py writes the profile: 0 -> w in t_ramp = 0.4 s, hold, slow down in 0.2 s to
  // k w (k = 0.25) for the last s = 3 % of the travel, stop in 0.1 s. Its duration in closed form:
  //   T = t_ramp/2 + (1 - k) t_down/2 + t_stop/2 + (Phi / w) ((1 - s) + s / k).
  // The network takes the phases from the table; at Phi = 2.2 rad * 200 * 2 = 880 rad (the
  // table's 879.65 rad rounded) the two agree to well under a millisecond; the ramps add
  // 3.5 s to the 34.8 s at full speed.
  const DriveSystemNetwork net = BuildDriveSystemNetwork(LoadProject(kFlaps));
  Box box = NominalBox(net);
  ASSERT_NE(PropagatePhysics(net, box).status, Status::kInfeasible);
  const double w = 25.3, phi = 2.2 * 200 * 2, k = 0.25, s = 0.03;
  const double closed = 0.2 + 0.5 * (1 - k) * 0.2 + 0.05 + phi / w * ((1 - s) + s / k);
  const Interval t = In(net, box, "travel_time.extension");
  EXPECT_NEAR(t.lower(), closed, 1e-3);
  EXPECT_NEAR(t.upper(), closed, 1e-3);
  EXPECT_GT(t.lower(), phi / w + 3.0);
  // Slower PDU, longer extension: T - t_ramps scales with 1 / w.
  Box slow = NominalBox(net);
  slow[net.network.FindVariable("pdu.max_output_speed").value] = Interval(w / 2, w / 2);
  ASSERT_NE(PropagatePhysics(net, slow).status, Status::kInfeasible);
  const double t_ramps = 0.2 + 0.5 * (1 - k) * 0.2 + 0.1 * (1 - 0.5 * k);
  EXPECT_NEAR(In(net, slow, "travel_time.extension").lower() - t_ramps, 2.0 * (t.lower() - t_ramps), 1e-6);
}

/// icsp and `highlift peak` (reduced_models::AnalysePeaks) compute the same sizing cases: for every
/// case the network builds, the enclosure over the project domains contains reduced_models'
/// nominal value and lies within its enclosure, within 3 %, and at the nominal values it collapses
/// onto it.
void ExpectAgreementWithPeak(const std::string& file, int cases) {
  SCOPED_TRACE(file);
  constexpr double kTolerance = 1e-6;  // relative; both sides widen eigenvalues by 1e-9
  const Project project = LoadProject(file);
  const DriveSystemNetwork net = BuildDriveSystemNetwork(project);
  Box wide = net.network.InitialBox();
  ASSERT_NE(PropagatePhysics(net, wide).status, Status::kInfeasible);
  Box nominal = NominalBox(net);
  ASSERT_NE(PropagatePhysics(net, nominal).status, Status::kInfeasible);
  reduced_models::PeakOptions options;
  options.rank = false;
  const reduced_models::PeakReport report = reduced_models::AnalysePeaks(project, options);
  int compared = 0, ruptures = 0;
  auto near = [&](double ours, double theirs) { return std::fabs(ours - theirs) <= kTolerance * std::fabs(theirs); };
  for (const reduced_models::PeakCase& pc : report.cases) {
    const std::string p = "peak." + pc.name + ".";
    if (net.network.FindVariable(p + "torque").value < 0) continue;  // not a scenario of the project
    SCOPED_TRACE(pc.name);
    ++compared;
    ruptures += pc.kind == "rupture";
    const Interval torque = In(net, wide, p + "torque");
    EXPECT_LE(torque.lower(), pc.tau_dynamic.nominal);
    EXPECT_GE(torque.upper(), pc.tau_dynamic.nominal);
    // Within peak's enclosures and close to them: the network encloses each tube's Ip by both of
    // its exact forms (the factored law and D^4 - d^4), peak by the factored law alone, which
    // overestimates the range of Ip over a wall domain (t occurs three times), so the network's
    // enclosures of the tubes' stiffness and inertia, and with them of w and w w1 J*, may be
    // narrower (by up to 2.1 % on the examples).
    for (const auto& [name, ours, theirs] : std::vector<std::tuple<std::string, Interval, Domain>>{
             {"torque", torque, pc.tau_dynamic.bounds}, {"speed", In(net, wide, p + "speed"), pc.w_max_bounds}}) {
      EXPECT_GE(ours.lower(), theirs.lo * (1 - kTolerance)) << name;
      EXPECT_LE(ours.upper(), theirs.hi * (1 + kTolerance)) << name;
      EXPECT_NEAR(ours.lower(), theirs.lo, 0.03 * theirs.lo) << name;
      EXPECT_NEAR(ours.upper(), theirs.hi, 0.03 * theirs.hi) << name;
    }
    // At the nominal values: the same w, w1, J*, c*, tau and static torque.
    for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
             {"speed", pc.w_max}, {"omega", pc.omega}, {"inertia", pc.J_star}, {"stiffness", pc.c_star},
             {"torque", pc.tau_dynamic.nominal}, {"static_torque", pc.tau_static}, {"total_torque", pc.tau_total.nominal}}) {
      const Interval x = In(net, nominal, p + name);
      EXPECT_TRUE(near(x.lower(), value) && near(x.upper(), value)) << name << " [" << x.lower() << ", " << x.upper() << "] vs " << value;
    }
  }
  EXPECT_EQ(compared, cases);  // the jam scenarios and rupture_wtb
  EXPECT_EQ(ruptures, 1);
}

TEST(DriveSystem, SizingCasesAgreeWithReducedModelsPeak) {
  ExpectAgreementWithPeak(kFlaps, 13);  // jam_l1 .. jam_r6 and the rupture of shaft_l1
  ExpectAgreementWithPeak(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a320_class_flaps.json", 9);
  ExpectAgreementWithPeak(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a320_class_slats.json", 21);
}

/// icsp and `highlift size` (reduced_models::Size) compute the same steady-state torque flow:
/// every component's input torque in every load case, the torques the limiter and brake settings
/// are checked against, at the nominal values and as enclosures over the project domains.
void ExpectAgreementWithSize(const std::string& file) {
  SCOPED_TRACE(file);
  constexpr double kNominal = 1e-9, kBounds = 1e-6;  // relative
  const Project project = LoadProject(file);
  const DriveSystemNetwork net = BuildDriveSystemNetwork(project);
  Box wide = net.network.InitialBox();
  ASSERT_EQ(PropagatePhysics(net, wide).status, Status::kFixedPoint);
  Box nominal = NominalBox(net);
  ASSERT_EQ(PropagatePhysics(net, nominal).status, Status::kFixedPoint);
  const reduced_models::SizingReport size = reduced_models::Size(project);
  auto near = [](double ours, double theirs, double tolerance) {
    return std::fabs(ours - theirs) <= tolerance * std::max(1.0, std::fabs(theirs));
  };
  auto expect = [&](const std::string& name, const reduced_models::Bounded& b) {
    const Interval n = In(net, nominal, name), w = In(net, wide, name);
    EXPECT_TRUE(near(n.lower(), b.nominal, kNominal) && near(n.upper(), b.nominal, kNominal))
        << name << " nominal " << ToString(n) << " vs " << b.nominal;
    EXPECT_TRUE(w.lower() <= b.nominal && b.nominal <= w.upper()) << name << " " << ToString(w) << " excludes " << b.nominal;
    EXPECT_TRUE(near(w.lower(), b.bounds.lo, kBounds) && near(w.upper(), b.bounds.hi, kBounds))
        << name << " " << ToString(w) << " vs [" << b.bounds.lo << ", " << b.bounds.hi << "]";
  };
  int compared = 0;
  for (const reduced_models::LoadCaseSizing& lc : size.cases) {
    for (const reduced_models::ComponentTorque& t : lc.components) {
      expect("torque." + lc.load_case + "." + t.component, t.torque);
      ++compared;
    }
  }
  for (const reduced_models::SettingRecommendation& r : size.settings) {
    const std::string name = r.component + (r.parameter == "lockout_torque_extend"    ? ".torque_through"
                                            : r.parameter == "lockout_torque_retract" ? ".torque_through_retract"
                                            : r.parameter == "max_brake_torque"       ? ".jam_grounding"
                                                                                      : ".holding_torque");
    expect(name, r.operating);
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

TEST(DriveSystem, TorqueFlowAgreesWithReducedModelsSize) {
  ExpectAgreementWithSize(kFlaps);
  ExpectAgreementWithSize(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a320_class_flaps.json");
  ExpectAgreementWithSize(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a320_class_slats.json");
  ExpectAgreementWithSize(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/hydraulic_pdu_flaps.json");
}

/// Whole-network soundness on the real physics (fixed seed): designs drawn inside the parameter
/// domains, with every derived quantity at its value for that design, satisfy the physics, so the
/// contracted box must contain them: every sampled parameter exactly, every derived quantity
/// (known to a few ulps from propagating the point design) at the centre of its enclosure. With
/// the requirements too, for the samples that meet them.
void ExpectSampledDesignsInside(const std::string& file, int samples) {
  SCOPED_TRACE(file);
  const DriveSystemNetwork net = BuildDriveSystemNetwork(LoadProject(file));
  const Network& n = net.network;
  Box wide = n.InitialBox();
  ASSERT_EQ(PropagatePhysics(net, wide).status, Status::kFixedPoint);
  Box constrained = n.InitialBox();
  const bool feasible = Propagator(n).Propagate(constrained).status != Status::kInfeasible;
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0, meeting_requirements = 0;
  // Physics: samples from the initial domains. Requirements: from the contracted domains, where
  // a sample meets them far more often.
  for (int t = 0; t < 5 * samples; ++t) {
    const bool with_requirements = t >= samples;
    if (with_requirements && !feasible) break;
    const Box& from = with_requirements ? constrained : n.InitialBox();
    Box point = n.InitialBox();
    std::vector<int> parameters;
    for (int v = 0; v < n.num_variables(); ++v) {
      if (n.variable(VariableId{v}).provenance == "propagated") continue;
      const Interval d = from[v];
      if (!std::isfinite(d.lower()) || !std::isfinite(d.upper())) continue;
      point[v] = Interval(std::clamp(d.lower() + (d.upper() - d.lower()) * u(rng), d.lower(), d.upper()));
      parameters.push_back(v);
    }
    Box design = point;
    if (PropagatePhysics(net, design).status == Status::kInfeasible) continue;  // outside the physics
    auto expect_inside = [&](const Box& box, const char* what) {
      for (int v : parameters) {
        EXPECT_TRUE(box[v].lower() <= design[v].lower() && design[v].upper() <= box[v].upper())
            << what << ": sample " << t << " " << n.variable(VariableId{v}).name << " = " << design[v].lower()
            << " excluded by " << ToString(box[v]);
      }
      for (int v = 0; v < n.num_variables(); ++v) {
        const Interval d = design[v];
        if (!std::isfinite(d.lower()) || !std::isfinite(d.upper())) continue;
        const double mid = 0.5 * (d.lower() + d.upper());
        if (d.upper() - d.lower() > 1e-6 * std::max(1.0, std::fabs(mid))) continue;  // not determined
        EXPECT_TRUE(box[v].lower() <= mid && mid <= box[v].upper())
            << what << ": sample " << t << " " << n.variable(VariableId{v}).name << " = " << mid << " excluded by "
            << ToString(box[v]);
      }
    };
    if (!with_requirements) {
      ++checked;
      expect_inside(wide, "physics");
      continue;
    }
    Box all = point;
    if (Propagator(n).Propagate(all).status == Status::kInfeasible) continue;  // misses a requirement
    ++meeting_requirements;
    expect_inside(constrained, "requirements");
  }
  EXPECT_GE(checked, samples / 2);
  if (feasible) {
    EXPECT_GE(meeting_requirements, 1) << "no sample of the contracted box met the requirements";
  }
  ::testing::Test::RecordProperty(file + ": samples meeting the requirements", meeting_requirements);
}

TEST(DriveSystemSoundness, SampledDesignsAreNeverExcluded) {
  ExpectSampledDesignsInside(kFlaps, 12);
  ExpectSampledDesignsInside(kInfeasible, 6);
  ExpectSampledDesignsInside(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a320_class_slats.json", 8);
}

/// The A380-class example with a wing-tip brake that never slips below `torque` (dynamic and
/// static torque both `torque`, point values).
Project WithBrakeTorque(double torque) {
  Project project = LoadProject(kFlaps);
  for (Component& c : project.components) {
    if (c.id != "wtb_left") continue;
    for (const char* name : {"max_dynamic_torque", "static_capacity"}) {
      Parameter& p = c.parameters[name];
      p.nominal = torque;
      p.domain = Domain::Point(torque);
    }
  }
  return project;
}

TEST(DriveSystem, NominalFlapDesignMeetsTheRuptureRequirementBecauseTheBrakeSlips) {
  // After a rupture of shaft_l1 the outboard shaft spins up to hundreds of rad/s before the
  // wing-tip brake engages; a rigid stop would then see w w1 J* of 1 to 5 kN*m. The brake is a
  // friction brake: it slips at the larger of its dynamic (500-700) and static (550-700 N*m)
  // torques, and so the peak next to it stays there, far inside shaft_l7's capacity / 1.5.
  const CheckResult r = CheckDriveSystem(BuildDriveSystemNetwork(LoadProject(kFlaps)));
  ASSERT_TRUE(r.feasible);
  ASSERT_TRUE(r.nominal_checked);
  EXPECT_TRUE(r.nominal_feasible) << r.nominal_explanation.text;
  EXPECT_GT(Final(r, "peak.rupture_wtb.torque").upper(), 1000.0);
  const Interval total = Final(r, "peak.rupture_wtb.total_torque");
  EXPECT_GE(total.lower(), 550.0 - 1e-9);
  EXPECT_LE(total.upper(), 700.0 + 1e-9);
}

TEST(DriveSystem, ABrakeThatDoesNotSlipMakesTheNominalDesignViolateTheRuptureRequirement) {
  // The same rupture against a brake of 5 kN*m: the rigid-stop peak, 2454 N*m plus 204 N*m
  // back-drive at the nominal values, times 1.5 exceeds shaft_l7's 2791 N*m. The domains can
  // meet the requirement (short latencies, a stiff enough shaft), the nominal design cannot, and
  // check says so.
  const CheckResult r = CheckDriveSystem(BuildDriveSystemNetwork(WithBrakeTorque(5000.0)));
  ASSERT_TRUE(r.feasible);
  ASSERT_TRUE(r.nominal_checked);
  EXPECT_FALSE(r.nominal_feasible);
  EXPECT_NE(r.nominal_explanation.text.find("rupture_wtb_shaft"), std::string::npos) << r.nominal_explanation.text;
  // The latencies that let the domains meet it: the brake must engage within about 129 ms.
  const Interval latency = Final(r, "wtb_left.engagement_latency");
  EXPECT_LT(latency.upper(), 150.0);
  EXPECT_GT(latency.upper(), 100.0);
}

TEST(DriveSystem, RequirementOnAMissingSizingCaseSaysWhyItIsMissing) {
  Project project = LoadProject(kFlaps);
  project.load_cases.clear();  // the sizing cases need the operating speed and the airloads
  try {
    BuildDriveSystemNetwork(project);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string message = e.message();
    EXPECT_NE(message.find("travel_time.extension"), std::string::npos) << message;  // the first such requirement
    EXPECT_NE(message.find("the sizing cases peak.<case>.* and the travel times could not be built"), std::string::npos)
        << message;
    EXPECT_NE(message.find("has no load cases"), std::string::npos) << message;
  }
}

TEST(DriveSystem, InfeasibleVariantNamesTheConflictingRequirements) {
  const DriveSystemNetwork net = BuildDriveSystemNetwork(LoadProject(kInfeasible));
  const CheckResult r = CheckDriveSystem(net);
  ASSERT_FALSE(r.feasible);
  std::vector<std::string> names;
  for (int c : r.explanation.conflict) names.push_back(net.network.constraint(ConstraintId{c}).info.label);
  EXPECT_EQ(names, (std::vector<std::string>{"extension_time", "jam_l1_fitting"}));
  // Minimal: the physics with both is infeasible, with either alone it is not (nor with all the
  // other requirements and one of the two).
  const int nc = net.network.num_constraints();
  for (int dropped : r.explanation.conflict) {
    std::vector<char> enabled(nc, 1);
    enabled[dropped] = 0;
    Box box = net.network.InitialBox();
    EXPECT_NE(Propagator(net.network).Propagate(box, enabled).status, Status::kInfeasible)
        << net.network.constraint(ConstraintId{dropped}).info.label;
  }
  // The chain: each requirement's way to the travel time law, where they meet in the PDU speed.
  const std::string& text = r.explanation.text;
  EXPECT_NE(text.find("from requirement 'extension_time':"), std::string::npos) << text;
  EXPECT_NE(text.find("from requirement 'jam_l1_fitting':"), std::string::npos) << text;
  EXPECT_NE(text.find("gives pdu.operating_speed in [20, "), std::string::npos) << text;
  EXPECT_NE(text.find("travel_time.extend_opposing' (travel time of 'extend_opposing' with the ramps"), std::string::npos)
      << text;
  EXPECT_NE(text.find("cannot hold for any values in the narrowed domains"), std::string::npos) << text;
  ASSERT_FALSE(r.explanation.chain.empty());
  EXPECT_EQ(net.network.constraint(ConstraintId{r.explanation.chain.front().constraint}).info.label, "extension_time");
}

// The optimize tests' one titanium tube (2 m, D in [20, 60] mm and t in [0.5, 4] mm, not design
// variables here) with G and tau_allow uncertain, under a capacity requirement written in D and t
// as the examples write theirs (1.5 x 400 N*m below the ultimate torque, tau_allow pi/16
// (D^4 - d^4) / D with pi/16 rounded to 0.19634954).
Project OneTubeUnderAWrittenCapacityRequirement() {
  nlohmann::json j = testing::OneTubeChain();
  nlohmann::json& shaft = j["components"][1]["parameters"];
  shaft["outer_diameter"].erase("design");
  shaft["wall_thickness"].erase("design");
  shaft["shear_modulus"] = {{"value", 44}, {"min", 43}, {"max", 51}, {"unit", "GPa"}};
  shaft["allowable_shear_stress"] = {{"value", 550}, {"min", 500}, {"max", 600}, {"unit", "MPa"}};
  j["requirements"] = nlohmann::json::array(
      {{{"id", "capacity"},
        {"description", "1.5 x 400 N*m below the ultimate torque"},
        {"expression", "1.5 * 400 N*m <= shaft_1.allowable_shear_stress * 0.19634954 * (shaft_1.outer_diameter^4 - "
                       "(shaft_1.outer_diameter - 2 * shaft_1.wall_thickness)^4) / shaft_1.outer_diameter"}}});
  return ParseProject(j.dump(), "one_tube.json");
}

// The requirement reads the tube's polar moment (D^4 - d^4 = 32/pi Ip exactly), so a load the tube
// must carry bounds its stiffness from below: Ip >= 1.5 T D / (tau_allow 0.19634954 32/pi) at the
// least D and the largest tau_allow, c = G Ip / L at the least G. Projected onto D and t one at a
// time the requirement cuts neither (the thinnest wall at the largest D and the smallest D with
// the thickest wall both carry the load), and c kept its value at their thinnest corner, 3.4
// times lower.
TEST(DriveSystem, AWrittenCapacityRequirementBoundsTheTubeStiffnessFromBelow) {
  const CheckResult r = CheckDriveSystem(BuildDriveSystemNetwork(OneTubeUnderAWrittenCapacityRequirement()));
  ASSERT_TRUE(r.feasible) << r.report.BriefReport();
  const double D = 0.020, t = 0.0005, L = 2.0, G = 43e9, tau = 600e6, T = 1.5 * 400.0;
  EXPECT_NEAR(Final(r, "shaft_1.outer_diameter").lower(), 1e3 * D, 1e-12);  // mm: not cut
  EXPECT_NEAR(Final(r, "shaft_1.wall_thickness").lower(), 1e3 * t, 1e-12);
  const double ip = T * D / (tau * 0.19634954 * 32 / M_PI);
  const Interval c = Final(r, "shaft_1.c");
  EXPECT_NEAR(c.lower(), G * ip / L, 1e-9 * G * ip / L);
  EXPECT_LE(c.lower(), G * ip / L);  // an enclosure: never above the analytic bound
  const double corner = G * M_PI / 32 * (std::pow(D, 4) - std::pow(D - 2 * t, 4)) / L;
  EXPECT_GT(c.lower(), 3 * corner);
  // The polar moment itself and the inertia J = rho Ip L follow.
  EXPECT_NEAR(Final(r, "shaft_1.polar_moment").lower(), ip, 1e-9 * ip);
  EXPECT_NEAR(Final(r, "shaft_1.J").lower(), 4420.0 * ip * L, 1e-9 * 4420.0 * ip * L);
}

TEST(CheckCommand, FeasibleProjectExitsZero) {
  const auto r = testing::RunCli({"check", "examples/a380_class_flaps.json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // Answer first: which statement concerns the domains, which the nominal design.
  EXPECT_EQ(r.out.rfind("feasible: the nominal design meets all 32 requirements of the project\n", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("Parameter domains: all "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Nominal design (every parameter at its nominal value): meets all 32 requirements."),
            std::string::npos)
      << r.out;
  // The parameter table with --all.
  const auto all = testing::RunCli({"check", "examples/a380_class_flaps.json", "--all"});
  EXPECT_EQ(all.exit_code, 0) << all.err;
  EXPECT_NE(all.out.find("shaft_l0a.c"), std::string::npos);
  EXPECT_NE(all.out.find("narrowed %"), std::string::npos);
}

TEST(CheckCommand, InfeasibleProjectExitsOneWithExplanation) {
  const auto r = testing::RunCli({"check", "examples/a380_class_flaps_infeasible.json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.out.rfind("infeasible: no values within the parameter domains meet extension_time and jam_l1_fitting "
                        "together\n", 0),
            0u)
      << r.out;
  EXPECT_NE(r.out.find("These requirements cannot be met together"), std::string::npos) << r.out;
}

TEST(CheckCommand, JsonHasTheSameContent) {
  const auto r = testing::RunCli({"check", "examples/a380_class_flaps_infeasible.json", "--json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["status"], "infeasible");
  EXPECT_EQ(doc["all_requirements_met"], false);
  EXPECT_EQ(doc["violated_requirements"], nlohmann::json({"extension_time", "jam_l1_fitting"}));
  EXPECT_GT(doc["parameters"].size(), 100u);
  EXPECT_TRUE(doc["parameters"][0].contains("provenance"));
}

TEST(CheckCommand, StoppedAtALimitIsNeitherMetNorViolated) {
  // The infeasible variant, cut off after 50 revisions: no conflict is proved yet, and check must
  // not claim either outcome.
  const auto text = testing::RunCli({"check", "examples/a380_class_flaps_infeasible.json", "--max-revisions", "50"});
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("stopped at a limit after 50 revisions"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("no requirement was proved violated, but the domains may narrow further"), std::string::npos)
      << text.out;
  EXPECT_EQ(text.out.find("all requirements can be met"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("infeasible"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.rfind("undecided: ", 0), 0u) << text.out;
  EXPECT_NE(text.err.find("warning: propagation stopped at a limit"), std::string::npos) << text.err;
  const auto json = testing::RunCli({"check", "examples/a380_class_flaps_infeasible.json", "--max-revisions", "50", "--json"});
  EXPECT_EQ(json.exit_code, 0) << json.err;
  const auto doc = nlohmann::json::parse(json.out);
  EXPECT_EQ(doc["status"], "stopped_at_limit");
  EXPECT_TRUE(doc["all_requirements_met"].is_null());
  EXPECT_FALSE(doc.contains("violated_requirements"));
}

TEST(CheckCommand, UsesEstimatedDomainsWhereTheProjectGivesNone) {
  // Shaft stiffness is not given in the example: the estimator derives it from the tube
  // geometry and material (provenance "estimated"); --no-estimate leaves the catalogue default.
  const auto r = testing::RunCli({"check", "examples/a380_class_flaps.json", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_NE(doc["estimation"].get<std::string>().find("0 conflicts"), std::string::npos) << doc["estimation"];
  std::string provenance;
  for (const auto& p : doc["parameters"])
    if (p["name"] == "shaft_l1.stiffness") provenance = p["provenance"];
  EXPECT_EQ(provenance, "estimated");

  const auto raw = testing::RunCli({"check", "examples/a380_class_flaps.json", "--json", "--no-estimate"});
  ASSERT_EQ(raw.exit_code, 0) << raw.err;
  const auto raw_doc = nlohmann::json::parse(raw.out);
  EXPECT_EQ(raw_doc["estimation"], "");
  for (const auto& p : raw_doc["parameters"]) {
    if (p["name"] == "shaft_l1.stiffness") {
      EXPECT_NE(p["provenance"], "estimated");
    }
  }
}

TEST(TradeoffCommand, SlicesTheSpeedDomain) {
  // The speed's display unit is rpm: 190-310 rpm spans the design domain of 20-32 rad/s.
  const auto r = testing::RunCli({"tradeoff", "examples/a380_class_flaps_infeasible.json", "--vary",
                                  "pdu.max_output_speed=190:310:4", "--show", "travel_time.extension,peak.jam_l1.torque",
                                  "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["rows"].size(), 4u);
  // Every slice conflicts (too slow for 32 s, or too hard a jam above about 25 rad/s); the
  // project itself says so. None is outside the domain.
  for (const auto& row : doc["rows"]) {
    EXPECT_FALSE(row["feasible"].get<bool>()) << row.dump();
    EXPECT_FALSE(row["outside_domain"].get<bool>()) << row.dump();
    EXPECT_EQ(row["status"], "infeasible") << row.dump();
  }
  // The slices are in rpm, the display unit: the first is 190-220 rpm = 19.9-23.0 rad/s.
  EXPECT_NEAR(doc["rows"][0]["slice"][1].get<double>(), 220.0, 1e-9);
  // The base project fixes the speed at 242 rpm: slices away from it are outside its domain, which
  // is not the same as a design that fails.
  const auto outside = testing::RunCli({"tradeoff", "examples/a380_class_flaps.json", "--vary",
                                        "pdu.max_output_speed=100:200:2", "--show", "travel_time.extension"});
  EXPECT_EQ(outside.exit_code, 0) << outside.err;
  EXPECT_NE(outside.out.find("outside the domain"), std::string::npos) << outside.out;
  const auto ok = testing::RunCli({"tradeoff", "examples/a380_class_flaps.json", "--vary",
                                   "gra_l1.ratio=150:250:2", "--show", "travel_time.extension"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("travel_time.extension [s]"), std::string::npos) << ok.out;
}

TEST(TradeoffCommand, UnknownNameIsInvalidInputWithSuggestion) {
  const auto r = testing::RunCli({"tradeoff", "examples/a380_class_flaps.json", "--vary", "pdu.max_output_sped=1:2:2",
                                  "--show", "travel_time.extension"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown quantity 'pdu.max_output_sped'; did you mean 'pdu.max_output_speed'?"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace highlift::icsp
