// Helpers for the component database tests: a scratch directory per test.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "common/scratch.h"
#include "highlift/componentdb/records.h"

namespace highlift::testing {

/// A fresh directory under the system temporary directory, removed at the end of the test when
/// it passed.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("highlift_db_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
    RemoveAfterTheTest(path_);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

/// A quantity with a point value, tagged E, source "test".
inline componentdb::Quantity PointQuantity(std::string name, double value, std::string unit) {
  componentdb::Quantity q;
  q.name = std::move(name);
  q.value = value;
  q.unit = std::move(unit);
  q.source = "test";
  return q;
}

/// A quantity given as an interval.
inline componentdb::Quantity IntervalQuantity(std::string name, double lo, double hi, std::string unit) {
  componentdb::Quantity q;
  q.name = std::move(name);
  q.lo = lo;
  q.hi = hi;
  q.unit = std::move(unit);
  q.source = "test";
  return q;
}

}  // namespace highlift::testing
