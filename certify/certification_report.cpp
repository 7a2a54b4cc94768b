// docs/certification.md and its error histogram, written by `cutcom certify --report`.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "campaign.hpp"

namespace cutcom::props {

namespace {

struct SpecClause {
  std::string id, title, file;
};

// The clauses, in spec order (`### ID — title` headings of spec/*.md).
std::vector<SpecClause> spec_clauses(const std::string& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".md" && e.path().filename() != "COVERAGE.md" && e.path().filename() != "README.md")
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<SpecClause> out;
  const std::regex heading(R"(^### ([A-Z0-9]+(?:-[A-Z0-9]+)*-[0-9]+) — (.*)$)");
  for (const auto& f : files) {
    std::ifstream in(f);
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
      if (std::regex_match(line, m, heading)) out.push_back({m[1].str(), m[2].str(), f.filename().string()});
  }
  return out;
}

// Why a clause has no branch in the trace: the families that are no rule decision of an engine.
std::string untraced_reason(const std::string& id) {
  for (const char* prefix : {"NC-", "TOOL-", "MD-"})
    if (id.rfind(prefix, 0) == 0) return "reading or data: decided by the shared reader, not traced";
  for (const char* prefix : {"PATH-", "ALARM-", "TRACE-", "CLI-"})
    if (id.rfind(prefix, 0) == 0) return "output model: holds for every run, not a branch";
  if (id.rfind("PROP-", 0) == 0) return "a property, not an engine rule";
  return "";
}

// Engine clauses without a branch of their own: constructions, alarms and rules whose outcome
// shows elsewhere. `evidence`: what in the campaign shows the clause at work -- "d:CLAUSE" or
// "d:CLAUSE/branch" (ref's decisions), "e:TAG" (CaseRecord::evidence), "v:VERDICT"; empty: not
// generated (the unit tests cover it).
struct Untraced {
  const char* id;
  const char* evidence;
  const char* why;
};
constexpr Untraced kUntraced[] = {
    {"TRC-EDGE-2", "d:TRC-EDGE-1/G460", "G460 is a branch of TRC-EDGE-1"},
    {"TRC-EDGE-3", "d:TRC-EDGE-1/G461", "G461 is a branch of TRC-EDGE-1"},
    {"TRC-EDGE-4", "d:TRC-EDGE-1/G462", "G462 is a branch of TRC-EDGE-1"},
    {"TRC-EDGE-7", "v:not-supported", "planned: both engines reject such a program naming the block (TRC-UNSUP-1)"},
    {"TRC-CD-1", "d:TRC-CD-3", "the holding back is a mechanism: every TRC-CD-3 decision compares held output"},
    {"TRC-CD-4", "d:TRC-CD-3/cut", "the cut follows every TRC-CD-3 cut (its path is compared)"},
    {"ARC-CENTRE-1", "d:ARC-CENTRE-2", "a construction: the centre of every circle, checked by ARC-CENTRE-2"},
    {"ARC-HELIX-1", "e:helix", "a construction: circles with a motion along the applicate"},
    {"TRC-ARC-CORNER-2", "d:TRC-ARC-CORNER-1/none", "what follows TRC-ARC-CORNER-1 none"},
    {"SAR-BLOCK-1", "e:sar:element", "reading of the SAR block: every SAR element"},
    {"SAR-P4-1", "d:SAR-TANGENT-1", "where P4 comes from: a branch of SAR-TANGENT-1 (alarm 10740 is not generated)"},
    {"SAR-P4-2", "d:SAR-TANGENT-1/p4-in-later-block", "a branch of SAR-TANGENT-1"},
    {"SAR-STOP-1", "e:alarm:SAR-STOP-1",
     "alarm 10746: the variant writes STOPRE between the SAR block and its direction block"},
    {"SAR-AGAIN-1", "e:alarm:SAR-AGAIN-1", "alarm 10743: the variant writes a second SAR block before the first ends"},
    {"SAR-POINTS-1", "e:sar:lead", "a construction: the approach's points P0-P4"},
    {"SAR-POINTS-2", "d:SAR-END-1", "a construction: the retraction's points"},
    {"SAR-DISCL-1", "d:SAR-DISCL-3", "the level of P2, which SAR-DISCL-3 decides against"},
    {"SAR-DISCL-2", "d:SAR-DISCL-3", "the level without DISCL or with DISCL=0 (drawn by the generators)"},
    {"SAR-DISRP-1", "d:SAR-DISRP-2",
     "the level of P1: DISRP above or below P4's plane (variants), decided against by SAR-DISRP-2"},
    {"SAR-SEG-1", "e:sar:element", "G340: the generators draw G340 and G341"},
    {"SAR-SEG-2", "e:sar:slow_infeed", "G341: the infeed sub-blocks"},
    {"SAR-FEED-1", "e:sar:element", "feeds of the sub-blocks (FAD drawn), compared with each element"},
    {"SAR-FEED-2", "d:SAR-END-1", "feeds of the retraction's sub-blocks"},
    {"SAR-ACTION-1", "e:actions", "actions of a block, compared with their positions"},
    {"SAR-TRC-1", "e:sar:element", "the SAR contour runs through the compensation: every SAR element"},
    {"SAR-END-2", "d:SAR-END-1/ends-at-p1", "a retraction without end point (cases 1 and 2)"},
    {"SAR-END-3", "d:SAR-END-1/ends-at-p2", "the start of the next block after cases 1 and 2"},
    {"SAR-VAR-1", "e:variables", "$P_APR, $P_AEP, $P_APDV of every approach"},
    {"TRC-RADIUS-1", "e:element:offset", "the effective radius of every equidistant"},
    {"TRC-SEL-2", "e:alarm:TRC-SEL-2", "alarm 10753"},
    {"TRC-SEL-3", "e:variant:one-plane-axis", "the variant writes one plane axis in the selection block"},
    {"TRC-SEL-4", "d:TRC-SEL-4", ""},
    {"TRC-SEL-5", "d:TRC-SEL-5", ""},
    {"TRC-SEL-6", "e:alarm:TRC-SEL-6", "alarm 10750"},
    {"TRC-SEL-7", "e:alarm:TRC-SEL-7", "alarm 17181"},
    {"TRC-PLANE-1", "e:alarm:TRC-PLANE-1", "alarm 10757"},
    {"TRC-UNSUP-1", "v:not-supported", "both engines reject naming the same block"},
    {"TRC-EQ-1", "e:element:offset", "a construction: every equidistant"},
    {"TRC-CORNER-2", "d:TRC-CORNER-3", "the contour angle is the margin of TRC-CORNER-3/4"},
    {"TRC-G450-1", "e:element:transition_circle", "a construction: every transition circle"},
    {"TRC-DISC-1", "e:variant:disc", "DISC > 0 is rejected as not supported (the variant writes DISC=1)"},
    {"TRC-G450-2", "d:TRC-RADIUS-2/zero", "a zero radius writes no transition circle"},
    {"TRC-G450-3", "d:TRC-CORNER-1/reversal", "a reversal is always a circle"},
    {"TRC-G451-1", "d:TRC-CORNER-3/keep-G451", "the intersection at an outer corner"},
    {"TRC-INNER-1", "d:TRC-CORNER-1/inner", "the intersection at an inner corner"},
    {"TRC-DUMMY-1", "e:element:infeed", "blocks without plane motion run at the corner point"},
    {"TRC-DUMMY-2", "e:alarm:TRC-DUMMY-2", "alarm 10762"},
    {"TRC-DUMMY-3", "e:variant:standing-block", "the variant programs the plane position where the tool stands"},
    {"TRC-DESEL-2", "e:alarm:TRC-DESEL-2", "alarm 10754"},
    {"TRC-DESEL-3", "d:TRC-DESEL-3", ""},
};

// Cases (or decisions) showing an evidence key in the campaign.
long evidence_count(const CampaignSummary& s, const std::string& key) {
  if (key.rfind("d:", 0) == 0) {
    std::string clause = key.substr(2), branch;
    if (auto slash = clause.find('/'); slash != std::string::npos)
      branch = clause.substr(slash + 1), clause.resize(slash);
    auto it = s.coverage.find(clause);
    if (it == s.coverage.end()) return 0;
    long n = 0;
    for (const auto& [b, count] : it->second)
      if (branch.empty() || b == branch) n += count.taken;
    return n;
  }
  if (key.rfind("e:", 0) == 0) {
    auto it = s.evidence.find(key.substr(2));
    return it == s.evidence.end() ? 0 : it->second;
  }
  if (key.rfind("v:", 0) == 0) {
    auto it = s.verdicts.find(key.substr(2));
    return it == s.verdicts.end() ? 0 : it->second;
  }
  return 0;
}

std::string percent(long n, long total) {
  return total ? fmt::format("{:.3f} %", 100.0 * static_cast<double>(n) / static_cast<double>(total)) : "-";
}

void write_histogram(const CampaignSummary& s, const std::string& path) {
  std::ofstream out(path);
  const double w = 720, h = 260, left = 60, bottom = 40;
  int lo = 160, hi = 0;
  long peak = 1;
  for (int i = 1; i < 161; ++i)
    if (s.error_bins[static_cast<std::size_t>(i)] > 0) lo = std::min(lo, i), hi = std::max(hi, i);
  for (long n : s.error_bins) peak = std::max(peak, n);
  if (lo > hi) lo = 1, hi = 160;
  lo = std::max(1, lo - 5), hi = std::min(160, hi + 5);
  double bw = (w - left - 20) / (hi - lo + 1);
  out << fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" font-family=\"sans-serif\" "
      "font-size=\"11\"><rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      w, h + 30);
  out << fmt::format(
      "<text x=\"{}\" y=\"16\" font-size=\"13\" font-weight=\"bold\">fast vs ref: largest coordinate error per "
      "agreeing case (mm, log scale), {} cases; {} with error exactly 0</text>\n",
      left, s.verdicts.count("agree") ? s.verdicts.at("agree") : 0, s.error_bins[0]);
  for (int i = lo; i <= hi; ++i) {
    long n = s.error_bins[static_cast<std::size_t>(i)];
    double bh = (h - bottom - 30) * static_cast<double>(n) / static_cast<double>(peak);
    double x = left + (i - lo) * bw;
    if (n > 0)
      out << fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"#1f5fbf\"/>\n", x,
                         h - bottom - bh, std::max(bw - 1, 1.0), bh);
    if ((i - 1) % 10 == 0)
      out << fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">1e{}</text>\n", x, h - bottom + 14,
                         (i - 1) / 10 - 20);
  }
  out << fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#333\"/>\n", left, h - bottom, w - 20,
                     h - bottom);
  out << fmt::format("<text x=\"{}\" y=\"{}\">peak bin: {} cases</text></svg>\n", left, h - bottom + 32, peak);
}

}  // namespace

