// The structural checker finds the mistakes a text generator makes, and passes valid text.
#include <gtest/gtest.h>

#include "highlift/export/modelica_check.h"

namespace highlift {
namespace {

std::string Issues(const std::string& text, const std::vector<GeneratedFile>& library = {}) {
  std::string out;
  for (const auto& issue : CheckModelica({{"M.mo", text}}, library)) out += issue.ToString() + "\n";
  return out;
}

constexpr const char* kValid = R"(model M "two inertias and a spring"
  Modelica.Mechanics.Rotational.Components.Inertia inertia1(J=0.1, phi(start=0, fixed=true))
    annotation (Placement(transformation(extent={{-10,-10},{10,10}})));
  Modelica.Mechanics.Rotational.Components.Spring spring(c=1e4) "a \"quoted\" comment; end X;";
  Modelica.Mechanics.Rotational.Components.Inertia inertia2(J=2);
  Modelica.Blocks.Sources.Sine sine(amplitude=10, f=5);
  Modelica.Mechanics.Rotational.Sources.Torque torque;
  /* connect(nowhere.x, y) in a comment */
equation
  connect(inertia1.flange_b, spring.flange_a) annotation (Line(points={{0,0},{1,1}}));
  connect(spring.flange_b, inertia2.flange_a);
  connect(sine.y, torque.tau);
  connect(torque.flange, inertia1.flange_a);
  annotation (experiment(StopTime=1));
end M;
)";

TEST(ModelicaCheck, PassesValidText) { EXPECT_EQ(Issues(kValid), ""); }

TEST(ModelicaCheck, EndNameMustMatchTheClass) {
  std::string text = kValid;
  text.replace(text.find("end M;"), 6, "end N;");
  const std::string issues = Issues(text);
  EXPECT_NE(issues.find("'end N;' closes model 'M'"), std::string::npos) << issues;
  EXPECT_NE(issues.find("write 'end M;'"), std::string::npos) << issues;
}

TEST(ModelicaCheck, UnclosedClassIsReported) {
  const std::string issues = Issues("model M\n  Real x;\nequation\n  x = 1;\n");
  EXPECT_NE(issues.find("model 'M' is never closed: add 'end M;'"), std::string::npos) << issues;
}

TEST(ModelicaCheck, NestedClassesAndControlEndsAreHandled) {
  const std::string text =
      "package P\n  model A\n    Real x;\n  equation\n    if x > 0 then\n      x = 1;\n    else\n"
      "      x = 2;\n    end if;\n  end A;\n  function f\n    input Real u;\n    output Real y;\n"
      "  algorithm\n    for i in 1:2 loop\n      y := u;\n    end for;\n  end f;\nend P;\n";
  EXPECT_EQ(Issues(text), "");
  std::string wrong = text;
  wrong.replace(wrong.find("end A;"), 6, "end P;");
  EXPECT_NE(Issues(wrong).find("'end P;' closes model 'A'"), std::string::npos) << Issues(wrong);
}

TEST(ModelicaCheck, UnbalancedBracketsAreReported) {
  EXPECT_NE(Issues("model M\n  Real x(start=1;\nend M;\n").find("'(' is never closed"), std::string::npos);
  EXPECT_NE(Issues("model M\n  Real x[2] = {1, 2];\nend M;\n").find("']' closes '{' opened on line 2"),
            std::string::npos);
  EXPECT_NE(Issues("model M\n  Real x = 1);\nend M;\n").find("')' without a matching opening bracket"),
            std::string::npos);
  // Brackets inside strings and comments do not count.
  EXPECT_EQ(Issues("model M \"(\"\n  // )\n  Real x = 1 \"{[\";\nend M;\n"), "");
}

TEST(ModelicaCheck, ConnectNeedsDeclaredComponentsAndConnectors) {
  std::string text = kValid;
  text.replace(text.find("connect(spring.flange_b, inertia2.flange_a)"), 43,
               "connect(spring.flange_b, inertia9.flange_a)");
  std::string issues = Issues(text);
  EXPECT_NE(issues.find("no component 'inertia9' is declared (in 'inertia9.flange_a')"), std::string::npos)
      << issues;

  text = kValid;
  text.replace(text.find("connect(spring.flange_b, inertia2.flange_a)"), 43,
               "connect(spring.flange_b, inertia2.flange_c)");
  issues = Issues(text);
  EXPECT_NE(issues.find("'flange_c' is not a connector of 'inertia2' "
                        "(Modelica.Mechanics.Rotational.Components.Inertia; connectors: flange_a, flange_b)"),
            std::string::npos)
      << issues;
}

TEST(ModelicaCheck, ConnectJoinsCompatibleConnectorsOnly) {
  std::string text = kValid;
  text.replace(text.find("connect(sine.y, torque.tau)"), 27, "connect(sine.y, torque.flange)");
  const std::string issues = Issues(text);
  EXPECT_NE(issues.find("joins a Real output to a rotational flange"), std::string::npos) << issues;
}

TEST(ModelicaCheck, MslNamesMustBeInTheList) {
  std::string text = kValid;
  text.replace(text.find("Components.Spring spring"), 24, "Components.Sprung spring");
  std::string issues = Issues(text);
  EXPECT_NE(issues.find("'Modelica.Mechanics.Rotational.Components.Sprung' is not in the list of MSL 4.0.0"),
            std::string::npos)
      << issues;
  // Also in expressions and through import aliases.
  issues = Issues("model M\n  import SI = Modelica.Units.SI;\n  SI.Torqe tau = Modelica.Constants.pie;\nend M;\n");
  EXPECT_NE(issues.find("'Modelica.Constants.pie' is not in the list"), std::string::npos) << issues;
  EXPECT_NE(issues.find("'Modelica.Units.SI.Torqe' is not in the list"), std::string::npos) << issues;
}

TEST(ModelicaCheck, ModifiersMustBeParametersOfTheMslClass) {
  std::string text = kValid;
  text.replace(text.find("spring(c=1e4)"), 13, "spring(k=1e4)");
  const std::string issues = Issues(text);
  EXPECT_NE(issues.find("modifier of 'spring' in 'M': 'k' is not a parameter or variable of "
                        "Modelica.Mechanics.Rotational.Components.Spring"),
            std::string::npos)
      << issues;
}

TEST(ModelicaCheck, LibraryClassesProvideConnectorsAndParameters) {
  const std::vector<GeneratedFile> library = {
      {"L/package.mo", "within;\npackage L\nend L;\n"},
      {"L/package.order", "Part\n"},
      {"L/Part.mo",
       "within L;\nmodel Part\n  extends Modelica.Mechanics.Rotational.Interfaces.PartialTwoFlanges;\n"
       "  parameter Real k = 1;\n  Modelica.Blocks.Interfaces.RealOutput y;\nequation\n"
       "  flange_a.phi = flange_b.phi;\n  flange_a.tau + flange_b.tau = 0;\n  y = k;\nend Part;\n"},
  };
  EXPECT_EQ(Issues("model M\n  L.Part part(k=2);\n  Modelica.Mechanics.Rotational.Components.Fixed fixed;\n"
                   "equation\n  connect(part.flange_a, fixed.flange);\nend M;\n",
                   library),
            "");
  const std::string issues =
      Issues("model M\n  L.Part part(q=2);\n  L.Nope nope;\nequation\n  connect(part.z, part.flange_a);\nend M;\n", library);
  EXPECT_NE(issues.find("'q' is not a parameter or variable of L.Part"), std::string::npos) << issues;
  EXPECT_NE(issues.find("unknown class 'L.Nope'"), std::string::npos) << issues;
  EXPECT_NE(issues.find("'z' is not a connector of 'part' (L.Part; connectors: flange_a, flange_b, y)"),
            std::string::npos)
      << issues;
}

TEST(ModelicaCheck, LibraryLayoutOneClassPerFileWithPackageOrder) {
  const std::vector<GeneratedFile> files = {
      {"L/package.mo", "within;\npackage L\nend L;\n"},
      {"L/package.order", "A\nGhost\n"},
      {"L/A.mo", "within L;\nmodel A\nend A;\n"},
      {"L/B.mo", "within L.Sub;\nmodel C\nend C;\n"},
  };
  std::string issues;
  for (const auto& i : CheckModelica(files)) issues += i.ToString() + "\n";
  EXPECT_NE(issues.find("'Ghost' is listed but there is no L/Ghost.mo"), std::string::npos) << issues;
  EXPECT_NE(issues.find("class 'B' of L is missing from package.order"), std::string::npos) << issues;
  EXPECT_NE(issues.find("'L/B.mo' must start with 'within L;'"), std::string::npos) << issues;
  EXPECT_NE(issues.find("'L/B.mo' must define exactly one class, 'B'"), std::string::npos) << issues;
}

TEST(ModelicaCheck, MslListKnowsTheClassesTheExamplesUse) {
  for (const char* c : {"Modelica.Mechanics.Rotational.Components.Inertia",
                        "Modelica.Mechanics.Rotational.Components.Clutch",
                        "Modelica.Blocks.Sources.CombiTimeTable", "Modelica.Units.SI.Torque"})
    EXPECT_TRUE(IsKnownMslName(c)) << c;
  EXPECT_FALSE(IsKnownMslName("Modelica.Mechanics.Rotational.Components.Flywheel"));
  const auto mods = MslModifiers("Modelica.Mechanics.Rotational.Components.Brake");
  for (const char* m : {"mu_pos", "peak", "cgeo", "fn_max", "useSupport"})
    EXPECT_NE(std::find(mods.begin(), mods.end(), m), mods.end()) << m;
  const auto cons = MslConnectors("Modelica.Mechanics.Rotational.Components.Brake");
  EXPECT_NE(std::find(cons.begin(), cons.end(), "f_normalized"), cons.end());
}

}  // namespace
}  // namespace highlift
