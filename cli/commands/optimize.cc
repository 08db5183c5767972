// `highlift optimize PROJECT.json --minimize mass|inertia|EXPR [--design NAME ...] [--tube-sizes FILE|standard]
// [--write OUT.json]`:
// synthesis by interval branch and bound (optimize::Optimize, docs/optimize.md). The answer first:
// status, best objective, certified lower bound and gap; then the design, the mass by component,
// what limits the design, and the counters. Exit 0 with a design (optimal or gap still open),
// 1 when the problem is proved infeasible (with check's explanation) or no design was found, 2 on
// invalid input (no design variable, unbounded objective, a name that is not a parameter).
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>

#include "command.h"
#include "estimated_project.h"
#include "highlift/campaign/campaign.h"
#include "highlift/componentdb/tube_sizes.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/estimation/estimator.h"
#include "highlift/core/validate.h"
#include "highlift/optimize/optimize.h"

namespace highlift::cli {
namespace {

class OptimizeCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    common_.AddTo(app);
    app.add_option("--minimize", options_.objective,
                   "the objective: mass (shafts by their tube law, other parts by their estimation laws), inertia "
                   "(at the PDU speed) or an expression of the constraint language (default mass)");
    app.add_option("--design", options_.design,
                   "a design variable COMPONENT.PARAMETER (repeatable), chosen within its domain; in addition to the "
                   "parameters the project marks \"design\": true")
        ->delimiter(',');
    app.add_option("--same-value", same_value_,
                   "A,B[,C...]: identical parts (repeatable, one group each): A is a design variable and B, C, ... "
                   "take its value (e.g. every actuator's ratio: gra_l1.ratio,gra_l2.ratio); each needs a \"min\" and "
                   "\"max\" with a common range")
        ->allow_extra_args(false);
    app.add_option("--pareto", pareto_,
                   "OBJ1,OBJ2: the Pareto front of two objectives by epsilon constraints (OBJ1 as --minimize; OBJ2 an "
                   "expression of the constraint language, e.g. mass,peak.jam_l1.torque)");
    app.add_option("--pareto-points", options_.pareto_points, "epsilon values of --pareto (default 5)")
        ->check(NumberIn(2, 50));
    app.add_option("--choose-part", choose_part_,
                   "a discrete choice COMPONENT (repeatable): the component is one of the database's parts of its "
                   "type, each part's values fixed from its row (provenance database); the search branches over them")
        ->delimiter(',');
    app.add_option("--tube-sizes", tube_sizes_,
                   "FILE or standard: every torque shaft whose outer_diameter and/or wall_thickness are design "
                   "variables is one of these tube sizes (CSV: designation,outer_diameter [mm],wall_thickness [mm]; "
                   "standard: the shipped ISO 3 R20 table, docs/optimize.md)");
    app.add_option("--write", write_, "write the project with the best design fixed (provenance \"optimized\") to this file");
    app.add_flag("--verify-transient", verify_transient_,
                 "run the best design's campaign (every jam and rupture, full transient simulations) at its nominal "
                 "point and --transient-samples quasi-random points of its remaining uncertain parameters, and report "
                 "its envelope; exit 1 when the campaign finds a negative margin or a failed run");
    app.add_option("--transient-samples", transient_samples_,
                   "quasi-random points per case of --verify-transient (default 4)")
        ->check(NumberIn(0, 100000));
    app.add_option("--transient-out", transient_out_,
                   "directory of --verify-transient's campaign result (default OUT.campaign beside --write, or "
                   "PROJECT-optimized.campaign)");
    app.add_option("--max-boxes", options_.max_boxes, "stop after this many boxes (default 20000)")->check(NumberIn(1, 1e9));
    app.add_option("--gap", options_.relative_gap, "stop when the relative gap is below this (default 1e-6)")
        ->check(NumberIn(0.0, 1.0));
    app.add_option("--time-limit", options_.max_seconds, "stop after this many seconds (default 60)")
        ->check(NumberIn(0.0, 1e6, true));
    app.add_flag("--no-verify", no_verify_,
                 "accept designs by the interval check alone, without running size and peak on each (faster; the "
                 "design may then fail `highlift size` or `highlift peak`)");
    app.add_flag("--no-verify-peak", no_verify_peak_,
                 "do not run peak on each design (size still runs); the design may then fail `highlift peak`");
    app.add_flag("--no-estimate", no_estimate_,
                 "use the project's own domains only: no database, fit or physics estimates (as check --no-estimate)");
  }

