// The plan of a campaign: its cases (sizing cases of reduced_models' peak analysis, simulated as
// sim::SizingScenario builds them, under every load case of the matching direction; ruptures of
// disconnectors; the project's own scenarios) and its samples (nominal, corners, Sobol or Latin
// hypercube points). Everything here is a pure function of the project and the options.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

#include <boost/random/sobol.hpp>

#include "highlift/campaign/campaign.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/message_number.h"
#include "highlift/core/project_io.h"
#include "highlift/core/text_table.h"
#include "highlift/icsp/drive_system.h"
#include "highlift/reduced_models/analyses.h"
#include "internal.h"

namespace highlift::campaign {

// ---------------------------------------------------------------------------------------------
// Options

std::string ToString(SamplingMethod method) {
  return method == SamplingMethod::kSobol ? "sobol" : "lhs";
}

SamplingMethod ParseSamplingMethod(const std::string& text) {
  if (text == "sobol") return SamplingMethod::kSobol;
  if (text == "lhs") return SamplingMethod::kLatinHypercube;
  throw InputError("--sampling '" + text + "' is unknown; choose 'sobol' or 'lhs' (Latin hypercube)");
}

std::string Shard::ToString() const { return std::to_string(index) + "/" + std::to_string(count); }

Shard Shard::Parse(const std::string& text) {
  const auto fail = [&]() -> Shard {
    throw InputError("--shard '" + text + "' is invalid: give I/N with 0 <= I < N, e.g. 0/4 for the first of 4 shards");
  };
  const auto slash = text.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == text.size()) return fail();
  const std::string i = text.substr(0, slash), n = text.substr(slash + 1);
  const auto digits = [](const std::string& s) {
    return s.size() <= 9 && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  if (!digits(i) || !digits(n)) return fail();
  Shard shard{std::stoi(i), std::stoi(n)};
  if (shard.count < 1 || shard.index >= shard.count) return fail();
  return shard;
}

std::optional<Shard> Shard::FromSlurmEnvironment() {
  const char* id = std::getenv("SLURM_ARRAY_TASK_ID");
  const char* count = std::getenv("SLURM_ARRAY_TASK_COUNT");
  if (!id || !count) return std::nullopt;
  const char* min = std::getenv("SLURM_ARRAY_TASK_MIN");
  const auto number = [](const char* name, const char* value) {
    const std::string s = value;
    if (s.empty() || s.size() > 9 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
      throw InputError(std::string(name) + "='" + s + "' is not a task number; run inside a Slurm job array or give --shard I/N");
    return std::stoi(s);
  };
  const int index = number("SLURM_ARRAY_TASK_ID", id) - (min ? number("SLURM_ARRAY_TASK_MIN", min) : 0);
  const int n = number("SLURM_ARRAY_TASK_COUNT", count);
  if (n < 1 || index < 0 || index >= n)
    throw InputError("the Slurm job array gives task " + std::string(id) + " of " + std::string(count) +
                     " tasks: submit the array as --array=0-" + std::to_string(std::max(n, 1) - 1) +
                     " (contiguous, from 0) or give --shard I/N");
  return Shard{index, n};
}

void CampaignOptions::Validate() const {
  if (samples < 0) throw InputError("--samples " + std::to_string(samples) + ": give 0 or more quasi-random points");
  if (samples > kMaxSamples)
    throw InputError("--samples " + std::to_string(samples) + " is beyond the limit of " + std::to_string(kMaxSamples) +
                     " quasi-random points per case: lower --samples");
  if (static_cast<int>(corners.size()) > kMaxCorners)
    throw InputError("--corners names " + std::to_string(corners.size()) + " parameters: at most " +
                     std::to_string(kMaxCorners) + " (2^" + std::to_string(kMaxCorners) +
                     " corners per case); sample the others with --samples");
  // The range of simulate's --elements: a value it refuses would fail every run.
  if (shaft_elements < 0 || shaft_elements > sim::DriveNetworkOptions::kMaxShaftElements)
    throw InputError("--elements " + std::to_string(shaft_elements) + " is out of range; give 1 to " +
                     std::to_string(sim::DriveNetworkOptions::kMaxShaftElements) +
                     " spring-dampers per shaft (as for simulate), or leave it out for the project's setting");
  if (max_steps_per_output < 0)
    throw InputError("--max-steps " + std::to_string(max_steps_per_output) +
                     ": give 1 or more solver steps per 1/" + std::to_string(kRowsPerRun) +
                     " of a run, or leave it out for the default of the tolerance (10000 at rtol 1e-5)");
  if (max_events < 1)
    throw InputError("the run limit max_events must be >= 1 (" + std::to_string(max_events) + ")");
  if (!(relative_tolerance == 0.0 || (relative_tolerance >= 1e-12 && relative_tolerance < 1)))
    throw InputError("--rtol " + FormatMessageNumber(relative_tolerance) +
                     " is out of range: give a relative tolerance from 1e-12 to below 1 (e.g. 1e-6), or leave it out "
                     "for the project's settings.relative_tolerance");
  for (const auto& p : case_patterns)
    if (p.empty()) throw InputError("--cases holds an empty pattern; give patterns such as 'jam_*,rupture_shaft_l1'");
}

long CampaignOptions::DefaultMaxStepsPerOutput(double relative_tolerance) {
  constexpr double kDefaultTolerance = 1e-5;
  if (!(relative_tolerance > 0) || relative_tolerance >= kDefaultTolerance) return kMaxStepsPerOutputAtDefaultTolerance;
  return std::lround(static_cast<double>(kMaxStepsPerOutputAtDefaultTolerance) *
                     std::pow(kDefaultTolerance / relative_tolerance, 0.2));
}

// ---------------------------------------------------------------------------------------------
// Cases

namespace {

bool GlobMatch(const char* pattern, const char* text) {
  if (*pattern == '\0') return *text == '\0';
  if (*pattern == '*') return GlobMatch(pattern + 1, text) || (*text != '\0' && GlobMatch(pattern, text + 1));
  if (*text == '\0') return false;
  return (*pattern == '?' || *pattern == *text) && GlobMatch(pattern + 1, text + 1);
}

std::string Join(const std::vector<std::string>& items, const std::string& separator = ", ") {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : separator) + s;
  return out;
}

}  // namespace

std::vector<CampaignCase> AllCases(const Project& project) {
  reduced_models::PeakOptions peak_options;
  peak_options.intervals = false;
  peak_options.rank = false;
  const reduced_models::PeakReport peaks = reduced_models::AnalysePeaks(project, peak_options);
  std::vector<CampaignCase> cases;
  std::set<std::string> names;
  const auto add = [&](CampaignCase c) {
    if (names.insert(c.name).second) cases.push_back(std::move(c));
  };
  const auto peak_of = [&](const std::string& kind, const std::string& component) -> const reduced_models::PeakCase* {
    for (const auto& pc : peaks.cases)
      if (pc.kind == kind && pc.component == component) return &pc;
    return nullptr;
  };
  // A failure under the load case SizingScenario picks, then under every other load case of the
  // same direction ("<name>@<load case>").
  const auto add_failure = [&](const std::string& kind, const std::string& component) {
    const Scenario first = sim::SizingScenario(project, kind, component);
    const reduced_models::PeakCase* pc = peak_of(kind, component);
    CampaignCase c{first.name, kind, component, first, pc ? pc->name : "", pc ? pc->load_path : std::vector<std::string>{}};
    const LoadCase* lc = project.FindLoadCase(first.load_case);
    add(c);
    if (!lc) return;
    for (const LoadCase& other : project.load_cases) {
      if (other.name == lc->name || other.direction != lc->direction) continue;
      CampaignCase more = c;
      more.scenario.load_case = other.name;
      more.scenario.name = more.name = first.name + "@" + other.name;
      add(more);
    }
  };
  for (const auto& pc : peaks.cases)
    if (pc.kind == kJamKind) add_failure(kJamKind, pc.component);
  for (const auto& pc : peaks.cases)
    if (pc.kind == "rupture") add_failure("rupture", pc.component);
  // Rupturable components that are no shaft segment (disconnectors): the peak analysis chooses
  // the segments whose rupture matters (not those outboard of the wing-tip brake).
  for (const Component& c : project.components) {
    const ComponentRoles r = RolesOf(c.type);
    if (r.rupturable && !r.segment) add_failure("rupture", c.id);
  }
  for (const Scenario& s : project.scenarios) {
    std::string component = s.jam_component.value_or(s.rupture_component.value_or(""));
    const reduced_models::PeakCase* pc = peak_of(s.kind, component);
    add({s.name, s.kind, component, s, pc ? pc->name : "", pc ? pc->load_path : std::vector<std::string>{}});
  }
  return cases;
}

// ---------------------------------------------------------------------------------------------
// Samples

namespace {

SampledParameter ResolveParameter(const Project& project, const std::string& name, const std::string& option) {
  const auto dot = name.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == name.size())
    throw InputError(option + " '" + name + "': give component.parameter, e.g. pdu.motor_inertia");
  SampledParameter p;
  p.component = name.substr(0, dot);
  p.parameter = name.substr(dot + 1);
  const Component* c = project.FindComponent(p.component);
  if (!c) {
    std::vector<std::string> ids;
    for (const Component& k : project.components) ids.push_back(k.id);
    throw InputError(option + " '" + name + "': the project has no component '" + p.component +
                     "'; the components are: " + Join(ids));
  }
  const ComponentTypeSpec* spec = FindComponentType(c->type);
  const ParameterSpec* ps = spec ? spec->FindParameter(p.parameter) : nullptr;
  auto given = c->parameters.find(p.parameter);
  if (!ps && given == c->parameters.end()) {
    std::vector<std::string> names;
    for (const auto& [k, v] : c->parameters)
      if (v.domain.bounded() && v.domain.width() > 0) names.push_back(k);
    throw InputError(option + " '" + name + "': component '" + p.component + "' (" + c->type +
                     ") has no parameter '" + p.parameter + "'" +
                     (names.empty() ? std::string() : "; its parameters with a domain are: " + Join(names)));
  }
  p.integer = ps && ps->kind == ParameterKind::kInteger;
  const bool boolean = ps && ps->kind != ParameterKind::kScalar && ps->kind != ParameterKind::kInteger;
  p.domain = given != c->parameters.end() ? given->second.domain : Domain::Whole();
  const bool has_value = given != c->parameters.end() && given->second.nominal.has_value();
  if (boolean || !p.domain.bounded() || !(p.domain.width() > 0) || !has_value) {
    std::string what = boolean ? "it is not a number"
                       : given == c->parameters.end() ? std::string("the project does not give it; the catalogue default applies")
                       : !has_value ? std::string("it has no value")
                       : p.domain.is_point() ? "its domain is the point " + FormatNumber(p.domain.lo, 6)
                                             : "its domain is unbounded";
    throw InputError(option + " '" + name + "': the parameter has no domain to sample (" + what +
                     "); give it \"min\" and \"max\" in the project (" +
                     (c->where.file.empty() ? std::string("component '") + c->id + "'" : c->where.ToString()) + ")");
  }
  p.nominal = *given->second.nominal;
  return p;
}

/// Every parameter the project gives (not a catalogue default) with a bounded domain of non-zero
/// width and a value. The catalogue's default domains are generic ranges of a type, not the
/// uncertainty of this design (a default backlash range on a gearbox without a stiffness would
/// only give models that cannot be built).
std::vector<SampledParameter> UncertainParameters(const Project& project) {
  std::vector<SampledParameter> out;
  for (const Component& c : project.components) {
    const ComponentTypeSpec* spec = FindComponentType(c.type);
    for (const auto& [name, value] : c.parameters) {
      const ParameterSpec* ps = spec ? spec->FindParameter(name) : nullptr;
      if (ps && ps->kind != ParameterKind::kScalar && ps->kind != ParameterKind::kInteger) continue;
      if (value.provenance == Provenance::kDefault) continue;
      if (!value.nominal || !value.domain.bounded() || !(value.domain.width() > 0)) continue;
      out.push_back({c.id, name, *value.nominal, value.domain, ps && ps->kind == ParameterKind::kInteger});
    }
  }
  return out;
}

/// x in [0, 1) from the top 53 bits.
double Unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

double FromUnit(const SampledParameter& p, double u, const Domain* narrowed = nullptr) {
  const Domain& d = narrowed ? *narrowed : p.domain;
  double v = d.lo + u * (d.hi - d.lo);
  if (p.integer) v = std::round(v);
  return std::clamp(v, p.domain.lo, p.domain.hi);
}

/// The catalogue's relations (ParameterRelation, which validation enforces) between parameters of
/// one component of which at least one is a plan parameter; the other side at its value.
std::vector<SampleRelation> SampleRelations(const Project& project, const std::vector<SampledParameter>& parameters) {
  std::map<std::string, int> index;
  for (std::size_t k = 0; k < parameters.size(); ++k) index[parameters[k].Name()] = static_cast<int>(k);
  std::vector<SampleRelation> out;
  for (const Component& c : project.components) {
    const ComponentTypeSpec* spec = FindComponentType(c.type);
    if (!spec) continue;
    for (const ParameterRelation& r : spec->relations) {
      SampleRelation s;
      s.divisor = r.divisor;
      s.text = c.id + "." + r.parameter + " <= " + c.id + "." + r.bound +
               (r.divisor == 1.0 ? std::string() : " / " + FormatNumber(r.divisor, 6));
      const auto side = [&](const std::string& name, int* at, double* fixed) {
        if (auto it = index.find(c.id + "." + name); it != index.end()) {
          *at = it->second;
          return true;
        }
        const auto p = c.parameters.find(name);
        if (p == c.parameters.end() || !p->second.nominal) return false;
        *fixed = *p->second.nominal;
        return true;
      };
      if (!side(r.parameter, &s.value_index, &s.value) || !side(r.bound, &s.bound_index, &s.bound)) continue;
      if (s.value_index < 0 && s.bound_index < 0) continue;  // nothing sampled: validation's business
      out.push_back(std::move(s));
    }
  }
  return out;
}

}  // namespace

