// RenderHtml: the page template (report/web/page.html) with the styles, the uPlot library, the
// page's script and the data inlined. One pass over the template, so nothing inserted is
// scanned for placeholders again.
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "highlift/report/report.h"

namespace highlift::report {
namespace detail {
std::string_view WebAsset(std::string_view name);
}  // namespace detail

namespace {

std::string EscapeHtml(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

/// JSON inside <script type="application/json">: no '<' at all, so no text of the data can
/// close the element ("</script>") or open a comment ("<!--"). '<' occurs only inside strings,
/// where \u003c means the same.
std::string ScriptSafeJson(const nlohmann::json& data) {
  const std::string text = data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '<') out += "\\u003c";
    else out += c;
  }
  return out;
}

/// The uPlot version from its package.json, for the page's footer.
std::string UplotVersion() {
  const nlohmann::json package = nlohmann::json::parse(detail::WebAsset("uplot_package"));
  return package.value("version", "");
}

}  // namespace

std::string RenderHtml(const DesignReport& report) {
  nlohmann::json data = report.data;
  data["generator"] = "highlift " HIGHLIFT_VERSION " with uPlot " + UplotVersion();
  const std::string name = data["project"].value("name", "");
  const std::vector<std::pair<std::string_view, std::string>> fill = {
      {"@GENERATOR@", EscapeHtml(data["generator"].get<std::string>())},
      {"@TITLE@", EscapeHtml("Design report: " + name)},
      {"/*@UPLOT_CSS@*/", std::string(detail::WebAsset("uplot_css"))},
      {"/*@PAGE_CSS@*/", std::string(detail::WebAsset("page_css"))},
      {"@TITLE@", EscapeHtml("Design report: " + name)},
      {"@DATA@", ScriptSafeJson(data)},
      {"/*@UPLOT_JS@*/", std::string(detail::WebAsset("uplot_js"))},
      {"/*@PAGE_JS@*/", std::string(detail::WebAsset("page_js"))},
      {"@LICENSE@", "uPlot " + UplotVersion() + "\n" + std::string(detail::WebAsset("uplot_license"))},
  };
  const std::string_view page = detail::WebAsset("page_html");
  std::string out;
  out.reserve(page.size() + 4 * 1024 * 1024);
  std::size_t at = 0;
  for (const auto& [placeholder, text] : fill) {
    const std::size_t found = page.find(placeholder, at);
    if (found == std::string_view::npos)
      throw std::logic_error("report page template: placeholder " + std::string(placeholder) + " missing or out of order");
    out.append(page.substr(at, found - at));
    out += text;
    at = found + placeholder.size();
  }
  out.append(page.substr(at));
  return out;
}

}  // namespace highlift::report
