// `highlift tradeoff PROJECT.json --vary NAME=LO:HI:N --show NAME[,NAME...] [--json]`: splits the
// domain of one quantity into N slices, propagates each and prints how the shown domains respond
// (the paper's trade-off study). A slice with no solution is marked infeasible, a slice that does
// not meet the project's domain of NAME "outside the domain", a slice whose propagation stopped at
// a limit says so (its domains are sound but may narrow further). Values are in the display unit
// of each quantity. Exit 0, or 2 on invalid input.
#include <cmath>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "command.h"
#include "estimated_project.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/core/text_table.h"
#include "highlift/core/units.h"
#include "highlift/icsp/drive_system.h"
#include "highlift/icsp/parser.h"

namespace highlift::cli {
namespace {

using icsp::Interval;

icsp::VariableId Lookup(const icsp::Network& net, const std::string& name, const std::string& option) {
  const icsp::VariableId v = net.FindVariable(name);
  if (v.value >= 0) return v;
  const auto close = icsp::ClosestNames(name, net.VariableNames());
  std::string msg = option + ": unknown quantity '" + name + "'";
  msg += close.empty() ? "; run `highlift check` to list the quantities" : "; did you mean '" + close[0] + "'?";
  throw InputError(msg);
}

class TradeoffCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    options_.AddTo(app);
    app.add_flag("--no-estimate", no_estimate_,
                 "Use the project's own domains only: no database, fit or physics estimates");
    app.add_option("--vary", vary_, "NAME=LO:HI:N, LO and HI in the quantity's display unit")->required();
    app.add_option("--show", show_, "NAME[,NAME...] quantities to print")->required()->delimiter(',');
  }

