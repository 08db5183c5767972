// Structural checker of Modelica text (see modelica_check.h). Two passes: the first tokenises
// every file and collects its classes (declarations, extends clauses, imports, connect
// statements), the second resolves type names against the HighLift classes and the MSL list and
// checks connects and modifiers.
#include "highlift/export/modelica_check.h"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "msl_classes.h"

namespace highlift {
namespace {

// ---- Tokens ------------------------------------------------------------------------------------

enum class TokenKind { kIdent, kNumber, kString, kSymbol };

struct Token {
  TokenKind kind;
  std::string text;
  int line;
};

bool IsIdentStart(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool IsDigit(char c) { return c >= '0' && c <= '9'; }

struct Tokenised {
  std::vector<Token> tokens;
  std::vector<ModelicaIssue> issues;
};

Tokenised Tokenise(const std::string& file, const std::string& text) {
  Tokenised out;
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = text.size();
  auto issue = [&](int at, std::string message) { out.issues.push_back({file, at, std::move(message)}); };
  while (i < n) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
    } else if (c == '/' && i + 1 < n && text[i + 1] == '/') {
      while (i < n && text[i] != '\n') ++i;
    } else if (c == '/' && i + 1 < n && text[i + 1] == '*') {
      const int start = line;
      i += 2;
      while (i + 1 < n && !(text[i] == '*' && text[i + 1] == '/')) {
        if (text[i] == '\n') ++line;
        ++i;
      }
      if (i + 1 >= n) {
        issue(start, "comment opened with /* is never closed");
        break;
      }
      i += 2;
    } else if (c == '"') {
      const int start = line;
      std::string s;
      ++i;
      while (i < n && text[i] != '"') {
        if (text[i] == '\\' && i + 1 < n) {
          s += text[i];
          ++i;
        }
        if (text[i] == '\n') ++line;
        s += text[i];
        ++i;
      }
      if (i >= n) {
        issue(start, "string literal is never closed");
        break;
      }
      ++i;
      out.tokens.push_back({TokenKind::kString, s, start});
    } else if (c == '\'') {  // quoted identifier
      std::string s = "'";
      ++i;
      while (i < n && text[i] != '\'') s += text[i++];
      ++i;
      out.tokens.push_back({TokenKind::kIdent, s + "'", line});
    } else if (IsIdentStart(c)) {
      std::string s;
      while (i < n && (IsIdentStart(text[i]) || IsDigit(text[i]))) s += text[i++];
      out.tokens.push_back({TokenKind::kIdent, s, line});
    } else if (IsDigit(c) || (c == '.' && i + 1 < n && IsDigit(text[i + 1]))) {
      std::string s;
      while (i < n && (IsDigit(text[i]) || text[i] == '.')) s += text[i++];
      if (i < n && (text[i] == 'e' || text[i] == 'E')) {
        s += text[i++];
        if (i < n && (text[i] == '+' || text[i] == '-')) s += text[i++];
        while (i < n && IsDigit(text[i])) s += text[i++];
      }
      out.tokens.push_back({TokenKind::kNumber, s, line});
    } else {
      static const char* kTwo[] = {":=", "==", "<=", ">=", "<>", ".+", ".-", ".*", "./", ".^"};
      std::string s(1, c);
      for (const char* two : kTwo)
        if (i + 1 < n && text[i] == two[0] && text[i + 1] == two[1]) s = two;
      i += s.size();
      out.tokens.push_back({TokenKind::kSymbol, s, line});
    }
  }
  return out;
}

bool Is(const Token& t, std::string_view text) {
  return (t.kind == TokenKind::kIdent || t.kind == TokenKind::kSymbol) && t.text == text;
}

const std::set<std::string_view> kClassKeywords = {"model",  "block", "package", "connector",
                                                   "record", "function", "type", "class"};
const std::set<std::string_view> kClassPrefixes = {"partial",  "encapsulated", "expandable",
                                                   "operator", "pure",         "impure",
                                                   "replaceable", "redeclare", "final"};
const std::set<std::string_view> kComponentPrefixes = {
    "parameter", "constant", "discrete", "input", "output", "flow",   "stream", "final",
    "inner",     "outer",    "replaceable", "redeclare", "each", "public", "protected"};
const std::set<std::string_view> kBuiltinTypes = {"Real",      "Integer",     "Boolean",
                                                  "String",    "StateSelect", "AssertionLevel",
                                                  "ExternalObject", "Clock"};

// ---- Collected structure -----------------------------------------------------------------------

struct Modifier {
  std::string name;
  int line;
  std::string value;  // the text after `name=` (tokens joined), empty for `name(...)`
};

struct Declaration {
  std::string type;  // as written
  std::string name;
  std::vector<Modifier> modifiers;
  int line = 0;
  bool parameter = false;  // parameter or constant
  bool is_protected = false;  // declared in a protected section
  bool binding = false;    // `= value` after the name (and its modifiers)
  std::string binding_value;  // its text (tokens joined), up to the comment
  std::string condition;   // `if <condition>` of a conditional component (tokens joined)
};

struct Extends {
  std::string type;
  std::vector<Modifier> modifiers;
  int line;
};

struct ConnectRef {
  std::vector<std::string> parts;  // "inertia1", "flange_a" (subscripts dropped)
};

struct Connect {
  ConnectRef a, b;
  int line;
};

struct ClassInfo {
  std::vector<std::pair<std::string, std::string>> assigned;  // `a.b = ...` equations: (a, b)
  std::string path;   // full name, e.g. HighLift.Mechanical.ShaftBrake
  std::string scope;  // enclosing package path ("" at top level)
  std::string kind;   // model, block, connector, ...
  std::string short_base;  // for short definitions `type X = Y`: Y as written
  std::string file;
  int line = 0;
  std::vector<Declaration> declarations;
  std::vector<Extends> extends;
  std::vector<Connect> connects;
  std::map<std::string, std::string> aliases;  // import X = A.B.C; and import A.B.C;
};

class Collector {
 public:
  Collector(std::string file, const std::vector<Token>& tokens, std::vector<ModelicaIssue>& issues,
            std::vector<ClassInfo>& classes)
      : file_(std::move(file)), t_(tokens), issues_(issues), classes_(classes) {}

