// The last MSL 4.0.0 Rotational elements a 1-D network uses: Components.Disc,
// Components.InitializeFlange, Sources.InverseSpeedDependentTorque, and Components.Gearbox as
// a composite of LossyGear and ElastoBacklash in series (MSL's own structure).
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>
#include <utility>

#include "composites.h"
#include "highlift/core/error.h"
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {
namespace {

using namespace msl;

/// Disc: flange_b.phi = flange_a.phi + deltaPhi, no inertia, the torque passes through
/// (flange_a.tau + flange_b.tau = 0). A rigid joint with an angle offset: a constraint on the
/// accelerations (its multiplier is flange_a.tau) and initial equations on the start angles and speeds.
class Disc : public TwoFlange {
 public:
  explicit Disc(const NetworkElement& e) : deltaPhi(Param(e, "deltaPhi")) {}
  std::vector<int> CoupledNodes() const override { return {a, b}; }
  /// The joint at the start, as initial equations (a holonomic row would give the speeds the
  /// offset too): phi_b - phi_a = deltaPhi, w_b - w_a = 0.
  void InitialEquations(std::vector<InitialEquation>& position, std::vector<InitialEquation>& speed) const override {
    position.push_back({{{b, 1.0}, {a, -1.0}}, deltaPhi});
    speed.push_back({{{b, 1.0}, {a, -1.0}}, 0.0});
  }
  void Constraints(Eval& e) override {
    Constraint& c = e.NewConstraint(index);
    c.row.assign({{a, 1.0}, {b, -1.0}});
    c.column.assign({{a, -1.0}, {b, 1.0}});  // multiplier = flange_a.tau
    constraint = e.n_constraints - 1;
  }
  void AfterSolve(Eval& e) override { tau = e.constraints[constraint].lambda; }
  /// MSL Disc.phi = flange_a.phi + deltaPhi/2 (the middle of the disc), and the torque through.
  std::vector<std::string> OutputNames() const override { return {"phi", "flange_a.tau"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = e.phi[a] + deltaPhi / 2;
    out[1] = tau;
  }
  double PeakTorque(const Eval&) const override { return tau; }
  double deltaPhi;
  int constraint = -1;
  double tau = 0.0;
};

/// InitializeFlange: the enabled inputs phi_start, w_start, a_start (use_phi_start, use_w_start,
/// use_a_start) give the initial equations flange.phi = phi_start, der(flange.phi) = w_start and
/// der(w) = a_start at the start time; flange.tau = 0 throughout. The first two join the start
/// equations of the inertias and motion sources (contradicting fixed start values are named);
/// the third joins their a_start equations (System::SolveInitialAccelerations). stateSelect
/// has nothing to choose here: a flange's angle and speed are the states of its node anyway.
class InitializeFlange : public Element {
 public:
  explicit InitializeFlange(const NetworkElement& e)
      : use_phi(Param(e, "use_phi_start") != 0), use_w(Param(e, "use_w_start") != 0),
        use_a(Param(e, "use_a_start") != 0) {}
  std::vector<std::string> Flanges() const override { return {"flange"}; }
  std::vector<std::string> SignalInputs() const override {
    std::vector<std::string> in;
    if (use_phi) in.push_back("phi_start");
    if (use_w) in.push_back("w_start");
    if (use_a) in.push_back("a_start");
    return in;
  }
  void Bind(const std::function<int(const std::string&)>& node_of,
            const std::function<int(const std::string&)>& signal_of) override {
    n = node_of("flange");
    if (use_phi) phi_in = signal_of("phi_start");
    if (use_w) w_in = signal_of("w_start");
    if (use_a) a_in = signal_of("a_start");
  }
  std::vector<int> Nodes() const override { return {n}; }
  MasslessRole RoleAt(int) const override { return MasslessRole::kNoTorque; }
  void InitialEquationsAt(const Eval& e, std::vector<InitialEquation>& position,
                          std::vector<InitialEquation>& speed) const override {
    if (use_phi) position.push_back({{{n, 1.0}}, e.signal[phi_in]});
    if (use_w) speed.push_back({{{n, 1.0}}, e.signal[w_in]});
    // The input at the start time, for InitialAccelerations (called after the start angles).
    if (use_a) a_start = e.signal[a_in];
  }
  void InitialAccelerations(std::vector<std::pair<int, double>>& acceleration) const override {
    if (use_a) acceleration.push_back({n, a_start});
  }
  std::vector<std::string> OutputNames() const override { return {"phi_flange", "w_flange"}; }
  void Outputs(const Eval& e, double* out) const override {
    out[0] = e.phi[n];
    out[1] = e.w[n];
  }
  bool use_phi, use_w, use_a;
  int n = -1, phi_in = -1, w_in = -1, a_in = -1;
  mutable double a_start = 0.0;
};

/// InverseSpeedDependentTorque (MSL after 4.0.0, see docs/simulation.md), w = flange - support:
///   TorqueDirection:  tau = tau_nominal * w_nominal / max(|w|, w0)
///   otherwise:        tau = tau_nominal * w / w0 for |w| < w0, tau_nominal * w_nominal / w beyond
/// (MSL's text; the second jumps at |w| = w0 unless w_nominal = w0). The roots w = +-w0 locate
/// the switch of branch; the integrator restarts there where the torque jumps.
class InverseSpeedDependentTorque : public TorqueSource {
 public:
  explicit InverseSpeedDependentTorque(const NetworkElement& e)
      : tau_nominal(Param(e, "tau_nominal")), w_nominal(Param(e, "w_nominal")), w0(Param(e, "w0")),
        same_direction(Param(e, "TorqueDirection") != 0) {}
  double U(const Eval& e) const override {
    const double w = W(e);
    if (same_direction) return tau_nominal * w_nominal / std::max(std::abs(w), w0);
    return std::abs(w) < w0 ? tau_nominal * w / w0 : tau_nominal * w_nominal / w;
  }
  int NumRoots() const override { return 2; }
  void Roots(const Eval& e, double* g) const override {
    g[0] = W(e) - w0;
    g[1] = W(e) + w0;
  }
  bool RootsNeedSolve() const override { return false; }  // the speed
  bool RootRestarts(int) const override { return !same_direction; }
  double tau_nominal, w_nominal, w0;
  bool same_direction;
};

/// A part of a composite with the given scalars and tables (the catalogue defaults filled in
/// by Network::AddElement), named `id`.
NetworkElement TablePart(const NetworkElement& owner, const std::string& type, const std::string& id,
                         std::map<std::string, double> scalars, std::map<std::string, Table> tables) {
  Network scratch;
  try {
    scratch.AddElement(type, "part", ElementParameters{std::move(scalars), std::move(tables)});
  } catch (const InputError& error) {
    throw InputError("element '" + owner.id + "' (" + owner.type + "): its part '" + id + "' (" + type +
                     ") is invalid: " + error.message());
  }
  NetworkElement part = scratch.elements().front();
  part.id = id;
  return part;
}

/// Gearbox as MSL builds it: lossyGear (ratio, lossTable, support) from flange_a, then
/// elastoBacklash (c, d, b, phi_rel0 = 0) to flange_b. The ElastoBacklash keeps the
/// composite's id, so its phi_rel, w_rel and torque are reported as the Gearbox's (MSL
/// Gearbox.phi_rel = flange_b.phi - lossyGear.flange_b.phi).
std::optional<Composite> ExpandGearbox(const NetworkElement& e) {
  Composite out;
  std::map<std::string, Table> tables;
  if (auto it = e.parameters.tables.find("lossTable"); it != e.parameters.tables.end()) tables["lossTable"] = it->second;
  const std::string gear = e.id + ".lossyGear";
  out.inner.Adopt(TablePart(e, "LossyGear", gear, {{"ratio", Param(e, "ratio")}}, std::move(tables)));
  std::map<std::string, double> elastic{{"c", Param(e, "c")}, {"d", Param(e, "d")}, {"b", Param(e, "b")}};
  for (const char* start : {"phi_rel_start", "w_rel_start", "phi_nominal"})
    if (Given(e, start)) elastic[start] = Param(e, start);
  out.inner.Adopt(TablePart(e, "ElastoBacklash", e.id, std::move(elastic), {}));
  out.inner.Connect(gear + ".flange_b", e.id + ".flange_a");
  out.ports["flange_a"] = {gear + ".flange_a"};
  out.ports["flange_b"] = {e.id + ".flange_b"};
  out.ports["support"] = {gear + ".support"};
  return out;
}

/// TorqueToAngleAdaptor (MSL: flange.tau = tau, phi = flange.phi, w = der(phi), a = der(w)):
/// the input acts on the flange's node as -tau (a Torque of the negated input), and angle,
/// speed and acceleration sensors give the outputs (w and a when use_w, use_a).
std::optional<Composite> ExpandTorqueToAngle(const NetworkElement& e) {
  Composite out;
  const std::string gain = e.id + ".gain", torque = e.id + ".torque";
  out.inner.Adopt(TablePart(e, "Gain", gain, {{"k", -1.0}}, {}));
  out.inner.Adopt(TablePart(e, "Torque", torque, {}, {}));
  out.inner.Connect(gain + ".y", torque + ".tau");
  out.ports["flange"] = {torque + ".flange"};
  out.ports["tau"] = {gain + ".u"};
  const bool use_w = Param(e, "use_w") != 0, use_a = Param(e, "use_a") != 0;
  for (auto [sensor, port, used] : {std::tuple{"AngleSensor", "phi", true}, std::tuple{"SpeedSensor", "w", use_w},
                                    std::tuple{"AccSensor", "a", use_a}}) {
    if (!used) continue;
    const std::string id = e.id + "." + port + "Sensor";
    out.inner.Adopt(TablePart(e, sensor, id, {}, {}));
    out.inner.Connect(id + ".flange", torque + ".flange");
    out.ports[port] = {id + "." + port};
  }
  return out;
}

/// AngleToTorqueAdaptor (MSL): the flange is moved by the inputs and the output tau is the
/// torque that takes (a torque sensor between the motion source and the flange). use_a: a Move
/// of (phi, w, a); otherwise the angle alone forced exactly (MSL Move_phi and Move_w, which
/// differentiate phi; MSL requires w = der(phi), so the input w is not read).
std::optional<Composite> ExpandAngleToTorque(const NetworkElement& e) {
  Composite out;
  const bool use_a = Param(e, "use_a") != 0, use_w = use_a || Param(e, "use_w") != 0;
  const std::string move = e.id + ".move";
  if (use_a) {
    out.inner.Adopt(TablePart(e, "Move", move, {}, {}));
    out.ports["phi"] = {move + ".u[1]"};
    out.ports["w"] = {move + ".u[2]"};
    out.ports["a"] = {move + ".u[3]"};
  } else {
    out.inner.Adopt(TablePart(e, "Position", move, {{"exact", 1.0}}, {}));
    out.ports["phi"] = {move + ".phi_ref"};
    if (use_w) out.ports["w"] = {};
  }
  out.inner.Adopt(TablePart(e, "TorqueSensor", e.id, {}, {}));
  out.inner.Connect(move + ".flange", e.id + ".flange_a");
  out.ports["flange"] = {e.id + ".flange_b"};
  out.ports["tau"] = {e.id + ".tau"};
  return out;
}

}  // namespace

std::optional<Composite> ExpandMslComposite(const NetworkElement& element) {
  if (element.type == "Gearbox") return ExpandGearbox(element);
  if (element.type == "TorqueToAngleAdaptor") return ExpandTorqueToAngle(element);
  if (element.type == "AngleToTorqueAdaptor") return ExpandAngleToTorque(element);
  return std::nullopt;
}

std::unique_ptr<Element> MakeExtraMslElement(const NetworkElement& e) {
  const std::string& t = e.type;
  if (t == "Disc") return std::make_unique<Disc>(e);
  if (t == "InitializeFlange") return std::make_unique<InitializeFlange>(e);
  if (t == "InverseSpeedDependentTorque") return std::make_unique<InverseSpeedDependentTorque>(e);
  return nullptr;
}

}  // namespace highlift::sim::detail
