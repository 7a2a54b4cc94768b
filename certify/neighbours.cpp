#include "neighbours.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <random>
#include <vector>

#include "cutcom/decimal.hpp"

namespace cutcom::props {

namespace {

struct Literal {
  std::size_t start, end;  // in the text
  std::string address;     // "X", "CR", "DISR", "$TC_DP6" …
  int line;
};

bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '$'; }

// The address a number at `at` belongs to: the letters right before it ("X12") or the name
// before its '=' ("CR=5", "$TC_DP6[1,1]=2"); empty for anything else.
std::string address_before(const std::string& t, std::size_t at, std::size_t line_start) {
  std::size_t i = at;
  if (i > line_start && t[i - 1] == '=') {
    --i;
    if (i > line_start && t[i - 1] == ']') {  // an indexed name: skip "[…]"
      while (i > line_start && t[i - 1] != '[') --i;
      if (i > line_start) --i;
    }
  }
  std::size_t e = i;
  while (i > line_start && is_name_char(t[i - 1])) --i;
  std::string name = t.substr(i, e - i);
  for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  static const char* const kAddresses[] = {"X",   "Y",   "Z",    "I",     "J",  "K",  "CR",
                                           "RND", "CHF", "DISR", "DISCL", "AP", "RP", "$TC_DP6"};
  for (const char* a : kAddresses)
    if (name == a) return name;
  return {};
}

std::vector<Literal> literals_of(const std::string& t) {
  std::vector<Literal> out;
  int line = 1;
  std::size_t line_start = 0;
  bool comment = false, quoted = false;
  for (std::size_t i = 0; i < t.size(); ++i) {
    char c = t[i];
    if (c == '\n') {
      ++line, line_start = i + 1, comment = quoted = false;
      continue;
    }
    if (comment) continue;
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == ';') {
      comment = true;
      continue;
    }
    bool starts = std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
    if (!starts || (i > 0 && (std::isdigit(static_cast<unsigned char>(t[i - 1])) || t[i - 1] == '.'))) continue;
    std::string address = address_before(t, i, line_start);
    std::size_t e = i + (c == '-' ? 1 : 0);
    while (e < t.size() && (std::isdigit(static_cast<unsigned char>(t[e])) || t[e] == '.')) ++e;
    if (address.empty() || !Decimal::parse(std::string_view(t).substr(i, e - i)).value) {
      i = e > i ? e - 1 : i;
      continue;
    }
    out.push_back({i, e, address, line});
    i = e - 1;
  }
  return out;
}

}  // namespace

Neighbour neighbour_of(const std::string& text, const MachineData& md, std::uint64_t seed, long k) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(k));
  Neighbour n{text, md, {}};
  std::vector<Literal> lits = literals_of(text);
  std::map<std::size_t, std::string> edits;  // literal index -> new text (a later move of one wins)
  int moves = lits.empty() ? 0 : 1 + static_cast<int>(rng() % 3);
  for (int m = 0; m < moves; ++m) {
    std::size_t i = rng() % lits.size();
    const Literal& l = lits[i];
    Decimal v = *Decimal::parse(std::string_view(text).substr(l.start, l.end - l.start)).value;
    Decimal w = v;
    if (rng() % 3 == 0) {  // onto an exact tie with another value of the same address
      std::vector<std::size_t> same;
      for (std::size_t j = 0; j < lits.size(); ++j)
        if (j != i && lits[j].address == l.address) same.push_back(j);
      if (!same.empty()) {
        const Literal& o = lits[same[rng() % same.size()]];
        w = *Decimal::parse(std::string_view(text).substr(o.start, o.end - o.start)).value;
      }
    }
    if (w == v) {  // a small step either way: a grid unit, a micrometre, a nanometre
      static constexpr std::int64_t kSteps[] = {1'000'000, 1'000, 1};  // in 10^-9 mm
      Decimal step = Decimal::from_units(Int128(kSteps[rng() % 3]));
      w = rng() % 2 ? v + step : v - step;
    }
    if (l.address == "$TC_DP6" && w.sign() < 0) w = -w;
    edits[i] = w.to_string();
    n.change += fmt::format("{}line {} {}: {} -> {}", n.change.empty() ? "" : "; ", l.line, l.address,
                            text.substr(l.start, l.end - l.start), w.to_string());
  }
  // From the back, so that earlier positions stay valid.
  for (auto it = edits.rbegin(); it != edits.rend(); ++it)
    n.text.replace(lits[it->first].start, lits[it->first].end - lits[it->first].start, it->second);
  if (k % 4 == 3) {  // the machine data near their ties too
    switch (rng() % 3) {
      case 0: {
        Decimal d = md.cutcom_corner_limit + Decimal::from_int(rng() % 2 ? 1 : -1);
        n.md.set("MD20210", d.to_string());
        n.change += "; MD20210 " + d.to_string();
        break;
      }
      case 1: {
        Decimal d = md.cutcom_curve_insert_limit + Decimal::from_int(rng() % 2 ? 1 : -1);
        if (d.sign() < 0) d = Decimal{};
        n.md.set("MD20230", d.to_string());
        n.change += "; MD20230 " + d.to_string();
        break;
      }
      default: {
        int blocks = std::max(1, md.cutcom_maxnum_check_blocks + (rng() % 2 ? 1 : -1));
        n.md.set("MD20240", std::to_string(blocks));
        n.change += "; MD20240 " + std::to_string(blocks);
      }
    }
  }
  return n;
}

}  // namespace cutcom::props
