// highlift db list|show|find|import|export: the component database of existing parts.
#include <iostream>

#include "command.h"
#include "highlift/componentdb/database.h"
#include "highlift/componentdb/io.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/text_table.h"

namespace highlift::cli {
namespace {

using componentdb::ComponentDatabase;
using componentdb::Quantity;
using Json = nlohmann::ordered_json;

std::string FormatQuantity(const Quantity& q) {
  std::string s;
  if (q.value) s = FormatNumber(*q.value, 6);
  if (q.lo) s += (s.empty() ? "" : " ") + std::string("[") + FormatNumber(*q.lo, 6) + ", " + FormatNumber(*q.hi, 6) + "]";
  if (q.unit != "1") s += " " + q.unit;
  return s;
}

std::string ParameterSummary(const componentdb::Part& p, std::size_t max_items = 3) {
  std::string s;
  for (std::size_t i = 0; i < p.parameters.size() && i < max_items; ++i)
    s += (i ? ", " : "") + p.parameters[i].name + " " + FormatQuantity(p.parameters[i]);
  if (p.parameters.size() > max_items) s += ", ...";
  return s;
}

void PrintParts(const std::vector<componentdb::Part>& parts, const std::string& database, bool json) {
  if (json) {
    componentdb::Records r;
    r.parts = parts;
    Json doc = componentdb::ToJson(r);
    Json out = Json::object();
    out["database"] = database;
    out["count"] = parts.size();
    out["parts"] = doc["parts"];
    std::cout << JsonText(out) << "\n";
    return;
  }
  TextTable table({"designation", "type", "program", "parameters"});
  for (const auto& p : parts) table.AddRow({p.designation, p.type, p.program, ParameterSummary(p)});
  std::cout << table.ToString() << parts.size() << " parts in " << database << "\n";
}

/// Options shared by the db subcommands.
struct DbOptions {
  std::string db;
  bool json = false;
  void AddTo(CLI::App& app) {
    app.add_option("--db", db, "Component database file (default: the shipped database in the user's data directory)");
    app.add_flag("--json", json, "Print one JSON document on stdout");
  }
};

class DbCommand : public Command {
 public:
  void Setup(CLI::App& app) override {
    app.require_subcommand(1);
    list_ = app.add_subcommand("list", "List parts (of one type, or 'material' for the materials)");
    list_->add_option("type", type_, "Component type, or 'material'");
    list_options_.AddTo(*list_);

    show_ = app.add_subcommand("show", "Show one part or material with every parameter, its tag and source");
    show_->add_option("designation", designation_, "Part designation or material name")->required();
    show_options_.AddTo(*show_);

    find_ = app.add_subcommand("find", "Find parts of a type by ranges on their parameters");
    find_->add_option("type", find_type_, "Component type, e.g. geared_rotary_actuator")->required();
    find_->add_option("--where", where_, "Range NAME=LO:HI [unit], e.g. ratio=150:250 or 'output_torque_rating=2:25 kN*m'; repeatable");
    find_options_.AddTo(*find_);

    import_ = app.add_subcommand("import", "Import parts and materials from CSV or JSON (all or nothing)");
    auto* file = import_->add_option("file", import_file_, "A .csv or .json file");
    auto* seed = import_->add_flag("--seed", import_seed_,
                                   "Import the parts and materials this highlift ships (its seed) instead of a file");
    file->excludes(seed);

    import_->add_flag("--replace", replace_, "Replace parts and materials that already exist instead of failing");
    import_options_.AddTo(*import_);

    export_ = app.add_subcommand("export", "Export every part and material as JSON or CSV");
    export_->add_option("file", export_file_, "Output .json or .csv file (default: JSON on stdout)");
    export_->add_option("--format", format_, "Format on stdout: json or csv")->check(CLI::IsMember({"json", "csv"}));
    export_options_.AddTo(*export_);
  }

  int Run() override {
    if (list_->parsed()) return List();
    if (show_->parsed()) return Show();
    if (find_->parsed()) return Find();
    if (import_->parsed()) return Import();
    if (export_->parsed()) return Export();
    return kInvalidInput;
  }

 private:
  int List() {
    auto db = componentdb::OpenDatabase(list_options_.db, ComponentDatabase::Mode::kReadOnly);
    if (type_ == "material" || type_ == "materials") {
      const auto materials = db.Materials();
      if (list_options_.json) {
        componentdb::Records r;
        r.materials = materials;
        Json out = Json::object();
        out["database"] = db.file().string();
        out["count"] = materials.size();
        out["materials"] = componentdb::ToJson(r)["materials"];
        std::cout << JsonText(out) << "\n";
        return kSuccess;
      }
      TextTable table({"material", "shear_modulus", "density", "allowable_shear_stress", "note"});
      for (const auto& m : materials) {
        const auto cell = [&](const char* name) {
          const Quantity* q = m.Find(name);
          return q ? FormatQuantity(*q) + " (" + componentdb::ToString(q->tag) + ")" : std::string();
        };
        table.AddRow({m.name, cell("shear_modulus"), cell("density"), cell("allowable_shear_stress"), m.note});
      }
      std::cout << table.ToString() << materials.size() << " materials in " << db.file().string() << "\n";
      return kSuccess;
    }
    CheckType(type_);
    PrintParts(db.Parts(type_), db.file().string(), list_options_.json);
    return kSuccess;
  }

