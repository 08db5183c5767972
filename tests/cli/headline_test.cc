// The headline numbers of every bundled example against the figures of domain.md (issue 20): PDU
// torque and power, the station input torque at the shaft, and the first eigenfrequency with the
// PDU clamped.
//
// The expected numbers are domain.md's, never our output: each is written here together with the
// sentence or table row of ../shared/reference/domain.md it comes from, and the test first checks
// that domain.md still says so (it skips, naming the paths looked at, where domain.md is absent).
//
// Tolerances are the ones domain.md's rounding allows:
// - a figure stands for half a unit of its last significant digit either side, but for no less
//   than half a unit of its second significant digit: domain.md derives its figures from inputs
//   with two significant digits ("about 20 kN m", "0.85", "about 6 kN m") and rounds the result
//   ("about 720", "58.8"), so "about 6 kW" is 5.5-6.5 and "58.8" is 58.3-59.3;
// - the first clamped eigenfrequency is that of domain.md's own lumped chain (the node inertias and
//   segment stiffnesses of its tables, clamped at the PDU), with every J and c over the range its
//   table gives ("1.2e-2 to 1.3e-2 each") widened by the rounding of the printed digits: the
//   frequency falls with J and rises with c, so the two corners bound it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/run_cli.h"
#include "common/shared_reference.h"