void write_report(const CampaignSummary& s, const std::string& markdown_path, const std::string& svg_path,
                  const std::string& spec_dir) {
  write_histogram(s, svg_path);
  std::ostringstream md;
  std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  long agree = s.verdicts.count("agree") ? s.verdicts.at("agree") : 0;
  md << "# Certification of fast against ref\n\n"
     << "Generated by `cutcom certify` (" << date << "; do not edit: run the command again). Each case is a\n"
     << "generated NC program run through both engines and compared decision by decision, then\n"
     << "coordinate by coordinate (PROP-DIFF-1, [tolerances.md](tolerances.md)), then by what the path\n"
     << "carries besides its geometry: feeds, each element's origin as the output names it (its block, the\n"
     << "insert or SAR movement it is, a transition circle's second corner), actions\n"
     << "and where they run, SAR's variables, notices (PROP-DIFF-3). fast also runs each case without\n"
     << "its trace, as `cutcom run` does, and so does ref where it compared CDON pieces; each must take\n"
     << "the same path bit for bit (PROP-TRACE-1). An\n"
     << "*unexplained* divergence (decisions that differ while ref's exact margin lies outside the\n"
     << "clause's band, coordinates beyond the tolerance, any of those data different, or a run\n"
     << "without the trace that differs) stops the campaign and is written to `tests/corpus/`.\n\n"
     << "## The campaign\n\n| | |\n|---|---|\n"
     << fmt::format("| seed | {} |\n| shards | {} ({}) |\n| cases | {} |\n", s.seed, s.shards.size(),
                    fmt::join(s.shards, ", "), s.cases)
     << fmt::format("| CPU time | {:.0f} s ({:.0f} cases/s per core) |\n", s.seconds,
                    s.seconds > 0 ? static_cast<double>(s.cases) / s.seconds : 0.0)
     << fmt::format("| unexplained divergences | **{}** |\n\n", s.divergences.size());
  md << "Reproduce a shard: `cutcom certify --seed " << s.seed
     << " --cases N --shard I/K --summary shard.json`; merge shards and write this page:\n"
     << "`cutcom certify --merge shard*.json --report docs/certification.md`. Case k of a campaign is\n"
     << "the same program whatever the sharding (its seed depends on the campaign seed and k only).\n"
     << "Every campaign run so far, its seed, its cases and what it found: [campaigns.md](campaigns.md).\n\n";
  md << "## Verdicts\n\n| verdict | cases | share |\n|---|---|---|\n";
  for (const auto& [v, n] : s.verdicts) md << fmt::format("| {} | {} | {} |\n", v, n, percent(n, s.cases));
  auto resumed = s.evidence.find("knife-edge-compared-after");
  md << "\n*agree*: same decisions, coordinates within the tolerance. *knife-edge*: a decision parted the\n"
     << "runs where ref's exact margin lies inside the clause's documented band; where the runs take the\n"
     << "same branch again after the next MD20240 + 1 blocks, they are compared on from there (PROP-DIFF-2: "
     << (resumed == s.evidence.end() ? 0 : resumed->second) << " of the knife edges were, and agree after it);\n"
     << "*knife-edge-ends-differ*: such a case after which one engine ends clean and the\n"
     << "other with an alarm or a rejection, or with other alarms. *not-supported*: both engines rejected the program "
        "naming the same line (TRC-UNSUP-1).\n"
     << "*over-budget*: the case ran longer than `--budget` seconds and was stopped, not compared (listed\n"
     << "below). *diverge* and *crash* stop a shard: each is an unexplained divergence. A decision\n"
     << "whose branch its own engine's margin contradicts under the clause's boundary rule\n"
     << "(PROP-BOUNDARY-1) is a divergence, never a knife edge.\n\n";
  md << "### Knife edges by clause\n\n| clause | cases | after which the runs end differently |\n|---|---|---|\n";
  for (const auto& [c, n] : s.knife_edges) {
    auto ending = s.knife_edges_ending_differently.find(c);
    md << fmt::format("| {} | {} | {} |\n", c, n,
                      ending == s.knife_edges_ending_differently.end() ? 0 : ending->second);
  }
  md << "\n## Unexplained divergences\n\n";
  if (s.divergences.empty()) md << "None.\n";
  for (const auto& d : s.divergences) md << "- " << d << "\n";
  if (!s.over_budget.empty())
    md << "\nCases over budget (replay with `cutcom certify --seed " << s.seed
       << " --show K`): " << fmt::format("{}", fmt::join(s.over_budget, ", ")) << ".\n";
  md << "\n## Mutants\n\n"
     << "How strong the certificate is: `scripts/mutants.sh` plants each patch of `mutants/` (one\n"
     << "realistic change of fast) and judges it by a 20,000-case campaign under PROP-BOUNDARY-1 and\n"
     << "PROP-KNIFE-1, then by the CI properties. The score, the killing check of every mutant and\n"
     << "every survivor's explanation are in [mutants.md](mutants.md).\n";
  md << "\n## Fuzzing\n\n"
     << "The fuzz targets (`fuzz/`, built with ASan and UBSan, each stopping at its first report) judge\n"
     << "what they generate by the same\n"
     << "comparison as the campaign (`props::replay`): `reader_fuzz` reads any bytes as NC text (the\n"
     << "reader must read them or reject them naming the line), `differential_fuzz` runs NC text or\n"
     << "generated contours through both engines. Every run, its executions and its findings (each in\n"
     << "the corpus): the fuzzing table of [campaigns.md](campaigns.md).\n";
  md << "\n## Coordinate error\n\n"
     << "The largest coordinate difference (mm, max norm over start, end and centre of every element)\n"
     << "between fast and ref per agreeing case, and the same relative to the case's documented\n"
     << "tolerance `64 u (max(L, R) + r (L/d_min) κ + L χ)` ([tolerances.md](tolerances.md)): the bound the\n"
     << "campaign certifies is that ratio staying at most 1.\n\n"
     << "| | error (mm) | error / tolerance |\n|---|---|---|\n";
  for (double p : {0.5, 0.9, 0.99, 0.999})
    md << fmt::format("| p{} | ≤ {:.3g} | ≤ {:.3g} |\n", p * 100, s.error_percentile(p), s.error_percentile(p, true));
  md << fmt::format("| max | {:.3g} (case {}) | {:.3g}{} |\n\n", s.max_error, s.max_error_case, s.max_ratio,
                    s.max_ratio_case.empty() ? "" : " (case " + s.max_ratio_case + ")");
  md << "Percentiles are upper edges of bins a tenth of a decade wide. " << s.error_bins[0] << " of " << agree
     << " agreeing cases match to the last bit.\n\n![error histogram]("
     << std::filesystem::path(svg_path).filename().string() << ")\n\n";
  md << "## Decision coverage\n\nFor every clause: each branch the reference engine took, how often, and how often\n"
     << "with its exact margin inside the clause's band (a knife edge).\n\n"
     << "| clause | branches taken (count, of them at a knife edge) |\n|---|---|\n";
  std::vector<SpecClause> clauses = spec_clauses(spec_dir);
  for (const SpecClause& c : clauses) {
    auto it = s.coverage.find(c.id);
    if (it == s.coverage.end()) continue;
    std::vector<std::string> parts;
    for (const auto& [branch, n] : it->second)
      parts.push_back(n.knife ? fmt::format("{} {} ({})", branch, n.taken, n.knife)
                              : fmt::format("{} {}", branch, n.taken));
    md << fmt::format("| {} | {} |\n", c.id, fmt::join(parts, ", "));
  }
  md << "\n### Engine clauses without a branch of their own\n\n"
     << "Constructions, alarms and rules whose outcome shows elsewhere: what in the campaign shows each\n"
     << "at work (a decision or branch of ref, an alarm, an element origin, a program variant), and how\n"
     << "often. *Not generated*: the unit tests named in [spec/COVERAGE.md](../spec/COVERAGE.md) cover it.\n\n"
     << "| clause | shown by | count | why |\n|---|---|---|---|\n";
  std::vector<std::string> other;
  long unreached = 0;
  for (const SpecClause& c : clauses) {
    if (s.coverage.count(c.id)) continue;
    if (!untraced_reason(c.id).empty()) {
      other.push_back(c.id);
      continue;
    }
    const Untraced* u = nullptr;
    for (const Untraced& x : kUntraced)
      if (c.id == x.id) u = &x;
    std::string key = u ? u->evidence : "";
    long n = key.empty() ? 0 : evidence_count(s, key);
    if (n == 0) ++unreached;
    md << fmt::format("| {} {} | {} | {} | {} |\n", c.id, c.title, key.empty() ? "—" : "`" + key + "`",
                      n == 0 ? std::string("**not reached**") : std::to_string(n),
                      u ? (std::string(u->why).empty() ? "a branch of its own, not reached" : u->why)
                        : "no evidence listed (certify/certification_report.cpp)");
  }
  md << fmt::format("\n{} engine clauses are not reached by the campaign (above, with the reason).\n", unreached);
  md << "\nNot engine rules, so without a branch: the reader, tool and machine data (NC-, TOOL-, MD-: the\n"
     << "shared reader decides them for both engines), the output model (PATH-, ALARM-, TRACE-, CLI-) and\n"
     << "the properties (PROP-): " << other.size() << " clauses.\n";
  md << "\n## Generators and alarms\n\n| generator style | cases |\n|---|---|\n";
  for (const auto& [k, n] : s.styles) md << fmt::format("| {} | {} |\n", k, n);
  // PROP-HAIR-1: each exact situation, exactly and a nanometre to either side.
  std::map<std::string, std::array<long, 3>> exact;
  for (const auto& [k, n] : s.styles) {
    if (k.rfind("exact/", 0) != 0) continue;
    std::size_t slash = k.rfind('/');
    std::string which = k.substr(slash + 1);
    auto& row = exact[k.substr(6, slash - 6)];
    row[which == "exactly" ? 0 : which == "a-hair-above" ? 1 : 2] += n;
  }
  md << "\n## Exact situations\n\nPROP-HAIR-1: the boundaries spec rules distinguish, generated exactly and a\n"
     << "nanometre (the program grid) to either side.\n\n"
     << "| situation | exactly | a nanometre above | a nanometre below |\n|---|---|---|---|\n";
  for (const auto& [k, row] : exact) md << fmt::format("| {} | {} | {} | {} |\n", k, row[0], row[1], row[2]);
  if (exact.empty()) md << "| (none in this campaign) | | | |\n";
  md << "\n| alarm | cases |\n|---|---|\n";
  for (const auto& [k, n] : s.alarms) md << fmt::format("| {} | {} |\n", k, n);
  std::ofstream(markdown_path) << md.str();
}

}  // namespace cutcom::props