  void Run() {
    CheckBalance();
    std::string within;
    if (pos_ < t_.size() && Is(t_[pos_], "within")) {
      ++pos_;
      while (pos_ < t_.size() && !Is(t_[pos_], ";")) within += t_[pos_++].text;
      ++pos_;
      within_ = within;
    }
    while (pos_ < t_.size()) {
      if (AtClassStart()) {
        ParseClass(within, {});
      } else if (Is(t_[pos_], "import")) {
        SkipStatement();
      } else {
        Issue(t_[pos_].line, "unexpected '" + t_[pos_].text + "' outside a class definition");
        SkipStatement();
      }
    }
  }

  const std::string& within() const { return within_; }
  std::vector<std::string> top_level;  // names of the top-level classes in this file

 private:
  void Issue(int line, std::string message) { issues_.push_back({file_, line, std::move(message)}); }

  void CheckBalance() {
    std::vector<const Token*> open;
    for (const Token& tok : t_) {
      if (tok.kind != TokenKind::kSymbol) continue;
      const std::string& s = tok.text;
      if (s == "(" || s == "[" || s == "{") {
        open.push_back(&tok);
      } else if (s == ")" || s == "]" || s == "}") {
        const char want = s == ")" ? '(' : s == "]" ? '[' : '{';
        if (open.empty()) {
          Issue(tok.line, "'" + s + "' without a matching opening bracket");
        } else if (open.back()->text[0] != want) {
          Issue(tok.line, "'" + s + "' closes '" + open.back()->text + "' opened on line " +
                              std::to_string(open.back()->line));
          open.pop_back();
        } else {
          open.pop_back();
        }
      }
    }
    for (const Token* tok : open)
      Issue(tok->line, "'" + tok->text + "' is never closed");
  }

  bool AtClassStart() const {
    std::size_t p = pos_;
    while (p < t_.size() && t_[p].kind == TokenKind::kIdent && kClassPrefixes.count(t_[p].text)) ++p;
    if (p + 1 >= t_.size()) return false;
    if (t_[p].kind != TokenKind::kIdent || !kClassKeywords.count(t_[p].text)) return false;
    if (p > 0 && Is(t_[p - 1], "end")) return false;
    return t_[p + 1].kind == TokenKind::kIdent || Is(t_[p + 1], "extends");
  }

  // Skips to the token after the next ';' at bracket depth 0.
  void SkipStatement() {
    int depth = 0;
    while (pos_ < t_.size()) {
      const Token& tok = t_[pos_++];
      if (tok.kind != TokenKind::kSymbol) continue;
      if (tok.text == "(" || tok.text == "[" || tok.text == "{") ++depth;
      if (tok.text == ")" || tok.text == "]" || tok.text == "}") --depth;
      if (tok.text == ";" && depth <= 0) return;
    }
  }

  // Index one past the bracket group starting at `p` (t_[p] is the opening bracket).
  std::size_t SkipGroup(std::size_t p) const {
    int depth = 0;
    for (; p < t_.size(); ++p) {
      const std::string& s = t_[p].text;
      if (t_[p].kind != TokenKind::kSymbol) continue;
      if (s == "(" || s == "[" || s == "{") ++depth;
      if (s == ")" || s == "]" || s == "}") {
        if (--depth == 0) return p + 1;
      }
    }
    return p;
  }

  // Reads a dotted name at `p`; advances p.
  std::string DottedName(std::size_t& p) const {
    std::string name;
    if (p < t_.size() && Is(t_[p], ".")) name += t_[p++].text;  // global lookup .A.B
    while (p < t_.size() && t_[p].kind == TokenKind::kIdent) {
      name += t_[p++].text;
      if (p + 1 < t_.size() && Is(t_[p], ".") && t_[p + 1].kind == TokenKind::kIdent) {
        name += '.';
        ++p;
      } else {
        break;
      }
    }
    return name;
  }

  // The top-level argument names of the modification starting at '(' at `p`.
  std::vector<Modifier> Modifiers(std::size_t p, std::size_t end) const {
    std::vector<Modifier> mods;
    int depth = 0;
    bool expect_name = true;
    for (std::size_t q = p; q < end; ++q) {
      const Token& tok = t_[q];
      if (tok.kind == TokenKind::kSymbol) {
        if (tok.text == "(" || tok.text == "[" || tok.text == "{") {
          ++depth;
          if (depth == 1) expect_name = true;
          continue;
        }
        if (tok.text == ")" || tok.text == "]" || tok.text == "}") {
          if (--depth == 0) break;
          continue;
        }
        if (tok.text == "," && depth == 1) {
          expect_name = true;
          continue;
        }
      }
      if (depth == 1 && expect_name && tok.kind == TokenKind::kIdent) {
        if (tok.text == "each" || tok.text == "final") continue;
        if (tok.text == "redeclare" || tok.text == "replaceable") {
          expect_name = false;  // a redeclaration is not checked
          continue;
        }
        mods.push_back({tok.text, tok.line, {}});
        expect_name = false;
        if (q + 1 < end && Is(t_[q + 1], "=")) {  // the value, up to ',' or ')' at this depth
          std::size_t v = q + 2;
          int inner = 0;
          for (; v < end; ++v) {
            const std::string& s = t_[v].text;
            if (t_[v].kind == TokenKind::kSymbol) {
              if (s == "(" || s == "[" || s == "{") ++inner;
              if (s == ")" || s == "]" || s == "}") {
                if (inner == 0) break;
                --inner;
              }
              if (s == "," && inner == 0) break;
            }
            mods.back().value += (mods.back().value.empty() ? "" : " ") + s;
          }
          q = v - 1;
        }
      } else if (depth == 1) {
        expect_name = false;
      }
    }
    return mods;
  }

