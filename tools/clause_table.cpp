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
  std::string id, title, kind, status, file;
};

struct Place {
  std::string file;
  int line;
};

const std::regex kId(R"(\b(NC|TOOL|MD|TRC|ARC|SAR|PATH|ALARM|TRACE|CLI|PROP)-[A-Z0-9]+(-[A-Z0-9]+)*-[0-9]+\b)");

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
    if (p.filename() == "COVERAGE.md" || p.filename() == "README.md") continue;
    auto lines = lines_of(p);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (lines[i].rfind("### ", 0) != 0) continue;
      auto ids = ids_in(lines[i]);
      if (ids.empty()) continue;
      Clause c;
      c.id = ids[0];
      auto dash = lines[i].find(" — ");
      c.title = dash == std::string::npos ? "" : lines[i].substr(dash + 5);
      c.file = p.filename().string();
      std::string meta = i + 1 < lines.size() ? lines[i + 1] : "";
      c.kind = field(meta, "Kind");
      c.status = field(meta, "Status");
      if (c.kind.empty() || c.status.empty())
        errors.push_back(fmt::format("{}: clause {} lacks its Kind/Source/Status line", c.file, c.id));
      if (index.count(c.id)) errors.push_back(fmt::format("clause {} is defined twice", c.id));
      index[c.id] = clauses.size();
      clauses.push_back(c);
    }
  }

  // 2. Citations in code, by part; `covers:` lines in tests, attached to the next test.
  std::map<std::string, std::map<std::string, std::vector<Place>>> cited;  // id -> part -> places
  std::map<std::string, std::set<std::string>> tests;                      // id -> test names
  auto rel = [&](const fs::path& p) { return fs::relative(p, root).string(); };
  for (const char* part : {"ref", "fast", "core", "cli"})
    for (const auto& p : sources(root / part, {".cpp", ".hpp", ".h"})) {
      auto lines = lines_of(p);
      for (std::size_t i = 0; i < lines.size(); ++i)
        for (const auto& id : ids_in(lines[i])) cited[id][part].push_back({rel(p), static_cast<int>(i + 1)});
    }
  const std::regex test_name(R"((TEST|TEST_F|RC_GTEST_PROP)\((\w+),\s*(\w+))");
  for (const char* part : {"tests", "props"})
    for (const auto& p : sources(root / part, {".cpp"})) {
      auto lines = lines_of(p);
      for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].find("covers:") == std::string::npos) continue;
        std::string name;
        for (std::size_t j = i + 1; j < lines.size() && name.empty(); ++j) {
          std::smatch m;
          if (std::regex_search(lines[j], m, test_name)) name = m[2].str() + "." + m[3].str();
        }
        if (name.empty()) errors.push_back(fmt::format("{}:{}: covers: line without a following test", rel(p), i + 1));
        for (const auto& id : ids_in(lines[i])) {
          tests[id].insert(name);
          if (!index.count(id)) errors.push_back(fmt::format("{}:{}: covers unknown clause {}", rel(p), i + 1, id));
        }
      }
    }

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

  // 4. The table.
  std::ostringstream t;
  t << "# Clause coverage\n\nGenerated by `tools/clause_table.cpp` (`cmake --build build --target spec-coverage`);\n"
       "checked by the `SpecCoverage` test. Links go to the first citation in each part.\n";
  std::string file;
  auto link = [](const std::vector<Place>& v) {
    if (v.empty()) return std::string("—");
    std::string s =
        fmt::format("[{}:{}](../{}#L{})", fs::path(v[0].file).filename().string(), v[0].line, v[0].file, v[0].line);
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
    for (const auto& n : tests[c.id]) names += (names.empty() ? "" : ", ") + n;
    bool impl = c.status.rfind("implemented", 0) == 0;
    implemented += impl;
    tested += impl && !tests[c.id].empty();
    std::string shared = link(cited[c.id]["core"]);
    if (shared == "—") shared = link(cited[c.id]["cli"]);
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
