#include <cstdio>
#include <fmt/format.h>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/sim/simulator.h"

namespace highlift::sim {

struct CsvSink::Impl {
  std::filesystem::path file;
  std::vector<std::string> signals;
  std::vector<int> columns;
  std::FILE* out = nullptr;
  std::string line;
};

CsvSink::CsvSink(const std::filesystem::path& file, std::vector<std::string> signals)
    : impl_(std::make_unique<Impl>()) {
  impl_->file = file;
  impl_->signals = std::move(signals);
}

CsvSink::~CsvSink() { End(); }

void CsvSink::Begin(const std::vector<std::string>& columns) {
  impl_->columns.clear();
  if (impl_->signals.empty()) {
    for (std::size_t i = 0; i < columns.size(); ++i) impl_->columns.push_back(static_cast<int>(i));
  } else {
    for (const auto& s : impl_->signals) {
      int found = -1;
      for (std::size_t i = 0; i < columns.size(); ++i)
        if (columns[i] == s) found = static_cast<int>(i);
      if (found < 0) {
        auto close = Suggest(s, columns);
        std::string hint;
        for (const auto& c : close) hint += (hint.empty() ? "" : ", ") + c;
        throw InputError("signal '" + s + "' is not an output of this network" +
                         (hint.empty() ? "" : "; closest: " + hint) +
                         " (outputs are instance paths such as 'inertia1.w')");
      }
      impl_->columns.push_back(found);
    }
  }
  impl_->out = std::fopen(impl_->file.string().c_str(), "w");
  if (impl_->out == nullptr)
    throw InputError("cannot write '" + impl_->file.string() +
                     "'; check that the folder exists and is writable");
  std::string header = "\"time\"";
  for (int c : impl_->columns) header += ",\"" + columns[c] + "\"";
  header += "\n";
  std::fputs(header.c_str(), impl_->out);
}

void CsvSink::Row(double time, const std::vector<double>& values) {
  if (impl_->out == nullptr) return;
  std::string& line = impl_->line;
  line.clear();
  fmt::format_to(std::back_inserter(line), "{:.17g}", time);
  for (int c : impl_->columns) fmt::format_to(std::back_inserter(line), ",{:.17g}", values[c]);
  line += '\n';
  std::fputs(line.c_str(), impl_->out);
}

void CsvSink::End() {
  if (impl_ && impl_->out != nullptr) {
    std::fclose(impl_->out);
    impl_->out = nullptr;
  }
}

}  // namespace highlift::sim