  void ParseClass(const std::string& scope, std::map<std::string, std::string> aliases) {
    while (kClassPrefixes.count(t_[pos_].text)) ++pos_;
    ClassInfo info;
    info.kind = t_[pos_].text;
    info.line = t_[pos_].line;
    info.file = file_;
    info.scope = scope;
    ++pos_;
    if (Is(t_[pos_], "extends")) {  // `model extends X` (class extension): skip its body
      Issue(info.line, "class extension (" + info.kind + " extends) is not supported by the checker");
      ++pos_;
    }
    const std::string name = t_[pos_].text;
    ++pos_;
    info.path = scope.empty() ? name : scope + "." + name;
    if (scope == within_) top_level.push_back(name);
    // The description string of the class (possibly concatenated with +).
    while (pos_ < t_.size() && (t_[pos_].kind == TokenKind::kString || Is(t_[pos_], "+"))) ++pos_;
    if (pos_ < t_.size() && Is(t_[pos_], "=")) {  // short class definition
      std::size_t p = pos_ + 1;
      while (p < t_.size() && t_[p].kind == TokenKind::kIdent &&
             (t_[p].text == "input" || t_[p].text == "output"))
        ++p;
      if (p < t_.size() && (t_[p].kind == TokenKind::kIdent || Is(t_[p], "."))) {
        std::size_t q = p;
        info.short_base = DottedName(q);
        if (q < t_.size() && Is(t_[q], "[")) q = SkipGroup(q);
        if (q < t_.size() && Is(t_[q], "(")) {
          const std::size_t end = SkipGroup(q);
          info.extends.push_back({info.short_base, Modifiers(q, end), info.line});
        } else {
          info.extends.push_back({info.short_base, {}, info.line});
        }
      }
      SkipStatement();
      info.aliases = aliases;
      classes_.push_back(std::move(info));
      return;
    }
    const std::size_t index = classes_.size();
    classes_.push_back(info);
    bool equations = false, is_protected = false;
    while (pos_ < t_.size()) {
      const Token& tok = t_[pos_];
      if (Is(tok, "end") && pos_ + 1 < t_.size() && t_[pos_ + 1].kind == TokenKind::kIdent &&
          !IsModelicaKeyword(t_[pos_ + 1].text)) {
        const std::string closing = t_[pos_ + 1].text;
        if (closing != name)
          Issue(tok.line, "'end " + closing + ";' closes " + info.kind + " '" + name +
                              "' (opened on line " + std::to_string(info.line) + "): write 'end " +
                              name + ";'");
        pos_ += 2;
        if (pos_ < t_.size() && Is(t_[pos_], ";")) {
          ++pos_;
        } else {
          Issue(tok.line, "'end " + closing + "' is not followed by ';'");
        }
        classes_[index].aliases = aliases;
        return;
      }
      if (AtClassStart()) {
        ParseClass(classes_[index].path, aliases);
        continue;
      }
      if (tok.kind == TokenKind::kIdent &&
          (tok.text == "equation" || tok.text == "algorithm")) {
        equations = true;
        ++pos_;
        continue;
      }
      if (Is(tok, "initial") && pos_ + 1 < t_.size() &&
          (Is(t_[pos_ + 1], "equation") || Is(t_[pos_ + 1], "algorithm"))) {
        equations = true;
        pos_ += 2;
        continue;
      }
      if (Is(tok, "public") || Is(tok, "protected")) {
        equations = false;
        is_protected = Is(tok, "protected");
        ++pos_;
        continue;
      }
      const std::size_t start = pos_;
      SkipStatement();
      const std::size_t end = pos_;  // one past ';'
      if (Is(t_[start], "annotation") || Is(t_[start], "external")) continue;
      if (equations) {
        CollectConnects(start, end, classes_[index]);
      } else if (Is(t_[start], "import")) {
        CollectImport(start, end, aliases);
      } else if (Is(t_[start], "extends")) {
        std::size_t p = start + 1;
        Extends e{DottedName(p), {}, t_[start].line};
        if (p < end && Is(t_[p], "(")) e.modifiers = Modifiers(p, SkipGroup(p));
        classes_[index].extends.push_back(std::move(e));
      } else {
        CollectDeclaration(start, end, classes_[index], is_protected);
      }
    }
    Issue(info.line, info.kind + " '" + name + "' is never closed: add 'end " + name + ";'");
  }

  void CollectImport(std::size_t p, std::size_t end, std::map<std::string, std::string>& aliases) {
    ++p;
    if (p + 1 < end && t_[p].kind == TokenKind::kIdent && Is(t_[p + 1], "=")) {
      const std::string alias = t_[p].text;
      p += 2;
      aliases[alias] = DottedName(p);
    } else {
      const std::string full = DottedName(p);
      const auto dot = full.rfind('.');
      if (p < end && Is(t_[p], ".")) return;  // import A.B.*; nothing to alias
      aliases[dot == std::string::npos ? full : full.substr(dot + 1)] = full;
    }
  }

