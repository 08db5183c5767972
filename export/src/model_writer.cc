// Rendering of one Modelica model, with a layered diagram layout (see model_writer.h).
#include "model_writer.h"

#include <algorithm>
#include <deque>
#include <set>
#include <sstream>

#include "highlift/core/error.h"
#include "highlift/export/modelica.h"

namespace highlift::modelica_detail {
namespace {

constexpr int kHalf = 10;      // half size of an icon in the diagram
constexpr int kSpacingX = 40;  // distance of layout columns
constexpr int kSpacingY = 40;  // distance of layout rows
constexpr std::size_t kLineWidth = 100;

std::string InstanceOf(const std::string& ref) { return ref.substr(0, ref.find('.')); }
std::string Port(const std::string& ref) {
  const auto dot = ref.find('.');
  return dot == std::string::npos ? std::string() : ref.substr(dot + 1);
}

bool IsFlange(const std::string& port) {
  return port.rfind("flange", 0) == 0 || port.rfind("support", 0) == 0 ||
         port.rfind("internalSupport", 0) == 0;
}
bool IsHydraulic(const std::string& port) { return port.rfind("port", 0) == 0; }

// Where a connector sits on an icon (icon coordinates -100..100, scaled to the 20x20 extent).
std::pair<int, int> PortOffset(const std::string& class_path, const std::string& port) {
  if (class_path.size() >= 5 && class_path.substr(class_path.size() - 5) == "Fixed") return {0, -10};
  static const std::map<std::string, std::pair<int, int>> kOffsets = {
      {"flange_a", {-10, 0}}, {"flange_b", {10, 0}},   {"flange", {10, 0}},
      {"support", {0, -10}},  {"y", {11, 0}},          {"u", {-12, 0}},
      {"u1", {-8, 0}},        {"u2", {0, -8}},         {"tau", {-12, 0}},
      {"w_ref", {-12, 0}},    {"phi_ref", {-12, 0}},   {"f_normalized", {0, 11}},
      {"apply", {0, 12}},     {"flange_left", {0, 10}}, {"flange_right", {10, 0}},
      {"flange_branch", {0, 10}}, {"phi", {11, -6}},   {"w", {11, -9}},
      {"eps", {0, 12}},       {"port", {10, 0}},       {"heatPort", {-10, -10}},
  };
  if (auto it = kOffsets.find(port); it != kOffsets.end()) return it->second;
  return {0, 0};
}

std::string Point(int x, int y) { return "{" + std::to_string(x) + "," + std::to_string(y) + "}"; }

// Documentation keeps its line breaks; quotes and backslashes are escaped.
std::string EscapeKeepingNewlines(const std::string& text) {
  std::string out;
  std::size_t start = 0;
  while (true) {
    const auto nl = text.find('\n', start);
    out += EscapeModelicaString(text.substr(start, nl == std::string::npos ? std::string::npos : nl - start));
    if (nl == std::string::npos) break;
    out += '\n';
    start = nl + 1;
  }
  return out;
}

std::string RenderModifier(const Modifier& m) {
  if (m.nested.empty()) return m.name + "=" + m.value;
  std::string s = m.name + "(";
  for (std::size_t i = 0; i < m.nested.size(); ++i)
    s += (i ? ", " : "") + m.nested[i].first + "=" + m.nested[i].second;
  return s + ")";
}

// Grounds (Fixed) connect to many parts; they do not spread the layout and sit below their
// first placed neighbour.
bool IsGround(const std::string& class_path) {
  return class_path.size() >= 6 && class_path.substr(class_path.size() - 6) == ".Fixed";
}

// Sources start the layout on the left.
bool IsSignalSource(const std::string& class_path) {
  return class_path.rfind("Modelica.Blocks.Sources.", 0) == 0;
}

}  // namespace

void ModelWriter::AddInstance(modelica_detail::Instance instance) {
  HIGHLIFT_CHECK(!HasInstance(instance.name), "ModelWriter: duplicate instance " + instance.name);
  instances_.push_back(std::move(instance));
}

void ModelWriter::AddConnect(std::string a, std::string b) { connects_.emplace_back(std::move(a), std::move(b)); }

void ModelWriter::AddParameter(std::string type, std::string name, std::string value, std::string comment) {
  parameters_.push_back("parameter " + type + " " + name + " = " + value + " \"" +
                        EscapeModelicaString(comment) + "\";");
}

void ModelWriter::AddEquation(std::string equation) { equations_.push_back(std::move(equation)); }

void ModelWriter::AddInitialEquation(std::string equation) { initial_equations_.push_back(std::move(equation)); }

bool ModelWriter::HasInstance(const std::string& name) const {
  return std::any_of(instances_.begin(), instances_.end(),
                     [&](const modelica_detail::Instance& i) { return i.name == name; });
}

// Layered layout: breadth-first over the connections from a signal source (else the first
// instance); the distance is the column, the order of discovery within a column the row.
// Groups not reached are laid out the same way below. Grounds go below a neighbour.
std::map<std::string, ModelWriter::Position> ModelWriter::Layout() const {
  std::map<std::string, std::string> class_of;
  for (const auto& inst : instances_) class_of[inst.name] = inst.class_path;
  std::map<std::string, std::vector<std::string>> neighbours;
  for (const auto& [a, b] : connects_) {
    const std::string ia = InstanceOf(a), ib = InstanceOf(b);
    if (ia == ib || !class_of.count(ia) || !class_of.count(ib)) continue;
    neighbours[ia].push_back(ib);
    neighbours[ib].push_back(ia);
  }
  std::vector<std::string> starts;
  for (const auto& inst : instances_)
    if (IsSignalSource(inst.class_path)) starts.push_back(inst.name);
  for (const auto& inst : instances_)
    if (!IsGround(inst.class_path)) starts.push_back(inst.name);
  std::map<std::string, Position> position;
  std::map<int, int> rows;  // column -> rows used in the current group
  int group_top = 0;
  for (const auto& start : starts) {
    if (position.count(start)) continue;
    rows.clear();
    std::map<std::string, int> layer{{start, 0}};
    std::deque<std::string> queue{start};
    int group_rows = 1;
    while (!queue.empty()) {
      const std::string current = queue.front();
      queue.pop_front();
      const int l = layer[current];
      const int row = rows[l]++;
      group_rows = std::max(group_rows, row + 1);
      position[current] = {l * kSpacingX, group_top - row * kSpacingY};
      for (const auto& next : neighbours[current]) {
        if (layer.count(next) || position.count(next) || IsGround(class_of[next])) continue;
        layer[next] = l + 1;
        queue.push_back(next);
      }
    }
    group_top -= group_rows * kSpacingY;
  }
  // Grounds: below their first placed neighbour, else after everything.
  int lowest = group_top;
  for (const auto& [name, p] : position) lowest = std::min(lowest, p.y);
  for (const auto& inst : instances_) {
    if (position.count(inst.name)) continue;
    Position p{0, lowest - kSpacingY};
    for (const auto& n : neighbours[inst.name]) {
      if (auto it = position.find(n); it != position.end()) {
        p = {it->second.x, lowest - kSpacingY};
        break;
      }
    }
    position[inst.name] = p;
    lowest = p.y;
  }
  return position;
}

std::string ModelWriter::Render() const {
  const auto position = Layout();
  std::ostringstream out;
  if (!within_.empty()) out << "within " << within_ << ";\n";
  out << "model " << name_;
  if (!description_.empty()) out << " \"" << EscapeModelicaString(description_) << "\"";
  out << "\n";
  for (const auto& p : parameters_) out << "  " << p << "\n";
  if (!parameters_.empty()) out << "\n";
  int xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  for (const auto& inst : instances_) {
    std::string head = "  " + inst.class_path + " " + inst.name;
    std::vector<std::string> mods;
    for (const auto& m : inst.modifiers) mods.push_back(RenderModifier(m));
    std::string one_line = head;
    if (!mods.empty()) {
      one_line += "(";
      for (std::size_t i = 0; i < mods.size(); ++i) one_line += (i ? ", " : "") + mods[i];
      one_line += ")";
    }
    if (one_line.size() <= kLineWidth) {
      out << one_line;
    } else {
      out << head << "(";
      for (std::size_t i = 0; i < mods.size(); ++i) out << "\n    " << mods[i] << (i + 1 < mods.size() ? "," : ")");
    }
    if (!inst.comment.empty()) out << "\n    \"" << EscapeModelicaString(inst.comment) << "\"";
    const Position p = position.at(inst.name);
    xmin = std::min(xmin, p.x);
    xmax = std::max(xmax, p.x);
    ymin = std::min(ymin, p.y);
    ymax = std::max(ymax, p.y);
    out << "\n    annotation (Placement(transformation(extent={" << Point(p.x - kHalf, p.y - kHalf) << ","
        << Point(p.x + kHalf, p.y + kHalf) << "})));\n";
  }
  if (!initial_equations_.empty()) {
    out << "\ninitial equation\n";
    for (const auto& e : initial_equations_) out << "  " << e << "\n";
  }
  out << "\nequation\n";
  std::map<std::string, std::string> class_of;
  for (const auto& inst : instances_) class_of[inst.name] = inst.class_path;
  for (const auto& [a, b] : connects_) {
    out << "  connect(" << a << ", " << b << ")";
    const std::string ia = InstanceOf(a), ib = InstanceOf(b);
    if (position.count(ia) && position.count(ib)) {
      const auto [dxa, dya] = PortOffset(class_of[ia], Port(a));
      const auto [dxb, dyb] = PortOffset(class_of[ib], Port(b));
      const Position pa = position.at(ia), pb = position.at(ib);
      out << "\n    annotation (Line(points={" << Point(pa.x + dxa, pa.y + dya) << ","
          << Point(pb.x + dxb, pb.y + dyb) << "}";
      const std::string pa_name = Port(a), pb_name = Port(b);
      if (IsHydraulic(pa_name) && IsHydraulic(pb_name)) {
        out << ", color={0,0,255}";
      } else if (!IsFlange(pa_name) || !IsFlange(pb_name)) {
        out << ", color={0,0,127}";
      }
      out << "))";
    }
    out << ";\n";
  }
  for (const auto& e : equations_) out << "  " << e << "\n";
  out << "\n  annotation (\n";
  if (experiment_) {
    out << "    experiment(StopTime=" << FormatModelicaReal(experiment_->stop_time, "StopTime")
        << ", Tolerance=" << FormatModelicaReal(experiment_->tolerance, "Tolerance")
        << ", Interval=" << FormatModelicaReal(experiment_->interval, "Interval") << "),\n";
  }
  out << "    Diagram(coordinateSystem(preserveAspectRatio=false, extent={"
      << Point(xmin - 2 * kHalf, ymin - 2 * kHalf) << "," << Point(xmax + 2 * kHalf, ymax + 2 * kHalf)
      << "}))";
  if (!documentation_.empty())
    out << ",\n    Documentation(info=\"" << EscapeKeepingNewlines(documentation_) << "\")";
  out << ");\nend " << name_ << ";\n";
  return out.str();
}

std::string FormatMatrix(const std::vector<std::vector<double>>& rows, const std::string& what) {
  std::string s = "[";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (r) s += "; ";
    for (std::size_t c = 0; c < rows[r].size(); ++c)
      s += (c ? ", " : "") + FormatModelicaReal(rows[r][c], what);
  }
  return s + "]";
}

}  // namespace highlift::modelica_detail
