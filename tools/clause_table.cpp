// Generates spec/COVERAGE.md: for every spec clause, where ref, fast and the shared code cite it
// and which tests cover it; checks that the spec and the code agree (spec/README.md).
//   clause_table --write SOURCE_DIR   regenerate spec/COVERAGE.md
//   clause_table --check SOURCE_DIR   fail if a rule is broken or the table is stale
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Clause {
  std::string id, title, kind, status, source, file;
};

struct Place {
  std::string file;
  int line;
  int rank = 0;  // where a reader should land first: the decision, then code, then comments
};

// A citation on the line that takes the decision (decide/raise/alarm) ranks first, then one in
// code of a .cpp, then a comment in a .cpp, then a header.
int rank_of(const fs::path& p, const std::string& line) {
  if (line.find("decide(") != std::string::npos || line.find("raise(") != std::string::npos ||
      line.find("decide_") != std::string::npos)
    return 0;
  bool comment = line.find_first_not_of(" \t") != std::string::npos && line.substr(line.find_first_not_of(" \t"), 2) == "//";
  if (p.extension() == ".cpp") return comment ? 2 : 1;
  return 3;
}

// FAMILY[-TOPIC…]-n: ALARM-1 and CLI-2 as well as TRC-CORNER-3 (spec/README.md).
const std::regex kId(R"(\b(NC|TOOL|MD|TRC|ARC|SAR|PATH|ALARM|TRACE|CLI|PROP)(-[A-Z0-9]+)*-[0-9]+\b)");

std::vector<std::string> lines_of(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::vector<fs::path> sources(const fs::path& dir, std::initializer_list<const char*> exts) {
  std::vector<fs::path> out;
  if (!fs::exists(dir)) return out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && std::find(exts.begin(), exts.end(), e.path().extension().string()) != exts.end())
      out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> ids_in(const std::string& line) {
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(line.begin(), line.end(), kId); it != std::sregex_iterator(); ++it)
    out.push_back(it->str());
  return out;
}

