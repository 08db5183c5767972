// The propagator's witness property: for random constraint networks built around a known
// solution point x*, propagation never removes x* from the box (and so never reports the
// network infeasible). 10^5 networks with every operator of the expression language,
// equations and inequalities, shared subexpressions, and every schedule.
// HIGHLIFT_WITNESS_SEED=<n> reruns with another seed; a failure prints the seed, the network
// index and the constraint texts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "highlift/icsp/network.h"
#include "highlift/icsp/propagator.h"

namespace highlift::icsp {
namespace {

/// A random expression over the variables with its value at x* (round to nearest) and a bound
/// on the round-off of that value (the sum of the magnitudes met on the way, times a margin).
struct Built {
  ExprId id;
  double value = 0.0;
  double magnitude = 0.0;
};

class RandomNetwork {
 public:
  explicit RandomNetwork(std::uint64_t seed) : random_(seed) {}

  double Uniform(double lo, double hi) { return lo + (hi - lo) * (static_cast<double>(random_() >> 11) * 0x1.0p-53); }
  int Pick(int n) { return static_cast<int>(random_() % static_cast<std::uint64_t>(n)); }

  /// Builds the network; false when a drawn expression was undefined or ill-conditioned at x*
  /// (the caller draws another network).
  bool Build(Network* net, std::vector<double>* witness) {
    const int n = 2 + Pick(6);
    x_.clear();
    vars_.clear();
    for (int i = 0; i < n; ++i) {
      const double x = Pick(4) == 0 ? Uniform(0.1, 5.0) : Uniform(-10.0, 10.0);
      x_.push_back(x);
      double lo = x - Uniform(0.0, 20.0) * (Pick(3) == 0 ? 0.0 : 1.0);
      double hi = x + Uniform(0.0, 20.0) * (Pick(3) == 0 ? 0.0 : 1.0);
      if (Pick(8) == 0) lo = -std::numeric_limits<double>::infinity();
      if (Pick(8) == 0) hi = std::numeric_limits<double>::infinity();
      vars_.push_back(net->AddVariable("x" + std::to_string(i), Interval(lo, hi)));
    }
    const int m = 1 + Pick(7);
    for (int c = 0; c < m; ++c) {
      const Built g = Expr(*net, 1 + Pick(3));
      if (!std::isfinite(g.value) || !std::isfinite(g.magnitude) || g.magnitude > 1e12) return false;
      // g(x*) is v up to round-off: |g(x*) - v| <= eps. The constraint holds at x* exactly.
      const double eps = 1e-9 * (1.0 + g.magnitude);
      ConstraintInfo info{"c" + std::to_string(c), "random", ConstraintRole::kPhysics};
      switch (Pick(3)) {
        case 0: net->AddConstraint(g.id, Relation::kEqual, net->Const(Interval(g.value - eps, g.value + eps)), info); break;
        case 1: net->AddConstraint(g.id, Relation::kLessEqual, net->Const(g.value + eps + Uniform(0.0, 1.0)), info); break;
        default: net->AddConstraint(g.id, Relation::kGreaterEqual, net->Const(g.value - eps - Uniform(0.0, 1.0)), info); break;
      }
    }
    *witness = x_;
    return true;
  }

 private:
  Built Leaf(Network& net) {
    if (Pick(4) == 0) {
      const double k = Uniform(-3.0, 3.0);
      return {net.Const(k), k, std::abs(k)};
    }
    const int i = Pick(static_cast<int>(x_.size()));
    return {net.Var(vars_[i]), x_[i], std::abs(x_[i])};
  }

