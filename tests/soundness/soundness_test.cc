// The soundness property of the reported enclosures (size, peak) and of the propagator's
// narrowed domains (check), on the bundled examples and on random chain projects, plus the
// counter-examples that once broke it. CI runs 10^4 points; bench/soundness runs 10^6.
// HIGHLIFT_SOUNDNESS_SEED=<n> reruns with another seed (a failure names the seed it used).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "common/run_cli.h"
#include "highlift/core/project_io.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/sampling.h"
#include "soundness/soundness.h"

namespace highlift::testing {
namespace {

/// Under the sanitizers (HIGHLIFT_SOUNDNESS_SCALE=10) every count is divided by the scale: the
/// release build runs the full 10^4 points; the sanitizer build looks for memory errors on the
/// same code paths.
constexpr int Scaled(int count) { return count / HIGHLIFT_SOUNDNESS_SCALE; }

std::uint64_t BaseSeed() {
  const char* env = std::getenv("HIGHLIFT_SOUNDNESS_SEED");
  return env && *env ? std::strtoull(env, nullptr, 10) : 20261201;
}

std::string Report(const SoundnessResult& r) {
  std::string out = std::to_string(r.points) + " points, " + std::to_string(r.checks) + " checks, " +
                    std::to_string(r.violations.size()) + " violations";
  for (std::size_t i = 0; i < r.violations.size() && i < 20; ++i) out += "\n  " + r.violations[i];
  return out;
}

Project Example(const std::string& name) {
  return LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / name);
}

class ExampleSoundness : public ::testing::TestWithParam<std::string> {};

TEST_P(ExampleSoundness, SizeAndPeakEnclosuresHoldAtSampledPoints) {
  SoundnessOptions options;
  options.points = Scaled(250);
  options.seed = BaseSeed();
  const SoundnessResult r = CheckEnclosures(Example(GetParam()), options);
  EXPECT_EQ(r.points, Scaled(250));
  EXPECT_GT(r.checks, Scaled(250) * 20);
  EXPECT_TRUE(r.violations.empty()) << Report(r);
}

TEST_P(ExampleSoundness, CheckKeepsEveryFeasiblePoint) {
  SoundnessOptions options;
  options.points = HIGHLIFT_SOUNDNESS_SCALE > 1 ? 2 : 8;
  options.seed = BaseSeed();
  const SoundnessResult r = CheckDomainSoundness(Example(GetParam()), options);
  EXPECT_EQ(r.points, options.points);
  EXPECT_TRUE(r.violations.empty()) << Report(r);
}

TEST_P(ExampleSoundness, TradeoffSlicesKeepEveryFeasiblePoint) {
  SoundnessOptions options;
  options.points = HIGHLIFT_SOUNDNESS_SCALE > 1 ? 1 : 3;
  options.seed = BaseSeed();
  const SoundnessResult r = CheckTradeoffSoundness(Example(GetParam()), "pdu.motor_inertia", 4, options);
  EXPECT_EQ(r.points, 4 * options.points);
  EXPECT_TRUE(r.violations.empty()) << Report(r);
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleSoundness,
                         ::testing::Values("a380_class_flaps.json", "a320_class_flaps.json", "a320_class_slats.json"),
                         [](const auto& info) {
                           std::string name = info.param.substr(0, info.param.find('.'));
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST(RandomProjectSoundness, SizeAndPeakEnclosuresHoldOnRandomChains) {
  // 90 random projects x 100 points: with the examples' 750, about 10^4 points in CI.
  SoundnessResult all;
  const std::uint64_t base = BaseSeed();
  for (std::uint64_t k = 0; k < 90; ++k) {
    SoundnessOptions options;
    options.points = Scaled(100);
    options.seed = base + k;
    const Project project = RandomChainProject(base + k);
    all.Merge(CheckEnclosures(project, options));
  }
  EXPECT_EQ(all.points, 90 * Scaled(100));
  EXPECT_TRUE(all.violations.empty()) << Report(all);
}

TEST(RandomProjectSoundness, CheckKeepsEveryFeasiblePointOnRandomChains) {
  SoundnessResult all;
  const std::uint64_t base = BaseSeed() + 1000;
  for (std::uint64_t k = 0; k < 10; ++k) {
    SoundnessOptions options;
    options.points = Scaled(10) > 0 ? Scaled(10) : 1;
    options.seed = base + k;
    RandomProjectOptions small;
    small.max_stations = 3;
    all.Merge(CheckDomainSoundness(RandomChainProject(base + k, small), options));
  }
  EXPECT_EQ(all.points, 10 * (Scaled(10) > 0 ? Scaled(10) : 1));
  EXPECT_TRUE(all.violations.empty()) << Report(all);
}

TEST(RandomChainProject, IsReproducibleFromItsSeed) {
  const Project a = RandomChainProject(42), b = RandomChainProject(42), c = RandomChainProject(43);
  EXPECT_EQ(DescribeDifference(a, b), "");
  EXPECT_NE(DescribeDifference(a, c), "");
}

// ---- The counter-examples of the enclosure defects, each a regression test ----------------

/// One wing: PDU, a system torque limiter, one station, a tip shaft, a wing-tip brake.
Project SmallChain() {
  Project p = RandomChainProject(7, {.max_stations = 1, .allow_two_wings = false});
  return p;
}

Parameter Uncertain(double nominal, double lo, double hi) {
  Parameter p;
  p.nominal = nominal;
  p.domain = {lo, hi};
  p.provenance = Provenance::kUser;
  return p;
}

/// tau_total of case `name` with every parameter at its nominal value (the point code path).
double PointTotal(const Project& project, const std::string& name) {
  reduced_models::PeakOptions point;
  point.intervals = false;
  point.rank = false;
  for (const auto& c : reduced_models::AnalysePeaks(project, point).cases)
    if (c.name == name) return c.tau_total.nominal;
  ADD_FAILURE() << "no case " << name;
  return 0.0;
}

const reduced_models::PeakCase& Case(const reduced_models::PeakReport& report, const std::string& name) {
  for (const auto& c : report.cases)
    if (c.name == name) return c;
  throw std::runtime_error("no case " + name);
}

TEST(EnclosureRegression, JamStaticPartSpansTheSystemLimiterEndStopDomain) {
  // Was: the static part of a jam behind a system torque limiter entered the total at the
  // limiter's nominal setting, so a setting at the end of its domain gave a total above the
  // enclosure. The system limiter passes min(tau, max(tau_2, tau - tau_B_max)) of the stall
  // torque (docs/reduced_models.md): with a brake that grounds the rest, its end-stop torque.
  Project p = SmallChain();
  Component* pdu = p.FindComponent("pdu");
  pdu->parameters["stall_torque"] = Uncertain(2000.0, 2000.0, 2000.0);
  Component* stl = p.FindComponent("stl_l");
  ASSERT_NE(stl, nullptr);
  stl->parameters["lockout_torque_extend"] = Uncertain(470.0, 423.0, 517.0);
  stl->parameters["end_stop_torque"] = Uncertain(587.5, 550.0, 620.0);
  stl->parameters["max_brake_torque"] = Uncertain(1800.0, 1700.0, 1900.0);
  const auto report = reduced_models::AnalysePeaks(p, {});
  const auto& jam = Case(report, "jam_gra_l1");
  EXPECT_NEAR(jam.tau_static, 587.5, 1e-9 * 587.5);
  EXPECT_LT(jam.tau_static_bounds.lo, 551.0);
  EXPECT_GT(jam.tau_static_bounds.hi, 619.0);
  Project at_620 = p;
  at_620.FindComponent("stl_l")->parameters["end_stop_torque"] = Uncertain(620.0, 620.0, 620.0);
  EXPECT_LE(PointTotal(at_620, "jam_gra_l1"), jam.tau_total.bounds.hi);
}

TEST(EnclosureRegression, RuptureBackDriveSpansTheAidingEfficiencyDomain) {
  // Was: the rupture's back-drive torque entered the total at nominal efficiency; the point 0.8
  // gave a larger maximum than the enclosure over [0.6, 0.8].
  Project p = SmallChain();
  Component* gra = p.FindComponent("gra_l1");
  gra->parameters["eta_aiding"] = Uncertain(0.7, 0.6, 0.8);
  const auto report = reduced_models::AnalysePeaks(p, {});
  const auto& rupture = Case(report, "rupture_shaft_l1");
  Project at_08 = p;
  at_08.FindComponent("gra_l1")->parameters["eta_aiding"] = Uncertain(0.8, 0.8, 0.8);
  EXPECT_LE(PointTotal(at_08, "rupture_shaft_l1"), rupture.tau_total.bounds.hi);
  EXPECT_GT(rupture.tau_static_bounds.hi, rupture.tau_static_bounds.lo);
}

TEST(EnclosureRegression, MarginIsTheWorstOverTheAllowableDomain) {
  // A margin must not read positive where a point of the domains violates it: the allowable
  // enters at its lower bound.
  // The actuator's allowable, limit / (ratio eta_opposing), is smallest at the smallest limit
  // and the largest efficiency: 10 kN*m / (200 x 0.9).
  Project p = SmallChain();
  Component* gra = p.FindComponent("gra_l1");
  gra->parameters["ratio"] = Uncertain(200.0, 200.0, 200.0);
  gra->parameters["eta_opposing"] = Uncertain(0.85, 0.8, 0.9);
  gra->parameters["limit_output_torque"] = Uncertain(50e3, 10e3, 80e3);
  const auto report = reduced_models::AnalysePeaks(p, {});
  const double smallest = 10e3 / (200.0 * 0.9);
  for (const auto& w : report.worst)
    if (w.component == "gra_l1") {
      EXPECT_NEAR(w.allowable_min, smallest, 1e-9 * smallest);
      EXPECT_LE(w.allowable_min, smallest);  // rounded down
      EXPECT_LE(w.margin, smallest / w.local_torque - 1.0 + 1e-12);
      return;
    }
  ADD_FAILURE() << "gra_l1 has no worst-case row";
}

TEST(EnclosureRegression, ZeroLimiterInertiaIsValidWithIntervals) {
  // Was: "point 'stl': inertia J must be >= 0" from an outward-rounded 0 * ratio^2.
  Project p = SmallChain();
  Parameter zero;
  zero.nominal = 0.0;
  zero.domain = Domain::Point(0.0);
  zero.provenance = Provenance::kUser;
  p.FindComponent("stl_l")->parameters["inertia"] = zero;
  EXPECT_NO_THROW(reduced_models::AnalysePeaks(p, {}));
  const std::filesystem::path file = std::filesystem::path(HIGHLIFT_BINARY_DIR) / "soundness_zero_inertia.json";
  SaveProject(p, file);
  const CliResult result = RunCli({"peak", file.string()});
  EXPECT_NE(result.exit_code, 2) << result.err;
  EXPECT_EQ(result.err.find("must be >= 0"), std::string::npos) << result.err;
}

TEST(EnclosureRegression, InfoAcceptsWideZero) {
  const CliResult result =
      RunCli({"info", (std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "a320_class_flaps.json").string(),
              "--wide", "0"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
}

TEST(Tightness, ReportedInPeakAndSizeJson) {
  const std::string example = (std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / "a320_class_flaps.json").string();
  for (const char* command : {"peak", "size"}) {
    const CliResult result = RunCli({command, example, "--json", "--tightness", "16"});
    ASSERT_LE(result.exit_code, 1) << result.err;
    const auto j = nlohmann::json::parse(result.out);
    int measured = 0;
    std::function<void(const nlohmann::json&)> walk = [&](const nlohmann::json& node) {
      if (node.is_object()) {
        if (node.contains("tightness")) {
          EXPECT_GE(node["tightness"].get<double>(), 1.0 - 1e-9) << command << ": " << node.dump();
          ++measured;
        }
        for (const auto& [key, value] : node.items()) walk(value);
      } else if (node.is_array()) {
        for (const auto& value : node) walk(value);
      }
    };
    walk(j);
    EXPECT_GT(measured, 5) << command;
  }
}

TEST(Tightness, ExactForAProjectWithoutUncertainty) {
  Project p = SmallChain();
  const auto uncertain = reduced_models::UncertainParameters(p);
  std::vector<double> x;
  for (const auto& u : uncertain) x.push_back(u.domain.lo);
  const Project point = reduced_models::FixParameters(p, uncertain, x);
  reduced_models::PeakOptions options;
  options.tightness_samples = 4;
  for (const auto& c : reduced_models::AnalysePeaks(point, options).cases) EXPECT_NEAR(c.tau_total.tightness, 1.0, 1e-6) << c.name;
}

}  // namespace
}  // namespace highlift::testing