std::string field(const std::string& line, const std::string& name) {
  auto at = line.find("**" + name + "**:");
  if (at == std::string::npos) return "";
  auto start = at + name.size() + 5;
  auto end = line.find(" · ", start);
  std::string v = line.substr(start, end == std::string::npos ? std::string::npos : end - start);
  while (!v.empty() && v.front() == ' ') v.erase(v.begin());
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 || (std::string(argv[1]) != "--write" && std::string(argv[1]) != "--check")) {
    std::cerr << "usage: clause_table --write|--check SOURCE_DIR\n";
    return 2;
  }
  bool write = std::string(argv[1]) == "--write";
  fs::path root = argv[2];
  std::vector<std::string> errors;

  // 1. The clauses, in spec order.
  std::vector<Clause> clauses;
  std::map<std::string, std::size_t> index;
  for (const auto& p : sources(root / "spec", {".md"})) {
    if (p.filename() == "COVERAGE.md" || p.filename() == "README.md" || p.filename() == "sources.md" ||
        p.filename() == "decisions.md")
      continue;
    auto lines = lines_of(p);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (lines[i].rfind("### ", 0) != 0) continue;
      auto ids = ids_in(lines[i]);
      if (ids.empty() || lines[i].rfind("### " + ids[0], 0) != 0) {
        // A heading that looks like a clause must be one the table recognises.
        if (std::regex_search(lines[i], std::regex(R"(^### [A-Z]+-[A-Z0-9-]+)")))
          errors.push_back(fmt::format("{}:{}: heading '{}' is not a clause ID the table recognises",
                                       p.filename().string(), i + 1, lines[i]));
        continue;
      }
      Clause c;
      c.id = ids[0];
      auto dash = lines[i].find(" — ");
      c.title = dash == std::string::npos ? "" : lines[i].substr(dash + 5);
      c.file = p.filename().string();
      std::string meta = i + 1 < lines.size() ? lines[i + 1] : "";
      c.kind = field(meta, "Kind");
      c.status = field(meta, "Status");
      c.source = field(meta, "Source");
      if (c.kind.empty() || c.status.empty())
        errors.push_back(fmt::format("{}: clause {} lacks its Kind/Source/Status line", c.file, c.id));
      if (index.count(c.id)) errors.push_back(fmt::format("clause {} is defined twice", c.id));
      index[c.id] = clauses.size();
      clauses.push_back(c);
    }
  }

  // 1b. Sources stand in the repository (spec/sources.md, spec/decisions.md): every document tag a
  // clause names is in the sources table, every decision it names is in the decisions.
  std::set<std::string> tags, decisions;
  for (const auto& l : lines_of(root / "spec" / "sources.md")) {
    std::smatch m;
    if (std::regex_search(l, m, std::regex(R"(^\| ([A-Z0-9]+) \|)")) && m[1] != "tag") tags.insert(m[1]);
  }
  for (const auto& l : lines_of(root / "spec" / "decisions.md")) {
    std::smatch m;
    if (std::regex_search(l, m, std::regex(R"(^\*\*([0-9]+)(, ([0-9]+))? — )"))) {
      decisions.insert(m[1]);
      if (m[3].matched) decisions.insert(m[3]);
    }
  }
  const std::regex tag_cite(R"(\b([A-Z]{2,3}[0-9]{2}|808D|ALM)\b(?= p\.| [0-9]{5}|;|,|$| \())");
  const std::regex number("[0-9]+");
  const std::regex decision_cite(R"(\bdecisions? ([0-9]+(?:[–,-] ?[0-9]+| and [0-9]+)*))");
  for (const Clause& c : clauses) {
    std::string both = c.kind + " · " + c.source;
    for (auto it = std::sregex_iterator(both.begin(), both.end(), tag_cite); it != std::sregex_iterator(); ++it)
      if (!tags.count((*it)[1]))
        errors.push_back(fmt::format("clause {} cites '{}', which spec/sources.md does not list", c.id, (*it)[1].str()));
    for (auto it = std::sregex_iterator(both.begin(), both.end(), decision_cite); it != std::sregex_iterator(); ++it) {
      std::string list = (*it)[1];
      for (auto n = std::sregex_iterator(list.begin(), list.end(), number); n != std::sregex_iterator(); ++n)
        if (!decisions.count(n->str()))
          errors.push_back(fmt::format("clause {} cites decision {}, which spec/decisions.md does not state", c.id, n->str()));
    }
  }

  // 2. Citations in code, by part; `covers:` lines in tests, attached to the next test.
  std::map<std::string, std::map<std::string, std::vector<Place>>> cited;  // id -> part -> places
  std::map<std::string, std::set<std::string>> tests;                      // id -> test names
  std::map<std::string, Place> test_place;                                 // test name -> where
  auto rel = [&](const fs::path& p) { return fs::relative(p, root).string(); };
  for (const char* part : {"ref", "fast", "core", "cli", "certify"})
    for (const auto& p : sources(root / part, {".cpp", ".hpp", ".h"})) {
      auto lines = lines_of(p);
      for (std::size_t i = 0; i < lines.size(); ++i)
        for (const auto& id : ids_in(lines[i]))
          cited[id][part].push_back({rel(p), static_cast<int>(i + 1), rank_of(p, lines[i])});
    }
  const std::regex test_name(R"((TEST|TEST_F|RC_GTEST_PROP)\((\w+),\s*(\w+))");
  std::map<std::string, std::set<std::string>> suites;  // part -> suite names
  for (const char* part : {"tests", "props"})
    for (const auto& p : sources(root / part, {".cpp"})) {
      auto lines = lines_of(p);
      for (const auto& l : lines) {
        std::smatch m;
        if (std::regex_search(l, m, test_name)) suites[part].insert(m[2].str());
      }
      for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].find("covers:") == std::string::npos) continue;
        std::string name;
        for (std::size_t j = i + 1; j < lines.size() && name.empty(); ++j) {
          std::smatch m;
          if (std::regex_search(lines[j], m, test_name)) {
            name = m[2].str() + "." + m[3].str();
            test_place[name] = {rel(p), static_cast<int>(j + 1)};
          }
        }
        if (name.empty()) errors.push_back(fmt::format("{}:{}: covers: line without a following test", rel(p), i + 1));
        for (const auto& id : ids_in(lines[i])) {
          tests[id].insert(name);
          if (!index.count(id)) errors.push_back(fmt::format("{}:{}: covers unknown clause {}", rel(p), i + 1, id));
        }
      }
    }

  // A property suite and a unit-test suite never share a name (a test name says which it is).
  for (const auto& s : suites["props"])
    if (suites["tests"].count(s)) errors.push_back(fmt::format("suite {} is both a unit-test and a property suite", s));

  // 3. Rules: every cited ID exists; implemented clauses are tested, TRC ones cited by both engines.
  for (const auto& [id, parts] : cited)
    if (!index.count(id))
      for (const auto& [part, places] : parts)
        errors.push_back(fmt::format("{}:{}: cites unknown clause {}", places[0].file, places[0].line, id));
  for (const Clause& c : clauses) {
    if (c.status.rfind("implemented", 0) != 0) continue;
    if (tests[c.id].empty()) errors.push_back(fmt::format("clause {} is implemented but no test covers it", c.id));
    if (c.id.rfind("TRC-", 0) == 0 && c.id != "TRC-RADIUS-1")
      for (const char* part : {"ref", "fast"})
        if (cited[c.id][part].empty()) errors.push_back(fmt::format("clause {} is not cited in {}/", c.id, part));
  }

  // 3b. The repository stands alone: no text refers to material outside it.
  const std::string outside[] = {std::string("../") + "shared", std::string("shared/") + "reference",
                                 std::string("trc-") + "digest"};
  for (const char* part : {"spec", "docs", "ref", "fast", "core", "cli", "certify", "props", "tests", "tools", "bench", "fuzz",
                           "examples", "scripts"})
    for (const auto& p : sources(root / part, {".md", ".cpp", ".hpp", ".h", ".sh", ".txt", ".mpf", ".MPF"})) {
      auto lines = lines_of(p);
      for (std::size_t i = 0; i < lines.size(); ++i)
        for (const auto& o : outside)
          if (lines[i].find(o) != std::string::npos)
            errors.push_back(fmt::format("{}:{}: refers to '{}', outside the repository", rel(p), i + 1, o));
    }

  // 4. The table.
  std::ostringstream t;
  t << "# Clause coverage\n\nGenerated by `tools/clause_table.cpp` (`cmake --build build --target spec-coverage`);\n"
       "checked by the `SpecCoverage` test. Links go to the citation where each part takes the decision\n"
       "(a `decide`/`raise` line), else its first in code; tests link to their definition.\n";
  std::string file;
  auto link = [](const std::vector<Place>& v) {
    if (v.empty()) return std::string("—");
    const Place& best = *std::min_element(v.begin(), v.end(), [](const Place& a, const Place& b) {
      return a.rank != b.rank ? a.rank < b.rank : a.file != b.file ? a.file < b.file : a.line < b.line;
    });
    std::string s =
        fmt::format("[{}:{}](../{}#L{})", fs::path(best.file).filename().string(), best.line, best.file, best.line);
    if (v.size() > 1) s += fmt::format(" +{}", v.size() - 1);
    return s;
  };
  int implemented = 0, tested = 0;
  for (const Clause& c : clauses) {
    if (c.file != file) {
      file = c.file;
      t << fmt::format(
          "\n## [{}]({})\n\n| clause | kind | status | ref | fast | shared | tests |\n"
          "|---|---|---|---|---|---|---|\n",
          file, file);
    }
    std::string names;
    for (const auto& n : tests[c.id]) {
      auto at = test_place.find(n);
      std::string entry = at == test_place.end() ? n
                                                 : fmt::format("[{}](../{}#L{})", n, at->second.file, at->second.line);
      names += (names.empty() ? "" : ", ") + entry;
    }
    bool impl = c.status.rfind("implemented", 0) == 0;
    implemented += impl;
    tested += impl && !tests[c.id].empty();
    std::string shared = link(cited[c.id]["core"]);
    if (shared == "—") shared = link(cited[c.id]["cli"]);
    if (shared == "—") shared = link(cited[c.id]["certify"]);
    t << fmt::format("| {} {} | {} | {} | {} | {} | {} | {} |\n", c.id, c.title, c.kind, c.status,
                     link(cited[c.id]["ref"]), link(cited[c.id]["fast"]), shared,
                     names.empty() ? "**none**" : fmt::format("{} ({})", tests[c.id].size(), names));
  }
  t << fmt::format("\n{} clauses, {} implemented, {} of them covered by tests.\n", clauses.size(), implemented, tested);

  fs::path out = root / "spec" / "COVERAGE.md";
  if (write) {
    std::ofstream(out) << t.str();
  } else {
    std::ifstream in(out);
    std::stringstream have;
    have << in.rdbuf();
    if (have.str() != t.str())
      errors.push_back("spec/COVERAGE.md is stale: run `cmake --build build --target spec-coverage` and commit it");
  }
  for (const auto& e : errors) std::cerr << "spec coverage: " << e << "\n";
  std::cout << fmt::format("{} clauses, {} implemented, {} covered by tests, {} problems\n", clauses.size(),
                           implemented, tested, errors.size());
  return errors.empty() ? 0 : 1;
}
