#include "msl_compare.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "highlift/core/project_io.h"

namespace highlift::testing {

namespace {

constexpr double kRelativeTube = 2e-3;
constexpr double kFloor = 1e-9;
constexpr double kTimeTolerance = 1e-3;  // s: switching times and the time tube at events

std::string Unquote(std::string s) {
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') return s.substr(1, s.size() - 2);
  return s;
}

bool IsDiscrete(const std::string& name) {
  const auto dot = name.rfind('.');
  const std::string leaf = dot == std::string::npos ? name : name.substr(dot + 1);
  return leaf == "mode" || leaf == "startForward" || leaf == "startBackward" || leaf == "stuck";
}

// Linear interpolation of a series with duplicated event times: `right` picks the right limit.
double At(const Series& s, double t, bool right) {
  const auto& ts = s.t;
  if (t <= ts.front()) return s.y.front();
  if (t >= ts.back()) return s.y.back();
  std::size_t i = right ? std::upper_bound(ts.begin(), ts.end(), t) - ts.begin()
                        : std::lower_bound(ts.begin(), ts.end(), t) - ts.begin();
  if (i == 0) return s.y.front();
  if (i >= ts.size()) return s.y.back();
  const double t0 = ts[i - 1], t1 = ts[i];
  if (right && t0 == t) return s.y[i - 1];
  if (!right && t1 == t) return s.y[i];
  if (t1 == t0) return s.y[i];
  return s.y[i - 1] + (s.y[i] - s.y[i - 1]) * (t - t0) / (t1 - t0);
}

// Segments (start time, value) after merging segments shorter than 1 us (solver artefacts such
// as Dymola's rows at t = 5e-11 s).
std::vector<std::pair<double, double>> Segments(const Series& s) {
  std::vector<std::pair<double, double>> seg;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (seg.empty() || s.y[i] != seg.back().second) seg.push_back({s.t[i], s.y[i]});
  std::vector<std::pair<double, double>> merged;
  for (std::size_t i = 0; i < seg.size(); ++i) {
    const double end = i + 1 < seg.size() ? seg[i + 1].first : s.t.back() + 1;
    if (end - seg[i].first < 1e-6) continue;
    if (!merged.empty() && merged.back().second == seg[i].second) continue;
    merged.push_back(seg[i]);
  }
  if (!merged.empty()) merged.front().first = s.t.front();
  return merged;
}

// Times where a Boolean becomes true.
std::vector<double> RisingEdges(const Series& s) {
  std::vector<double> edges;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.y[i] != 0 && (i == 0 || s.y[i - 1] == 0)) edges.push_back(s.t[i]);
  return edges;
}

std::vector<double> EventTimes(const Series& s) {
  std::vector<double> ev;
  for (std::size_t i = 1; i < s.t.size(); ++i)
    if (s.t[i] == s.t[i - 1]) ev.push_back(s.t[i]);
  return ev;
}

}  // namespace

Series ReferenceCsv::Column(const std::string& name) const {
  auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) throw std::runtime_error("reference has no column '" + name + "'");
  const std::size_t c = it - columns.begin();
  Series s;
  for (const auto& r : rows) {
    s.t.push_back(r[0]);
    s.y.push_back(r[c]);
  }
  return s;
}

ReferenceCsv ReadReferenceCsv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  ReferenceCsv csv;
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  for (std::string cell; std::getline(header, cell, ',');) csv.columns.push_back(Unquote(cell));
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    csv.rows.push_back(std::move(row));
  }
  return csv;
}

std::vector<std::string> ReadComparisonSignals(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::vector<std::string> names;
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty() && line != "time") names.push_back(line);
  }
  return names;
}

bool ExampleComparison::passed() const {
  if (!report.ok()) return false;
  for (const auto& s : signals)
    if (!s.informative && !s.passed) return false;
  return true;
}

const std::vector<ExampleSpec>& MslExamples() {
  static const std::vector<ExampleSpec> examples = {
      {"First", "First.csv", {}},
      {"Backlash", "Backlash.csv", {}},
      {"Friction", "Friction.csv", {}},
      {"CoupledClutches", "CoupledClutches.csv", {}},
      {"LossyGearDemo1", "LossyGearDemo1.csv", {}},
      // Two friction elements lock one rigid shaft: the split of the locking torque, and so the
      // mode labels, are not unique (README of reference/msl); only the motion is compared.
      {"LossyGearDemo2", "LossyGearDemo2.csv",
       {"bearingFriction.mode", "bearingFriction.startBackward", "bearingFriction.startForward",
        "gear.mode"}},
      {"TestBraking", "ModelicaTest/TestBraking.csv", {}},
  };
  return examples;
}