/// --feasible: the project's interval constraint network (icsp::BuildDriveSystemNetwork: its
/// physics and requirements), the variable of every plan parameter, and the box in which every
/// parameter that is not a plan parameter is fixed at its nominal value (a campaign run keeps
/// them there), propagated to its fixed point: the sampled parameters' domains narrowed by the
/// requirements. Propagation never removes a point that satisfies the constraints, so drawing
/// from the narrowed domains loses no feasible point.
struct FeasibleSet {
  icsp::DriveSystemNetwork network;
  std::vector<int> variable;      ///< per plan parameter: its variable (-1: not in the network)
  icsp::Box base;                 ///< the others fixed, propagated
  std::vector<Domain> narrowed;   ///< per plan parameter: its domain within `base`
};

namespace {

std::shared_ptr<const FeasibleSet> MakeFeasibleSet(const Project& project, const std::vector<SampledParameter>& parameters,
                                                   int corner_count) {
  auto set = std::make_shared<FeasibleSet>();
  set->network = icsp::BuildDriveSystemNetwork(project);
  const icsp::Network& net = set->network.network;
  set->base = net.InitialBox();
  std::set<int> planned;
  for (const SampledParameter& p : parameters) {
    const int v = net.FindVariable(p.Name()).value;
    set->variable.push_back(v);
    if (v >= 0) planned.insert(v);
  }
  for (const auto& [v, value] : set->network.nominal) {
    icsp::Interval& x = set->base[static_cast<std::size_t>(v)];
    if (planned.count(v) || icsp::IsEmpty(x) || value < x.lower() || value > x.upper()) continue;
    x = icsp::Interval(value, value);
  }
  // Corner parameters take the corners' values, not draws: their whole domains stay.
  icsp::PropagationOptions options;
  options.record_reasons = false;
  icsp::Propagator propagator(net, options);
  const icsp::PropagationReport report = propagator.Propagate(set->base);
  if (report.status == icsp::Status::kInfeasible)
    throw InputError("--feasible: no point of the sampled parameters' domains can meet the project's requirements with "
                     "the other parameters at their values (propagation proves it); `highlift check` explains which "
                     "requirements conflict. Leave out --feasible, or widen the domains");
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    Domain d = parameters[k].domain;
    const int v = set->variable[k];
    if (v >= 0 && static_cast<int>(k) >= corner_count) {
      const icsp::Interval& x = set->base[static_cast<std::size_t>(v)];
      d.lo = std::max(d.lo, x.lower());
      d.hi = std::min(d.hi, x.upper());
      if (!(d.lo <= d.hi)) d = parameters[k].domain;  // cannot happen after a non-empty fixed point
    }
    set->narrowed.push_back(d);
  }
  return set;
}

}  // namespace

