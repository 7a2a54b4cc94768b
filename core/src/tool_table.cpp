// TOOL-DATA-1, TOOL-NAME-1, TOOL-FILE-1, NC-OFFSET-2: the control's tool table and settable work
// offsets, from the program's own assignments or from the control's archive files.
#include <fmt/format.h>

#include <cctype>
#include <cstring>

#include "archive_file.hpp"
#include "cutcom/reader.hpp"
#include "word_lexer.hpp"

namespace cutcom {

void ToolTable::assign(const ToolDataAssignment& a) {
  EdgeData& e = edges_[{a.tool, a.edge}];
  if (a.parameter >= 1 && a.parameter <= 25) e.values[static_cast<std::size_t>(a.parameter)] = a.value;
  switch (a.parameter) {
    case 1:
      e.type = a.value;
      break;
    case 2:
      e.position = a.value;
      break;
    case 6:
      e.radius = a.value;
      break;
    case 15:
      e.wear = a.value;
      break;
    default:  // lengths, other wear and base values: no effect on 2D radius compensation (read back only)
      break;
  }
}

void ToolTable::name(const ToolNameAssignment& a) { names_[a.name] = a.tool; }

const EdgeData* ToolTable::find(std::int64_t tool, std::int64_t edge) const {
  auto it = edges_.find({tool, edge});
  return it == edges_.end() ? nullptr : &it->second;
}

std::optional<std::string> ToolTable::name_of(std::int64_t tool) const {
  for (const auto& [name, number] : names_)
    if (number == tool) return name;
  return std::nullopt;
}

std::optional<std::int64_t> ToolTable::number_of(const std::string& name) const {
  auto it = names_.find(name);
  if (it == names_.end()) return std::nullopt;
  return it->second;
}

namespace {

using archive::trim;
using archive::upper;

// Calls f(line number, line, upper-case trimmed line) for each line of an archive with data.
template <class F>
void archive_lines(std::istream& in, const std::string& source_name, int channel, F f) {
  archive::read_lines(
      in, f,
      [&](int n, const std::string& what) -> void { throw InputError(n, 1, fmt::format("{}: {}", source_name, what)); },
      channel);
}

}  // namespace

void ToolTable::load(std::istream& in, const std::string& source_name, int channel) {
  archive_lines(in, source_name, channel, [&](int n, const std::string& line, const std::string& u) {
    // The edge parameters $TC_DPn (n a number: $TC_DPCE, $TC_DPH, $TC_DPC1 … are other data) and
    // the names. (Sum and setup offsets are read too: a radius part other than 0 is refused, TOOL-SUM-1.)
    auto numbered = [&](std::string_view prefix) {
      return u.rfind(prefix, 0) == 0 && u.size() > prefix.size() && lexer::is_digit(u[prefix.size()]);
    };
    bool ours = numbered("$TC_DP") || u.rfind("$TC_TP2[", 0) == 0 || u.rfind("$TC_TP2 ", 0) == 0 ||
                numbered("$TC_SCP") || numbered("$TC_ECP");
    if (!ours) {
      // Other tool management data ($TC_TP8, $TC_DPCE, $TC_DPH, $TC_MOP…, $TC_ADPT…, $A_…): no
      // effect on the path.
      if (u[0] == '$') return;
      throw InputError(n, 1,
                       fmt::format("{}: not a line of a tool-offset archive ($TC_DPn[t,d]=…, "
                                   "$TC_TP2[t]=\"NAME\")",
                                   source_name));
    }
    BlockWords w;
    try {
      parse_block_words(line, n, w);
    } catch (const InputError& e) {
      throw InputError(n, e.column(), fmt::format("{}: {}", source_name, e.detail()));
    }
    for (int k = 0; k < w.tool_data_count; ++k) assign(w.tool_data[static_cast<std::size_t>(k)]);
    for (int k = 0; k < w.tool_names_count; ++k) name(w.tool_names[static_cast<std::size_t>(k)]);
  });
}

void ToolTable::define(std::string_view spec) {
  auto fail = [&](std::size_t at, const std::string& what) -> void {
    throw InputError(0, static_cast<int>(at) + 1, what);
  };
  std::size_t eq = spec.rfind('=');
  if (eq == std::string_view::npos) fail(spec.size(), "TOOL[/EDGE]=RADIUS expected, e.g. 3=5 or \"FLAT 10\"/2=4.98");
  std::string_view value = spec.substr(eq + 1);
  std::optional<std::int64_t> position;  // TOOL-TURN-1: RADIUS,POSITION makes a turning tool
  if (std::size_t comma = value.find(','); comma != std::string_view::npos) {
    auto p = Decimal::parse(trim(value.substr(comma + 1)));
    position = p.value ? p.value->to_integer() : std::nullopt;
    if (!position || *position < 1 || *position > 9)
      fail(eq + 1 + comma + 1, "the cutting edge position after ',' is a whole number 1 … 9 (a turning tool)");
    value = value.substr(0, comma);
  }
  auto radius = Decimal::parse(trim(value));
  if (!radius.value) fail(eq + 1, fmt::format("'{}' is not a radius in mm", trim(value)));
  std::string_view tool = trim(spec.substr(0, eq));
  std::int64_t edge = 1;
  if (std::size_t slash = tool.rfind('/'); slash != std::string_view::npos) {
    auto d = Decimal::parse(trim(tool.substr(slash + 1)));
    auto n = d.value ? d.value->to_integer() : std::nullopt;
    if (!n || *n < 1 || *n > 32000) fail(slash + 1, "the edge (D) after '/' is a number 1 … 32000");
    edge = *n;
    tool = trim(tool.substr(0, slash));
  }
  if (tool.size() >= 2 && tool.front() == '"' && tool.back() == '"') tool = tool.substr(1, tool.size() - 2);
  if (tool.empty()) fail(0, "the tool (a number or a name) is missing before '='");
  std::int64_t number = 0;
  auto as_number = Decimal::parse(tool);
  if (auto n = as_number.value ? as_number.value->to_integer() : std::nullopt) {
    if (*n < 1 || *n > 32000) fail(0, "tool numbers are 1 … 32000");
    number = *n;
  } else if (auto named = number_of(std::string(tool))) {
    number = *named;
  } else {
    // A name not in the table yet gets a number no edge and no name uses (TOOL-NAME-1 selects by name).
    number = 32000;
    auto used = [&](std::int64_t t) {
      for (const auto& [key, e] : edges_)
        if (key.first == t) return true;
      for (const auto& [name, t2] : names_)
        if (t2 == t) return true;
      return false;
    };
    while (used(number)) --number;
    names_[std::string(tool)] = number;
  }
  EdgeData& e = edges_[{number, edge}];
  if (position) {  // a turning tool (type 500) with its cutting edge position $TC_DP2
    e.type = e.values[1] = Decimal::from_int(500);
    e.position = e.values[2] = Decimal::from_int(*position);
  } else if (e.type.is_zero()) {
    e.type = e.values[1] = Decimal::from_int(120);  // an end mill unless the table says
  }
  e.radius = e.values[6] = *radius.value;
}

void OffsetTable::set(int index, int axis, Decimal value) {
  Point3& p = offsets_[index];
  coord(p, axis) = value;
}

Point3 OffsetTable::translation(int index) const {
  auto it = offsets_.find(index);
  return it == offsets_.end() ? Point3{} : it->second;
}

bool OffsetTable::defined(int index) const { return index == 0 || offsets_.count(index) != 0; }

namespace {

class OffsetLine {
 public:
  OffsetLine(std::string_view s, int line, const std::string& source) : s_(s), line_(line), source_(source) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(line_, static_cast<int>(i_) + 1, fmt::format("{}: {}", source_, what));
  }
  void space() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
  }
  void expect(char c) {
    space();
    if (i_ >= s_.size() || s_[i_] != c) fail(fmt::format("'{}' expected", c));
    ++i_;
    space();
  }
  bool accept(char c) {
    space();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      space();
      return true;
    }
    return false;
  }
  std::string word() {
    space();
    std::string w;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' || s_[i_] == '$'))
      w.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(s_[i_++]))));
    return w;
  }
  Decimal number() {
    space();
    std::size_t start = i_;
    if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
    while (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.')) ++i_;
    auto r = Decimal::parse(s_.substr(start, i_ - start));
    if (!r.value) fail(fmt::format("'{}' is not a number", s_.substr(start, i_ - start)));
    return *r.value;
  }
  // A geometry axis' index, or -1 for any other axis of the channel (A, B, C, a spindle …): a
  // real archive lists them all, and their offsets do not move the tool in X, Y, Z.
  int axis() {
    std::string a = word();
    if (a == "X") return 0;
    if (a == "Y") return 1;
    if (a == "Z") return 2;
    // Rotary and additional axes as machines name them: A, B, C, U, V, W, SP, each perhaps numbered.
    std::size_t letters = a.rfind("SP", 0) == 0 ? 2 : (!a.empty() && std::strchr("ABCUVW", a[0]) ? 1 : 0);
    bool other = letters != 0 && std::all_of(a.begin() + static_cast<std::ptrdiff_t>(letters), a.end(),
                                             [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
    if (!other)
      fail(fmt::format("'{}' is not a geometry axis (X, Y, Z) nor a rotary or additional axis (A, B, C, U, V, W, SP)",
                       a));
    return -1;
  }
  bool end() {
    space();
    return i_ >= s_.size() || s_[i_] == ';';
  }
  static bool neutral_rotation(const Decimal& v) { return v.is_zero(); }
  static bool neutral_scale(const Decimal& v) { return v == Decimal::from_int(1) || v.is_zero(); }
  void reject_rotation() { fail("a rotation in a settable offset is SINUMERIK NC that cutcom does not simulate"); }
  void reject_scale() { fail("a scale in a settable offset is not simulated"); }
  void reject_mirror() { fail("a mirror in a settable offset is not simulated"); }

  // One component of offset `index`, axis `a` (-1: not a geometry axis, passed over).
  void component(OffsetTable& table, int index, int a, const std::string& component, const Decimal& v) {
    if (component == "TR") {
      if (a >= 0) table.set(index, a, v);
    } else if (component == "FI") {  // the fine offset adds to the coarse one
      if (a >= 0) table.set(index, a, coord(table.translation(index), a) + v);
    } else if (component == "RT") {
      if (!neutral_rotation(v)) reject_rotation();
    } else if (component == "SC") {
      if (!neutral_scale(v)) reject_scale();
    } else if (component == "MI") {
      if (!v.is_zero()) reject_mirror();
    } else {
      fail(fmt::format("'{}' is not a frame component (TR, FI, RT, SC, MI)", component));
    }
  }

  // $P_UIFR[n]=CTRANS(X,10,Y,20):CFINE(…):CROT(…):CMIRROR(…):CSCALE(…), as the control writes
  // it, or $P_UIFR[n,X,TR]=10 (also FI, and RT/SC/MI at their neutral value). n = 0 is G500's.
  void run(OffsetTable& table) {
    if (word() != "$P_UIFR") fail("only $P_UIFR[n]… lines set settable offsets");
    expect('[');
    Decimal idx = number();
    auto n = idx.to_integer();
    if (!n || *n < 0 || *n > 99) fail("settable offset numbers are 0 … 99 (G500 = 0, G54 = 1, G505 = 5, …)");
    int index = static_cast<int>(*n);
    if (accept(',')) {
      int a = axis();
      expect(',');
      std::string name = word();
      expect(']');
      expect('=');
      component(table, index, a, name, number());
    } else {
      expect(']');
      expect('=');
      // The functions of the assignment, joined by ':'; CTRANS sets the axes it names and clears
      // the others (the frame is assigned whole), CFINE adds.
      Point3 coarse, fine;
      do {
        std::string fn = word();
        static const char* const kKnown[] = {"CTRANS", "CFINE", "CROT", "CMIRROR", "CSCALE"};
        if (std::find(std::begin(kKnown), std::end(kKnown), fn) == std::end(kKnown))
          fail(fmt::format("'{}': a settable offset is CTRANS, CFINE, CROT, CMIRROR or CSCALE(axis, value, …)", fn));
        expect('(');
        if (accept(')')) continue;
        do {
          int a = axis();
          if (fn == "CMIRROR") reject_mirror();  // a mirrored axis is named alone: any is a mirror
          expect(',');
          Decimal v = number();
          if (fn == "CTRANS" && a >= 0) coord(coarse, a) = v;
          if (fn == "CFINE" && a >= 0) coord(fine, a) = v;
          if (fn == "CROT" && !neutral_rotation(v)) reject_rotation();
          if (fn == "CSCALE" && !neutral_scale(v)) reject_scale();
        } while (accept(','));
        expect(')');
      } while (accept(':'));
      for (int a = 0; a < 3; ++a) table.set(index, a, coord(coarse, a) + coord(fine, a));
    }
    if (!end()) fail("unexpected text after the assignment");
    // G500's frame is zero on nearly every machine (an archive lists it so); another one would
    // move the blocks before the program's first G54 … in a system cutcom does not output.
    const Point3 g500 = table.translation(0);
    if (index == 0 && !(g500.x.is_zero() && g500.y.is_zero() && g500.z.is_zero()))
      fail("$P_UIFR[0], the frame G500 selects, other than zero is not simulated");
  }

 private:
  std::string_view s_;
  std::size_t i_ = 0;
  int line_;
  const std::string& source_;
};

}  // namespace

void OffsetTable::load(std::istream& in, const std::string& source_name, int channel) {
  archive_lines(in, source_name, channel, [&](int n, const std::string& line, const std::string& u) {
    if (u.rfind("$P_UIFR", 0) != 0) {
      if (u[0] == '$') return;  // other frames of the archive ($P_CHBFR, …) do not change the path here
      throw InputError(n, 1, fmt::format("{}: not a settable-offset line ($P_UIFR[n]=CTRANS(…))", source_name));
    }
    OffsetLine(trim(line), n, source_name).run(*this);
  });
}

}  // namespace cutcom
