// A downstream program linking highlift::highlift from an installed tree.
#include <highlift/core/error.h>
#include <highlift/core/text_table.h>

#include <iostream>

int main() {
  highlift::TextTable table({"quantity", "value"}, {1});
  table.AddRow({"tau_max", highlift::FormatNumber(1234.5)});
  const std::string text = table.ToString();
  if (text.find("1234") == std::string::npos) return 1;
  try {
    throw highlift::InputError("component 'x': bad", {"p.json", "/components/0", 3, 5});
  } catch (const highlift::InputError& e) {
    if (std::string(e.what()).find("p.json:3:5") == std::string::npos) return 1;
  }
  std::cout << text;
  return 0;
}