bool Plan::SatisfiesRequirements(const std::vector<double>& values) const {
  if (!feasible) return true;
  icsp::Box box = feasible->base;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const int v = feasible->variable[k];
    if (v < 0) continue;
    icsp::Interval& x = box[static_cast<std::size_t>(v)];
    // A value outside the narrowed domain is proved infeasible already.
    if (icsp::IsEmpty(x) || values[k] < x.lower() || values[k] > x.upper()) return false;
    x = icsp::Interval(values[k], values[k]);
  }
  icsp::PropagationOptions options;
  options.record_reasons = false;
  icsp::Propagator propagator(feasible->network.network, options);
  return propagator.Propagate(box).status != icsp::Status::kInfeasible;
}

Sample Plan::SampleOf(int run) const {
  const CampaignCase& c = cases.at(static_cast<std::size_t>(CaseOf(run)));
  Sample s;
  s.index = SampleIndexOf(run);
  s.values.reserve(parameters.size());
  for (const auto& p : parameters) s.values.push_back(p.nominal);
  if (s.index == 0) {
    s.label = "nominal";
    return s;
  }
  const int corners = corner_count > 0 ? 1 << corner_count : 0;
  if (s.index <= corners) {
    const int bits = s.index - 1;
    s.label = "corner " + std::to_string(bits) + " (";
    for (int k = 0; k < corner_count; ++k) {
      const bool high = (bits >> k) & 1;
      s.values[k] = high ? parameters[k].domain.hi : parameters[k].domain.lo;
      s.label += std::string(k ? "," : "") + (high ? "max" : "min");
    }
    s.label += ")";
    return s;
  }
  // Quasi-random point n of this case: depends on the seed, the case name and n only.
  const int n = s.index - 1 - corners;
  const std::size_t first = static_cast<std::size_t>(corner_count);
  const std::size_t dimension = parameters.size() - first;
  const std::uint64_t case_seed = detail::Hash64(std::to_string(options.seed) + "\n" + c.name);
  const auto narrowed = [this](std::size_t k) { return feasible ? &feasible->narrowed[k] : nullptr; };
  if (options.sampling == SamplingMethod::kSobol) {
    s.label = "sobol " + std::to_string(n);
    boost::random::sobol sobol(dimension);
    sobol.seed(static_cast<std::uint64_t>(n) + 1);  // index 0 is the all-zero point
    for (std::size_t j = 0; j < dimension; ++j) {
      // Digital shift (XOR with per-case random bits) keeps the net property of the sequence.
      const std::uint64_t shift = detail::SplitMix64(case_seed + 0x9e3779b97f4a7c15ULL * (j + 1));
      s.values[first + j] = FromUnit(parameters[first + j], Unit(sobol() ^ shift), narrowed(first + j));
    }
  } else {
    s.label = "lhs " + std::to_string(n);
    const int strata = options.samples;
    for (std::size_t j = 0; j < dimension; ++j) {
      // The stratum of point n in dimension j: a Fisher-Yates permutation seeded by (case, j).
      std::vector<int> order(static_cast<std::size_t>(strata));
      for (int k = 0; k < strata; ++k) order[static_cast<std::size_t>(k)] = k;
      std::uint64_t state = detail::SplitMix64(case_seed ^ (0xa0761d6478bd642fULL * (j + 1)));
      for (int k = strata - 1; k > 0; --k) {
        state = detail::SplitMix64(state);
        std::swap(order[static_cast<std::size_t>(k)], order[state % static_cast<std::uint64_t>(k + 1)]);
      }
      const std::uint64_t jitter = detail::SplitMix64(case_seed ^ detail::SplitMix64((j + 1) * 1000003ULL + static_cast<std::uint64_t>(n)));
      const double u = (order[static_cast<std::size_t>(n)] + Unit(jitter)) / strata;
      s.values[first + j] = FromUnit(parameters[first + j], u, narrowed(first + j));
    }
  }
  // Draws that break a parameter relation are rejected: the sampled parameters of the broken
  // relations are drawn again, uniformly, from a stream of (case, point, attempt, parameter)
  // only; the other coordinates keep their quasi-random values. With --feasible, a point that
  // satisfies the relations but whose propagation proves a requirement violated is rejected
  // whole: every sampled parameter is drawn again, uniformly over its narrowed domain (so the
  // accepted redraws are uniform over the points the propagation cannot exclude).
  for (int attempt = 1; attempt <= kMaxDraws; ++attempt) {
    std::set<int> redraw;
    for (const SampleRelation& r : relations) {
      if (r.Holds(s.values)) continue;
      for (int k : {r.value_index, r.bound_index})
        if (k >= corner_count) redraw.insert(k);
    }
    if (redraw.empty() && !SatisfiesRequirements(s.values))
      for (int k = corner_count; k < static_cast<int>(parameters.size()); ++k) redraw.insert(k);
    if (redraw.empty()) break;
    ++s.rejected;
    for (int k : redraw) {
      const std::uint64_t bits = detail::SplitMix64(
          case_seed ^ detail::SplitMix64(0x51afd7ed558ccd1dULL * static_cast<std::uint64_t>(attempt) +
                                         0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(k + 1) +
                                         static_cast<std::uint64_t>(n)));
      s.values[static_cast<std::size_t>(k)] =
          FromUnit(parameters[static_cast<std::size_t>(k)], Unit(bits), narrowed(static_cast<std::size_t>(k)));
    }
  }
  if (s.rejected > 0)
    s.label += ", " + std::to_string(s.rejected) + (s.rejected == 1 ? " rejected draw" : " rejected draws");
  return s;
}