  void CollectDeclaration(std::size_t p, std::size_t end, ClassInfo& info, bool is_protected) {
    bool parameter = false;
    while (p < end && t_[p].kind == TokenKind::kIdent && kComponentPrefixes.count(t_[p].text)) {
      parameter = parameter || t_[p].text == "parameter" || t_[p].text == "constant";
      ++p;
    }
    if (p >= end || !(t_[p].kind == TokenKind::kIdent || Is(t_[p], "."))) return;
    const int line = t_[p].line;
    const std::string type = DottedName(p);
    if (p < end && Is(t_[p], "[")) p = SkipGroup(p);
    // One or more component names, separated by commas at depth 0.
    while (p < end && t_[p].kind == TokenKind::kIdent) {
      Declaration d;
      d.type = type;
      d.name = t_[p].text;
      d.line = line;
      d.parameter = parameter;
      d.is_protected = is_protected;
      ++p;
      if (p < end && Is(t_[p], "[")) p = SkipGroup(p);
      if (p < end && Is(t_[p], "(")) {
        const std::size_t close = SkipGroup(p);
        d.modifiers = Modifiers(p, close);
        p = close;
      }
      d.binding = p < end && Is(t_[p], "=");
      // Skip the binding, condition, comment and annotation up to a ',' or ';' at depth 0; keep
      // the condition.
      bool in_condition = false;
      while (p < end && !Is(t_[p], ",") && !Is(t_[p], ";")) {
        if (Is(t_[p], "if") && !d.binding) {
          in_condition = true;
          ++p;
          continue;
        }
        if (t_[p].kind == TokenKind::kString || Is(t_[p], "annotation")) in_condition = false;
        if (d.binding && d.binding_value.empty() && Is(t_[p], "=") && p + 1 < end &&
            t_[p + 1].kind != TokenKind::kString)
          d.binding_value = t_[p + 1].text;  // the first token: enough for true/false
        if (Is(t_[p], "(") || Is(t_[p], "[") || Is(t_[p], "{")) {
          p = SkipGroup(p);
        } else {
          if (in_condition) d.condition += (d.condition.empty() ? "" : " ") + t_[p].text;
          ++p;
        }
      }
      info.declarations.push_back(std::move(d));
      if (p < end && Is(t_[p], ",")) ++p;
      else break;
    }
  }

  // connect(a.b, c.d) anywhere in an equation statement (also inside for/if), and equations
  // that give a component's connector a value (`motor.tau = tau_drive;`).
  void CollectConnects(std::size_t p, std::size_t end, ClassInfo& info) {
    for (std::size_t q = p; q + 3 < end; ++q) {
      const bool statement_start = q == p || Is(t_[q - 1], ";") || Is(t_[q - 1], "then") ||
                                   Is(t_[q - 1], "else") || Is(t_[q - 1], "loop");
      if (statement_start && t_[q].kind == TokenKind::kIdent && Is(t_[q + 1], ".") &&
          t_[q + 2].kind == TokenKind::kIdent && Is(t_[q + 3], "="))
        info.assigned.emplace_back(t_[q].text, t_[q + 2].text);
    }
    for (; p + 1 < end; ++p) {
      if (!(Is(t_[p], "connect") && Is(t_[p + 1], "("))) continue;
      const int line = t_[p].line;
      std::size_t q = p + 2;
      auto ref = [&]() {
        ConnectRef r;
        while (q < end && t_[q].kind == TokenKind::kIdent) {
          r.parts.push_back(t_[q].text);
          ++q;
          if (q < end && Is(t_[q], "[")) q = SkipGroup(q);
          if (q < end && Is(t_[q], ".")) ++q;
          else break;
        }
        return r;
      };
      Connect c;
      c.line = line;
      c.a = ref();
      if (q < end && Is(t_[q], ",")) ++q;
      else Issue(line, "connect() needs two connector references separated by ','");
      c.b = ref();
      if (!(q < end && Is(t_[q], ")"))) Issue(line, "malformed connect(): expected ')' after the second connector");
      info.connects.push_back(std::move(c));
    }
  }

  std::string file_;
  const std::vector<Token>& t_;
  std::vector<ModelicaIssue>& issues_;
  std::vector<ClassInfo>& classes_;
  std::size_t pos_ = 0;
  std::string within_;
};

// ---- Resolution and checks ---------------------------------------------------------------------

struct Resolved {
  enum Where { kUnknown, kBuiltin, kMsl, kLibrary } where = kUnknown;
  std::string path;
};

class Checker {
 public:
  Checker(std::vector<ClassInfo>& classes, std::vector<ModelicaIssue>& issues)
      : classes_(classes), issues_(issues) {
    for (std::size_t i = 0; i < classes_.size(); ++i) by_path_[classes_[i].path] = i;
  }

  Resolved Resolve(const std::string& name, const ClassInfo& context) const {
    if (name.empty()) return {};
    if (kBuiltinTypes.count(name)) return {Resolved::kBuiltin, name};
    std::string first = name.substr(0, name.find('.'));
    std::string rest = name.size() > first.size() ? name.substr(first.size()) : "";
    if (auto it = context.aliases.find(first); it != context.aliases.end())
      return ResolveFull(it->second + rest);
    // Lexical lookup: the class itself and its enclosing scopes.
    std::string scope = context.path;
    while (true) {
      const std::string candidate = scope.empty() ? name : scope + "." + name;
      if (by_path_.count(candidate)) return {Resolved::kLibrary, candidate};
      // A class in an enclosing scope that declares `first` as a nested class.
      if (scope.empty()) break;
      const auto dot = scope.rfind('.');
      scope = dot == std::string::npos ? "" : scope.substr(0, dot);
    }
    return ResolveFull(name);
  }

  Resolved ResolveFull(const std::string& name) const {
    if (by_path_.count(name)) return {Resolved::kLibrary, name};
    if (msl::Find(name)) return {Resolved::kMsl, name};
    return {Resolved::kUnknown, name};
  }

