// The hand-written HighLift library: shipped exactly as in export/modelica/, structurally valid,
// one class per file with package.order, documented.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "export_test_util.h"

namespace highlift {
namespace {

using testing::ReadText;

TEST(HighLiftLibrary, EmbeddedFilesEqualTheSourceTree) {
  const auto root = std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "export" / "modelica";
  std::set<std::string> on_disk;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root / "HighLift"))
    if (entry.is_regular_file()) on_disk.insert(std::filesystem::relative(entry.path(), root).generic_string());
  const auto files = HighLiftLibraryFiles();
  std::set<std::string> embedded;
  for (const auto& f : files) {
    embedded.insert(f.path);
    EXPECT_EQ(f.content, ReadText(root / f.path)) << f.path << " differs from the embedded copy: rebuild";
  }
  EXPECT_EQ(embedded, on_disk);
  EXPECT_GE(files.size(), 30u);
}

TEST(HighLiftLibrary, PassesTheStructuralCheck) {
  const auto files = HighLiftLibraryFiles();
  std::string issues;
  for (const auto& issue : CheckModelica(files)) issues += issue.ToString() + "\n";
  EXPECT_EQ(issues, "");
}

TEST(HighLiftLibrary, HasThePapersComponents) {
  std::set<std::string> paths;
  for (const auto& f : HighLiftLibraryFiles()) paths.insert(f.path);
  for (const char* p :
       {"HighLift/Mechanical/ShaftBrake.mo", "HighLift/Mechanical/NonlinearSpring.mo",
        "HighLift/Mechanical/TorqueLimiter.mo", "HighLift/Mechanical/LossyInertia.mo",
        "HighLift/Mechanical/GeneralRotationalElement.mo", "HighLift/Mechanical/GearedRotaryActuator.mo",
        "HighLift/Mechanical/Disconnector.mo", "HighLift/Mechanical/Jam.mo",
        "HighLift/Control/Monitoring.mo", "HighLift/Drives/PDU.mo",
        "HighLift/Hydraulics/TurbulentResistance.mo", "HighLift/Hydraulics/ServoValve.mo",
        "HighLift/Hydraulics/DifferentialCylinder.mo", "HighLift/Hydraulics/VariableDisplacementMotor.mo",
        "HighLift/Hydraulics/PressureSource.mo", "HighLift/Hydraulics/Tank.mo"})
    EXPECT_TRUE(paths.count(p)) << p;
}

TEST(HighLiftLibrary, EveryClassIsDocumentedAndUsesSiTypes) {
  for (const auto& f : HighLiftLibraryFiles()) {
    if (f.path.find(".mo") == std::string::npos || f.path.find("package.mo") != std::string::npos) continue;
    if (f.path.find("/Interfaces/Port.mo") != std::string::npos) continue;
    EXPECT_NE(f.content.find("Documentation(info="), std::string::npos) << f.path << " has no documentation";
  }
  // The paper's laws appear in the code, not only in the documentation.
  const auto text = [](const std::string& path) {
    for (const auto& f : HighLiftLibraryFiles())
      if (f.path == path) return f.content;
    return std::string();
  };
  EXPECT_NE(text("HighLift/Mechanical/StribeckFriction.mo")
                .find("tau_C + d_vis*w + tau_S*exp(-f_exp*abs(w)) + (1 - eta_internal)*abs(tau_load)"),
            std::string::npos);
  EXPECT_NE(text("HighLift/Mechanical/NonlinearSpring.mo").find("(phi_rel - phi1_ext)/(phi2_ext - phi1_ext)"),
            std::string::npos);
  EXPECT_NE(text("HighLift/Mechanical/ShaftBrake.mo").find("parameter SI.Torque tauB_max"), std::string::npos);
}

}  // namespace
}  // namespace highlift