namespace highlift {
namespace {

using testing::RunCli;

/// A figure of domain.md: its value, the number of significant digits it is printed with, and the
/// text of domain.md that states it.
struct Figure {
  double value = 0;
  int digits = 2;
  std::string quote;
};

/// Half a unit of the figure's last significant digit, and no less than half a unit of its second.
double Tolerance(const Figure& f) {
  const int exponent = static_cast<int>(std::floor(std::log10(std::fabs(f.value))));
  return 0.5 * std::pow(10.0, exponent - std::min(f.digits, 2) + 1);
}

/// [lo, hi] of a table entry: the printed range widened by half a unit of its last printed digit.
struct Range {
  double lo = 0, hi = 0;
};
Range Rounded(double lo, double hi, double unit) { return {lo - 0.5 * unit, hi + 0.5 * unit}; }
Range Rounded(double value, double unit) { return Rounded(value, value, unit); }

/// domain.md's lumped chain of one wing, PDU clamped: node inertias outboard of the PDU and the
/// stiffness of the segment inboard of each node.
struct Chain {
  std::vector<Range> J;  // kg*m^2
  std::vector<Range> c;  // N*m/rad, c[i] between node i-1 (the clamped PDU for i = 0) and node i
  std::vector<std::string> quotes;
};

/// First eigenfrequency [Hz] of a clamped chain (tridiagonal K, diagonal M), by bisection on the
/// number of eigenvalues of K - lambda M below zero (the signs of an LDL^T factorisation).
double FirstClampedHz(const std::vector<double>& J, const std::vector<double>& c) {
  const std::size_t n = J.size();
  std::vector<double> diagonal(n, 0.0), off(n, 0.0);  // off[i] couples node i-1 and node i
  for (std::size_t i = 0; i < n; ++i) {
    diagonal[i] += c[i];
    if (i > 0) {
      diagonal[i - 1] += c[i];
      off[i] = -c[i];
    }
  }
  const auto below = [&](double lambda) {
    int count = 0;
    double d = 1.0;
    for (std::size_t i = 0; i < n; ++i) {
      d = diagonal[i] - lambda * J[i] - (i > 0 ? off[i] * off[i] / d : 0.0);
      if (d == 0.0) d = -1e-300;
      count += d < 0;
    }
    return count;
  };
  double lo = 0.0, hi = 1e9;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (below(mid) >= 1 ? hi : lo) = mid;
  }
  return std::sqrt(lo) / (2.0 * std::numbers::pi);
}

/// The interval of the first clamped eigenfrequency over the table's ranges.
Range FirstClampedRange(const Chain& chain) {
  std::vector<double> J_lo, J_hi, c_lo, c_hi;
  for (const auto& r : chain.J) J_lo.push_back(r.lo), J_hi.push_back(r.hi);
  for (const auto& r : chain.c) c_lo.push_back(r.lo), c_hi.push_back(r.hi);
  return {FirstClampedHz(J_hi, c_lo), FirstClampedHz(J_lo, c_hi)};
}

struct Headline {
  std::string file;            // relative to the source dir
  std::string section;         // of domain.md
  Figure pdu_torque;           // N*m, both wings, extension against the opposing load
  Figure pdu_power;            // kW
  Figure station_input;        // N*m at the shaft
  std::string station_gearbox; // station 1's down-drive on the shaft ...
  std::string through_shaft;   // ... and the shaft outboard of it: the station takes the difference
  std::optional<Chain> chain;  // domain.md's lumped chain, when it gives one
};

// domain.md s3, one wing: PCU (clamped), RGB, S1..S6, WTB.
Chain Section3Chain() {
  Chain c;
  c.J = {Rounded(4.7e-3, 1e-4)};
  for (int i = 0; i < 6; ++i) c.J.push_back(Rounded(1.2e-2, 1.3e-2, 1e-3));
  c.J.push_back(Rounded(8.8e-4, 1e-5));
  for (double v : {1914.0, 2552.0, 2188.0, 2188.0, 1435.0, 1435.0, 1675.0, 3349.0}) c.c.push_back(Rounded(v, 1.0));
  c.quotes = {"| RGB | 4.0 | 4.7e-3 |",
              "| S1..S6 | 7.0, 10.5, 14.0, 17.5, 21.0, 24.0 | 1.2e-2 to 1.3e-2 each |",
              "| WTB | 25.5 | 8.8e-4 |",
              "| PCU-RGB | 4.0 | 50 x 2.0 | 1914 |",
              "| RGB-S1 | 3.0 | 50 x 2.0 | 2552 |",
              "| S1-S2, S2-S3 | 3.5 | 50 x 2.0 | 2188 |",
              "| S3-S4, S4-S5 | 3.5 | 45 x 1.8 | 1435 |",
              "| S5-S6 | 3.0 | 45 x 1.8 | 1675 |",
              "| S6-WTB | 1.5 | 45 x 1.8 | 3349 |"};
  return c;
}

// domain.md s4, one wing: PCU (clamped), RGB, T1..T4, WTB.
Chain Section4Chain() {
  Chain c;
  c.J = {Rounded(1.4e-3, 1e-4)};
  for (int i = 0; i < 4; ++i) c.J.push_back(Rounded(2.0e-3, 2.3e-3, 1e-4));
  c.J.push_back(Rounded(4.3e-4, 1e-5));
  for (double v : {1262.0, 2525.0, 721.0, 721.0, 842.0, 2525.0}) c.c.push_back(Rounded(v, 1.0));
  c.quotes = {"| RGB | 2.0 | 1.4e-3 |", "| T1 / T2 / T3 / T4 | 3.0 / 6.5 / 10.0 / 13.0 | 2.0e-3 to 2.3e-3 each |",
              "| WTB | 14.0 | 4.3e-4 |",
              "Segment stiffness c: PCU-RGB 1262, RGB-T1 2525, T1-T2 721, T2-T3 721, T3-T4 842, T4-WTB 2525 N m/rad."};
  return c;
}

Headline A380Class(const std::string& file) {
  return {file,
          "s3",
          {720, 2, "PCU about 720 N m and 18 kW for both wings"},
          {18, 2, "PCU about 720 N m and 18 kW for both wings"},
          {58.8, 3, "station input torque 58.8 N m opposing"},
          "tgb_l1",
          "shaft_l2a",
          Section3Chain()};
}

std::vector<Headline> Headlines() {
  return {
      A380Class("examples/a380_class_flaps.json"),
      A380Class("examples/hydraulic_pdu_flaps.json"),
      A380Class("examples/a380_class_flaps_infeasible.json"),
      {"examples/a320_class_flaps.json",
       "s4",
       {190, 2, "PCU about 190 N m and 6 kW for both wings"},
       {6, 1, "PCU about 190 N m and 6 kW for both wings"},
       {23.5, 3, "station input 23.5 N m opposing"},
       "tgb_l1",
       "shaft_l2a",
       Section4Chain()},
      // domain.md s5 gives no node table for the slats: no eigenfrequency to compare with.
      {"examples/a320_class_slats.json",
       "s5",
       {320, 2, "PCU about 320 N m and 7 kW for both wings"},
       {7, 1, "PCU about 320 N m and 7 kW for both wings"},
       {15.7, 3, "actuator output 2 kN m -> 15.7 N m at the shaft"},
       "tgb_l1",
       "shaft_l2",
       std::nullopt},
  };
}

/// domain.md with every run of white space made one blank, so quotes may span its line breaks.
std::string ReadFlattened(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string flat;
  for (char ch : buffer.str()) {
    const bool space = std::isspace(static_cast<unsigned char>(ch)) != 0;
    if (space && (flat.empty() || flat.back() == ' ')) continue;
    flat += space ? ' ' : ch;
  }
  return flat;
}

TEST(Headline, ToleranceIsTheRoundingOfTheFigure) {
  EXPECT_DOUBLE_EQ(Tolerance({720, 2, ""}), 5.0);
  EXPECT_DOUBLE_EQ(Tolerance({18, 2, ""}), 0.5);
  EXPECT_DOUBLE_EQ(Tolerance({6, 1, ""}), 0.5);
  EXPECT_DOUBLE_EQ(Tolerance({58.8, 3, ""}), 0.5);
  EXPECT_DOUBLE_EQ(Tolerance({190, 2, ""}), 5.0);
}

TEST(Headline, ClampedChainOfTwoMassesHasTheAnalyticFirstMode) {
  // Two unit inertias on unit springs from a wall: w^2 = (3 - sqrt 5) / 2.
  EXPECT_NEAR(FirstClampedHz({1.0, 1.0}, {1.0, 1.0}), std::sqrt((3.0 - std::sqrt(5.0)) / 2.0) / (2 * std::numbers::pi), 1e-9);
}

TEST(Headline, ExamplesMatchDomainFigures) {
  HIGHLIFT_REQUIRE_SHARED(domain_md, "domain.md");
  const std::string domain = ReadFlattened(domain_md);
  ASSERT_FALSE(domain.empty()) << domain_md;
  for (const Headline& h : Headlines()) {
    SCOPED_TRACE(h.file + " against domain.md " + h.section);
    for (const Figure* f : {&h.pdu_torque, &h.pdu_power, &h.station_input})
      ASSERT_NE(domain.find(f->quote), std::string::npos) << "domain.md no longer says '" << f->quote << "'";

    // Exit 1: the examples' station limiter brakes are out of their rule (README's table, issue 26).
    const auto size = RunCli({"size", h.file, "--json"});
    ASSERT_EQ(size.exit_code, 1) << size.err << size.out.substr(0, 2000);
    const auto report = nlohmann::json::parse(size.out);
    const nlohmann::json* extend = nullptr;
    for (const auto& c : report.at("load_cases"))
      if (c.at("direction") == "extend") extend = &c;
    ASSERT_NE(extend, nullptr);
    const double shaft_speed = extend->at("pdu_speed_rad_s").get<double>();
    const double torque = extend->at("pdu_torque_N_m").at("nominal").get<double>();
    const double power = extend->at("pdu_power_W").at("nominal").get<double>() / 1e3;
    EXPECT_NEAR(torque, h.pdu_torque.value, Tolerance(h.pdu_torque)) << h.pdu_torque.quote;
    EXPECT_NEAR(power, h.pdu_power.value, Tolerance(h.pdu_power)) << h.pdu_power.quote;
    // What the station takes from the shaft: the torque at its gearbox's input less the torque
    // passed on outboard (the station's gear torque, its efficiencies and its drag).
    double inboard = std::numeric_limits<double>::quiet_NaN(), outboard = inboard;
    for (const auto& c : extend->at("components")) {
      const double t = c.at("torque_N_m").at("nominal").get<double>();
      if (c.at("component") == h.through_shaft) outboard = t;
      if (c.at("component") == h.station_gearbox) {
        inboard = t;
        EXPECT_DOUBLE_EQ(c.at("speed_rad_s").get<double>(), shaft_speed);  // on the shaft
      }
    }
    ASSERT_FALSE(std::isnan(inboard) || std::isnan(outboard)) << h.station_gearbox << ", " << h.through_shaft;
    EXPECT_NEAR(inboard - outboard, h.station_input.value, Tolerance(h.station_input)) << h.station_input.quote;

    if (!h.chain) continue;
    for (const auto& quote : h.chain->quotes)
      ASSERT_NE(domain.find(quote), std::string::npos) << "domain.md no longer says '" << quote << "'";
    const Range expected = FirstClampedRange(*h.chain);
    const auto modes = RunCli({"modes", h.file, "--json"});
    ASSERT_EQ(modes.exit_code, 0) << modes.err;
    const auto m = nlohmann::json::parse(modes.out);
    bool full = false;
    for (const auto& model : m.at("models")) {
      if (model.at("reduction") != "full") continue;
      full = true;
      const double f1 = model.at("clamped_hz").at(0).get<double>();
      EXPECT_GE(f1, expected.lo) << "domain.md's chain gives " << expected.lo << " to " << expected.hi << " Hz";
      EXPECT_LE(f1, expected.hi) << "domain.md's chain gives " << expected.lo << " to " << expected.hi << " Hz";
    }
    EXPECT_TRUE(full);
  }
}

}  // namespace
}  // namespace highlift