  // Connectors of a class (declared and inherited): name -> kind (nullopt when unknown).
  std::map<std::string, std::optional<msl::ConnectorKind>> Connectors(const Resolved& r, int depth = 0) const {
    std::map<std::string, std::optional<msl::ConnectorKind>> out;
    if (depth > 20) return out;
    if (r.where == Resolved::kMsl) {
      for (const auto& c : msl::Find(r.path)->connectors) out[c.name] = c.kind;
      return out;
    }
    if (r.where != Resolved::kLibrary) return out;
    const ClassInfo& info = classes_[by_path_.at(r.path)];
    for (const Extends& e : info.extends)
      for (auto& [k, v] : Connectors(Resolve(e.type, info), depth + 1)) out[k] = v;
    for (const Declaration& d : info.declarations) {
      const Resolved type = Resolve(d.type, info);
      std::optional<msl::ConnectorKind> kind;
      if (IsConnector(type, kind)) out[d.name] = kind;
    }
    return out;
  }

  // The class of the library `r` names, or nullptr (and `known` false) when it is none.
  const ClassInfo* LibraryClass(const Resolved& r, bool& known) const {
    if (r.where == Resolved::kLibrary) return &classes_[by_path_.at(r.path)];
    known = false;
    return nullptr;
  }

  // All names a modifier may use on an instance of a class (its declared and inherited
  // components); `known` is false when the class is not fully known.
  std::set<std::string> ModifierNames(const Resolved& r, bool& known, int depth = 0) const {
    std::set<std::string> out;
    if (depth > 20) return out;
    if (r.where == Resolved::kMsl) {
      const auto* c = msl::Find(r.path);
      out.insert(c->modifiers.begin(), c->modifiers.end());
      for (const auto& con : c->connectors) out.insert(con.name);
      return out;
    }
    if (r.where == Resolved::kBuiltin) {
      for (const char* a : {"start", "fixed", "min", "max", "nominal", "unit", "displayUnit",
                            "quantity", "stateSelect"})
        out.insert(a);
      return out;
    }
    const ClassInfo* info = LibraryClass(r, known);
    if (info == nullptr) return out;
    for (const Extends& e : info->extends) {
      auto inherited = ModifierNames(Resolve(e.type, *info), known, depth + 1);
      out.insert(inherited.begin(), inherited.end());
    }
    for (const Declaration& d : info->declarations) out.insert(d.name);
    return out;
  }

  bool IsConnector(const Resolved& type, std::optional<msl::ConnectorKind>& kind, int depth = 0) const {
    msl::ConnectorKind k;
    if (msl::ConnectorClassKind(type.path, k)) {
      kind = k;
      return true;
    }
    if (type.where == Resolved::kMsl) return msl::Find(type.path)->kind == "connector";
    if (type.where != Resolved::kLibrary || depth > 20) return false;
    const ClassInfo& info = classes_[by_path_.at(type.path)];
    if (info.kind == "connector") return true;
    for (const Extends& e : info.extends)
      if (IsConnector(Resolve(e.type, info), kind, depth + 1)) return true;
    return false;
  }

  void Run() {
    for (const ClassInfo& info : classes_) CheckClass(info);
  }

  /// The completeness checks of the classes defined in `files` (CheckModelicaCompleteness).
  void RunCompleteness(const std::set<std::string>& files) {
    for (const ClassInfo& info : classes_)
      if (files.count(info.file)) CheckCompleteness(info);
  }

 private:
  void Issue(const ClassInfo& info, int line, std::string message) {
    issues_.push_back({info.file, line, std::move(message)});
  }

  void CheckType(const ClassInfo& info, const std::string& type, int line, const std::string& what) {
    const Resolved r = Resolve(type, info);
    if (r.where == Resolved::kUnknown) {
      if (type.rfind("Modelica.", 0) == 0 || r.path.rfind("Modelica.", 0) == 0) {
        Issue(info, line, what + ": '" + r.path +
                              "' is not in the list of MSL 4.0.0 classes the exporter may use "
                              "(export/src/msl_classes.cc)");
      } else {
        Issue(info, line, what + ": unknown class '" + type + "'");
      }
    }
  }

  void CheckModifiers(const ClassInfo& info, const std::string& type,
                      const std::vector<Modifier>& modifiers, const std::string& what) {
    const Resolved r = Resolve(type, info);
    if (r.where == Resolved::kUnknown || modifiers.empty()) return;
    bool known = true;
    const auto names = ModifierNames(r, known);
    if (!known) return;
    for (const Modifier& m : modifiers) {
      if (names.count(m.name)) continue;
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      Issue(info, m.line, what + ": '" + m.name + "' is not a parameter or variable of " + r.path +
                              (list.empty() ? "" : " (known: " + list + ")"));
    }
  }

  void CheckClass(const ClassInfo& info) {
    for (const Extends& e : info.extends) {
      CheckType(info, e.type, e.line, "extends in '" + info.path + "'");
      CheckModifiers(info, e.type, e.modifiers, "extends " + e.type + " in '" + info.path + "'");
    }
    std::map<std::string, const Declaration*> components;
    for (const Declaration& d : info.declarations) {
      CheckType(info, d.type, d.line, "declaration of '" + d.name + "' in '" + info.path + "'");
      CheckModifiers(info, d.type, d.modifiers, "modifier of '" + d.name + "' in '" + info.path + "'");
      components[d.name] = &d;
    }
    if (info.connects.empty()) return;
    // Components inherited from base classes can be connected too.
    bool known = true;
    std::set<std::string> inherited;
    for (const Extends& e : info.extends) {
      auto names = ModifierNames(Resolve(e.type, info), known);
      inherited.insert(names.begin(), names.end());
    }
    const auto own_connectors = Connectors({Resolved::kLibrary, info.path});
    for (const Connect& c : info.connects) {
      auto a = CheckRef(info, c.a, c.line, components, inherited, own_connectors);
      auto b = CheckRef(info, c.b, c.line, components, inherited, own_connectors);
      if (a && b && *a && *b && !msl::Compatible(**a, **b))
        Issue(info, c.line, "connect(" + Join(c.a) + ", " + Join(c.b) + ") in '" + info.path +
                                "' joins a " + msl::ToString(**a) + " to a " + msl::ToString(**b));
    }
  }

