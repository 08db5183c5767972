// Design-load campaigns: every failure case of a drive-system project (a jam at each actuator, a
// rupture of each shaft segment and disconnector, the project's own scenarios) simulated over
// samples of the parameter domains (the nominal point, corners of chosen parameters, quasi-random
// points), with the single-DOF estimate beside each run. The result is the design-load envelope:
// per component the largest |torque| any run put into it, the case, sample and time, against its
// capacity.
//
//   const Project project = LoadProject("examples/a380_class_flaps.json");
//   campaign::CampaignOptions options;
//   options.case_patterns = {"jam_*"};
//   options.samples = 16;
//   const campaign::Plan plan = campaign::MakePlan(project, options);    // throws InputError
//   campaign::ExecutionOptions run;
//   run.directory = "out";                                               // out/campaign.sqlite
//   const campaign::CampaignReport report = campaign::RunCampaign(project, plan, run);
//   std::cout << campaign::LoadSummary("out").FullReport();
//
// Storage: one SQLite file per campaign (or per shard), every finished run committed in its own
// transaction (WAL), so a killed campaign loses nothing and the same command resumes it. Runs are
// deterministic functions of (case, sample): the envelope is the same whatever the number of
// threads, shards or interruptions. Schema and file names: docs/campaign.md.
#pragma once

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "highlift/core/project.h"
#include "highlift/sim/drive_network.h"

namespace highlift::campaign {

/// How the quasi-random points of `--samples` are drawn.
enum class SamplingMethod {
  kSobol,           ///< Sobol sequence (Joe-Kuo directions), digitally shifted per case
  kLatinHypercube,  ///< one point per stratum of every parameter, strata permuted per case
};
std::string ToString(SamplingMethod method);
/// "sobol" or "lhs"; throws InputError naming the value and the choices otherwise.
SamplingMethod ParseSamplingMethod(const std::string& text);

/// A deterministic part of a campaign: run r belongs to shard r mod count.
struct Shard {
  int index = 0;  ///< 0 .. count-1
  int count = 1;  ///< 1: the whole campaign
  bool whole() const { return count == 1; }
  std::string ToString() const;  ///< "I/N"
  /// "I/N" with 0 <= I < N; throws InputError naming the text and the form otherwise.
  static Shard Parse(const std::string& text);
  /// From SLURM_ARRAY_TASK_ID (minus SLURM_ARRAY_TASK_MIN) and SLURM_ARRAY_TASK_COUNT when set;
  /// nullopt when not inside a Slurm job array. Throws InputError for inconsistent values.
  static std::optional<Shard> FromSlurmEnvironment();
};

struct CampaignOptions {
  /// Glob patterns (`*`, `?`) over the case names; empty: every case. A pattern that matches no
  /// case is an InputError listing the cases.
  std::vector<std::string> case_patterns;
  /// "component.parameter": every combination of the lower and upper bound of these parameters
  /// (2^k samples per case, the others at their nominal values). At most kMaxCorners.
  std::vector<std::string> corners;
  /// Quasi-random points per case over the domains of `vary`.
  int samples = 0;
  /// Seed of the quasi-random points (with the case name: each run's point depends only on the
  /// case, the sample index and this seed).
  std::uint64_t seed = 1;
  SamplingMethod sampling = SamplingMethod::kSobol;
  /// "component.parameter" sampled by `samples`; empty: every parameter the project gives (not a
  /// catalogue default) with a bounded domain of non-zero width (booleans excepted).
  std::vector<std::string> vary;
  /// Model of every run: full (split shafts) or reduced (lumped chains).
  sim::DriveResolution model = sim::DriveResolution::kFull;
  /// Spring-dampers per torque shaft in the full model; 0: the project's setting (at least 4);
  /// otherwise 1 to sim::DriveNetworkOptions::kMaxShaftElements, as for `simulate`.
  int shaft_elements = 0;
  /// --feasible: sampled points also satisfy the project's requirements, as far as the interval
  /// constraint network (icsp, what `check` propagates) can tell: the quasi-random points are
  /// drawn over the domains narrowed by the requirements (the parameters not sampled at their
  /// values), and a point whose propagation proves a requirement violated is rejected and drawn
  /// again (Sample::rejected). Corners and the nominal point are not redrawn.
  bool feasible = false;
  /// Relative tolerance of the simulator in every run (--rtol); 0: the project's
  /// settings.relative_tolerance (1e-5 in the bundled examples). docs/validation.md, "Envelope
  /// against tolerance", measures how far the envelope at a tolerance is from the converged one.
  double relative_tolerance = 0.0;
  /// Guards of every run, so that a sample that makes the model chatter or stiff becomes a failed
  /// run instead of a run that never ends. A sizing case of the A380-class example takes 4000 to
  /// 6000 steps and a few hundred events in all. The rows of a campaign run are kRowsPerRun
  /// equidistant points (the peaks follow every step, not the rows), so the step limit is per
  /// 1/kRowsPerRun of the simulated time.
  /// Solver steps between two rows (--max-steps); 0: DefaultMaxStepsPerOutput of the run's
  /// tolerance, which MakePlan puts into Plan::options (and the campaign's identity).
  long max_steps_per_output = 0;
  int max_events = 20000;             ///< discrete events of one run
  static constexpr int kRowsPerRun = 20;
  /// The step guard at the default tolerance 1e-5 and above.
  static constexpr long kMaxStepsPerOutputAtDefaultTolerance = 10000;
  /// The step guard of a tolerance: kMaxStepsPerOutputAtDefaultTolerance at rtol >= 1e-5, times
  /// (1e-5 / rtol)^(1/5) below it (39 811 at 1e-8). A BDF run's step count grows about as
  /// rtol^(-1/(q+1)) with its order q; the A380-class ruptures take 2.1 times the steps at 1e-8
  /// that they take at 1e-5 on average, and the worst needed 10 000 to 12 000 steps in one
  /// 1/20 of its run at 1e-8 (docs/validation.md, "Envelope against tolerance").
  static long DefaultMaxStepsPerOutput(double relative_tolerance);

