// `highlift campaign PROJECT [--out DIR] [--cases PATTERNS] [--corners PARAMS] [--samples N
// [--seed S] [--sampling sobol|lhs] [--vary PARAMS] [--feasible]] [--model full|reduced] [--jobs N]
// [--rtol R] [--max-steps N] [--shard I/N] [--json]`: the design-load campaign (every jam, rupture and scenario of the
// project over samples of the parameter domains), results in DIR/campaign.sqlite, committed run
// by run (the same command resumes a killed campaign).
// `highlift campaign summary DIR [--json]`: the envelope of a result file.
// `highlift campaign merge DIR... [--out DIR]`: merges the shard files of a Slurm job array.
// Exit 0 when the campaign is complete with every margin >= 0 and no failed run, 1 otherwise,
// 2 on invalid input (nothing is written then). docs/campaign.md.
#include <unistd.h>

#include <iostream>

#include "command.h"
#include "highlift/campaign/campaign.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/core/text_table.h"
#include "highlift/core/validate.h"

namespace highlift::cli {
namespace {

/// `interrupted_now`: a signal stopped this command's own session (main() then exits 130); a
/// summary of a file that an earlier session left interrupted says so in "interrupted".
int PrintSummary(const campaign::CampaignSummary& summary, bool json, bool interrupted_now = false) {
  if (json) {
    nlohmann::json document = summary.ToJson();
    if (interrupted_now) document["status"] = "interrupted";  // as every interrupted command's
    std::cout << JsonText(document) << "\n";
  }
  else std::cout << summary.FullReport() << "\n";
  return summary.complete() && summary.ok() ? kSuccess : kViolated;
}

class CampaignCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    app.add_option("project", project_, "JSON project file (drive system)");
    app.add_flag("--json", json_, "Print the summary as one JSON document on stdout");
    app.add_option("--out", out_, "directory of the result file campaign.sqlite (default: <project file name>.campaign, e.g. a380_class_flaps.campaign)");
    app.add_option("--cases", options_.case_patterns,
                   "only the cases matching these glob patterns, comma-separated (e.g. 'jam_*,rupture_shaft_l1')")
        ->delimiter(',');
    app.add_option("--corners", options_.corners,
                   "every combination of the min and max of these parameters, comma-separated "
                   "(e.g. pdu.motor_inertia,wtb_left.engagement_latency)")
        ->delimiter(',');
    app.add_option("--samples", options_.samples,
                   "quasi-random points per case over the parameter domains (default 0; at most " +
                       std::to_string(campaign::CampaignOptions::kMaxSamples) + ")");
    app.add_option("--seed", options_.seed, "seed of the quasi-random points (default 1)");
    app.add_flag("--feasible", options_.feasible,
                 "draw only points that the project's requirements allow (the constraint network of check; "
                 "a point it proves infeasible is drawn again, counted as a rejected draw)");
    app.add_option("--sampling", sampling_, "sobol (default) or lhs (Latin hypercube)");
    app.add_option("--vary", options_.vary,
                   "the parameters --samples varies, comma-separated (default: every parameter with a min and max)")
        ->delimiter(',');
    app.add_option("--model", model_, "full (default: split shafts) or reduced (lumped chains)");
    app.add_option("--elements", options_.shaft_elements,
                   "spring-dampers per torque shaft in the full model (default: the project's, at least 4; 1 to " +
                       std::to_string(sim::DriveNetworkOptions::kMaxShaftElements) + ", as for simulate)")
        ->check(NumberIn(1, sim::DriveNetworkOptions::kMaxShaftElements));
    app.add_option("--rtol", options_.relative_tolerance,
                   "relative tolerance of the simulator in every run (default: the project's "
                   "settings.relative_tolerance; docs/validation.md: envelope against tolerance)");
    app.add_option("--max-steps", options_.max_steps_per_output,
                   "solver steps a run may take per 1/" + std::to_string(campaign::CampaignOptions::kRowsPerRun) +
                       " of its simulated time before it fails as stiff or chattering (default: 10000 at rtol "
                       "1e-5 and above, more at a tighter --rtol, 39811 at 1e-8; docs/campaign.md)");
    app.add_option("--jobs", jobs_, "threads (default: every core)");
    app.add_option("--shard", shard_,
                   "run part I of N (0 <= I < N) into DIR/campaign-shard-I-of-N.sqlite (default inside a Slurm job "
                   "array: SLURM_ARRAY_TASK_ID of SLURM_ARRAY_TASK_COUNT)");

