// The station input gearbox (model/src/components/station_input_gearbox.cc), the component type
// added in one file: its declaration in the catalogue, its laws composed of the branch gearbox's
// and the station torque limiter's, and its expansion into two elements.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "highlift/core/catalogue.h"
#include "highlift/core/project_io.h"
#include "highlift/model/component_model.h"
#include "highlift/model/drive_network.h"

namespace highlift::model {
namespace {

const char* const kType = "station_input_gearbox";

std::filesystem::path RigFile() {
  return std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "tests" / "model" / "station_input_gearbox.json";
}

/// Reads the values given, else the catalogue defaults of `type` (as the analyses do).
class DefaultsReader final : public ParameterReader<double> {
 public:
  DefaultsReader(std::string type, std::map<std::string, double> given)
      : spec_(*FindComponentType(type)), given_(std::move(given)) {}
  double operator()(std::string_view name) const override {
    auto it = given_.find(std::string(name));
    return it != given_.end() ? it->second : *spec_.FindParameter(name)->nominal;
  }
  bool Has(std::string_view name) const override {
    const ParameterSpec* p = spec_.FindParameter(name);
    return given_.count(std::string(name)) > 0 || (p && p->nominal);
  }
  double Nominal(std::string_view name) const override { return (*this)(name); }

 private:
  const ComponentTypeSpec& spec_;
  std::map<std::string, double> given_;
};

TEST(StationInputGearbox, IsDeclaredAsAGearWithAStationLimiterOnItsBranch) {
  const ComponentTypeSpec* spec = FindComponentType(kType);
  ASSERT_NE(spec, nullptr);
  EXPECT_TRUE(spec->roles.station_limiter);
  EXPECT_TRUE(spec->roles.lumps_inertia);
  EXPECT_FALSE(spec->roles.chain_member);
  ASSERT_NE(spec->GearedPort(), nullptr);
  EXPECT_EQ(spec->GearedPort()->name, "branch");
  EXPECT_FALSE(spec->FindPort("through")->required);
  // The gear stage counts on the shaft, the limiter behind it on the actuator input.
  EXPECT_EQ(spec->FindParameter("inertia")->referred_to, ReferenceSide::kShaft);
  for (const char* name : {"lockout_torque_extend", "lockout_torque_retract", "end_stop_torque", "stiffness_normal",
                           "max_brake_torque", "limiter_inertia"})
    EXPECT_EQ(spec->FindParameter(name)->referred_to, ReferenceSide::kActuatorInput) << name;
  // Its defaults are the station's of domain.md s3: 2:1 and a 180 N*m (90 N*m at the shaft) limiter.
  EXPECT_DOUBLE_EQ(*spec->FindParameter("ratio")->nominal, 2.0);
  EXPECT_DOUBLE_EQ(*spec->FindParameter("lockout_torque_extend")->nominal, 180.0);
  EXPECT_DOUBLE_EQ(*spec->FindParameter("lockout_torque_retract")->nominal, 0.7 * 180.0);
  // Registered in catalogue order, right after the separate station limiter.
  const auto names = ComponentTypeNames();
  const auto at = std::find(names.begin(), names.end(), kType);
  ASSERT_NE(at, names.end());
  EXPECT_EQ(*std::prev(at), "station_torque_limiter");
  EXPECT_EQ(ComponentModels()[static_cast<std::size_t>(at - names.begin())]->type(), kType);
}

TEST(StationInputGearbox, LimitsThePowerLeavingAtItsBranch) {
  const ComponentModel* m = FindComponentModel(kType);
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->LimitedPort(), "branch");
  EXPECT_EQ(FindComponentModel("station_torque_limiter")->LimitedPort(), "");
  EXPECT_EQ(m->PowerPorts(), (std::vector<std::string>{"branch", "through"}));
  const PortRatio law = m->SpeedRatioLaw("input", "branch");
  EXPECT_EQ(law.parameter, "ratio");
  EXPECT_EQ(law.power, -1);
  EXPECT_EQ(m->SpeedRatioLaw("input", "through").power, 0);
  // Its settings follow the station limiter's rules.
  const auto rules = m->SettingRules(), station = FindComponentModel("station_torque_limiter")->SettingRules();
  ASSERT_EQ(rules.size(), station.size());
  for (std::size_t i = 0; i < rules.size(); ++i) {
    EXPECT_EQ(rules[i].parameter, station[i].parameter);
    EXPECT_EQ(rules[i].against, station[i].against);
    EXPECT_EQ(rules[i].factor, station[i].factor);
  }
}

TEST(StationInputGearbox, LumpsTheLimiterInertiaAcrossTheGearStage) {
  const DefaultsReader p(kType, {{"ratio", 2.0}, {"inertia", 6.25e-4}, {"limiter_inertia", 5e-4}});
  const Lumped<double> lumped = FindComponentModel(kType)->LumpedAtInput(p);
  EXPECT_DOUBLE_EQ(lumped.J, 6.25e-4 + 5e-4 / 4.0);
  EXPECT_FALSE(lumped.c.has_value());  // rigid: the limiter's c1 is in the down-drive only
  const DefaultsReader elastic(kType, {{"stiffness", 3e4}});
  ASSERT_TRUE(FindComponentModel(kType)->LumpedAtInput(elastic).c.has_value());
  EXPECT_DOUBLE_EQ(*FindComponentModel(kType)->LumpedAtInput(elastic).c, 3e4);
}

TEST(StationInputGearbox, SteadyLawIsTheBranchGearboxLaw) {
  const std::map<std::string, double> values = {{"ratio", 2.0}, {"eta_mesh", 0.97}, {"coulomb_torque", 0.1}};
  const DefaultsReader unit(kType, values), gearbox("branch_gearbox", values);
  for (const double branch : {117.6, -70.0, 0.0}) {
    SteadyFlow<double> in;
    in.through = 60.0;
    in.branch = branch;
    in.w = 25.3;
    const double expected = FindComponentModel("branch_gearbox")->InputTorque(gearbox, in);
    EXPECT_DOUBLE_EQ(FindComponentModel(kType)->InputTorque(unit, in), expected) << branch;
    // Opposing: tau_branch / (ratio eta); aiding: tau_branch eta / ratio; plus the through torque and drag.
    const double stage = branch >= 0 ? branch / (2.0 * 0.97) : branch * 0.97 / 2.0;
    EXPECT_NEAR(expected - 60.0 - stage, 0.1 + 0.35 * 0.1 * std::exp(-10 * 25.3) + 1e-4 * 25.3, 1e-9);
  }
}

TEST(StationInputGearbox, ExpandsIntoABranchGearboxWithALimiterInItsDownDrive) {
  const Project project = LoadProject(RigFile());
  const DriveModel model = BuildDriveModel(project);
  const Network& net = model.network;
  auto element = [&](const std::string& id) -> const NetworkElement* {
    for (const NetworkElement& e : net.elements())
      if (e.id == id) return &e;
    return nullptr;
  };
  auto connected = [&](const std::string& a, const std::string& b) {
    for (const NetworkConnection& k : net.connections())
      if ((k.a.ToString() == a && k.b.ToString() == b) || (k.a.ToString() == b && k.b.ToString() == a)) return true;
    return false;
  };
  for (const std::string id : {"sig_1", "sig_2"}) {
    const NetworkElement* gear = element(id);
    const NetworkElement* limiter = element(id + ".limiter");
    ASSERT_NE(gear, nullptr) << id;
    ASSERT_NE(limiter, nullptr) << id;
    EXPECT_EQ(gear->type, "BranchGearbox");
    EXPECT_EQ(limiter->type, "TorqueLimiter");
    EXPECT_EQ(model.component_of.at(id + ".limiter"), id);
    EXPECT_TRUE(connected(id + ".flange_branch", id + ".limiter.flange_a")) << id;
    EXPECT_DOUBLE_EQ(gear->parameters.scalars.at("ratio"), 2.0);
    EXPECT_DOUBLE_EQ(limiter->parameters.scalars.at("J"), 5e-4);
    // The retract end stop keeps the extend ratio tau2/tau1 (as the separate limiter's).
    const auto& s = limiter->parameters.scalars;
    EXPECT_DOUBLE_EQ(s.at("tau2_ret") / s.at("tau1_ret"), s.at("tau2_ext") / s.at("tau1_ext"));
  }
  EXPECT_DOUBLE_EQ(element("sig_1.limiter")->parameters.scalars.at("tau1_ext"), 180.0);
  EXPECT_DOUBLE_EQ(element("sig_1.limiter")->parameters.scalars.at("tau1_ret"), 126.0);
  EXPECT_TRUE(connected("sig_1.limiter.flange_b", "gra_1.flange_a"));
  EXPECT_TRUE(connected("sig_2.limiter.flange_b", "gra_2.flange_a"));
  // The actuators turn at half the shaft speed behind the 2:1 stages.
  EXPECT_DOUBLE_EQ(model.speed_factor.at("gra_1"), 0.5);
}

TEST(StationInputGearbox, RefusesAnEndStopBelowTheLockOut) {
  Project project = LoadProject(RigFile());
  Component* sig = nullptr;
  for (Component& c : project.components)
    if (c.id == "sig_1") sig = &c;
  ASSERT_NE(sig, nullptr);
  Parameter& end_stop = sig->parameters["end_stop_torque"];
  end_stop.nominal = 150.0;
  end_stop.domain = Domain::Point(150.0);
  end_stop.provenance = Provenance::kUser;
  try {
    BuildDriveModel(project);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("component 'sig_1' (station_input_gearbox): 'end_stop_torque'"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("must exceed both lock-out torques"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace highlift::model
