// libFuzzer target: the report page (report/src/render_html.cc) with hostile data. Every text of
// the page's data comes from its inputs (component ids, names, notes of the project; case names
// and messages of a campaign): the input is a JSON document used as the data (or, when it does
// not parse, a string used as the project's name and a campaign message). The page must keep its
// structure whatever the text: the data island ends where it should (no "</script" or "<!--"
// inside it), and the page has exactly the script elements of the template.
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "highlift/report/report.h"

namespace {

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string Lower(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  static const std::size_t scripts = [] {
    highlift::report::DesignReport empty;
    empty.data = {{"project", {{"name", "x"}}}};
    return Count(Lower(highlift::report::RenderHtml(empty)), "</script");
  }();
  highlift::report::DesignReport report;
  nlohmann::json parsed = nlohmann::json::parse(text, nullptr, false);
  if (parsed.is_object()) {
    report.data = std::move(parsed);
    if (!report.data.contains("project") || !report.data["project"].is_object()) report.data["project"] = {{"name", text}};
    if (!report.data["project"].contains("name") || !report.data["project"]["name"].is_string())
      report.data["project"]["name"] = text;
  } else {
    report.data = {{"project", {{"name", text}}},
                   {"campaign", {{"failed", {{{"message", text}, {"case", text}}}}}},
                   {"components", {{{"id", text}, {"note", text}}}}};
  }
  std::string page;
  try {
    page = highlift::report::RenderHtml(report);
  } catch (const nlohmann::json::type_error&) {
    return 0;  // text that is not UTF-8: the readers refuse it before it reaches the report
  }
  const std::string lower = Lower(page);
  if (Count(lower, "</script") != scripts) __builtin_trap();  // the data closed a script element
  const std::size_t island = lower.find("id=\"report-data\">");
  if (island == std::string::npos) __builtin_trap();
  const std::size_t end = lower.find("</script", island);
  const std::string json = page.substr(island + 17, end - island - 17);
  if (json.find("<!--") != std::string::npos || Lower(json).find("<script") != std::string::npos) __builtin_trap();
  if (nlohmann::json::parse(json, nullptr, false).is_discarded()) __builtin_trap();  // the island is the data
  return 0;
}