bool SampleRelation::Holds(const std::vector<double>& values) const {
  const double v = value_index >= 0 ? values.at(static_cast<std::size_t>(value_index)) : value;
  const double b = bound_index >= 0 ? values.at(static_cast<std::size_t>(bound_index)) : bound;
  return v * divisor <= b;
}

int detail::RejectedDraws(const std::string& label) {
  const std::size_t at = label.rfind(", ");
  if (at == std::string::npos || label.find(" rejected draw", at) == std::string::npos) return 0;
  return std::atoi(label.c_str() + at + 2);
}

Project Plan::Apply(const Project& project, const Sample& sample) const {
  Project p = project;
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    Component* c = p.FindComponent(parameters[k].component);
    HIGHLIFT_CHECK(c != nullptr, "plan parameter of a component that is not in the project");
    c->parameters[parameters[k].parameter].nominal = sample.values[k];
  }
  return p;
}

std::string ProjectHash(const Project& project) { return detail::Hex(detail::Hash64(ProjectToJson(project).dump())); }

Plan MakePlan(const Project& project, const CampaignOptions& options) {
  options.Validate();
  if (!sim::IsDriveSystemProject(project))
    throw InputError("a campaign simulates the drive system of the project, which has no components: add "
                     "\"components\" and \"connections\"");
  Plan plan;
  plan.options = options;
  if (plan.options.max_steps_per_output == 0)
    plan.options.max_steps_per_output = CampaignOptions::DefaultMaxStepsPerOutput(
        options.relative_tolerance > 0 ? options.relative_tolerance : project.settings.relative_tolerance);
  plan.project_name = project.name;
  const std::vector<CampaignCase> all = AllCases(project);
  if (options.case_patterns.empty()) {
    plan.cases = all;
  } else {
    std::vector<std::string> names;
    for (const auto& c : all) names.push_back(c.name);
    for (const auto& pattern : options.case_patterns) {
      const bool any = std::any_of(all.begin(), all.end(), [&](const CampaignCase& c) {
        return GlobMatch(pattern.c_str(), c.name.c_str());
      });
      if (!any)
        throw InputError("--cases '" + pattern + "' matches no case; the cases are: " + Join(names));
    }
    for (const auto& c : all)
      if (std::any_of(options.case_patterns.begin(), options.case_patterns.end(),
                      [&](const std::string& pattern) { return GlobMatch(pattern.c_str(), c.name.c_str()); }))
        plan.cases.push_back(c);
  }

  std::set<std::string> seen;
  for (const auto& name : options.corners) {
    if (!seen.insert(name).second) throw InputError("--corners names '" + name + "' twice");
    plan.parameters.push_back(ResolveParameter(project, name, "--corners"));
  }
  plan.corner_count = static_cast<int>(plan.parameters.size());
  if (options.samples > 0) {
    std::vector<SampledParameter> varied;
    if (options.vary.empty()) {
      varied = UncertainParameters(project);
    } else {
      for (const auto& name : options.vary) varied.push_back(ResolveParameter(project, name, "--vary"));
    }
    std::set<std::string> in_vary;
    for (const auto& p : varied) {
      if (!in_vary.insert(p.Name()).second) throw InputError("--vary names '" + p.Name() + "' twice");
      if (!seen.count(p.Name())) plan.parameters.push_back(p);  // a corner parameter keeps its corners
    }
    if (plan.parameters.size() == static_cast<std::size_t>(plan.corner_count))
      throw InputError("--samples " + std::to_string(options.samples) +
                       ": the project has no parameter with a domain to sample (give parameters \"min\" and \"max\")");
    const std::size_t dimension = plan.parameters.size() - static_cast<std::size_t>(plan.corner_count);
    if (options.sampling == SamplingMethod::kSobol && dimension > BOOST_RANDOM_SOBOL_MAX_DIMENSION)
      throw InputError("--samples: " + std::to_string(dimension) + " parameters exceed the " +
                       std::to_string(BOOST_RANDOM_SOBOL_MAX_DIMENSION) +
                       " dimensions of the Sobol directions; choose --sampling lhs or fewer --vary parameters");
  }
  plan.samples_per_case = 1 + (plan.corner_count > 0 ? 1 << plan.corner_count : 0) + options.samples;
  const long long runs = static_cast<long long>(plan.cases.size()) * plan.samples_per_case;
  if (runs > CampaignOptions::kMaxRuns)
    throw InputError(std::to_string(plan.cases.size()) + " case(s) x " + std::to_string(plan.samples_per_case) +
                     " sample(s) = " + std::to_string(runs) + " runs, beyond the limit of " + std::to_string(CampaignOptions::kMaxRuns) +
                     " runs of a campaign: lower --samples (or name fewer --corners), or select fewer cases with --cases");
  if (options.samples > 0) plan.relations = SampleRelations(project, plan.parameters);
  if (options.feasible) {
    if (options.samples == 0)
      throw InputError("--feasible applies to the quasi-random points of --samples (the nominal point and --corners "
                       "are the user's choice): give --samples N");
    plan.feasible = MakeFeasibleSet(project, plan.parameters, plan.corner_count);
  }

  plan.project_hash = ProjectHash(project);
  std::string identity = plan.project_hash + "\nmodel " + sim::ToString(options.model) + "\nelements " +
                         std::to_string(options.shaft_elements) + "\nsamples " + std::to_string(options.samples) +
                         "\nseed " + std::to_string(options.seed) + "\nsampling " + ToString(options.sampling) +
                         "\nlimits " + std::to_string(plan.options.max_steps_per_output) + " " + std::to_string(options.max_events);
  // Only a tolerance other than the project's enters the identity (campaigns from before --rtol
  // keep theirs); the project's own tolerance is part of the project hash.
  if (options.feasible) identity += "\nfeasible";
  if (options.relative_tolerance > 0) identity += "\nrtol " + nlohmann::json(options.relative_tolerance).dump();
  for (const auto& c : plan.cases) identity += "\ncase " + c.name;
  for (const auto& p : plan.parameters) identity += "\nparameter " + p.Name();
  identity += "\ncorners " + std::to_string(plan.corner_count);
  plan.campaign_id = detail::Hex(detail::Hash64(identity));
  return plan;
}

}  // namespace highlift::campaign