  int Show() {
    auto db = componentdb::OpenDatabase(show_options_.db, ComponentDatabase::Mode::kReadOnly);
    componentdb::Records r;
    if (auto part = db.FindPart(designation_)) r.parts.push_back(*part);
    else if (auto material = db.FindMaterial(designation_)) r.materials.push_back(*material);
    else
      throw InputError("no part or material '" + designation_ + "' in " + db.file().string() +
                       "; list them with 'highlift db list'");
    if (show_options_.json) {
      std::cout << JsonText(componentdb::ToJson(r)) << "\n";
      return kSuccess;
    }
    const auto& quantities = r.parts.empty() ? r.materials[0].properties : r.parts[0].parameters;
    if (!r.parts.empty()) {
      const auto& p = r.parts[0];
      std::cout << p.designation << " (" << p.type << ")\n";
      if (!p.program.empty()) std::cout << "program:  " << p.program << "\n";
      if (!p.supplier.empty()) std::cout << "supplier: " << p.supplier << "\n";
      if (!p.note.empty()) std::cout << "note:     " << p.note << "\n";
    } else {
      std::cout << r.materials[0].name << " (material)\n";
      if (!r.materials[0].note.empty()) std::cout << "note:     " << r.materials[0].note << "\n";
    }
    TextTable table({"parameter", "value", "SI", "tag", "source"});
    for (const auto& q : quantities) {
      std::string si = q.value_si ? FormatNumber(*q.value_si, 6) : "";
      if (!q.domain_si.is_point())
        si += (si.empty() ? "" : " ") + std::string("[") + FormatNumber(q.domain_si.lo, 6) + ", " +
              FormatNumber(q.domain_si.hi, 6) + "]";
      table.AddRow({q.name, FormatQuantity(q), si, componentdb::ToString(q.tag), q.source});
    }
    std::cout << table.ToString();
    return kSuccess;
  }

  int Find() {
    CheckType(find_type_);
    componentdb::PartQuery query;
    query.type = find_type_;
    for (const auto& w : where_) query.conditions.push_back(componentdb::ParseRangeCondition(w, find_type_));
    auto db = componentdb::OpenDatabase(find_options_.db, ComponentDatabase::Mode::kReadOnly);
    PrintParts(db.Find(query), db.file().string(), find_options_.json);
    return kSuccess;
  }

  int Import() {
    if (import_file_.empty() && !import_seed_)
      throw InputError("db import: give a .csv or .json file to import, or --seed for the parts this highlift ships");
    componentdb::Records records = import_seed_ ? componentdb::SeedRecords() : componentdb::ReadRecords(import_file_);
    auto db = componentdb::OpenDatabase(import_options_.db, ComponentDatabase::Mode::kCreate);
    componentdb::ImportOptions options;
    options.replace = replace_;
    const auto report = db.Import(std::move(records), options);
    if (import_options_.json) {
      Json out{{"database", db.file().string()},     {"parts_added", report.parts_added},
               {"parts_replaced", report.parts_replaced}, {"materials_added", report.materials_added},
               {"materials_replaced", report.materials_replaced}};
      std::cout << JsonText(out) << "\n";
    } else {
      std::cout << "imported " << (import_seed_ ? std::string("the shipped seed") : import_file_) << " into " << db.file().string() << ": " << report.BriefReport() << "\n";
    }
    return kSuccess;
  }

  int Export() {
    auto db = componentdb::OpenDatabase(export_options_.db, ComponentDatabase::Mode::kReadOnly);
    const auto records = db.Export();
    if (!export_file_.empty()) {
      componentdb::WriteRecords(records, export_file_);
      std::cerr << "exported " << records.parts.size() << " parts and " << records.materials.size()
                << " materials to " << export_file_ << "\n";
      return kSuccess;
    }
    if (format_ == "csv") std::cout << componentdb::ToCsv(records);
    else std::cout << JsonText(componentdb::ToJson(records)) << "\n";
    return kSuccess;
  }

  static void CheckType(const std::string& type) {
    if (type.empty() || FindComponentType(type)) return;
    std::string all;
    for (const auto& t : ComponentTypes()) all += (all.empty() ? "" : ", ") + t.name;
    const auto s = Suggest(type, [] {
      std::vector<std::string> names;
      for (const auto& t : ComponentTypes()) names.push_back(t.name);
      return names;
    }());
    throw InputError("unknown component type '" + type + "'" + (s.empty() ? "" : "; did you mean '" + s.front() + "'?") +
                     " Valid types: " + all + ", material");
  }

  CLI::App* list_ = nullptr;
  CLI::App* show_ = nullptr;
  CLI::App* find_ = nullptr;
  CLI::App* import_ = nullptr;
  CLI::App* export_ = nullptr;
  DbOptions list_options_, show_options_, find_options_, import_options_, export_options_;
  std::string type_, designation_, find_type_, import_file_, export_file_, format_ = "json";
  std::vector<std::string> where_;
  bool replace_ = false;
  bool import_seed_ = false;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(DbCommand, "db", "Component database: list, show, find, import, export parts")

}  // namespace highlift::cli