ExampleComparison CompareExample(const std::string& example, const std::filesystem::path& reference_dir,
                                 const std::string& csv_path,
                                 const std::vector<std::string>& informative) {
  ExampleComparison result;
  result.example = example;
  const Project project =
      LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "tests" / "sim" / "msl" / (example + ".json"));
  const sim::Network network = sim::NetworkFromProject(project);
  sim::Simulator simulator(network);
  sim::SimulationOptions options;
  options.stop_time = project.scenarios.at(0).stop_time;
  options.output_interval = project.settings.output_interval;
  options.relative_tolerance = project.settings.relative_tolerance;
  sim::MemorySink sink;
  result.report = simulator.Run(options, sink);

  const ReferenceCsv ref = ReadReferenceCsv(reference_dir / csv_path);
  std::filesystem::path signals_file = reference_dir / csv_path;
  signals_file.replace_extension(".comparisonSignals.txt");
  for (const std::string& name : ReadComparisonSignals(signals_file)) {
    SignalComparison c;
    c.name = name;
    c.discrete = IsDiscrete(name);
    c.informative = std::find(informative.begin(), informative.end(), name) != informative.end();
    const Series r = ref.Column(name);
    if (sink.Column(name) < 0) {
      c.note = "not an output of the simulation";
      result.signals.push_back(c);
      continue;
    }
    Series s{sink.times(), sink.Series(name)};
    if (s.t.empty()) {
      c.note = "no rows";
      result.signals.push_back(c);
      continue;
    }
    const auto [lo, hi] = std::minmax_element(r.y.begin(), r.y.end());
    c.range = *hi - *lo;
    if (!c.discrete) {
      c.tolerance = kRelativeTube * c.range + kFloor;
      std::vector<double> events = EventTimes(r);
      for (double e : EventTimes(s)) events.push_back(e);
      std::sort(events.begin(), events.end());
      for (std::size_t i = 0; i < r.t.size(); ++i) {
        const double t = r.t[i];
        const bool right = i + 1 < r.t.size() ? r.t[i + 1] != t : true;
        double err = std::abs(At(s, t, right) - r.y[i]);
        // Within 1 ms of an event: distance to the band the simulation covers in [t-1ms, t+1ms].
        auto near = std::lower_bound(events.begin(), events.end(), t - kTimeTolerance);
        if (err > c.tolerance && near != events.end() && *near <= t + kTimeTolerance) {
          double lo_y = std::min(At(s, t - kTimeTolerance, true), At(s, t + kTimeTolerance, false));
          double hi_y = std::max(At(s, t - kTimeTolerance, true), At(s, t + kTimeTolerance, false));
          auto a = std::lower_bound(s.t.begin(), s.t.end(), t - kTimeTolerance);
          auto b = std::upper_bound(s.t.begin(), s.t.end(), t + kTimeTolerance);
          for (auto it = a; it != b; ++it) {
            lo_y = std::min(lo_y, s.y[it - s.t.begin()]);
            hi_y = std::max(hi_y, s.y[it - s.t.begin()]);
          }
          err = r.y[i] < lo_y ? lo_y - r.y[i] : (r.y[i] > hi_y ? r.y[i] - hi_y : 0.0);
        }
        if (err > c.max_error) {
          c.max_error = err;
          c.at_time = t;
        }
      }
      c.passed = c.max_error <= c.tolerance;
    } else {
      c.tolerance = kTimeTolerance;
      const std::string leaf = name.substr(name.rfind('.') + 1);
      std::vector<double> rt, st;
      std::vector<double> rv, sv;
      if (leaf == "mode" || leaf == "stuck") {
        for (auto [t, v] : Segments(r)) rt.push_back(t), rv.push_back(v);
        for (auto [t, v] : Segments(s)) st.push_back(t), sv.push_back(v);
      } else {
        rt = RisingEdges(r);
        st = RisingEdges(s);
        rv.assign(rt.size(), 1.0);
        sv.assign(st.size(), 1.0);
      }
      if (rv != sv) {
        std::ostringstream note;
        note << "sequence differs: reference";
        for (std::size_t i = 0; i < rt.size(); ++i) note << " " << rv[i] << "@" << rt[i];
        note << "; simulation";
        for (std::size_t i = 0; i < st.size(); ++i) note << " " << sv[i] << "@" << st[i];
        c.note = note.str();
        c.max_error = INFINITY;
        c.passed = false;
      } else {
        for (std::size_t i = 0; i < rt.size(); ++i) {
          const double d = std::abs(rt[i] - st[i]);
          if (d > c.max_error) {
            c.max_error = d;
            c.at_time = rt[i];
          }
        }
        c.passed = c.max_error <= c.tolerance;
        c.note = std::to_string(rt.size()) + (leaf == "mode" ? " segments" : " switches");
      }
    }
    result.signals.push_back(c);
  }
  return result;
}

}  // namespace highlift::testing
