// Two kernels that run at every step of a simulation, each beside what it replaced, so that
// their ratio is measured in one run (docs/performance.md, issue 30, twenty-second pass):
// - CVODE's weighted RMS norm of a 411-state vector (rupture_shaft_l4a's system; about six norms
//   per step): one running sum (our kernel before, in SUNDIALS' order) against ours (eight
//   partial sums), both through the vector's operations table as CVODE calls them; SUNDIALS' own
//   serial kernel for scale;
// - the smooth sign of the regularised friction laws: std::tanh against SmoothSign, on
//   arguments spread as in rupture_shaft_l4a (where the library's tanh reached its expm1: a
//   million calls, 30 % with |x| below 0.005, 19 % between 5 and 20).
#include <benchmark/benchmark.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "fast_kernels.h"
#include "model.h"
#include "sundials_compat.h"

namespace {

using highlift::sim::detail::SmoothSign;

constexpr int kStates = 411;

// The norm as our kernel computed it before the twenty-second pass: one running sum.
sunrealtype OneRunningSum(N_Vector x, N_Vector w) {
  const sunindextype n = NV_LENGTH_S(x);
  const double *xd = NV_DATA_S(x), *wd = NV_DATA_S(w);
  double sum = 0.0;
  for (sunindextype i = 0; i < n; ++i) {
    const double p = xd[i] * wd[i];
    sum += p * p;
  }
  return std::sqrt(sum / static_cast<double>(n));
}

enum class NormKernel { kSundials, kOneRunningSum, kOurs };

void Norm(benchmark::State& state, NormKernel kernel) {
  highlift::sim::detail::SundialsContext ctx;
  N_Vector x = N_VNew_Serial(kStates, ctx), w = N_VNew_Serial(kStates, ctx);
  if (kernel != NormKernel::kSundials) {
    highlift::sim::detail::InstallFastVectorOps(x);
    highlift::sim::detail::InstallFastVectorOps(w);
  }
  if (kernel == NormKernel::kOneRunningSum) x->ops->nvwrmsnorm = OneRunningSum;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < kStates; ++i) {
    NV_Ith_S(x, i) = u(random) * 1e-5;
    NV_Ith_S(w, i) = 1.0 / (1e-5 * std::abs(u(random)) + 1e-6);
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(N_VWrmsNorm(x, w));
    benchmark::ClobberMemory();
  }
  N_VDestroy(x);
  N_VDestroy(w);
}
void BM_WrmsNormSundials(benchmark::State& state) { Norm(state, NormKernel::kSundials); }
void BM_WrmsNormOneRunningSum(benchmark::State& state) { Norm(state, NormKernel::kOneRunningSum); }
void BM_WrmsNormOurs(benchmark::State& state) { Norm(state, NormKernel::kOurs); }
BENCHMARK(BM_WrmsNormSundials);
BENCHMARK(BM_WrmsNormOneRunningSum);
BENCHMARK(BM_WrmsNormOurs);

// |x| log-uniform within each share of the calls counted in rupture_shaft_l4a, random signs.
std::vector<double> FrictionArguments() {
  const double edges[] = {1e-6, 0.005, 0.05, 0.5, 2.0, 5.0, 20.0};
  const double shares[] = {0.30, 0.13, 0.18, 0.11, 0.09, 0.19};
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xs;
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < static_cast<int>(shares[k] * 4096); ++i) {
      const double x = edges[k] * std::pow(edges[k + 1] / edges[k], u(random));
      xs.push_back(u(random) < 0.5 ? -x : x);
    }
  std::shuffle(xs.begin(), xs.end(), random);
  return xs;
}
void Sign(benchmark::State& state, bool ours) {
  const std::vector<double> xs = FrictionArguments();
  for (auto _ : state) {
    double sum = 0.0;
    for (double x : xs) sum += ours ? SmoothSign(x) : std::tanh(x);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(xs.size()));
}
void BM_TanhLibrary(benchmark::State& state) { Sign(state, false); }
void BM_SmoothSign(benchmark::State& state) { Sign(state, true); }
BENCHMARK(BM_TanhLibrary);
BENCHMARK(BM_SmoothSign);

}  // namespace
