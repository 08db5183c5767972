// Drive-system projects to simulation models, and the scenarios (sim/src/drive_network.cc):
// the structure of the full and reduced models, the errors, and the qualitative results the
// issue names for the scenarios of examples/a380_class_flaps.json, with the energy balance.
#include "highlift/sim/drive_network.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <cmath>
#include <map>

#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/sim/simulator.h"

namespace highlift::sim {
namespace {

constexpr double kEnergyTolerance = 2e-3;  // |residual| / scale of the energy balance

const Project& Example() {
  static const Project project = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps.json");
  return project;
}

bool Has(const Network& net, const std::string& id, const std::string& type) {
  const NetworkElement* e = net.Find(id);
  return e != nullptr && e->type == type;
}

template <class F>
void ExpectThrowsWith(F f, const std::string& text) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one containing: " << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

struct Run {
  DriveModel model;
  MemorySink sink;
  SimulationReport report;
  double At(const std::string& column, double t) const {
    const int c = sink.Column(column);
    EXPECT_GE(c, 0) << "no column " << column;
    if (c < 0) return NAN;
    const auto& times = sink.times();
    const auto it = std::lower_bound(times.begin(), times.end(), t);
    const std::size_t i = std::min<std::size_t>(it - times.begin(), times.size() - 1);
    return sink.rows()[i][c];
  }
  double MaxAbs(const std::string& column, double from = -1) const {
    const int c = sink.Column(column);
    EXPECT_GE(c, 0) << "no column " << column;
    double m = 0;
    for (std::size_t i = 0; c >= 0 && i < sink.times().size(); ++i)
      if (sink.times()[i] >= from) m = std::max(m, std::abs(sink.rows()[i][c]));
    return m;
  }
};

std::unique_ptr<Run> Simulate(const Project& project, const Scenario& scenario, DriveResolution resolution,
                              double stop_time, double output_interval = 2e-3) {
  auto run = std::make_unique<Run>();
  DriveNetworkOptions options;
  options.resolution = resolution;
  run->model = BuildDriveNetwork(project, &scenario, options);
  Simulator simulator(run->model.network);
  SimulationOptions o = run->model.Options(project);
  o.stop_time = stop_time;
  o.output_interval = output_interval;
  o.energy = true;
  DerivedColumnSink sink(run->model.derived, run->sink);
  run->report = simulator.Run(o, sink);
  EXPECT_TRUE(run->report.ok()) << run->report.FullReport();
  return run;
}

void ExpectEnergyBalance(const SimulationReport& report) {
  ASSERT_TRUE(report.energy.computed);
  const double scale = report.energy.Scale();
  EXPECT_GT(scale, 0);
  EXPECT_LT(std::abs(report.energy.Residual()), kEnergyTolerance * scale)
      << "source " << report.energy.source_work << " J, dissipated " << report.energy.dissipated << " J, kinetic "
      << report.energy.kinetic_start << " -> " << report.energy.kinetic_end << " J, potential "
      << report.energy.potential_start << " -> " << report.energy.potential_end << " J, impulsive "
      << report.energy.impulsive_loss << " J";
}

TEST(DriveNetworkOptions, DefaultsAreValidAndResolutionsRoundTrip) {
  DriveNetworkOptions options;
  EXPECT_NO_THROW(options.Validate());
  EXPECT_EQ(options.resolution, DriveResolution::kFull);
  for (auto r : {DriveResolution::kFull, DriveResolution::kReduced}) EXPECT_EQ(ParseDriveResolution(ToString(r)), r);
  ExpectThrowsWith([] { ParseDriveResolution("fine"); }, "model 'fine' is not a model resolution; choose 'full'");
  options.shaft_elements = -1;
  ExpectThrowsWith([&] { options.Validate(); }, "option shaft_elements = -1 must be 0");
}

TEST(DriveNetwork, FullModelNamesElementsAfterTheComponents) {
  const DriveModel model = BuildDriveNetwork(Example(), {.scenario = "extension"});
  const Network& net = model.network;
  EXPECT_EQ(model.shaft_elements, 4);  // the project's setting, at least 4
  EXPECT_EQ(model.load_case, "extend_opposing");
  EXPECT_DOUBLE_EQ(model.stop_time, 40.0);
  EXPECT_TRUE(Has(net, "pdu", "PDU"));
  EXPECT_TRUE(Has(net, "stl_left", "TorqueLimiter"));
  EXPECT_TRUE(Has(net, "stl_l3", "TorqueLimiter"));
  EXPECT_TRUE(Has(net, "tgb_l3", "BranchGearbox"));
  EXPECT_TRUE(Has(net, "gra_l3", "GearedRotaryActuator"));
  EXPECT_TRUE(Has(net, "wtb_left", "WingTipBrake"));
  EXPECT_TRUE(Has(net, "brg_l3", "LossyInertia"));
  EXPECT_TRUE(Has(net, "monitor", "Monitoring"));
  for (int i = 1; i <= 4; ++i) EXPECT_TRUE(Has(net, "shaft_l3a.e" + std::to_string(i), "SpringDamper"));
  EXPECT_EQ(net.Find("shaft_l3a.e5"), nullptr);
  EXPECT_TRUE(Has(net, "shaft_l3a.m0", "LossyInertia"));  // drag_per_length > 0, at the ends
  EXPECT_TRUE(Has(net, "shaft_l3a.m2", "Inertia"));
  EXPECT_TRUE(Has(net, "gra_l3.airload", "Torque"));
  EXPECT_TRUE(Has(net, "gra_l3.airload_table", "CombiTable1Ds"));
  // Airload against the output angle: 5 kN*m at 0, 20 kN*m at the travel of 2.2 rad, opposing.
  const auto& table = net.Find("gra_l3.airload_table")->parameters.tables.at("table");
  EXPECT_DOUBLE_EQ(table.front()[1], -5000);
  EXPECT_DOUBLE_EQ(table.back()[0], 2.2);
  EXPECT_DOUBLE_EQ(table.back()[1], -20000);
  // The shaft torque column is derived from the spring-damper at port a.
  bool derived = false;
  for (const auto& d : model.derived)
    if (d.name == "shaft_l3a.tau") derived = d.source == "shaft_l3a.e1.tau" && d.factor == -1.0;
  EXPECT_TRUE(derived);
  EXPECT_EQ(model.component_of.at("shaft_l3a.e2"), "shaft_l3a");
}

TEST(DriveNetwork, ElementsOptionSplitsEveryShaft) {
  const DriveModel model = BuildDriveNetwork(Example(), {.shaft_elements = 7, .scenario = "extension"});
  EXPECT_TRUE(Has(model.network, "shaft_l1.e7", "SpringDamper"));
  EXPECT_EQ(model.network.Find("shaft_l1.e8"), nullptr);
}

TEST(DriveNetwork, ScenarioPartsRuptureAndJam) {
  const DriveModel rupture = BuildDriveNetwork(Example(), {.scenario = "rupture_wtb"});
  EXPECT_TRUE(Has(rupture.network, "shaft_l1.e2", "Disconnector"));  // mid-span of shaft_l1
  EXPECT_DOUBLE_EQ(rupture.network.Find("shaft_l1.e2")->parameters.scalars.at("t_disconnect"), 1.0);
  const DriveModel jam = BuildDriveNetwork(Example(), {.scenario = "jam_l3"});
  ASSERT_TRUE(Has(jam.network, "gra_l3.jam", "Jam"));
  EXPECT_DOUBLE_EQ(jam.network.Find("gra_l3.jam")->parameters.scalars.at("t_jam"), 1.0);
  EXPECT_DOUBLE_EQ(jam.network.Find("gra_l3.jam")->parameters.scalars.at("c"), 1e5 * 200 * 200);
  EXPECT_EQ(jam.network.Find("gra_l1.jam"), nullptr);
}

// Regression (issue 26, item 3): the A320-class slats give each actuator's load_inertia only as
// an interval, [1e-4, 2e-3] kg*m^2. The reduced models (peak) count such a parameter at the
// middle of its domain; the drive model dropped it (J_load = 0), so a jammed slat actuator
// stopped its input inertia alone on the jam's damper and reported 1017 N*m at its input against
// 290-442 N*m of peak. Both now read the same value.
TEST(DriveNetwork, AnActuatorLoadInertiaGivenAsAnIntervalCountsAtItsMiddleAsInThePeakAnalysis) {
  const Project slats = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a320_class_slats.json");
  const Parameter& given = slats.FindComponent("gra_l1")->parameters.at("load_inertia");
  ASSERT_FALSE(given.nominal.has_value());
  ASSERT_DOUBLE_EQ(given.domain.lo, 1e-4);
  ASSERT_DOUBLE_EQ(given.domain.hi, 2e-3);
  for (const char* scenario : {"extension", "jam_l1"}) {
    const DriveModel m = BuildDriveNetwork(slats, {.scenario = scenario});
    const NetworkElement* gra = m.network.Find("gra_l1");
    ASSERT_NE(gra, nullptr);
    EXPECT_DOUBLE_EQ(gra->parameters.scalars.at("J_load"), 0.5 * (1e-4 + 2e-3)) << scenario;
  }
  // A catalogue default domain is no value: the A380-class actuators give their own.
  const DriveModel a380 = BuildDriveNetwork(Example(), {.scenario = "extension"});
  EXPECT_DOUBLE_EQ(a380.network.Find("gra_l1")->parameters.scalars.at("J_load"), 0.0388);
}

TEST(DriveNetwork, ReducedModelLumpsChainsBetweenGearboxes) {
  const DriveModel full = BuildDriveNetwork(Example(), {.scenario = "extension"});
  const DriveModel reduced =
      BuildDriveNetwork(Example(), {.resolution = DriveResolution::kReduced, .scenario = "extension"});
  EXPECT_LT(reduced.network.elements().size(), full.network.elements().size() / 2);
  // ujoint_left - shaft_l0a - brg_l0 - shaft_l0b is one chain.
  EXPECT_TRUE(Has(reduced.network, "ujoint_left-shaft_l0b.spring", "SpringDamper"));
  EXPECT_EQ(reduced.network.Find("shaft_l0a.e1"), nullptr);
  bool note = false;
  for (const auto& n : reduced.notes) note = note || n == "ujoint_left-shaft_l0b: ujoint_left, shaft_l0a, brg_l0, shaft_l0b";
  EXPECT_TRUE(note);
  int shaft_columns = 0;
  for (const auto& d : reduced.derived)
    if (d.source == "ujoint_left-shaft_l0b.spring.tau") ++shaft_columns;
  EXPECT_EQ(shaft_columns, 2);  // shaft_l0a.tau and shaft_l0b.tau
}

TEST(DriveNetwork, ErrorsNameTheThingAndTheRemedy) {
  ExpectThrowsWith([] { BuildDriveNetwork(Example(), {.scenario = "rupture_wtbx"}); },
                   "scenario 'rupture_wtbx' is not in the project; did you mean 'rupture_wtb'?");
  Scenario jam = SizingScenario(Example(), "jam", "gra_l2");
  EXPECT_EQ(jam.name, "jam_l2");  // the project's own scenario
  jam.jam_component = "shaft_l1";
  ExpectThrowsWith([&] { BuildDriveNetwork(Example(), &jam, {}); },
                   "scenario 'jam_l2': jam component 'shaft_l1' must be a jam element or an actuator");
  Scenario bad_case = jam;
  bad_case.jam_component = "gra_l2";
  bad_case.load_case = "extend_opposin";
  ExpectThrowsWith([&] { BuildDriveNetwork(Example(), &bad_case, {}); },
                   "scenario 'jam_l2': unknown load case 'extend_opposin'; did you mean 'extend_opposing'?");
  Project p = Example();
  p.FindComponent("shaft_l2a")->parameters.at("length").nominal.reset();
  ExpectThrowsWith([&] { BuildDriveNetwork(p, {.scenario = "extension"}); },
                   "component 'shaft_l2a' (torque_shaft): parameter 'length' has no value for the drive model (simulate, export)");
}

TEST(DriveNetwork, SizingScenarioMadeUpForARupture) {
  const Scenario s = SizingScenario(Example(), "rupture", "shaft_l3a");
  EXPECT_EQ(s.name, "rupture_shaft_l3a");
  EXPECT_EQ(s.load_case, "retract_aiding");  // the airload aids the motion: the worst case
  // The project's rupture_wtb extends against the opposing load: not the sizing condition.
  EXPECT_EQ(SizingScenario(Example(), "rupture", "shaft_l1").name, "rupture_shaft_l1");
  ASSERT_TRUE(s.rupture_time.has_value());
  EXPECT_DOUBLE_EQ(*s.rupture_time, 1.0);
  EXPECT_EQ(s.wtb_trigger, "monitor");
}

// The scenarios of examples/a380_class_flaps.json at full resolution (4 spring-dampers per
// shaft, 443 states), as the issue describes them.

// Extension, the whole 40 s cycle: the drive runs up to the commanded speed, the speed along the
// transmission (referred to the PDU) varies only slightly, the STL input torque rises with the
// airloads, the flaps travel their full angle, nothing locks out or brakes, and at the end the
// pressure-off brakes hold the stopped drive.
TEST(DriveScenarios, ExtensionSpeedsAlongTheTransmissionAndRisingSystemLimiterTorque) {
  const Scenario& scenario = *Example().FindScenario("extension");
  const auto run = Simulate(Example(), scenario, DriveResolution::kFull, scenario.stop_time, 0.01);
  // PI speed loop: within the lag of a ramped load (about 0.1 rad/s) of the 25.3 rad/s command.
  const double w_pdu = run->At("pdu.w", 20.0);
  EXPECT_NEAR(w_pdu, 25.3, 0.25);
  for (double t : {5.0, 20.0, 30.0})
    for (const std::string column : {"appu_left.w", "appu_right.w", "fppu.w", "shaft_l4a.m2.w", "shaft_r6.m2.w"})
      EXPECT_NEAR(run->At(column, t), run->At("pdu.w", t), 0.01 * w_pdu) << column << " at " << t << " s";
  // Station speeds through the 2:1 station gearbox and the 200:1 actuator.
  EXPECT_NEAR(run->At("gra_l3.w", 20.0), w_pdu / 2, 0.01 * w_pdu);
  const double early = std::abs(run->At("stl_left.tau", 2.0)), late = std::abs(run->At("stl_left.tau", 33.0));
  EXPECT_GT(early, 50.0);
  EXPECT_GT(late, 2.5 * early) << "STL torque " << early << " -> " << late << " N*m";
  EXPECT_LT(late, 470.0) << "below the STL lock-out torque";
  EXPECT_LT(run->MaxAbs("stl_left.y"), 1e-9);  // no lock-out in normal operation
  EXPECT_LT(run->MaxAbs("monitor.wtb"), 0.5);   // no fault
  // Full travel: 140 shaft revolutions, 2.2 rad at each actuator output.
  EXPECT_NEAR(run->At("gra_l1.output_angle.phi", scenario.stop_time), 2.2, 0.05 * 2.2);
  EXPECT_NEAR(run->At("gra_r6.output_angle.phi", scenario.stop_time), 2.2, 0.05 * 2.2);
  EXPECT_GT(run->At("pdu.brake", scenario.stop_time), 0.5);
  EXPECT_LT(std::abs(run->At("pdu.w", scenario.stop_time)), 1e-6);
  ExpectEnergyBalance(run->report);
}

// Rupture of shaft_l1 (between the root gearbox and station l1) at 1 s while extending against
// the opposing loads: the outboard part is back-driven by the aiding airloads, the monitor
// detects it, the wing-tip brakes stop it and the PDU shuts down; the largest shaft torque of the
// event outboard of the rupture occurs at the WTB (the paper's result).
TEST(DriveScenarios, RuptureMonitorAppliesTheWingTipBrakeWhichTakesTheLargestTorque) {
  const Scenario& scenario = *Example().FindScenario("rupture_wtb");
  const auto run = Simulate(Example(), scenario, DriveResolution::kFull, scenario.stop_time);
  EXPECT_LT(run->At("monitor.wtb", 0.99), 0.5);
  EXPECT_GT(run->At("monitor.wtb", 1.2), 0.5);
  EXPECT_GT(run->At("appu_left.w", 0.99), 20.0);   // extending before the rupture
  EXPECT_LT(run->At("appu_left.w", 1.12), -20.0);  // back-driven after it
  EXPECT_LT(std::abs(run->At("appu_left.w", scenario.stop_time)), 1e-3);  // held by the WTB
  EXPECT_GT(run->At("pdu.brake", scenario.stop_time), 0.5);              // shut down
  const double wtb = run->MaxAbs("wtb_left.tau", 1.0);
  EXPECT_GT(wtb, 200.0);
  for (const std::string shaft : {"shaft_l2a", "shaft_l2b", "shaft_l3a", "shaft_l3b", "shaft_l4a", "shaft_l4b",
                                  "shaft_l5a", "shaft_l5b", "shaft_l6"})
    EXPECT_GT(wtb, run->MaxAbs(shaft + ".tau", 1.0)) << shaft;
  // The healthy side is stopped by its brakes without being driven into them.
  EXPECT_LT(run->MaxAbs("stl_right.tau", 1.0), 470.0);
  ExpectEnergyBalance(run->report);
}

// Jam of the actuator at station l3 at 1 s at full speed: the station limiter locks out (its
// balls reach the end stop and its brake grounds the drive); the peak torques are reported per
// component, and the shaft ahead of the station carries more than in normal operation.
TEST(DriveScenarios, JamLocksOutTheStationLimiterAndReportsPeaks) {
  const Scenario& scenario = *Example().FindScenario("jam_l3");
  const auto run = Simulate(Example(), scenario, DriveResolution::kFull, scenario.stop_time);
  EXPECT_LT(run->At("stl_l3.y", 0.99), 1e-9);
  EXPECT_GT(run->MaxAbs("stl_l3.y", 1.0), 0.99);  // locked out
  const auto peaks = ComponentPeakTorques(run->model, Example(), run->report);
  const auto find = [&](const std::string& id) {
    for (const auto& p : peaks)
      if (p.element == id) return std::abs(p.tau);
    return -1.0;
  };
  EXPECT_GT(find("stl_l3"), 180.0);  // beyond its lock-out torque
  EXPECT_GT(find("shaft_l3a"), 1.5 * std::abs(run->At("shaft_l3a.tau", 0.99)));
  ExpectEnergyBalance(run->report);
}

// The Newton systems with the node angles and spring twists eliminated before KLU factors the
// rest (the default) against the whole systems factored: the same jam, the same peaks within
// the tolerance's noise, and no setup that had to fall back to the whole matrix.
TEST(DriveScenarios, EliminatingAnglesAndTwistsFromTheNewtonSystemsKeepsThePeaks) {
  const Scenario& scenario = *Example().FindScenario("jam_l3");
  std::vector<SimulationReport> reports;
  for (const char* solver : {"sparse", "sparse_whole"}) {
    DriveNetworkOptions options;
    options.resolution = DriveResolution::kFull;
    const DriveModel model = BuildDriveNetwork(Example(), &scenario, options);
    Simulator simulator(model.network);
    SimulationOptions o = model.Options(Example());
    o.linear_solver = solver;
    o.relative_tolerance = 1e-8;
    DiscardSink sink;
    reports.push_back(simulator.Run(o, sink));
    ASSERT_TRUE(reports.back().ok()) << reports.back().FullReport();
  }
  const std::string& reduced = reports[0].statistics.linear_solver;
  EXPECT_NE(reduced.find("states eliminated"), std::string::npos) << reduced;
  EXPECT_EQ(reduced.find("factored whole"), std::string::npos) << reduced;
  EXPECT_EQ(reports[1].statistics.linear_solver.find("eliminated"), std::string::npos);
  ASSERT_EQ(reports[0].peak_torques.size(), reports[1].peak_torques.size());
  double largest = 0.0, worst = 0.0;
  for (const auto& p : reports[1].peak_torques) largest = std::max(largest, std::abs(p.tau));
  for (std::size_t i = 0; i < reports[0].peak_torques.size(); ++i) {
    // |tau|: where the largest excursions either way are equal within the noise, the sign of
    // the peak is either.
    const double a = std::abs(reports[0].peak_torques[i].tau), b = std::abs(reports[1].peak_torques[i].tau);
    worst = std::max(worst, std::abs(a - b) / largest);
    EXPECT_NEAR(a, b, 1e-6 * largest) << reports[0].peak_torques[i].element;
  }
  std::cout << "largest peak difference " << worst << " of " << largest << " N*m; steps "
            << reports[0].statistics.steps << " / " << reports[1].statistics.steps << "\n";
}

// The transmission is mirrored about the PDU: a rupture at the same place on the left and on the
// right wing gives the same peaks, whatever the stop time (which changes the integrator's step
// sequence). Regression: a brake that stuck with its torque at its capacity (a station limiter
// at the end stop) could miss the breakaway root and hold 840 N*m instead of slipping at 633.
TEST(DriveScenarios, MirroredRupturesGiveMirroredPeaksIndependentOfTheStepSequence) {
  auto peaks = [&](const std::string& shaft, double stop) {
    Scenario s = SizingScenario(Example(), "rupture", shaft);
    s.stop_time = stop;
    const auto run = Simulate(Example(), s, DriveResolution::kFull, stop);
    std::map<std::string, double> by_component;
    for (const auto& p : ComponentPeakTorques(run->model, Example(), run->report)) by_component[p.element] = std::abs(p.tau);
    return by_component;
  };
  const auto left = peaks("shaft_l5b", 2.0), right = peaks("shaft_r5b", 1.2);
  for (const auto& [l, r] : std::vector<std::pair<std::string, std::string>>{
           {"stl_l6", "stl_r6"}, {"wtb_left", "wtb_right"}, {"shaft_l7", "shaft_r7"}, {"shaft_l6", "shaft_r6"}}) {
    ASSERT_TRUE(left.count(l) && right.count(r)) << l;
    EXPECT_NEAR(left.at(l), right.at(r), 1e-3 * left.at(l)) << l << " / " << r;
  }
  // 700 N*m separated slipping (633) from sticking (840) while the example's station limiters had
  // a 180 N*m friction brake (the old 90 N*m catalogue default x 2 left under the 180 N*m trip);
  // with the catalogue's 2 x tau_1 = 360 N*m on the actuator input side (issue 20) the mirrored
  // runs agree at 883 N*m. The mirror equality above at two stop times is the step-sequence
  // check; this bound only catches a gross change.
  EXPECT_LT(left.at("stl_l6"), 1000.0);
}

// The reduced model (inertias lumped at gearboxes and stations) gives the same qualitative
// rupture result and peak torques close to the full model's.
TEST(DriveScenarios, ReducedModelAgreesWithTheFullModelOnTheRupture) {
  const Scenario& scenario = *Example().FindScenario("rupture_wtb");
  const auto full = Simulate(Example(), scenario, DriveResolution::kFull, scenario.stop_time);
  const auto reduced = Simulate(Example(), scenario, DriveResolution::kReduced, scenario.stop_time);
  const double a = full->MaxAbs("wtb_left.tau", 1.0), b = reduced->MaxAbs("wtb_left.tau", 1.0);
  EXPECT_NEAR(b, a, 0.1 * a) << "WTB peak full " << a << " N*m, reduced " << b << " N*m";
  ExpectEnergyBalance(reduced->report);
}

// Regression: since the A320-class slats' actuator load_inertia (given only as an interval)
// counts at the middle of its domain, ruptures of the reduced model at the nominal point chattered
// 48-55 ms after the rupture (CV_TOO_MUCH_WORK after 100 000 steps at one instant): a station
// limiter brake (stl_l1 in rupture_shaft_l4) stuck at its capacity within roundoff re-fired its
// capacity root every 1e-13 s, its break-away rejected each time. They run, passively.
TEST(DriveScenarios, SlatsRupturesWithTheLoadInertiaRunPassively) {
  static const Project slats = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a320_class_slats.json");
  for (const char* shaft : {"shaft_l4", "shaft_r3"}) {
    SCOPED_TRACE(shaft);
    const Scenario scenario = SizingScenario(slats, "rupture", shaft);
    ASSERT_TRUE(scenario.rupture_time.has_value());
    const auto run = Simulate(slats, scenario, DriveResolution::kReduced, *scenario.rupture_time + 0.2);
    EXPECT_TRUE(run->report.ok()) << run->report.BriefReport();
    EXPECT_TRUE(run->report.passivity.passive()) << run->report.passivity.BriefReport();
    EXPECT_LT(run->report.events.size(), 2000u);  // 284 and 250; 100 045 and 100 100 before the fix
    ExpectEnergyBalance(run->report);
  }
}

// A shaft rupture's station limiters engage their brakes where the brake's normal force leaves an
// exact zero (a root function flat on one side of its crossing). Regula falsi crept a tenth of the
// bracket per probe towards such a crossing (up to 98 evaluations of the model for one root; 9.8
// per located root in this run); the crossing is now extrapolated along the function's other side
// (6.0). The count is of evaluations, not time: deterministic, and the same on every machine.
TEST(DriveScenarios, AShaftRuptureLocatesItsRootsInFewEvaluations) {
  const Scenario scenario = SizingScenario(Example(), "rupture", "shaft_l4a");
  const auto run = Simulate(Example(), scenario, DriveResolution::kFull, scenario.stop_time);
  const SolverStatistics& s = run->report.statistics;
  const long located = s.reinitialisations + s.continuous_roots;
  ASSERT_GT(located, 50) << run->report.FullReport();
  // One evaluation per step for the root functions at its end; the rest locates the roots.
  const double per_root = static_cast<double>(s.root_evaluations - s.steps) / static_cast<double>(located);
  std::cout << "steps " << s.steps << ", root evaluations " << s.root_evaluations << ", roots " << located
            << ": " << per_root << " evaluations per located root beyond the steps' own\n";
  EXPECT_LT(per_root, 8.0) << "evaluations per located root";
  ExpectEnergyBalance(run->report);
}

}  // namespace
}  // namespace highlift::sim