  // Parameters of a class that have no value: its own declarations without a binding and the
  // inherited ones the extends clause does not bind. `known` is false for an unknown class.
  std::set<std::string> Required(const Resolved& r, bool& known, int depth = 0) const {
    std::set<std::string> out;
    if (depth > 20 || r.where == Resolved::kBuiltin) return out;
    if (r.where == Resolved::kMsl) {
      for (auto& p : msl::RequiredParameters(r.path)) out.insert(p);
      return out;
    }
    const ClassInfo* info = LibraryClass(r, known);
    if (info == nullptr) return out;
    for (const Extends& e : info->extends) {
      for (const auto& p : Required(Resolve(e.type, *info), known, depth + 1)) {
        const bool bound = std::any_of(e.modifiers.begin(), e.modifiers.end(),
                                       [&](const Modifier& m) { return m.name == p && !m.value.empty(); });
        if (!bound) out.insert(p);
      }
    }
    for (const Declaration& d : info->declarations)
      if (d.parameter && !d.binding) out.insert(d.name);
    return out;
  }

  // The default of a Boolean parameter of a class: "true", "false" or "" (unknown).
  std::string BooleanDefault(const Resolved& r, const std::string& name, int depth = 0) const {
    if (depth > 20) return "";
    if (r.where == Resolved::kMsl) {
      for (const auto& c : msl::ConditionalConnectors(r.path))
        if (c.parameter == name) return c.default_value ? "true" : "false";
      return "";
    }
    if (r.where != Resolved::kLibrary) return "";
    const ClassInfo& info = classes_[by_path_.at(r.path)];
    for (const Declaration& d : info.declarations)
      if (d.name == name) return d.binding_value == "true" || d.binding_value == "false" ? d.binding_value : "";
    for (const Extends& e : info.extends) {
      for (const Modifier& m : e.modifiers)
        if (m.name == name && (m.value == "true" || m.value == "false")) return m.value;
      const std::string v = BooleanDefault(Resolve(e.type, info), name, depth + 1);
      if (!v.empty()) return v;
    }
    return "";
  }

  // Components a class declares protected (its own and inherited ones).
  std::set<std::string> ProtectedNames(const Resolved& r, int depth = 0) const {
    std::set<std::string> out;
    if (depth > 20 || r.where != Resolved::kLibrary) return out;
    const ClassInfo& info = classes_[by_path_.at(r.path)];
    for (const Extends& e : info.extends) {
      auto inherited = ProtectedNames(Resolve(e.type, info), depth + 1);
      out.insert(inherited.begin(), inherited.end());
    }
    for (const Declaration& d : info.declarations)
      if (d.is_protected) out.insert(d.name);
    return out;
  }

  // Conditional connectors of a class (declared and inherited): connector -> condition.
  std::map<std::string, std::string> ConditionalConnectorsOf(const Resolved& r, int depth = 0) const {
    std::map<std::string, std::string> out;
    if (depth > 20) return out;
    if (r.where == Resolved::kMsl) {
      for (const auto& c : msl::ConditionalConnectors(r.path)) out[c.connector] = c.parameter;
      return out;
    }
    if (r.where != Resolved::kLibrary) return out;
    const ClassInfo& info = classes_[by_path_.at(r.path)];
    for (const Extends& e : info.extends)
      for (auto& [k, v] : ConditionalConnectorsOf(Resolve(e.type, info), depth + 1)) out[k] = v;
    for (const Declaration& d : info.declarations) {
      std::optional<msl::ConnectorKind> kind;
      if (!d.condition.empty() && IsConnector(Resolve(d.type, info), kind)) out[d.name] = d.condition;
    }
    return out;
  }

  // The value of a condition ("useSupport", "not elastic") on an instance: "true", "false" or
  // "" when it cannot be told (an expression, a parameter without a literal default).
  std::string Evaluate(const std::string& condition, const Declaration& d, const Resolved& type) const {
    std::string name = condition;
    bool negate = false;
    if (name.rfind("not ", 0) == 0) {
      negate = true;
      name = name.substr(4);
    }
    if (name.find(' ') != std::string::npos) return "";
    std::string value;
    for (const Modifier& m : d.modifiers)
      if (m.name == name) value = m.value;
    if (value.empty()) value = BooleanDefault(type, name);
    if (value != "true" && value != "false") return "";
    return (value == "true") != negate ? "true" : "false";
  }

  void CheckCompleteness(const ClassInfo& info) {
    // A class a user simulates (an example, an exported model) gives every parameter a value.
    const bool simulated = info.kind == "model" && (info.path.rfind("HighLift.Examples.", 0) == 0 ||
                                                    info.path.rfind("HighLift.Models.", 0) == 0 ||
                                                    info.path.find('.') == std::string::npos);
    std::set<std::pair<std::string, std::string>> connected(info.assigned.begin(), info.assigned.end());
    for (const Connect& c : info.connects)
      for (const ConnectRef* r : {&c.a, &c.b})
        if (r->parts.size() >= 2) connected.insert({r->parts[0], r->parts[1]});
    for (const Declaration& d : info.declarations) {
      if (simulated && d.parameter && !d.binding)
        Issue(info, d.line, "parameter '" + d.name + "' of " + info.kind + " '" + info.path +
                                "' has no value: give it a binding (= value)");
      const Resolved type = Resolve(d.type, info);
      if (type.where != Resolved::kMsl && type.where != Resolved::kLibrary) continue;
      std::optional<msl::ConnectorKind> own_kind;
      if (IsConnector(type, own_kind)) continue;  // a connector of the class itself
      const std::string what = "instance '" + d.name + "' (" + type.path + ") in '" + info.path + "'";
      bool known = true;
      for (const auto& p : Required(type, known)) {
        const bool given = std::any_of(d.modifiers.begin(), d.modifiers.end(),
                                       [&](const Modifier& m) { return m.name == p && !m.value.empty(); });
        if (!given)
          Issue(info, d.line, what + ": parameter '" + p + "' has no value (no default in " + type.path +
                                  " and no modifier): give it, e.g. " + d.name + "(" + p + "=...)");
      }
      if (!d.condition.empty()) continue;  // a conditional instance: its connections are conditional too
      const auto conditional = ConditionalConnectorsOf(type);
      const auto hidden = ProtectedNames(type);
      for (const auto& [connector, kind] : Connectors(type)) {
        if (hidden.count(connector)) continue;  // internal (the MSL pattern of conditional inputs)
        const bool is_connected = connected.count({d.name, connector}) > 0;
        auto cond = conditional.find(connector);
        if (cond != conditional.end()) {
          const std::string enabled = Evaluate(cond->second, d, type);
          if (enabled == "false" && is_connected)
            Issue(info, d.line, what + ": connector '" + connector + "' is connected but disabled (" +
                                    cond->second + " is false): set it true or remove the connection");
          if (enabled == "true" && !is_connected)
            Issue(info, d.line, what + ": connector '" + connector + "' is enabled (" + cond->second +
                                    ") but not connected: connect it or disable it");
          continue;
        }
        const bool input = kind && (*kind == msl::ConnectorKind::kRealInput || *kind == msl::ConnectorKind::kBooleanInput);
        if (input && !is_connected)
          Issue(info, d.line, what + ": input '" + connector + "' is not connected: connect it to a signal source");
      }
    }
  }