  Built Expr(Network& net, int depth) {
    if (depth == 0) return Leaf(net);
    const Built a = Expr(net, depth - 1);
    const auto sum = [](double v, double ma, double mb) { return std::abs(v) + ma + mb; };
    switch (Pick(14)) {
      case 0: { const Built b = Expr(net, depth - 1); return {net.Add(a.id, b.id), a.value + b.value, sum(a.value + b.value, a.magnitude, b.magnitude)}; }
      case 1: { const Built b = Expr(net, depth - 1); return {net.Sub(a.id, b.id), a.value - b.value, sum(a.value - b.value, a.magnitude, b.magnitude)}; }
      case 2: {
        const Built b = Expr(net, depth - 1);
        const double v = a.value * b.value;
        return {net.Mul(a.id, b.id), v, std::abs(v) + a.magnitude * std::abs(b.value) + b.magnitude * std::abs(a.value) + a.magnitude * b.magnitude};
      }
      case 3: {
        const Built b = Expr(net, depth - 1);
        if (std::abs(b.value) < 0.5 || b.magnitude > 10 * std::abs(b.value)) return a;  // keep away from 0
        const double v = a.value / b.value;
        return {net.Div(a.id, b.id), v, std::abs(v) + (a.magnitude + std::abs(v) * b.magnitude) / std::abs(b.value)};
      }
      case 4: return {net.Unary(Op::kNeg, a.id), -a.value, a.magnitude};
      case 5: return {net.Unary(Op::kSqr, a.id), a.value * a.value, a.value * a.value + 2 * std::abs(a.value) * a.magnitude + a.magnitude * a.magnitude};
      case 6: {
        const int k = 2 + Pick(3);
        const double v = std::pow(a.value, k);
        return {net.PowInt(a.id, k), v, std::pow(std::abs(a.value) + a.magnitude, k) * 4};
      }
      case 7:
        if (a.value < 0.5) return a;
        return {net.Sqrt(a.id), std::sqrt(a.value), std::sqrt(a.value) + a.magnitude / std::sqrt(a.value)};
      case 8:
        if (a.value > 5.0) return a;
        return {net.Unary(Op::kExp, a.id), std::exp(a.value), std::exp(a.value) * (1.0 + a.magnitude)};
      case 9:
        if (a.value < 0.5) return a;
        return {net.Unary(Op::kLog, a.id), std::log(a.value), std::abs(std::log(a.value)) + a.magnitude / a.value};
      case 10: return {net.Unary(Op::kAbs, a.id), std::abs(a.value), a.magnitude};
      case 11: {
        const Built b = Expr(net, depth - 1);
        const bool min = Pick(2) == 0;
        const double v = min ? std::min(a.value, b.value) : std::max(a.value, b.value);
        return {net.Binary(min ? Op::kMin : Op::kMax, a.id, b.id), v, a.magnitude + b.magnitude};
      }
      case 12: {
        const bool sin = Pick(2) == 0;
        const double v = sin ? std::sin(a.value) : std::cos(a.value);
        return {net.Unary(sin ? Op::kSin : Op::kCos, a.id), v, 1.0 + a.magnitude};
      }
      default:
        if (a.value < 0.5) return a;
        return {net.PowReal(a.id, 1.5), std::pow(a.value, 1.5), std::pow(a.value, 1.5) * (1.0 + a.magnitude)};
    }
  }

  std::mt19937_64 random_;
  std::vector<double> x_;
  std::vector<VariableId> vars_;
};

std::uint64_t BaseSeed() {
  const char* env = std::getenv("HIGHLIFT_WITNESS_SEED");
  return env && *env ? std::strtoull(env, nullptr, 10) : 20261201;
}

TEST(WitnessProperty, PropagationKeepsAKnownSolutionOfRandomNetworks) {
  const std::uint64_t seed = BaseSeed();
  RandomNetwork draw(seed);
  int networks = 0, violations = 0, narrowed = 0;
  const Schedule schedules[] = {Schedule::kSweep, Schedule::kFifo, Schedule::kLifo};
  // 10^5 networks; a quarter under the sanitizers (HIGHLIFT_WITNESS_NETWORKS from CMake).
  while (networks < HIGHLIFT_WITNESS_NETWORKS) {
    Network net;
    std::vector<double> witness;
    if (!draw.Build(&net, &witness)) continue;
    PropagationOptions options;
    options.schedule = schedules[networks % 3];
    options.ratio = networks % 2 == 0 ? 0.0 : 0.01;
    options.record_reasons = false;
    const Box initial = net.InitialBox();
    Box box = initial;
    const PropagationReport report = Propagate(net, box, options);
    bool inside = report.status != Status::kInfeasible;
    for (std::size_t i = 0; inside && i < witness.size(); ++i) inside = box[i].lower() <= witness[i] && witness[i] <= box[i].upper();
    for (std::size_t i = 0; i < witness.size(); ++i)
      if (box[i].lower() != initial[i].lower() || box[i].upper() != initial[i].upper()) ++narrowed;
    if (!inside && ++violations <= 5) {
      std::string text;
      for (int c = 0; c < net.num_constraints(); ++c) text += "\n  " + net.ConstraintText(ConstraintId{c});
      for (std::size_t i = 0; i < witness.size(); ++i)
        text += "\n  x" + std::to_string(i) + "* = " + std::to_string(witness[i]) + " in [" + std::to_string(box[i].lower()) +
                ", " + std::to_string(box[i].upper()) + "]";
      ADD_FAILURE() << "seed " << seed << ", network " << networks << ": " << ToString(report.status) << text;
    }
    ++networks;
  }
  EXPECT_EQ(violations, 0) << "of " << networks << " networks (seed " << seed << ")";
  // The property must not hold vacuously: propagation narrows most networks.
  EXPECT_GT(narrowed, networks);
}

}  // namespace
}  // namespace highlift::icsp
