// The robust check's enclosure of the peak torque of a jam, w w1 J* (Options::dependency_splits):
// the first eigenfrequency w1 falls and J* rises with every inertia of the moving part, so plain
// interval evaluation takes w1 at the light corner and J* at the heavy one. Enclosed by partition
// instead, the check accepts a thinner shaft on the A320-class flaps, and that shaft still meets
// the jam requirement at sampled points of the uncertain parameters (the enclosure stays sound).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "highlift/core/project_io.h"
#include "highlift/estimation/estimator.h"
#include "highlift/icsp/drive_system.h"
#include "highlift/icsp/propagator.h"
#include "highlift/optimize/optimize.h"

namespace highlift::optimize {
namespace {

constexpr const char* kWall = "shaft_l1.wall_thickness";

/// The A320-class flaps (physics estimates only) with shaft_l1's wall a design variable from 0.4
/// to 2 times its value; everything else keeps its domain.
Project Flaps() {
  Project p = LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "a320_class_flaps.json");
  estimation::EstimateProject(p, nullptr);
  // The settings inside their rules (the example's own are not certain over the domains):
  // limiter lock-outs and tip-brake capacities at the middle of their domains, the station
  // limiters' brakes at 4 times the example's.
  for (Component& c : p.components) {
    auto middle = [&](const std::string& name) {
      const auto it = c.parameters.find(name);
      if (it == c.parameters.end() || !(it->second.domain.hi > it->second.domain.lo)) return;
      const double v = 0.5 * (it->second.domain.lo + it->second.domain.hi);
      it->second.nominal = v;
      it->second.domain = {v, v};
    };
    if (c.type == "station_torque_limiter" || c.type == "system_torque_limiter") middle("lockout_torque_extend");
    if (c.type == "wing_tip_brake") middle("static_capacity");
    if (c.type == "station_torque_limiter") {
      Parameter& b = c.parameters.at("max_brake_torque");
      b.nominal = 4.0 * *b.nominal;
      b.domain = {*b.nominal, *b.nominal};
    }
  }
  Parameter& t = p.FindComponent("shaft_l1")->parameters.at("wall_thickness");
  t.domain = {0.4 * *t.nominal, 2.0 * *t.nominal};
  t.design = true;
  return p;
}

/// The thinnest wall (on a grid of 0.5 % of the domain) that the robust check accepts.
double ThinnestAccepted(DesignEvaluator& e, std::string* failure_below) {
  const auto [lo, hi] = e.domains().front();
  double last = NAN;
  for (int i = 200; i >= 0; --i) {
    const double t = lo + (hi - lo) * i / 200.0;
    const PointCheck c = e.Check({t});
    if (!c.feasible) {
      if (failure_below) *failure_below = c.failure;
      break;
    }
    last = t;
  }
  return last;
}

TEST(RobustCheck, PartitionedJamTorqueAcceptsAThinnerShaftThatStillMeetsTheJamRequirement) {
  const Project p = Flaps();
  Options plain;
  plain.verify_size = false;
  plain.verify_peak = false;
  plain.dependency_splits = 0;
  Options sharp = plain;
  sharp.dependency_splits = Options{}.dependency_splits;
  ASSERT_GT(sharp.dependency_splits, 0);
  DesignEvaluator old_check(p, plain), new_check(p, sharp);
  ASSERT_EQ(new_check.variables(), std::vector<std::string>{kWall});
  std::string old_failure, new_failure;
  const double t_old = ThinnestAccepted(old_check, &old_failure);
  const double t_new = ThinnestAccepted(new_check, &new_failure);
  ASSERT_TRUE(std::isfinite(t_old) && std::isfinite(t_new)) << old_failure << "; " << new_failure;
  // The plain enclosure rejects the thinner walls at the jam requirement of that shaft.
  EXPECT_NE(old_failure.find("jam_l1_shaft"), std::string::npos) << old_failure;
  EXPECT_LT(t_new, 0.97 * t_old) << "plain " << t_old << " m, partitioned " << t_new << " m";
  EXPECT_FALSE(old_check.Check({t_new}).feasible);

  // Soundness: at the thinnest accepted wall, every sampled point of the uncertain parameters
  // (uniform in their domains) meets jam_l1_shaft when every quantity is computed at that point.
  Project design = FixDesign(p, {{kWall, t_new}});
  std::mt19937_64 rng(7);
  int checked = 0;
  for (int s = 0; s < 40; ++s) {
    Project point = design;
    for (Component& c : point.components)
      for (auto& [name, par] : c.parameters)
        if (std::isfinite(par.domain.lo) && std::isfinite(par.domain.hi) && par.domain.hi > par.domain.lo) {
          const double v = std::uniform_real_distribution<double>(par.domain.lo, par.domain.hi)(rng);
          par.nominal = v;
          par.domain = {v, v};
        }
    const icsp::DriveSystemNetwork dsn = icsp::BuildDriveSystemNetwork(point);
    const icsp::Network& net = dsn.network;
    std::vector<char> definitions(net.num_constraints(), 0), with_jam(net.num_constraints(), 0);
    for (int k = 0; k < net.num_constraints(); ++k) {
      const icsp::Constraint& con = net.constraint(icsp::ConstraintId{k});
      definitions[k] = with_jam[k] = con.info.role == icsp::ConstraintRole::kPhysics &&
                                     (con.kind == icsp::Constraint::Kind::kMonotone || con.relation == icsp::Relation::kEqual);
      const auto it = dsn.requirement_of.find(k);
      if (it != dsn.requirement_of.end() && it->second == "jam_l1_shaft") with_jam[k] = 1;
    }
    icsp::Box box = net.InitialBox();
    icsp::Propagator propagator(net);
    if (propagator.Propagate(box, definitions).status == icsp::Status::kInfeasible) continue;  // not a consistent point
    ++checked;
    icsp::Box again = net.InitialBox();
    EXPECT_NE(propagator.Propagate(again, with_jam).status, icsp::Status::kInfeasible)
        << "sample " << s << ": the accepted wall " << t_new << " m fails jam_l1_shaft there";
  }
  EXPECT_GE(checked, 20);
}

}  // namespace
}  // namespace highlift::optimize