  static std::string Join(const ConnectRef& r) {
    std::string s;
    for (const auto& p : r.parts) s += (s.empty() ? "" : ".") + p;
    return s;
  }

  // The connector kind of a reference (outer optional: the reference is valid; inner: kind known).
  std::optional<std::optional<msl::ConnectorKind>> CheckRef(
      const ClassInfo& info, const ConnectRef& ref, int line,
      const std::map<std::string, const Declaration*>& components,
      const std::set<std::string>& inherited,
      const std::map<std::string, std::optional<msl::ConnectorKind>>& own_connectors) {
    const std::string text = Join(ref);
    if (ref.parts.empty()) {
      Issue(info, line, "connect() in '" + info.path + "' has an empty connector reference");
      return std::nullopt;
    }
    if (ref.parts.size() == 1) {
      if (auto it = own_connectors.find(ref.parts[0]); it != own_connectors.end()) return it->second;
      Issue(info, line, "connect() in '" + info.path + "': '" + text +
                            "' is not a connector declared in '" + info.path + "'");
      return std::nullopt;
    }
    const auto it = components.find(ref.parts[0]);
    if (it == components.end()) {
      if (inherited.count(ref.parts[0])) return std::optional<msl::ConnectorKind>();
      Issue(info, line, "connect() in '" + info.path + "': no component '" + ref.parts[0] +
                            "' is declared (in '" + text + "')");
      return std::nullopt;
    }
    const Resolved type = Resolve(it->second->type, info);
    if (type.where == Resolved::kUnknown) return std::nullopt;  // reported with the declaration
    const auto connectors = Connectors(type);
    const auto con = connectors.find(ref.parts[1]);
    if (con == connectors.end()) {
      std::string list;
      for (const auto& [n, k] : connectors) list += (list.empty() ? "" : ", ") + n;
      Issue(info, line, "connect() in '" + info.path + "': '" + ref.parts[1] +
                            "' is not a connector of '" + ref.parts[0] + "' (" + type.path +
                            "; connectors: " + (list.empty() ? "none" : list) + ")");
      return std::nullopt;
    }
    return con->second;
  }

  std::vector<ClassInfo>& classes_;
  std::vector<ModelicaIssue>& issues_;
  std::map<std::string, std::size_t> by_path_;
};

// Every `Modelica.` dotted name (outside strings and comments) must be in the MSL list; names
// used through an import alias are checked by the declaration checks.
void CheckMslNames(const std::string& file, const std::vector<Token>& tokens,
                   std::vector<ModelicaIssue>& issues) {
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (!(tokens[i].kind == TokenKind::kIdent && tokens[i].text == "Modelica")) continue;
    if (i > 0 && Is(tokens[i - 1], ".")) continue;
    std::string name = "Modelica";
    std::size_t p = i + 1;
    while (p + 1 < tokens.size() && Is(tokens[p], ".") && tokens[p + 1].kind == TokenKind::kIdent) {
      name += "." + tokens[p + 1].text;
      p += 2;
    }
    if (!IsKnownMslName(name))
      issues.push_back({file, tokens[i].line,
                        "'" + name + "' is not in the list of MSL 4.0.0 names the exporter may use "
                                     "(export/src/msl_classes.cc)"});
    i = p - 1;
  }
}

