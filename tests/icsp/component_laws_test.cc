// Every component law written once serves the propagator: each type's lumped law and
// steady-state law instantiated with the symbolic scalar (model::Sym), rendered as constraint
// text and propagated over point domains, encloses the same law evaluated in double.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>
#include <string>

#include "highlift/icsp/parser.h"
#include "highlift/icsp/propagator.h"
#include "highlift/model/component_model.h"

namespace highlift::icsp {
namespace {

using model::Sym;

/// A value in [0.5, 1.5) per parameter name (fixed, differs between names).
double ValueOf(std::string_view name) { return 0.5 + static_cast<double>(std::hash<std::string_view>{}(name) % 1000) / 1000.0; }

/// Every parameter has a value except those in `absent`; counts are 2.
template <class T>
class Reader : public model::ParameterReader<T> {
 public:
  explicit Reader(std::set<std::string> absent) : absent_(std::move(absent)) {}
  bool Has(std::string_view name) const override { return !absent_.count(std::string(name)); }
  double Nominal(std::string_view) const override { return 2.0; }

 protected:
  std::set<std::string> absent_;
};
class DoubleReader final : public Reader<double> {
 public:
  using Reader::Reader;
  double operator()(std::string_view name) const override { return ValueOf(name); }
};
/// The parameters as variables "p.<name>" of a network, each with its point domain.
class SymReader final : public Reader<Sym> {
 public:
  SymReader(std::set<std::string> absent, Network& net) : Reader(std::move(absent)), net_(net) {}
  Sym operator()(std::string_view name) const override {
    const std::string var = "p." + std::string(name);
    if (net_.FindVariable(var).value < 0) net_.AddVariable(var, Interval(ValueOf(name), ValueOf(name)));
    return Sym::Variable(var, model::Sign::Positive());
  }

 private:
  Network& net_;
};

/// The box of `y` after propagating y == law over the point domains.
Interval Propagated(Network& net, const Sym& law) {
  const std::string y = "y" + std::to_string(net.num_variables());
  net.AddVariable(y, Whole());
  AddConstraintText(net, y + " == " + law.Text(), {y, "law", ConstraintRole::kPhysics});
  Box box = net.InitialBox();
  const PropagationReport report = Propagate(net, box);
  EXPECT_EQ(report.status, Status::kFixedPoint);
  return box[net.FindVariable(y).value];
}

void ExpectEncloses(const Interval& box, double value, const std::string& what) {
  EXPECT_LE(box.lower(), value) << what;
  EXPECT_GE(box.upper(), value) << what;
  EXPECT_LE(box.upper() - box.lower(), 1e-12 * std::fabs(value) + 1e-300) << what << " is not tight";
}

void CheckLaws(const model::ComponentModel& m, const std::set<std::string>& absent) {
  const std::string type(m.type());
  Network net;
  const SymReader sym(absent, net);
  const DoubleReader num(absent);
  const model::Lumped<double> lumped = m.LumpedAtInput(num);
  const model::Lumped<Sym> symbolic = m.LumpedAtInput(sym);
  ExpectEncloses(Propagated(net, symbolic.J), lumped.J, type + " J");
  ASSERT_EQ(lumped.c.has_value(), symbolic.c.has_value()) << type;
  if (lumped.c) ExpectEncloses(Propagated(net, *symbolic.c), *lumped.c, type + " c");
  // The steady-state law opposing and aiding, with friction: through and branch torques of both
  // signs (outboard variables with point domains), the actuator load, the speed.
  for (double sign : {1.0, -1.0}) {
    const double through = 3.0 * sign, branch = 2.0 * sign, load = 40.0 * sign, w = 5.0;
    const model::SteadyFlow<double> in{through, branch, load, w, 1.0};
    const std::string t = "t" + std::to_string(net.num_variables()), b = "b" + std::to_string(net.num_variables());
    net.AddVariable(t, Interval(through, through));
    net.AddVariable(b, Interval(branch, branch));
    const model::Sign s = sign > 0 ? model::Sign::Positive() : model::Sign::Negative();
    const model::SteadyFlow<Sym> sym_in{Sym::Variable(t, s), Sym::Variable(b, s), Sym(load), Sym(w), Sym(1.0)};
    ExpectEncloses(Propagated(net, m.InputTorque(sym, sym_in)), m.InputTorque(num, in),
                   type + " input torque, sign " + std::to_string(sign));
  }
}

TEST(ComponentLaws, EveryTypeServesThePropagatorTheLawItServesDouble) {
  for (const model::ComponentModel* m : model::ComponentModels()) CheckLaws(*m, std::set<std::string>{});
}

TEST(ComponentLaws, TheTubeLawsServeThePropagatorWhenNoStiffnessOrInertiaIsGiven) {
  for (const model::ComponentModel* m : model::ComponentModels()) {
    if (!m->roles().segment) continue;
    CheckLaws(*m, {"stiffness", "inertia"});
    CheckLaws(*m, {"stiffness", "inertia", "linear_density"});
  }
}

TEST(ComponentLaws, ATorqueOfEitherSignIsSplitAndStillEnclosed) {
  for (const model::ComponentModel* m : model::ComponentModels()) {
    Network net;
    const SymReader sym(std::set<std::string>{}, net);
    const DoubleReader num(std::set<std::string>{});
    net.AddVariable("t", Interval(-3.0, -3.0));
    const model::SteadyFlow<Sym> sym_in{Sym::Variable("t", model::Sign::Either()), Sym(0.0), Sym(0.0), Sym(1.0), Sym(0.0)};
    const model::SteadyFlow<double> in{-3.0, 0.0, 0.0, 1.0, 0.0};
    ExpectEncloses(Propagated(net, m->InputTorque(sym, sym_in)), m->InputTorque(num, in), std::string(m->type()));
  }
}

}  // namespace
}  // namespace highlift::icsp
