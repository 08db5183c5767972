#include <fmt/format.h>

#include <charconv>
#include <string_view>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/sim/simulator.h"

namespace highlift::sim {

struct CsvSink::Impl {
  std::filesystem::path file;
  std::vector<std::string> signals;
  std::vector<int> columns;
  std::unique_ptr<OutputFile> out;
  std::string line;
  double last_time = 0.0;
  long rows = 0;
};

CsvSink::CsvSink(const std::filesystem::path& file, std::vector<std::string> signals)
    : impl_(std::make_unique<Impl>()) {
  impl_->file = file;
  impl_->signals = std::move(signals);
}

// Without End() (an exception left the run) the temporary file is removed: the old file stays.
CsvSink::~CsvSink() = default;

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
  impl_->out = std::make_unique<OutputFile>(impl_->file, "results file");
  std::string header = "\"time\"";
  for (int c : impl_->columns) header += ",\"" + columns[c] + "\"";
  header += "\n";
  impl_->out->Write(header);
}

void CsvSink::Row(double time, const std::vector<double>& values) {
  if (!impl_->out) return;
  // Each number the shortest text that reads back as the same double (std::to_chars): exact
  // like 17 significant digits, and several times faster than fmt's "{:.17g}", which takes
  // the slow arbitrary-precision path for most values (more than half of a run with --out).
  constexpr std::size_t kWidest = 24;  // "-2.2250738585072014e-308" and a comma
  std::string& line = impl_->line;
  line.resize((impl_->columns.size() + 1) * (kWidest + 1) + 1);
  char* p = line.data();
  char* const end = line.data() + line.size();
  p = std::to_chars(p, end, time).ptr;
  for (int c : impl_->columns) {
    *p++ = ',';
    p = std::to_chars(p, end, values[c]).ptr;
  }
  *p++ = '\n';
  impl_->out->Write(std::string_view(line.data(), static_cast<std::size_t>(p - line.data())));  // throws InputError on a failed write
  impl_->last_time = time;
  ++impl_->rows;
}

void CsvSink::End() {
  if (!impl_ || !impl_->out || impl_->out->committed()) return;
  if (!InterruptRequested() || impl_->out->is_stdout()) {
    impl_->out->Commit();
    return;
  }
  // Interrupted: the rows so far go to FILE.partial with a trailer line; FILE stays unchanged.
  impl_->out->Write(fmt::format("# partial output: interrupted by signal {} after {} rows, at t = {:.17g} s; "
                                "the run did not reach its stop time\n",
                                InterruptSignal(), impl_->rows, impl_->last_time));
  std::filesystem::path partial = impl_->file;
  partial += ".partial";
  impl_->out->CommitAs(partial);
  SetPartialOutputFile(partial.string());
}

}  // namespace highlift::sim
