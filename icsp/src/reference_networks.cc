#include "highlift/icsp/reference_networks.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "highlift/core/error.h"

namespace highlift::icsp {

namespace {

std::string G17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : s_(seed) {}
  std::uint64_t Next() {
    s_ += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = s_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double U01() { return static_cast<double>(Next() >> 11) * 0x1p-53; }
  int Below(int m) { return static_cast<int>(Next() % static_cast<std::uint64_t>(m)); }

 private:
  std::uint64_t s_;
};

}  // namespace

ReferenceNetwork MakeDriveTrainNetwork(int size, bool infeasible) {
  HIGHLIFT_CHECK(size > 0, "icsp: network size must be positive");
  const int n = std::max(1, size / 5);
  ReferenceNetwork net;
  net.header = std::string(infeasible ? "dtinf" : "dt") + " n_stations=" + std::to_string(n);
  const double w = 1.0, tau_allow = 7.0, jsum_max = 1.7 * n;
  const double tend_max = infeasible ? 5.5 : 6.0;
  auto J = [](int i) { return 6 * i + 0; };
  auto C = [](int i) { return 6 * i + 1; };
  auto TAU = [](int i) { return 6 * i + 2; };
  auto R = [](int i) { return 6 * i + 3; };
  auto T = [n](int i) { return i == n ? 6 * n : 6 * i + 4; };
  auto S = [](int i) { return 6 * i + 5; };
  for (int i = 0; i < n; ++i) {
    const std::string s = std::to_string(i);
    net.variables.push_back({"J_" + s, 1, 10});
    net.variables.push_back({"c_" + s, 1, 10});
    net.variables.push_back({"tau_" + s, 0, 1000});
    net.variables.push_back({"r_" + s, 1, 4});
    net.variables.push_back({"T_" + s, i == 0 ? 1.0 : 0.0, i == 0 ? 1.5 : 1e6});
    net.variables.push_back({"S_" + s, 0, 1e7});
  }
  net.variables.push_back({"T_" + std::to_string(n), 0, 1e6});
  for (int i = 0; i < n; ++i) {
    const double load = (1.0 + 0.5 * (i % 4)) * (10.0 / n);
    const double eta = 0.9 + 0.025 * (i % 3);
    net.constraints.push_back({"TAU", {TAU(i), C(i), J(i)}, w, 0});
    net.constraints.push_back({"LEQK", {TAU(i), -1, -1}, tau_allow, 0});
    net.constraints.push_back({"TREC", {T(i + 1), T(i), R(i)}, load, eta});
    net.constraints.push_back({"LEQV", {T(i), TAU(i), -1}, 0, 0});
    if (i == 0) net.constraints.push_back({"EQV", {S(0), J(0), -1}, 0, 0});
    else net.constraints.push_back({"SUM", {S(i), S(i - 1), J(i)}, 0, 0});
  }
  net.constraints.push_back({"LEQK", {S(n - 1), -1, -1}, jsum_max, 0});
  net.constraints.push_back({"LEQK", {T(n), -1, -1}, tend_max, 0});
  if (!infeasible) {
    // Witness: T_0 = 1, r_i = 4, c_i = 10, J_i = max(1, T_i^2/10), tau_i = sqrt(c_i J_i).
    net.witness.assign(net.variables.size(), 0.0);
    double t = 1.0, s = 0.0;
    for (int i = 0; i < n; ++i) {
      const double load = (1.0 + 0.5 * (i % 4)) * (10.0 / n);
      const double eta = 0.9 + 0.025 * (i % 3);
      const double j = std::max(1.0, t * t / 10.0);
      s += j;
      net.witness[J(i)] = j;
      net.witness[C(i)] = 10.0;
      net.witness[TAU(i)] = std::sqrt(10.0 * j);
      net.witness[R(i)] = 4.0;
      net.witness[T(i)] = t;
      net.witness[S(i)] = s;
      t = t + load / (4.0 * eta);
    }
    net.witness[T(n)] = t;
  }
  return net;
}

ReferenceNetwork MakeRandomNetwork(int size) {
  HIGHLIFT_CHECK(size > 0, "icsp: network size must be positive");
  const int N = size;
  const int M = std::max(3, N / 2);
  ReferenceNetwork net;
  net.header = "rnd seed=20240601 N=" + std::to_string(N);
  SplitMix64 rng(20240601);
  std::vector<double> xs(M);
  for (int j = 0; j < M; ++j) xs[j] = 10.0 * rng.U01();
  for (int j = 0; j < M; ++j) net.variables.push_back({"x_" + std::to_string(j), 0, 10});
  for (int k = 0; k < N; ++k) {
    const int type = static_cast<int>(rng.Next() % 3);
    int a = rng.Below(M);
    int b = rng.Below(M);
    while (b == a) b = rng.Below(M);
    if (type == 0) {
      int c = rng.Below(M);
      while (c == a || c == b) c = rng.Below(M);
      volatile double prod = xs[a] * xs[b];  // no FMA contraction
      const double kk = prod + xs[c];
      net.constraints.push_back({"MULADD", {a, b, c}, kk - 1e-6, kk + 1e-6});
    } else if (type == 1) {
      volatile double root = std::sqrt(xs[a]);
      const double kk = root - xs[b];
      net.constraints.push_back({"SQRTSUB", {a, b, -1}, kk - 1e-6, kk + 1e-6});
    } else {
      if (xs[a] > xs[b]) std::swap(a, b);
      net.constraints.push_back({"LEQV", {a, b, -1}, 0, 0});
    }
  }
  net.witness = xs;
  return net;
}

std::string ToNetText(const ReferenceNetwork& net) {
  std::string out = "# " + net.header + "\n";
  out += "# nvar " + std::to_string(net.variables.size()) + " nctr " + std::to_string(net.constraints.size()) + "\n";
  out += "# var <idx> <name> <lo> <hi>\n";
  out += "# ctr <idx> <TYPE> <v0> <v1> <v2> <k1> <k2>   (canonical g(v) OP 0, see REPORT.md)\n";
  for (std::size_t i = 0; i < net.variables.size(); ++i) {
    const auto& v = net.variables[i];
    out += "var " + std::to_string(i) + " " + v.name + " " + G17(v.lo) + " " + G17(v.hi) + "\n";
  }
  for (std::size_t i = 0; i < net.constraints.size(); ++i) {
    const auto& c = net.constraints[i];
    out += "ctr " + std::to_string(i) + " " + c.type + " " + std::to_string(c.v[0]) + " " +
           std::to_string(c.v[1]) + " " + std::to_string(c.v[2]) + " " + G17(c.k1) + " " + G17(c.k2) + "\n";
  }
  for (std::size_t i = 0; i < net.witness.size(); ++i) {
    out += "witness " + std::to_string(i) + " " + G17(net.witness[i]) + "\n";
  }
  return out;
}

Network BuildNetwork(const ReferenceNetwork& ref) {
  Network net;
  net.Reserve(static_cast<int>(ref.variables.size()), static_cast<int>(ref.variables.size() + 7 * ref.constraints.size()),
              static_cast<int>(ref.constraints.size()));
  std::vector<ExprId> var;
  var.reserve(ref.variables.size());
  for (const auto& v : ref.variables) var.push_back(net.Var(net.AddVariable(v.name, Interval(v.lo, v.hi))));
  int index = 0;
  for (const auto& c : ref.constraints) {
    ConstraintInfo info{c.type + "#" + std::to_string(index++), "", ConstraintRole::kPhysics};
    if (c.type == "TAU") {  // Sub(tau, Mul(Const w, Sqrt(Mul(c, J)))) = 0
      net.AddConstraint(net.Sub(var[c.v[0]], net.Mul(net.Const(c.k1), net.Sqrt(net.Mul(var[c.v[1]], var[c.v[2]])))),
                        Relation::kEqual, std::move(info));
    } else if (c.type == "LEQK") {  // Sub(x, Const K) <= 0
      net.AddConstraint(net.Sub(var[c.v[0]], net.Const(c.k1)), Relation::kLessEqual, std::move(info));
    } else if (c.type == "TREC") {  // Sub(T1, Add(T0, Div(Const load, Mul(r, Const eta)))) = 0
      net.AddConstraint(
          net.Sub(var[c.v[0]], net.Add(var[c.v[1]], net.Div(net.Const(c.k1), net.Mul(var[c.v[2]], net.Const(c.k2))))),
          Relation::kEqual, std::move(info));
    } else if (c.type == "LEQV") {  // Sub(a, b) <= 0
      net.AddConstraint(net.Sub(var[c.v[0]], var[c.v[1]]), Relation::kLessEqual, std::move(info));
    } else if (c.type == "SUM") {  // Sub(S, Add(Sp, J)) = 0
      net.AddConstraint(net.Sub(var[c.v[0]], net.Add(var[c.v[1]], var[c.v[2]])), Relation::kEqual, std::move(info));
    } else if (c.type == "EQV") {  // Sub(a, b) = 0
      net.AddConstraint(net.Sub(var[c.v[0]], var[c.v[1]]), Relation::kEqual, std::move(info));
    } else if (c.type == "MULADD") {  // Sub(Add(Mul(a, b), c), Const [k1, k2]) = 0
      net.AddConstraint(net.Sub(net.Add(net.Mul(var[c.v[0]], var[c.v[1]]), var[c.v[2]]), net.Const(Interval(c.k1, c.k2))),
                        Relation::kEqual, std::move(info));
    } else if (c.type == "SQRTSUB") {  // Sub(Sub(Sqrt(a), b), Const [k1, k2]) = 0
      net.AddConstraint(net.Sub(net.Sub(net.Sqrt(var[c.v[0]]), var[c.v[1]]), net.Const(Interval(c.k1, c.k2))),
                        Relation::kEqual, std::move(info));
    } else {
      throw InputError("icsp: unknown reference constraint type '" + c.type +
                       "'; expected TAU, LEQK, TREC, LEQV, SUM, EQV, MULADD or SQRTSUB");
    }
  }
  return net;
}

}  // namespace highlift::icsp
