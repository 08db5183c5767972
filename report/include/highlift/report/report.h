// The design report of a drive-system project (`highlift report`): one self-contained HTML file
// with the verdict of the interval check first, the architecture drawn along the span, the
// steady-state torque flow, the modes, the peak loads (single-DOF beside transient simulation
// beside capacity) and the time histories of the project's scenarios. Scripts (the uPlot
// plotting library, the page's own code), styles and data are inlined: the file opens offline
// and refers to nothing outside itself (docs/report.md).
//
//   const Project project = LoadProject("examples/a380_class_flaps.json");
//   Project estimated = project;  // the interval check runs on the estimated domains
//   estimation::EstimateProject(estimated, &database, {});
//   const DesignReport report = BuildDesignReport(project, estimated, "estimated 40 parameters", {});
//   std::ofstream("report.html") << RenderHtml(report);
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "highlift/core/project.h"
#include "highlift/icsp/drive_system.h"

namespace highlift::report {

struct ReportOptions {
  /// Simulate every sizing case of the peak analysis at full resolution (the transient peak
  /// beside the single-DOF estimate). false: single-DOF estimates and capacities only.
  bool transient = true;
  /// Spring-dampers per torque shaft in the simulations; 0: the project's shaft_elements, at
  /// least sim::DriveNetworkOptions::kMinShaftElements.
  int shaft_elements = 0;
  /// Simulate the project's scenarios for the time histories (a scenario that is also a sizing
  /// case is simulated once).
  bool scenarios = true;
  /// Points per signal in a time history at most: longer runs keep, per bucket of rows, the
  /// rows of the smallest and the largest value (peaks survive the thinning).
  int max_points = 1500;
  /// Simulations run side by side on this many threads; 0: the hardware's threads.
  int threads = 0;
  /// The interval check (the summary), as `highlift check`.
  icsp::PropagationOptions propagation;
  /// A design-load campaign of this project (`highlift campaign`): its result folder or file.
  /// Empty (the default): none. The peak-load section then adds the envelope over the samples
  /// (per component the largest torque of any case and sample against its capacity) and, per
  /// case, the largest transient peak over the samples; the worst margins include the envelope's.
  /// A campaign of another project, or of this one before it changed, is an input error.
  std::filesystem::path campaign;
  /// A result of `highlift optimize PROJECT --json` (the document it prints, saved with `> FILE`).
  /// Empty (the default): none. The page then adds a Synthesis section: the status, the best
  /// design's objective (its worst case over the remaining uncertain parameters) beside the
  /// certified lower bound and the gap, the design table, what limits the design, the mass by
  /// component and, for a `--pareto` run, a plot of the front. The result must belong to this
  /// project (the content hash optimize recorded: the project it read, or the design its --write
  /// wrote); another project's, or a file that is not such a document, is an input error.
  std::filesystem::path optimize;

  /// Throws InputError naming the option when a value is invalid.
  void Validate() const;
};

/// Wall-clock seconds of the parts of a report.
struct ReportTimings {
  double check = 0.0;         ///< interval propagation (and the nominal design)
  double sizing = 0.0;
  double modes = 0.0;
  double peaks = 0.0;         ///< single-DOF peak analysis
  double campaign = 0.0;      ///< reading the campaign's results
  double simulations = 0.0;   ///< wall time of all simulations (side by side)
  double simulated = 0.0;     ///< sum of the simulations' own wall times
  int simulation_count = 0;
  double total = 0.0;         ///< BuildDesignReport, all of it
  double Tool() const { return total - simulations; }  ///< everything but the simulations
};

struct DesignReport {
  nlohmann::json data;        ///< everything the page shows (docs/report.md lists the keys)
  bool feasible = true;       ///< the check's verdict on the domains (false also for failed simulations: no)
  bool nominal_feasible = true;
  bool simulations_ok = true; ///< every simulation reached its stop time
  bool campaign_ok = true;    ///< no campaign, or one that is complete, with no failed run and no negative margin
  bool synthesis_ok = true;   ///< no optimize result, or one with a design (optimal or stopped at a limit)
  ReportTimings timings;
  /// "report of NAME: feasible domains, nominal design violates X; 36 cases simulated in 12 s".
  std::string BriefReport() const;
};

/// Runs the analyses and collects what the page shows. `project` as loaded (sizing, modes,
/// peaks and simulations read it, as `highlift size/modes/peak/simulate` do); `estimated` the
/// same with the estimator's domains (the interval check reads it, as `highlift check` does;
/// pass `project` again to check the project's own domains), `estimation_brief` the estimator's
/// one-line report ("" when not estimated). Throws InputError when the project is no drive
/// system or an analysis cannot read it.
DesignReport BuildDesignReport(const Project& project, const Project& estimated, const std::string& estimation_brief,
                               const ReportOptions& options = {});

/// The Synthesis section's data (`data["synthesis"]`, docs/report.md) from `result`, a document of
/// `highlift optimize --json` read from `file` (named in messages). Throws InputError naming the
/// file, the JSON path, what was found and what is valid when the document is malformed or
/// belongs to another project (its `project_hash` is neither `project`'s content hash nor, as
/// `design_hash`, that of the design optimize wrote: `campaign::ProjectHash`).
nlohmann::json SynthesisJson(const Project& project, const nlohmann::json& result, const std::string& file);
/// Reads `file` (an InputError when it cannot be read or is not JSON) and returns SynthesisJson.
nlohmann::json ReadSynthesis(const Project& project, const std::filesystem::path& file);

/// The self-contained HTML page of the report.
std::string RenderHtml(const DesignReport& report);

/// The `highlift check --json` document of a check result: the verdict on the domains
/// ("all_requirements_met", null when propagation stopped at a limit), the violated requirements
/// and the explanation of the conflict, the nominal design's verdict, and every parameter
/// (initial and final domain, narrowing, provenance).
nlohmann::json CheckDocument(const Project& project, const icsp::DriveSystemNetwork& net,
                             const icsp::CheckResult& result, const std::string& estimation_brief);

/// The verdict of a check document in words, answer first: `highlift check` prints these lines
/// before anything else and the report's summary shows them. Each statement says what it is
/// about: the parameter domains (some values within them meet the requirements, or none do) or
/// the nominal design (every parameter at its nominal value).
struct Verdict {
  std::string status;    ///< "feasible", "feasible_domains_nominal_violates", "infeasible", "undecided"
  std::string headline;  ///< one line, e.g. "infeasible: no values within the parameter domains meet extension_time and jam_l1_fitting together"
  std::string domains;   ///< the statement about the parameter domains
  std::string nominal;   ///< the statement about the nominal design ("" when it was not checked)
};
Verdict DescribeVerdict(const nlohmann::json& check_document);

/// What `highlift check` decides, printed with its verdict and in its JSON ("scope"): the
/// project's requirements over the parameter domains. The component margins (allowables against
/// the steady and peak loads, the station limiter's setting rules) are `size` and `peak`, which
/// may exit 1 where check exits 0.
inline constexpr const char* kCheckScope =
    "the project's requirements over the parameter domains; component margins against their allowables and the "
    "setting rules are `highlift size` and `highlift peak` (they may fail where check passes)";

/// Requirement labels of the constraints of an explanation's conflict.
std::vector<std::string> ConflictLabels(const icsp::DriveSystemNetwork& net, const icsp::Explanation& explanation);

}  // namespace highlift::report
