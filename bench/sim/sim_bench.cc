// Chain of N inertias joined by elastic backlash elements (spring-damper with backlash), with
// bearing friction at every node, driven by a speed source: wall time per simulated second.
// Target: N = 1000 simulates 1 s in under 0.5 s on one core (docs/performance.md).
#include <benchmark/benchmark.h>

#include <string>

#include "highlift/sim/simulator.h"

namespace {

using highlift::sim::ElementParameters;
using highlift::sim::Network;

Network Chain(int n) {
  Network net;
  net.AddElement("Fixed", "fixed");
  net.AddElement("Sine", "w_ref", {{{"amplitude", 0.1}, {"f", 2.0}, {"offset", 10.0}}, {}});
  net.AddElement("Speed", "speed", {{{"f_crit", 50.0}}, {}});
  net.Connect("w_ref.y", "speed.w_ref");
  net.Connect("speed.support", "fixed.flange");
  for (int i = 0; i < n; ++i) {
    const std::string k = std::to_string(i);
    ElementParameters inertia{{{"J", 0.01}, {"w_start", 10.0}}, {}};
    if (i == 0) inertia.scalars["phi_start"] = 0.0;
    net.AddElement("Inertia", "inertia" + k, inertia);
    net.AddElement("BearingFriction", "bearing" + k, {{}, {{"tau_pos", {{0.0, 0.05}, {100.0, 0.1}}}}});
    net.Connect("inertia" + k + ".flange_b", "bearing" + k + ".flange_a");
    net.Connect("bearing" + k + ".support", "fixed.flange");
    if (i == 0) {
      net.Connect("speed.flange", "inertia0.flange_a");
    } else {
      const std::string prev = std::to_string(i - 1);
      net.AddElement("ElastoBacklash", "backlash" + k,
                     {{{"c", 1e4}, {"d", 5.0}, {"b", 1e-3},
                       // start in contact, loaded by the drag of the nodes downstream
                       {"phi_rel_start", -(0.5e-3 + (n - i) * 0.055 / 1e4)}},
                      {}});
      net.Connect("inertia" + prev + ".flange_b", "backlash" + k + ".flange_a");
      net.Connect("backlash" + k + ".flange_b", "inertia" + k + ".flange_a");
    }
  }
  return net;
}

class NullSink : public highlift::sim::OutputSink {
 public:
  void Begin(const std::vector<std::string>&) override {}
  void Row(double, const std::vector<double>& values) override { benchmark::DoNotOptimize(values.data()); }
};

void BM_ChainOneSecond(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Network net = Chain(n);
  highlift::sim::SimulationOptions options;
  options.stop_time = 1.0;
  options.output_interval = 1e-2;
  long steps = 0, events = 0, rhs = 0;
  for (auto _ : state) {
    highlift::sim::Simulator sim(net);
    NullSink sink;
    const auto report = sim.Run(options, sink);
    if (!report.ok()) state.SkipWithError(report.message.c_str());
    steps = report.statistics.steps;
    events = static_cast<long>(report.events.size());
    rhs = report.statistics.rhs_evaluations;
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["events"] = static_cast<double>(events);
  state.counters["f_evals"] = static_cast<double>(rhs);
  state.SetLabel("wall time = cost of 1 simulated second");
}

BENCHMARK(BM_ChainOneSecond)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