    summary_ = app.add_subcommand("summary", "print the envelope of a campaign result (DIR or file)");
    summary_->add_option("directory", summary_path_, "the --out directory of the campaign, or a result file")->required();
    summary_->add_flag("--json", summary_json_, "Print one JSON document on stdout");

    merge_ = app.add_subcommand("merge", "merge the shard files of a campaign into campaign.sqlite");
    merge_->add_option("inputs", merge_inputs_, "directories (or files) holding the shard files")->required();
    merge_->add_option("--out", merge_out_, "directory of the merged campaign.sqlite (default: the first input directory)");
    merge_->add_flag("--json", summary_json_, "Print the merged summary as one JSON document on stdout");
    app.require_subcommand(0, 1);
  }

  int Run() override {
    if (summary_->parsed()) return PrintSummary(campaign::LoadSummary(summary_path_), summary_json_);
    if (merge_->parsed()) {
      std::filesystem::path out = merge_out_;
      if (out.empty()) {
        const std::filesystem::path& first = merge_inputs_.front();
        out = std::filesystem::is_directory(first) ? first : first.parent_path();
        if (out.empty()) out = ".";
      }
      const std::filesystem::path merged = campaign::MergeShards(merge_inputs_, out);
      std::cerr << "highlift campaign merge: " << merge_inputs_.size() << " input(s) merged into " << merged.string() << "\n";
      return PrintSummary(campaign::LoadSummary(merged), summary_json_);
    }
    if (project_.empty())
      throw InputError("give the project file: highlift campaign PROJECT [--out DIR] (or `campaign summary DIR`, "
                       "`campaign merge DIR...`)");

    // Everything is checked before anything is written.
    campaign::ExecutionOptions run;
    if (!shard_.empty()) run.shard = campaign::Shard::Parse(shard_);
    else if (auto slurm = campaign::Shard::FromSlurmEnvironment()) run.shard = *slurm;
    if (jobs_ < 0) throw InputError("--jobs " + std::to_string(jobs_) + ": give 1 or more threads (0: every core)");
    run.jobs = jobs_;
    if (!sampling_.empty()) options_.sampling = campaign::ParseSamplingMethod(sampling_);
    if (!model_.empty()) options_.model = sim::ParseDriveResolution(model_);
    const Project project = LoadValidProject(project_);
    const campaign::Plan plan = campaign::MakePlan(project, options_);
    run.directory = out_.empty() ? std::filesystem::path(project_).stem().concat(".campaign") : std::filesystem::path(out_);
    run.progress = &std::cerr;
    run.progress_is_terminal = isatty(STDERR_FILENO) != 0;
    std::cerr << "highlift campaign: " << plan.cases.size() << " case(s) x " << plan.samples_per_case << " sample(s) = "
              << plan.runs() << " runs (" << sim::ToString(options_.model) << " model, rtol "
              << FormatNumber(options_.relative_tolerance > 0 ? options_.relative_tolerance
                                                              : project.settings.relative_tolerance,
                              3)
              << ", at most " << plan.options.max_steps_per_output << " steps per 1/"
              << campaign::CampaignOptions::kRowsPerRun << " of a run, campaign " << plan.campaign_id
              << ")" << (run.shard.whole() ? "" : ", shard " + run.shard.ToString()) << " -> "
              << campaign::ResultFile(run.directory, run.shard).string() << "\n";
    const campaign::CampaignReport report = campaign::RunCampaign(project, plan, run);
    std::cerr << report.BriefReport() << "\n";
    campaign::CampaignSummary summary = campaign::LoadSummary(report.file);
    if (report.interrupted_signal != 0) summary.interrupted_signal = report.interrupted_signal;  // main() then exits 130
    return PrintSummary(summary, json_, report.interrupted_signal != 0);
  }

 private:
  std::string project_;
  bool json_ = false;
  std::string out_;
  campaign::CampaignOptions options_;
  std::string sampling_;
  std::string model_;
  int jobs_ = 0;
  std::string shard_;
  CLI::App* summary_ = nullptr;
  std::string summary_path_;
  bool summary_json_ = false;
  CLI::App* merge_ = nullptr;
  std::vector<std::filesystem::path> merge_inputs_;
  std::string merge_out_;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(CampaignCommand, "campaign",
                          "design-load campaign: every failure case over samples of the parameter domains, on all "
                          "cores or as Slurm shards (summary, merge)")

}  // namespace highlift::cli
