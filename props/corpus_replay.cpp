// The corpus (tests/corpus/): every numerical edge case found by the properties or by
// `cutcom certify`, with ref's expected output. Replayed on every CI run: ref must give the
// stored output exactly, and fast must agree with it (PROP-DIFF-1). docs/edge-cases.md explains
// each case.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "campaign.hpp"
#include "compare.hpp"
#include "cutcom/fast/engine.hpp"
#include "cutcom/output.hpp"
#include "cutcom/ref/engine.hpp"
#include "run_case.hpp"

namespace cutcom::props {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

template <class Sink>
bool run(const std::string& engine, const std::string& text, const MachineData& md, Sink& sink) {
  std::istringstream in(text);
  ProgramReader reader(in, md.initial_state());
  try {
    return engine == "ref" ? ref::run(reader, md, sink) : fast::run(reader, md, sink);
  } catch (const UnsupportedError&) {
    return false;
  }
}

// A verdict as tests/corpus/verdicts.txt pins it: "agree" or "knife-edge CLAUSE".
std::string pinned_form(const Verdict& v) {
  if (v.kind == Verdict::Kind::kAgree) return "agree";
  return (v.kind == Verdict::Kind::kKnifeEdge ? "knife-edge " : "diverge ") + v.clause;
}

// tests/corpus/verdicts.txt: "NAME.mpf knife-edge CLAUSE" lines (# comments); other cases agree.
std::map<std::string, std::string> pinned_verdicts() {
  std::map<std::string, std::string> pins;
  std::ifstream in(std::filesystem::path(CUTCOM_CORPUS_DIR) / "verdicts.txt");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::size_t space = line.find(' ');
    if (space != std::string::npos) pins[line.substr(0, space)] = line.substr(space + 1);
  }
  return pins;
}

// PROP-CORPUS-1 for one case: ref gives the stored output exactly, fast agrees with it; the verdict.
std::string replays(const std::filesystem::path& p) {
  std::string text = slurp(p);
  MachineData md;
  std::filesystem::path md_file = p;
  md_file.replace_extension(".md");
  if (std::filesystem::exists(md_file)) {
    std::ifstream in(md_file);
    md.load(in, md_file.string());
  }
  // ref: exactly the stored output.
  std::ostringstream json;
  JsonWriter writer(json, "ref", false);
  run("ref", text, md, writer);
  writer.finish();
  std::filesystem::path expected = p;
  expected.replace_extension(".ref.json");
  EXPECT_EQ(json.str(), slurp(expected)) << "ref's output changed";
  // fast: agrees with ref, decisions first.
  CollectingSink r, f;
  run("ref", text, md, r);
  run("fast", text, md, f);
  std::istringstream in(text);
  ProgramReader reader(in, md.initial_state());
  std::vector<Block> blocks;
  Block b;
  while (reader.next(b)) blocks.push_back(b);
  Verdict v = compare(r.result, f.result,
                      Tolerance::for_program(conditioning_of(blocks, md.cutcom_maxnum_check_blocks, &r.result)));
  EXPECT_NE(v.kind, Verdict::Kind::kDiverge) << v.explanation;
  std::string verdict = pinned_form(v);
  // PROP-TRACE-1: both engines take the same path without their trace.
  for (const char* engine : {"ref", "fast"}) {
    UntracedSink u;
    run(engine, text, md, u);
    std::optional<std::string> d =
        untraced_difference(engine == std::string("ref") ? r.result : f.result, u.result, engine);
    EXPECT_FALSE(d) << *d;
  }
  return verdict;
}

// covers: PROP-CORPUS-1 PROP-DIFF-1 PROP-TRACE-1
TEST(Corpus, EveryCaseReplays) {
  std::vector<std::filesystem::path> cases;
  for (const auto& e : std::filesystem::directory_iterator(CUTCOM_CORPUS_DIR))
    if (e.path().extension() == ".mpf") cases.push_back(e.path());
  std::sort(cases.begin(), cases.end());
  ASSERT_FALSE(cases.empty());
  const std::map<std::string, std::string> pins = pinned_verdicts();
  ASSERT_FALSE(pins.empty());
  for (const auto& p : cases) {
    const std::string name = p.filename().string();
    SCOPED_TRACE(name);
    std::string verdict = replays(p);
    auto pin = pins.find(name);
    EXPECT_EQ(verdict, pin == pins.end() ? "agree" : pin->second)
        << "the verdict pinned in tests/corpus/verdicts.txt changed (PROP-CORPUS-1): review, then pin \"" << name << " "
        << verdict << "\" (or leave an agreeing case out)";
  }
  for (const auto& [name, verdict] : pins)
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(CUTCOM_CORPUS_DIR) / name))
        << name << " is pinned, not in the corpus";
}

// What a divergence leaves behind replays as written: ref's output of the file itself, comment
// line included (campaign 20261122: the stored output had every line number one short).
// covers: PROP-CORPUS-1
TEST(Corpus, AWrittenCaseReplays) {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("cutcom-corpus-test-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  for (long k : {0L, 3L, 4L, 5L}) {
    SCOPED_TRACE(k);
    std::filesystem::path p = write_corpus_case(dir.string(), "case-" + std::to_string(k), 20261122, k, "a test");
    ASSERT_TRUE(std::filesystem::exists(p));
    replays(p);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cutcom::props
