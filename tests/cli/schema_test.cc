// docs/project.schema.json is valid JSON and agrees with the code: its component type enum is
// the catalogue's list of type names, and the keys it allows in each object are the keys the
// reader accepts (read from the reader's own "Allowed keys: ..." message).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"

namespace highlift {
namespace {

nlohmann::json Schema() {
  std::ifstream in(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "docs" / "project.schema.json");
  EXPECT_TRUE(in.good());
  return nlohmann::json::parse(in);  // throws on invalid JSON
}

std::set<std::string> Keys(const nlohmann::json& properties) {
  std::set<std::string> keys;
  for (const auto& [key, value] : properties.items()) keys.insert(key);
  return keys;
}

/// The keys the reader allows where `document` has the unknown key "zz_unknown": parsed from
/// its "allowed keys: a, b, c" message.
std::set<std::string> ReaderKeys(const std::string& document) {
  try {
    ParseProject(document, "probe.json");
  } catch (const InputError& e) {
    const std::string m = e.message();
    EXPECT_NE(m.find("unknown key 'zz_unknown'"), std::string::npos) << m;
    const auto at = m.find("llowed keys: ");  // "Allowed keys: " or "; allowed keys: "
    EXPECT_NE(at, std::string::npos) << m;
    if (at == std::string::npos) return {};
    std::set<std::string> keys;
    std::string list = m.substr(at + 13);
    std::size_t start = 0;
    while (start < list.size()) {
      std::size_t end = list.find(", ", start);
      if (end == std::string::npos) end = list.size();
      std::string key = list.substr(start, end - start);
      while (!key.empty() && (key.back() == '.' || key.back() == ' ')) key.pop_back();
      keys.insert(key);
      start = end + 2;
    }
    return keys;
  }
  ADD_FAILURE() << "the reader accepted an unknown key in " << document;
  return {};
}

const char* const kHead = R"("format": "highlift-project/1", "name": "probe")";

std::string Doc(const std::string& rest) { return std::string("{") + kHead + (rest.empty() ? "" : ", " + rest) + "}"; }

TEST(Schema, IsDraft2020JsonSchema) {
  const nlohmann::json s = Schema();
  EXPECT_EQ(s.at("$schema"), "https://json-schema.org/draft/2020-12/schema");
  EXPECT_EQ(s.at("type"), "object");
  EXPECT_FALSE(s.at("additionalProperties").get<bool>());
  const std::set<std::string> required = {"format", "name"};
  EXPECT_EQ(s.at("required").get<std::set<std::string>>(), required);
  EXPECT_EQ(s.at("properties").at("format").at("const"), "highlift-project/1");
  // Every $ref resolves to a definition.
  std::function<void(const nlohmann::json&)> check = [&](const nlohmann::json& j) {
    if (j.is_object()) {
      if (j.contains("$ref")) {
        const std::string ref = j.at("$ref");
        ASSERT_EQ(ref.rfind("#/$defs/", 0), 0u) << ref;
        EXPECT_TRUE(s.at("$defs").contains(ref.substr(8))) << ref;
      }
      for (const auto& [k, v] : j.items()) check(v);
    } else if (j.is_array()) {
      for (const auto& v : j) check(v);
    }
  };
  check(s);
}

TEST(Schema, ComponentTypeEnumIsTheCatalogue) {
  const nlohmann::json s = Schema();
  std::vector<std::string> schema_types = s.at("$defs").at("component_type").at("enum");
  std::vector<std::string> catalogue;
  for (const auto& t : ComponentTypes()) catalogue.push_back(t.name);
  EXPECT_EQ(schema_types, catalogue);  // same names, same order
}

TEST(Schema, TopLevelKeysAreTheReaders) {
  const nlohmann::json s = Schema();
  EXPECT_EQ(Keys(s.at("properties")), ReaderKeys(Doc(R"("zz_unknown": 1)")));
}

TEST(Schema, NestedObjectKeysAreTheReaders) {
  const nlohmann::json defs = Schema().at("$defs");
  EXPECT_EQ(Keys(defs.at("settings").at("properties")), ReaderKeys(Doc(R"("settings": {"zz_unknown": 1})")));
  EXPECT_EQ(Keys(defs.at("experiment").at("properties")), ReaderKeys(Doc(R"("experiment": {"zz_unknown": 1})")));
  EXPECT_EQ(Keys(defs.at("component_common").at("properties")),
            ReaderKeys(Doc(R"("components": [{"id": "p", "type": "pdu", "zz_unknown": 1}])")));
  EXPECT_EQ(Keys(defs.at("requirement").at("properties")),
            ReaderKeys(Doc(R"("requirements": [{"id": "r", "expression": "a.b >= 1", "zz_unknown": 1}])")));
  EXPECT_EQ(Keys(defs.at("load_case").at("properties")),
            ReaderKeys(Doc(R"("load_cases": [{"name": "l", "zz_unknown": 1}])")));
  EXPECT_EQ(Keys(defs.at("table").at("properties")),
            ReaderKeys(Doc(R"("load_cases": [{"name": "l", "pdu_speed": {"points": [[0, 0]], "zz_unknown": 1}}])")));
  EXPECT_EQ(Keys(defs.at("scenario").at("properties")),
            ReaderKeys(Doc(R"("scenarios": [{"name": "s", "kind": "extension", "zz_unknown": 1}])")));
  EXPECT_EQ(Keys(defs.at("event").at("properties")),
            ReaderKeys(Doc(R"("scenarios": [{"name": "s", "kind": "jam",
                               "jam": {"component": "g", "time": "1 s", "zz_unknown": 1}}])")));
  EXPECT_EQ(Keys(defs.at("scenario").at("properties").at("wtb").at("properties")),
            ReaderKeys(Doc(R"("scenarios": [{"name": "s", "kind": "extension",
                               "wtb": {"trigger": "monitor", "zz_unknown": 1}}])")));
  EXPECT_EQ(Keys(defs.at("quantity_object").at("properties")),
            ReaderKeys(Doc(R"("components": [{"id": "s", "type": "torque_shaft",
                                "parameters": {"length": {"value": "1 m", "zz_unknown": 1}}}])")));
}

TEST(Schema, ExamplesUseOnlyTypesOfTheEnum) {
  const nlohmann::json s = Schema();
  const auto types = s.at("$defs").at("component_type").at("enum").get<std::set<std::string>>();
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    const nlohmann::json doc = nlohmann::json::parse(in);
    for (const auto& [key, value] : doc.items())
      EXPECT_TRUE(s.at("properties").contains(key)) << entry.path() << ": " << key;
    for (const auto& c : doc.value("components", nlohmann::json::array())) EXPECT_TRUE(types.count(c.at("type").get<std::string>())) << c.dump();
  }
}

}  // namespace
}  // namespace highlift