  int Run() override {
    for (const std::string& text : same_value_) {
      std::vector<std::string> group;
      for (std::size_t from = 0;;) {
        const std::size_t comma = text.find(',', from);
        group.push_back(text.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
        if (group.back().empty())
          throw InputError("--same-value '" + text + "': an empty name; give COMPONENT.PARAMETER names separated by "
                           "commas, the design variable first (e.g. gra_l1.ratio,gra_l2.ratio)");
        if (comma == std::string::npos) break;
        from = comma + 1;
      }
      options_.same_value.push_back(std::move(group));
    }
    options_.verify_size = !no_verify_;
    options_.verify_peak = !no_verify_ && !no_verify_peak_;
    options_.Validate();
    if (!pareto_.empty()) {
      const auto comma = pareto_.find(',');
      if (comma == std::string::npos || comma == 0 || comma + 1 == pareto_.size())
        throw InputError("--pareto '" + pareto_ + "': give two objectives OBJ1,OBJ2 (e.g. mass,peak.jam_l1.torque)");
      options_.objective = pareto_.substr(0, comma);
      options_.pareto = pareto_.substr(comma + 1);
      options_.Validate();
    }
    if (!tube_sizes_.empty()) {
      options_.tube_sizes = componentdb::LoadTubeSizes(tube_sizes_);
      options_.Validate();
    }
    if (transient_samples_ != 4 && !verify_transient_)
      throw InputError("--transient-samples needs --verify-transient");
    std::optional<componentdb::ComponentDatabase> database;
    EstimatedProject loaded;
    if (choose_part_.empty()) {
      // Every member of a --same-value group is marked as the design variables are, so that the
      // estimator leaves what follows from it by a law to the network (as for the design).
      std::vector<std::string> marked = options_.design;
      for (const std::vector<std::string>& group : options_.same_value) marked.insert(marked.end(), group.begin(), group.end());
      loaded = LoadEstimatedProject(common_, !no_estimate_, marked);
    } else {
      // Each part combination is estimated after its parts are applied (what a part implies
      // follows it), so the project is loaded as given.
      loaded.project = LoadValidProject(common_.project);
      database.emplace(OpenEstimationDatabase(common_.db));
      options_.choose_part = PartChoices(loaded.project, *database);
      if (!no_estimate_)
        options_.prepare = [&database, this](Project& p) {
          MarkDesign(p, options_.design);
          estimation::EstimateProject(p, &*database, {});
        };
    }
    const optimize::Report report = optimize::Optimize(loaded.project, options_);
    // The project as given (not the estimated one) with the chosen parts and the design fixed, so
    // that `highlift size` and `peak` read the same file the engineer wrote.
    // The project as given: its content hash identifies the result (`highlift report --optimize`
    // shows a result only beside the project it belongs to, or beside the design written from it).
    const Project given = LoadValidProject(common_.project);
    std::optional<Project> design;
    if (report.found) {
      Project out = given;
      for (const auto& [component, designation] : report.parts)
        for (const optimize::PartChoice& c : options_.choose_part)
          for (const optimize::PartOption& part : c.parts)
            if (c.component == component && part.designation == designation) optimize::ApplyPart(out, component, part);
      std::vector<std::pair<std::string, double>> values;
      for (const auto& d : report.design) values.push_back({d.name, d.value_si});
      design = optimize::FixDesign(out, values);
      for (const auto& [component, size] : report.tube_sizes)
        for (const char* p : {"outer_diameter", "wall_thickness"}) {
          auto& ps = design->FindComponent(component)->parameters;
          const auto it = ps.find(p);
          if (it != ps.end() && it->second.provenance == Provenance::kOptimized)
            it->second.note = "highlift optimize: tube size " + size + " of --tube-sizes " + report.tube_table;
        }
      if (!write_.empty()) SaveProject(*design, write_);
    }
    std::optional<campaign::CampaignSummary> transient;
    if (verify_transient_ && design) transient = VerifyTransient(*design);
    if (common_.json) {
      nlohmann::json j = report.ToJson();
      j["project"] = common_.project;
      j["project_name"] = given.name;
      j["project_hash"] = campaign::ProjectHash(given);
      // The design as `--write` writes it (and as `highlift report` reads it back).
      if (design) j["design_hash"] = campaign::ProjectHash(ParseProject(ProjectToJson(*design).dump(), common_.project));
      if (!write_.empty() && report.found) j["written"] = write_;
      if (transient) j["transient"] = transient->ToJson();
      std::cout << j.dump(2) << "\n";
    } else {
      std::cout << report.BriefReport() << "\n\n" << report.FullReport();
      if (!loaded.estimation_brief.empty()) std::cout << "domains: " << loaded.estimation_brief << "\n";
      if (!write_.empty() && report.found) std::cout << "wrote " << write_ << "\n";
      if (transient) std::cout << "\nTransient verification of the best design:\n" << transient->FullReport();
    }
    if (verify_transient_ && !design) std::cerr << "highlift optimize: no transient verification: no design was found\n";
    if (!write_.empty() && !report.found)
      std::cerr << "highlift optimize: nothing written to " << write_ << ": no design was found\n";
    if (transient && !transient->ok()) return kViolated;
    return report.found ? kSuccess : kViolated;
  }

 private:
  /// The best design's campaign (reusing the campaign module as `highlift campaign` does): every
  /// case at the nominal point and transient_samples_ points of the remaining domains.
  campaign::CampaignSummary VerifyTransient(const Project& design) const {
    campaign::CampaignOptions co;
    co.samples = transient_samples_;
    const campaign::Plan plan = campaign::MakePlan(design, co);
    campaign::ExecutionOptions run;
    run.directory = !transient_out_.empty() ? std::filesystem::path(transient_out_)
                    : !write_.empty()       ? std::filesystem::path(write_).replace_extension(".campaign")
                                            : std::filesystem::path(common_.project).stem().concat("-optimized.campaign");
    std::cerr << "highlift optimize: transient verification: " << plan.cases.size() << " case(s) x "
              << plan.samples_per_case << " sample(s) = " << plan.runs() << " runs -> "
              << campaign::ResultFile(run.directory, run.shard).string() << "\n";
    const campaign::CampaignReport report = campaign::RunCampaign(design, plan, run);
    std::cerr << report.BriefReport() << "\n";
    return campaign::LoadSummary(report.file);
  }

  /// The database's parts of each --choose-part component's type, as values to fix.
  std::vector<optimize::PartChoice> PartChoices(const Project& project, const componentdb::ComponentDatabase& db) const {
    std::vector<optimize::PartChoice> out;
    for (const std::string& id : choose_part_) {
      const Component* c = project.FindComponent(id);
      if (!c) throw InputError("--choose-part " + id + ": no component '" + id + "' in " + common_.project);
      optimize::PartChoice choice{id, {}};
      const ComponentTypeSpec* type = FindComponentType(c->type);
      for (const componentdb::Part& part : db.Parts(c->type)) {
        optimize::PartOption option{part.designation, {}};
        for (const componentdb::Quantity& q : part.parameters) {
          const ParameterSpec* spec = type ? type->FindParameter(q.name) : nullptr;
          if (!spec || (spec->kind != ParameterKind::kScalar && spec->kind != ParameterKind::kInteger)) continue;
          Parameter par;
          par.nominal = q.value_si ? *q.value_si : 0.5 * (q.domain_si.lo + q.domain_si.hi);
          par.domain = q.domain_si.bounded() ? q.domain_si : Domain::Point(*par.nominal);
          par.provenance = Provenance::kDatabase;
          par.note = "database part " + part.designation;
          par.database_part = part.designation;
          option.values[q.name] = par;
        }
        choice.parts.push_back(std::move(option));
      }
      if (choice.parts.empty()) {
        std::set<std::string> types;
        for (const componentdb::Part& part : db.Parts()) types.insert(part.type);
        std::string have;
        for (const std::string& t : types) have += (have.empty() ? "" : ", ") + t;
        throw InputError("--choose-part " + id + ": the database " + db.file().string() + " has no part of type '" +
                         c->type + "' (" + (have.empty() ? "it has no parts" : "it has parts of: " + have) +
                         "); choose a component of a type it has parts of, or import parts with 'highlift db import'");
      }
      out.push_back(std::move(choice));
    }
    return out;
  }

  CommonOptions common_;
  optimize::Options options_;
  std::string write_;
  std::vector<std::string> choose_part_;
  std::vector<std::string> same_value_;  // --same-value, one group per occurrence
  std::string tube_sizes_;
  std::string pareto_;
  bool verify_transient_ = false;
  int transient_samples_ = 4;
  std::string transient_out_;
  bool no_verify_ = false;
  bool no_verify_peak_ = false;
  bool no_estimate_ = false;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(OptimizeCommand, "optimize",
                          "find the design of least mass, inertia or any expression that meets every requirement and "
                          "margin, with a certified lower bound (interval branch and bound)")

}  // namespace highlift::cli