  static constexpr int kMaxCorners = 12;  ///< 4096 corners per case
  /// Quasi-random points per case (--samples): a Latin hypercube draws a permutation of this
  /// many strata per parameter and run.
  static constexpr int kMaxSamples = 100000;
  /// Runs of a whole campaign (cases x samples per case): about 7 kB of results each in the
  /// A380-class example, and seconds of CPU time each.
  static constexpr long kMaxRuns = 1000000;

  /// Throws InputError naming the option when a value is invalid.
  void Validate() const;
};

/// One failure case of the campaign.
struct CampaignCase {
  std::string name;        ///< scenario name, e.g. "jam_l3", "rupture_shaft_l2a", "extension"
  std::string kind;        ///< "jam", "rupture" or the scenario's kind
  std::string component;   ///< jammed actuator or ruptured shaft/disconnector ("" for others)
  Scenario scenario;       ///< what is simulated (load case, failure, stop time)
  std::string peak_case;   ///< the single-DOF case of the same failure ("" none)
  std::vector<std::string> load_path;  ///< components carrying the case's peak (shaft speed)
};

/// A parameter the campaign sets (corners or samples), with its domain in SI.
struct SampledParameter {
  std::string component;
  std::string parameter;
  double nominal = 0.0;
  Domain domain;
  bool integer = false;  ///< rounded to whole numbers
  std::string Name() const { return component + "." + parameter; }
};

/// A relation between parameters that every sampled point satisfies: a ParameterRelation of the
/// catalogue (value <= bound / divisor), which validation enforces, between two parameters of one
/// component of which at least one is sampled; each side a plan parameter or its fixed value.
struct SampleRelation {
  int value_index = -1;  ///< into Plan::parameters; -1: fixed at `value`
  double value = 0.0;
  int bound_index = -1;  ///< into Plan::parameters; -1: fixed at `bound`
  double bound = 0.0;
  double divisor = 1.0;
  std::string text;      ///< e.g. "wtb_left.max_dynamic_torque <= wtb_left.static_capacity"
  bool Holds(const std::vector<double>& values) const;
};

/// The interval constraint network of the project for --feasible (defined in plan.cc).
struct FeasibleSet;

/// One point: the value of every plan parameter.
struct Sample {
  int index = 0;
  std::string label;           ///< "nominal", "corner 3 (min,max)", "sobol 5", "lhs 5"
  std::vector<double> values;  ///< per Plan::parameters, SI
  int rejected = 0;            ///< draws rejected because they broke a Plan::relations
};

/// The cases times the samples of a campaign, fixed before anything runs.
struct Plan {
  CampaignOptions options;
  std::vector<CampaignCase> cases;
  std::vector<SampledParameter> parameters;  ///< corner parameters first, then the sampled ones
  int corner_count = 0;                      ///< of the first corner_count parameters' corners
  int samples_per_case = 1;                  ///< 1 (nominal) + 2^corners + samples
  std::string project_name;
  std::string project_hash;                  ///< 16 hex digits of the project's JSON text
  std::string campaign_id;                   ///< 16 hex digits of project hash, cases, samples, model
  /// The parameter relations a quasi-random point must satisfy; a draw that breaks one is
  /// rejected and the parameters of the broken relations are drawn again (Sample::rejected).
  std::vector<SampleRelation> relations;
  static constexpr int kMaxDraws = 1000;     ///< per point; then the point is kept as drawn
  /// --feasible: the project's constraint network, the box of the parameters not sampled (at their
  /// values) and the sampled domains narrowed by propagation; null otherwise.
  std::shared_ptr<const FeasibleSet> feasible;
  /// --feasible: whether the propagation of the network with every plan parameter at its value in
  /// `values` (the others at their nominal values) does not prove a requirement violated.
  bool SatisfiesRequirements(const std::vector<double>& values) const;

