// docs/components.md, generated from the catalogue (tests/core/catalogue_markdown_test.cc checks
// that the committed file is up to date).
#include <cmath>

#include "highlift/core/catalogue.h"
#include "highlift/core/text_table.h"

namespace highlift {

namespace {

std::string Show(double si, const ParameterSpec& p) {
  if (std::isinf(si)) return si > 0 ? "inf" : "-inf";
  const std::string unit = p.unit.empty() ? "1" : p.unit;
  return FormatNumber(FromSI(si, unit, p.dimension), 4);
}

std::string ShowDomain(const Domain& d, const ParameterSpec& p) {
  if (d.is_point()) return Show(d.lo, p);
  return "[" + Show(d.lo, p) + ", " + Show(d.hi, p) + "]";
}

std::string Escape(std::string s) {
  std::string out;
  for (char ch : s) {
    if (ch == '|') out += "\\|";
    else if (ch == '*') out += "\\*";
    else out += ch;
  }
  return out;
}

std::string Code(const std::string& s) { return s.empty() ? "" : "`" + s + "`"; }

std::string Kind(const ParameterSpec& p) {
  switch (p.kind) {
    case ParameterKind::kInteger: return "integer";
    case ParameterKind::kBoolean: return "boolean";
    case ParameterKind::kTable: return "table";
    case ParameterKind::kText: return "text";
    case ParameterKind::kScalar: break;
  }
  return "";
}

}  // namespace

std::string CatalogueMarkdown() {
  std::string md;
  md += "# Component reference\n\n";
  md += "<!-- Generated from the type declarations (model/src/components/<type>.cc) by highlift::CatalogueMarkdown();\n"
        "     do not edit by hand.\n";
  md += "     Regenerate: HIGHLIFT_UPDATE_DOCS=1 ctest -R CatalogueMarkdown.DocsAreUpToDate -->\n\n";
  md += "The drive-system component types of a project file ([project-format.md](project-format.md)). Each type\n"
        "declares its ports and its parameters once, in its own file (`model/src/components/<type>.cc`); the\n"
        "reader, the interval propagator, the estimator, the database, the reduced models, the simulator and the\n"
        "Modelica exporter all read that declaration.\n\n";
  md += "Columns: **unit** is the display unit (a file may use any unit of the same dimension; inside\n"
        "highlift all values are SI); **nominal** is the default value when the file gives none; **default\n"
        "domain** the default interval (a single number: a point); **valid range** the physically valid\n"
        "values (outside is an input error). **source** says where the default comes from: `domain.md sN (tag)`\n"
        "is section N of the reference data with its tag (P published, P-low weak source, E engineering\n"
        "estimate), `paper` the HighLift library paper, `estimate` a catalogue estimate with its reasoning.\n"
        "Optional parameters without a nominal value stay unknown unless the file gives them.\n\n";
  md += "**referred to** is the side of the gears the value counts on: `shaft side` (the torque tubes, at the PDU\n"
        "output speed), `motor side` (one PDU motor), `PDU output`, `actuator input` (behind the station gearbox)\n"
        "or `actuator output` (the flap track). Every inertia, stiffness, damping and torque states it. Referring a\n"
        "value across a gear of ratio i = input speed / output speed multiplies a torque by i and an inertia or a\n"
        "stiffness by i^2: domain.md s3 gives the flap inertia as 9.7e-3 kg\\*m^2 at the shaft, which is\n"
        "4 x 9.7e-3 = 0.0388 kg\\*m^2 at the input of an actuator behind a 2:1 station gearbox. A project file\n"
        "gives each value on the side its parameter states.\n\n";
  md += "Ports: the flange nearer the PDU along the power path is `input` (or `a`); gear `ratio` = input speed\n"
        "/ output speed (branch gearbox: input / branch speed).\n\n";
  md += "| type | name | ports |\n|---|---|---|\n";
  for (const auto& t : ComponentTypes()) {
    std::string ports;
    for (const auto& p : t.ports) ports += (ports.empty() ? "" : ", ") + Code(p.name) + (p.required ? "" : " (optional)");
    md += "| [" + Code(t.name) + "](#" + t.name + ") | " + t.display_name + " | " + ports + " |\n";
  }
  md += "\n";
  for (const auto& t : ComponentTypes()) {
    md += "## " + t.name + "\n\n";
    md += "**" + t.display_name + "**. " + Escape(t.description) + "\n\n";
    md += "| port | kind | required | meaning |\n|---|---|---|---|\n";
    for (const auto& p : t.ports)
      md += "| " + Code(p.name) + " | " + PortKindName(p.kind) + " | " +
            (p.required ? "yes" : "no") + " | " + Escape(p.description) + " |\n";
    md += "\n";
    if (t.parameters.empty()) continue;
    md += "| parameter | symbol | unit | referred to | nominal | default domain | valid range | meaning | source |\n";
    md += "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& p : t.parameters) {
      const std::string kind = Kind(p);
      const bool text = p.kind == ParameterKind::kText || p.kind == ParameterKind::kTable;
      std::string meaning = Escape(p.description);
      if (!kind.empty()) meaning = "(" + kind + ") " + meaning;
      if (p.optional) meaning += " (optional)";
      md += "| " + Code(p.name) + " | " + Code(p.symbol) + " | " + (text ? "" : Code(p.unit)) + " | " +
            ReferenceSideLabel(p.referred_to) + " | " + (p.nominal ? Show(*p.nominal, p) : "") + " | " + (text ? "" : ShowDomain(p.default_domain, p)) + " | " +
            (text ? "" : ShowDomain(p.valid_range, p)) + " | " + meaning + " | " + Escape(p.source) + " |\n";
    }
    md += "\n";
  }
  return md;
}

}  // namespace highlift