// Library layout: HighLift/A/B.mo holds class B `within HighLift.A;`; package.mo holds the
// package of its folder; package.order lists exactly the classes and packages of its folder.
void CheckLayout(const std::vector<GeneratedFile>& files,
                 const std::map<std::string, std::pair<std::string, std::vector<std::string>>>& mo_files,
                 std::vector<ModelicaIssue>& issues) {
  std::map<std::string, std::set<std::string>> entries;  // folder -> class names in it
  std::set<std::string> folders_with_package;
  for (const auto& [path, within_and_names] : mo_files) {
    const auto slash = path.rfind('/');
    if (slash == std::string::npos) continue;  // a model file at the top level
    const std::string folder = path.substr(0, slash);
    std::string stem = path.substr(slash + 1);
    stem = stem.substr(0, stem.size() - 3);
    std::string package = folder;
    std::replace(package.begin(), package.end(), '/', '.');
    const auto& [within, names] = within_and_names;
    if (stem == "package") {
      folders_with_package.insert(folder);
      const auto parent_slash = folder.rfind('/');
      const std::string name = parent_slash == std::string::npos ? folder : folder.substr(parent_slash + 1);
      const std::string parent = parent_slash == std::string::npos ? "" : package.substr(0, package.rfind('.'));
      if (within != parent)
        issues.push_back({path, 1, "package.mo of '" + package + "' must start with 'within " + parent + ";'"});
      if (names.size() != 1 || names[0] != name)
        issues.push_back({path, 1, "package.mo in " + folder + " must define exactly package '" + name + "'"});
      if (parent_slash != std::string::npos) entries[folder.substr(0, parent_slash)].insert(name);
    } else {
      if (within != package)
        issues.push_back({path, 1, "'" + path + "' must start with 'within " + package + ";'"});
      if (names.size() != 1 || names[0] != stem)
        issues.push_back({path, 1, "'" + path + "' must define exactly one class, '" + stem + "'"});
      entries[folder].insert(stem);
    }
  }
  std::set<std::string> folders_with_order;
  for (const GeneratedFile& f : files) {
    const auto slash = f.path.rfind('/');
    if (f.path.size() < 13 || f.path.substr(f.path.size() - 13) != "package.order") continue;
    const std::string folder = slash == std::string::npos ? "" : f.path.substr(0, slash);
    folders_with_order.insert(folder);
    std::istringstream in(f.content);
    std::set<std::string> listed;
    int line_no = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_no;
      if (line.empty()) continue;
      if (!listed.insert(line).second)
        issues.push_back({f.path, line_no, "'" + line + "' is listed twice"});
      if (!entries[folder].count(line))
        issues.push_back({f.path, line_no, "'" + line + "' is listed but there is no " + folder + "/" +
                                               line + ".mo or " + folder + "/" + line + "/package.mo"});
    }
    for (const auto& name : entries[folder])
      if (!listed.count(name))
        issues.push_back({f.path, 0, "class '" + name + "' of " + folder + " is missing from package.order"});
  }
  for (const auto& folder : folders_with_package)
    if (!folders_with_order.count(folder))
      issues.push_back({folder + "/package.mo", 0, "package folder " + folder + " has no package.order"});
}

}  // namespace

std::string ModelicaIssue::ToString() const {
  return file + ":" + std::to_string(line) + ": " + message;
}

bool IsKnownMslName(std::string_view path) { return msl::Find(path) != nullptr; }

std::vector<std::string> MslModifiers(std::string_view class_path) {
  const auto* c = msl::Find(class_path);
  return c ? c->modifiers : std::vector<std::string>{};
}

std::vector<std::string> MslConnectors(std::string_view class_path) {
  std::vector<std::string> out;
  if (const auto* c = msl::Find(class_path))
    for (const auto& con : c->connectors) out.push_back(con.name);
  return out;
}

std::vector<ModelicaIssue> CheckModelicaCompleteness(const std::vector<GeneratedFile>& files,
                                                     const std::vector<GeneratedFile>& library) {
  std::vector<ModelicaIssue> ignored;  // syntax and names: CheckModelica
  std::vector<ClassInfo> classes;
  std::set<std::string> checked_paths;
  for (const auto& f : files) checked_paths.insert(f.path);
  auto collect = [&](const GeneratedFile& f) {
    if (f.path.size() < 3 || f.path.substr(f.path.size() - 3) != ".mo") return;
    Tokenised tok = Tokenise(f.path, f.content);
    Collector(f.path, tok.tokens, ignored, classes).Run();
  };
  for (const auto& f : library)
    if (!checked_paths.count(f.path)) collect(f);
  for (const auto& f : files) collect(f);
  std::vector<ModelicaIssue> issues;
  Checker(classes, issues).RunCompleteness(checked_paths);
  std::stable_sort(issues.begin(), issues.end(), [](const ModelicaIssue& a, const ModelicaIssue& b) {
    return std::tie(a.file, a.line) < std::tie(b.file, b.line);
  });
  return issues;
}

std::vector<ModelicaIssue> CheckModelica(const std::vector<GeneratedFile>& files,
                                         const std::vector<GeneratedFile>& library) {
  std::vector<ModelicaIssue> issues;
  std::vector<ClassInfo> classes;
  std::set<std::string> checked_paths;
  for (const auto& f : files) checked_paths.insert(f.path);
  std::vector<ModelicaIssue> library_issues;  // issues in library files not being checked
  std::map<std::string, std::pair<std::string, std::vector<std::string>>> mo_files;
  auto collect = [&](const GeneratedFile& f, std::vector<ModelicaIssue>& sink) {
    if (f.path.size() < 3 || f.path.substr(f.path.size() - 3) != ".mo") return;
    Tokenised tok = Tokenise(f.path, f.content);
    sink.insert(sink.end(), tok.issues.begin(), tok.issues.end());
    CheckMslNames(f.path, tok.tokens, sink);
    Collector collector(f.path, tok.tokens, sink, classes);
    collector.Run();
    mo_files[f.path] = {collector.within(), collector.top_level};
  };
  for (const auto& f : library)
    if (!checked_paths.count(f.path)) collect(f, library_issues);
  for (const auto& f : files) collect(f, issues);
  // Classes of every file serve for lookups; issues are kept for the checked files only.
  std::vector<ModelicaIssue> all;
  Checker(classes, all).Run();
  for (auto& issue : all)
    if (checked_paths.count(issue.file)) issues.push_back(std::move(issue));
  std::map<std::string, std::pair<std::string, std::vector<std::string>>> checked_mo;
  for (const auto& [path, v] : mo_files)
    if (checked_paths.count(path)) checked_mo[path] = v;
  CheckLayout(files, checked_mo, issues);
  std::stable_sort(issues.begin(), issues.end(), [](const ModelicaIssue& a, const ModelicaIssue& b) {
    return std::tie(a.file, a.line) < std::tie(b.file, b.line);
  });
  return issues;
}

}  // namespace highlift