  int runs() const { return static_cast<int>(cases.size()) * samples_per_case; }
  int CaseOf(int run) const { return run / samples_per_case; }
  int SampleIndexOf(int run) const { return run % samples_per_case; }
  /// The point of a run: a pure function of the case, the sample index and the seed.
  Sample SampleOf(int run) const;
  /// The project with the run's parameter values as nominal values.
  Project Apply(const Project& project, const Sample& sample) const;
};

/// The cases of a project before filtering (for listing), in campaign order: the jams, the
/// ruptures, then the project's scenarios not among them.
std::vector<CampaignCase> AllCases(const Project& project);

/// Checks the options against the project and fixes the plan. Throws InputError (unknown case
/// filter, unknown parameter, a parameter with no domain to sample, a project without drive
/// system) before anything is written.
Plan MakePlan(const Project& project, const CampaignOptions& options);

/// What one run produced.
struct RunResult {
  int run = 0;
  int case_index = 0;
  int sample = 0;
  std::string sample_label;
  std::vector<double> values;       ///< per Plan::parameters
  bool ok = true;
  /// SIGINT/SIGTERM (highlift::InterruptRequested()) stopped the simulation: the run is not a
  /// result and stays to do (RunCampaign does not commit it).
  bool interrupted = false;
  std::string message;              ///< the failure (solver or model) when !ok
  double peak = 0.0;                ///< N*m at the shaft speed, largest on the case's load path
  std::string peak_component;
  double peak_time = 0.0;           ///< s
  std::optional<double> single_dof; ///< N*m, the single-DOF estimate of the case at this sample
  std::vector<sim::PeakTorque> components;  ///< per component, its own torque (element = id)
  long steps = 0;
  /// The simulator's passivity monitor: elements whose dissipated power fell below zero
  /// (stored per run in the table `passivity`, counted in the summary).
  sim::PassivityReport passivity;
  double build_seconds = 0.0;       ///< model building
  double simulate_seconds = 0.0;    ///< the simulator's run
  double single_dof_seconds = 0.0;  ///< the single-DOF estimate
};

/// One transient simulation of a failure case, as `peak --transient` and every campaign run make it.
struct CaseSimulation {
  sim::SimulationReport report;               ///< status, message, solver statistics, wall time
  /// The largest shaft or wing-tip brake torque on the load path (every shaft and brake when the
  /// path is empty), N*m referred to the shaft (PDU output) speed; element "" when none.
  sim::PeakTorque load_path_peak;
  std::vector<sim::PeakTorque> components;    ///< per component, its own torque (element = id)
  double build_seconds = 0.0;                 ///< model building and assembly
};

/// Builds the drive model of `scenario` (its load case, failure and stop time) and simulates it
/// with output rows every 1 ms at most (the peaks follow every step). Throws InputError when the
/// model cannot be built; a failing simulation is reported, not thrown.
/// `limits` (optional): a campaign run, kRowsPerRun rows and its max_steps_per_output and
/// max_events; otherwise rows every 1 ms and the simulator's limits.
CaseSimulation SimulateCase(const Project& project, const Scenario& scenario, const std::vector<std::string>& load_path,
                            const sim::DriveNetworkOptions& options, const CampaignOptions* limits = nullptr);

/// Runs one simulation of the plan (thread-safe: no shared mutable state). Never throws for a
/// failing run: the result says what went wrong.
RunResult ExecuteRun(const Project& project, const Plan& plan, int run);

struct ExecutionOptions {
  std::filesystem::path directory = "campaign";  ///< where the result file goes
  int jobs = 0;          ///< threads; 0: every core this process may use
  Shard shard;           ///< the part of the campaign to run
  /// Progress to this stream (nullptr: none): a bar on a terminal, one line per run otherwise.
  std::ostream* progress = nullptr;
  bool progress_is_terminal = false;
};

struct CampaignReport {
  std::filesystem::path file;  ///< the result file
  int runs_in_shard = 0;
  int runs_done_before = 0;    ///< resumed: already in the file
  int runs_done_now = 0;
  int failures = 0;            ///< of all runs in the file
  /// SIGINT/SIGTERM stopped this session (0: it ran to the end): the runs it had not finished
  /// stay to do, and the same command resumes them.
  int interrupted_signal = 0;
  int runs_left = 0;           ///< runs of the shard not in the file when the session ended
  double wall_seconds = 0.0;
  double run_seconds = 0.0;    ///< sum over this session's runs of build + single-DOF + simulate
  double simulate_seconds = 0.0;
  std::string BriefReport() const;
};

/// The result file of a shard in `directory`: campaign.sqlite for the whole campaign,
/// campaign-shard-I-of-N.sqlite otherwise.
std::filesystem::path ResultFile(const std::filesystem::path& directory, const Shard& shard);

/// Runs (or resumes) the shard of the plan. Throws InputError when the result file holds another
/// campaign (nothing is written then), or when another process is running into the same result
/// file (the message names its pid, host and start time; see the lock file ResultFile + ".lock").
/// SIGINT/SIGTERM (highlift::InterruptRequested()) stop it cleanly: no new run starts, the runs
/// the signal interrupted are not committed (they stay to do), the finished ones are, and the
/// report says so (interrupted_signal).
CampaignReport RunCampaign(const Project& project, const Plan& plan, const ExecutionOptions& options);

/// Merges complete shard files (given as files or directories holding them) into
/// `out`/campaign.sqlite. Throws InputError, writing nothing, for shards of different campaigns,
/// a shard given twice, missing or incomplete shards, a shard whose runs do not match their
/// checksums (edited after the runs), an existing output file, or another merge into it.
std::filesystem::path MergeShards(const std::vector<std::filesystem::path>& inputs, const std::filesystem::path& out);

/// Per component: the largest |torque| of the campaign.
struct EnvelopeRow {
  std::string component;
  double torque = 0.0;          ///< N*m, signed, at the component's own speed
  std::string case_name;
  int sample = 0;
  std::string sample_label;
  double time = 0.0;            ///< s
  std::string capacity_name;    ///< e.g. "torque capacity" ("" none)
  double capacity = 0.0;        ///< N*m, nominal design (0: none)
  std::optional<double> margin; ///< capacity / |torque| - 1
};

/// Per case: its runs.
struct CasePeakRow {
  std::string case_name;
  std::string kind;
  std::string load_case;
  int runs = 0;
  int failures = 0;
  double peak = 0.0;            ///< N*m at the shaft speed, largest over the samples
  std::string peak_component;
  int peak_sample = 0;
  double peak_time = 0.0;
  std::optional<double> single_dof;      ///< at the nominal sample
  std::optional<double> single_dof_max;  ///< largest over the samples
};

struct FailureRow {
  int run = 0;
  std::string case_name;
  int sample = 0;
  std::string message;
};

struct CampaignSummary {
  std::filesystem::path file;
  std::string campaign_id;
  std::string project_name;
  std::string project_hash;
  std::string model;
  /// The simulator's relative tolerance of every run (0: a file from before it was recorded).
  double relative_tolerance = 0.0;
  std::string shard;           ///< "0/1" for a whole or merged campaign
  int runs_total = 0;          ///< in this file's shard
  int runs_done = 0;
  int failures = 0;
  /// Runs in which an element's dissipated power fell below zero (the simulator's passivity
  /// monitor); -1 when the file predates the monitor.
  int not_passive = 0;
  int rejected_draws = 0;      ///< sampled draws rejected for breaking a parameter relation or (--feasible) a requirement
  int cases = 0;
  int samples_per_case = 0;
  std::vector<std::string> parameters;
  std::vector<EnvelopeRow> envelope;
  std::vector<CasePeakRow> case_peaks;
  std::vector<FailureRow> failed;
  /// The signal that stopped the last session of an incomplete file (its table
  /// `interruptions`; 0 when none is recorded, as in files begun before the table), or the
  /// command's own session: the summary then says "interrupted", when, and how to resume.
  int interrupted_signal = 0;
  std::string interrupted_time;  ///< UTC, ISO 8601, of the recorded interruption ("" unknown)
  /// Runs whose stored results no longer match the checksum recorded when they were committed
  /// (edited or damaged since); the summary flags them and is not ok.
  std::vector<int> edited_runs;

  bool complete() const { return runs_done == runs_total; }
  /// Every margin >= 0, no failure and not interrupted.
  bool ok() const;
  std::string BriefReport() const;
  std::string FullReport() const;
  nlohmann::json ToJson() const;
};

/// The fingerprint of a project's content that a campaign records (its project_hash): 16 hex
/// digits of a hash of the project's canonical JSON. A report compares it to tell whether a
/// campaign's results belong to the project as it is now.
std::string ProjectHash(const Project& project);

/// Reads a result file, or the campaign.sqlite of a directory. Throws InputError naming the
/// file when there is none (a directory with only shard files: merge them first).
CampaignSummary LoadSummary(const std::filesystem::path& file_or_directory);

}  // namespace highlift::campaign
