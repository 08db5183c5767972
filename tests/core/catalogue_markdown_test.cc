#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "highlift/core/catalogue.h"

namespace highlift {
namespace {

TEST(CatalogueMarkdown, ListsEveryTypePortAndParameter) {
  const std::string md = CatalogueMarkdown();
  for (const auto& t : ComponentTypes()) {
    EXPECT_NE(md.find("## " + t.name + "\n"), std::string::npos) << t.name;
    for (const auto& p : t.parameters) EXPECT_NE(md.find("| `" + p.name + "` |"), std::string::npos) << p.name;
  }
  // display units and values: 44 GPa, [43, 51]; a material constant has no gear side (empty cell)
  EXPECT_NE(md.find("| `shear_modulus` | `G` | `GPa` |  | 44 | [43, 51] |"), std::string::npos);
  EXPECT_NE(md.find("| `drag_per_length` | `tau_d` | `N*m/m` | shaft side | 0.25 |"), std::string::npos);
}

// docs/components.md is generated; set HIGHLIFT_UPDATE_DOCS=1 to rewrite it.
TEST(CatalogueMarkdown, DocsAreUpToDate) {
  std::string path = HIGHLIFT_SOURCE_DIR;  // (not string + literal: a false -Warray-bounds of GCC 12)
  path += "/docs/components.md";
  const std::string md = CatalogueMarkdown();
  if (const char* update = std::getenv("HIGHLIFT_UPDATE_DOCS"); update && std::string(update) == "1") {
    std::ofstream(path, std::ios::binary) << md;
  }
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << path << " is missing; run the test with HIGHLIFT_UPDATE_DOCS=1";
  std::stringstream committed;
  committed << in.rdbuf();
  EXPECT_TRUE(committed.str() == md)
      << path << " is out of date with the declarations (model/src/components/<type>.cc); regenerate it: HIGHLIFT_UPDATE_DOCS=1 ctest -R "
                 "CatalogueMarkdown.DocsAreUpToDate";
}

}  // namespace
}  // namespace highlift