  int Run() override {
    const auto eq = vary_.find('=');
    std::string name, lo_s, hi_s, n_s;
    if (eq != std::string::npos) {
      name = vary_.substr(0, eq);
      std::stringstream rest(vary_.substr(eq + 1));
      std::getline(rest, lo_s, ':');
      std::getline(rest, hi_s, ':');
      std::getline(rest, n_s, ':');
    }
    double lo = 0, hi = 0, count = 0;
    if (!CLI::detail::lexical_cast(lo_s, lo) || !CLI::detail::lexical_cast(hi_s, hi) ||
        !CLI::detail::lexical_cast(n_s, count))
      throw InputError("--vary '" + vary_ + "' is not NAME=LO:HI:N; write e.g. --vary pdu.max_output_speed=20:30:5");
    if (!std::isfinite(lo) || !std::isfinite(hi))
      throw InputError("--vary '" + vary_ + "': LO and HI must be finite numbers (not inf or nan)");
    if (!(lo < hi) || !(count >= 1 && count <= 1000) || count != std::floor(count)) {
      throw InputError("--vary '" + vary_ + "': need LO < HI and a whole N from 1 to 1000");
    }
    // HI - LO must be a finite number: the slices are LO + k (HI - LO) / N (1e308 - -1e308 is inf).
    if (!std::isfinite(hi - lo))
      throw InputError("--vary '" + vary_ + "': the width HI - LO = " + FormatMessageNumber(hi - lo) +
                       " is beyond the largest number; give LO and HI whose difference is finite (e.g. within -1e300 to 1e300)");
    const int n = static_cast<int>(count);
    const EstimatedProject loaded = LoadEstimatedProject(options_, !no_estimate_);
    const Project& project = loaded.project;
    const icsp::DriveSystemNetwork dn = icsp::BuildDriveSystemNetwork(project);
    const icsp::Network& net = dn.network;
    const icsp::VariableId varied = Lookup(net, name, "--vary");
    std::vector<icsp::VariableId> shown;
    for (const auto& s : show_) shown.push_back(Lookup(net, s, "--show"));
    const std::string unit = net.variable(varied).unit;
    // Display unit -> SI (with the unit's offset, e.g. degC).
    UnitConversion to_si;
    if (!unit.empty() && unit != "1") to_si = ParseUnit(unit);
    for (const double x : {lo, hi})
      if (!std::isfinite(to_si.scale * x + to_si.offset))
        throw InputError("--vary '" + vary_ + "': " + FormatMessageNumber(x) + " " + unit + " is beyond the largest number in SI units (" +
                         FormatMessageNumber(to_si.scale * x + to_si.offset) + "); give LO and HI within +-" +
                         FormatMessageNumber(1e300 / std::abs(to_si.scale)) + " " + unit);
    icsp::Propagator prop(net, {});
    std::vector<std::string> header{name + (unit.empty() ? "" : " [" + unit + "]")};
    for (const auto& v : shown) {
      const auto& u = net.variable(v).unit;
      header.push_back(net.variable(v).name + (u.empty() ? "" : " [" + u + "]"));
    }
    TextTable table(header);
    nlohmann::json rows = nlohmann::json::array();
    for (int k = 0; k < n; ++k) {
      const double a = lo + (hi - lo) * k / n, b = lo + (hi - lo) * (k + 1) / n;
      icsp::Box box = net.InitialBox();
      double lo_si = to_si.scale * a + to_si.offset, hi_si = to_si.scale * b + to_si.offset;
      if (lo_si > hi_si) std::swap(lo_si, hi_si);
      box[varied.value] = icsp::Meet(box[varied.value], Interval(lo_si, hi_si));
      // A slice outside the project's domain of NAME is not a design that fails: say so.
      const bool outside = icsp::IsEmpty(box[varied.value]);
      const icsp::Status status = outside ? icsp::Status::kInfeasible : prop.Propagate(box).status;
      const bool ok = !outside && status != icsp::Status::kInfeasible;
      std::vector<std::string> cells{"[" + FormatNumber(a, 5) + ", " + FormatNumber(b, 5) + "]" +
                                     (status == icsp::Status::kStoppedAtLimit ? " (stopped at a limit)" : "")};
      nlohmann::json row = {{"slice", {a, b}}, {"feasible", ok}, {"outside_domain", outside},
                            {"status", outside ? "outside_domain" : icsp::ToString(status)}};
      for (const auto& v : shown) {
        const auto& u = net.variable(v).unit;
        if (!ok) {
          cells.push_back(outside ? "outside the domain" : "infeasible");
          row[net.variable(v).name] = nullptr;
          continue;
        }
        const double x0 = icsp::ToDisplay(box[v.value].lower(), u), x1 = icsp::ToDisplay(box[v.value].upper(), u);
        cells.push_back("[" + FormatNumber(x0, 5) + ", " + FormatNumber(x1, 5) + "]");
        row[net.variable(v).name] = {std::isfinite(x0) ? nlohmann::json(x0) : nlohmann::json("-inf"),
                                     std::isfinite(x1) ? nlohmann::json(x1) : nlohmann::json("inf")};
      }
      table.AddRow(cells);
      rows.push_back(row);
    }
    if (options_.json) {
      std::cout << JsonText(nlohmann::json{{"vary", name}, {"unit", unit}, {"rows", rows}}) << "\n";
    } else {
      int feasible = 0;
      for (const auto& row : rows) feasible += row["feasible"].get<bool>();
      std::cout << name << " over [" << FormatNumber(lo, 5) << ", " << FormatNumber(hi, 5) << "]"
                << (unit.empty() ? "" : " " + unit) << ": " << feasible << " of " << n
                << " slices can meet every requirement\n\n"
                << table.ToString();
    }
    return kSuccess;
  }

 private:
  CommonOptions options_;
  bool no_estimate_ = false;  // skip the estimator (domains as given and catalogue defaults)
  std::string vary_;
  std::vector<std::string> show_;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(TradeoffCommand, "tradeoff",
                          "split one domain into slices, propagate each and show how other domains respond")

}  // namespace highlift::cli
