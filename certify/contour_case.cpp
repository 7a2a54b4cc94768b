#include "contour_case.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <sstream>

namespace cutcom::props {

std::string fixed(std::int64_t units, int decimals) {
  std::uint64_t a = units < 0 ? static_cast<std::uint64_t>(-(units + 1)) + 1 : static_cast<std::uint64_t>(units);
  std::uint64_t one = 1;
  for (int i = 0; i < decimals; ++i) one *= 10;
  return fmt::format("{}{}.{:0{}}", units < 0 ? "-" : "", a / one, a % one, decimals);
}

namespace {
// The corner mode of a contour block, and the new side where it changes.
std::string side_word(const Step& s, bool right) {
  std::string w = s.g451 ? "G451" : "G450";
  if (s.flip || s.again) w += right ? " G42" : " G41";
  return w;
}
}  // namespace

namespace {
std::string level(bool ac, std::int64_t v, int decimals) {
  return ac ? "AC(" + fixed(v, decimals) + ")" : fixed(v, decimals);
}

// The words of a SAR block after its contour G code.
std::string sar_words(int side, int seg, std::int64_t disr, bool discl, bool ac, std::int64_t v, bool fad,
                      int decimals) {
  std::string w = fmt::format("G{} G{} DISR={}", side, seg, fixed(disr, decimals));
  if (discl) w += " DISCL=" + level(ac, v, decimals);
  if (fad) w += " FAD=200";
  return w;
}
}  // namespace

namespace {
bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The end of a number [-]digits[.digits] at i, or i if there is none.
std::size_t number_end(const std::string& s, std::size_t i) {
  std::size_t j = i;
  if (j < s.size() && s[j] == '-') ++j;
  std::size_t d = j;
  while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.')) ++j;
  return j == d ? i : j;
}

// becomes X=(-1.616+R7*SHIFT[1])-R7*SHIFT[1] (R7 * SHIFT[1] = 3.75), CR=2.5 becomes
// CR=(2.5*SHIFT[0])/SHIFT[0]: the value comes back through binary64 a few ulps off.
std::string parametric_line(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    if (s[i] == ';') {
      out += s.substr(i);
      break;
    }
    bool start = i == 0 || !name_char(s[i - 1]);
    if (start && std::string("XYZIJK").find(s[i]) != std::string::npos) {
      std::size_t e = number_end(s, i + 1);
      if (e > i + 1 && (e == s.size() || !name_char(s[e]))) {
        out += fmt::format("{}=({}+R7*SHIFT[1])-R7*SHIFT[1]", s[i], s.substr(i + 1, e - i - 1));
        i = e;
        continue;
      }
    }
    bool done = false;
    for (const char* w : {"CR=", "DISR=", "DISCL=", "RND=", "CHF="}) {
      std::string k(w);
      if (start && s.compare(i, k.size(), k) == 0) {
        std::size_t e = number_end(s, i + k.size());
        if (e > i + k.size()) {
          out += fmt::format("{}({}*SHIFT[0])/SHIFT[0]", k, s.substr(i + k.size(), e - i - k.size()));
          i = e;
          done = true;
          break;
        }
      }
    }
    if (!done) out += s[i++];
  }
  return out;
}
}  // namespace

std::string to_parametric_program(const std::string& plain) {
  std::istringstream in(plain);
  std::string out = "DEF REAL SHIFT[2]=SET(0.5, 1.25)\nDEF INT ONCE\nR7=3\n";
  std::string line;
  bool opened = false;
  while (std::getline(in, line)) {
    bool end = line.find("M30") != std::string::npos || line.find("M2 ") != std::string::npos;
    bool code = !line.empty() && line[0] != ';' && line[0] != '$';
    if (code && !opened && !end) {
      out += "IF R7*SHIFT[1] == 3.75\nFOR ONCE=1 TO 1\n";
      opened = true;
    }
    if (end && opened) {
      out += "ENDFOR\nELSE\nG1 X999\nENDIF\n";
      opened = false;
    }
    out += (code ? parametric_line(line) : line) + "\n";
  }
  if (opened) out += "ENDFOR\nELSE\nG1 X999\nENDIF\n";
  return out;
}

std::string to_program(const ContourCase& c) {
  // Plane axes: abscissa / ordinate / applicate letters for G17, G18, G19.
  const char* a = c.plane == 17 ? "X" : c.plane == 18 ? "Z" : "Y";
  const char* b = c.plane == 17 ? "Y" : c.plane == 18 ? "X" : "Z";
  const char* h = c.plane == 17 ? "Z" : c.plane == 18 ? "Y" : "X";
  std::string p = fmt::format("$TC_DP1[1,1]=120\n$TC_DP6[1,1]={}\n", fixed(c.radius_um, c.decimals));
  int n = 10;
  const SarEnds& sar = c.sar;
  const int v = c.variant;
  // PROP-DIFF-3: what the path carries besides its geometry, varied by the case's own numbers
  // rather than a random draw (every seed's programs keep their geometry): selection and
  // deselection blocks in G0, feed per revolution.
  // The key is read off what the metamorphic properties keep (the steps' kinds and counts, not
  // their coordinates): a translated, turned, mirrored or scaled case gets the same words.
  std::uint64_t key = c.steps.size() * 7919U + static_cast<std::uint64_t>(c.edge_select * 31 + c.edge_deselect);
  for (const Step& s : c.steps)
    key = key * 131U + static_cast<std::uint64_t>((s.arc ? 1 : 0) + (s.g451 ? 2 : 0) + 4 * s.dummies);
  const bool rapid_ends = !c.plane_only && key % 4 == 1;
  const bool per_revolution = !c.plane_only && key % 6 == 2;
  // TRC-RADIUS-3: for a fifth of the cases without CDON a D (or T) change on a straight contour block
  // that is not the first of a selection (the blend's other cases are not supported).
  int d_change = -1;
  if (!c.plane_only && !c.cdon && c.radius_um > 0 && v != 3 && v != 4 && v != 5 && key % 5 == 3)
    for (std::size_t i = 1; i < c.steps.size() && d_change < 0; ++i) {
      const Step& s = c.steps[i];
      const Step& before = c.steps[i - 1];
      if (!s.arc && !s.polar && !s.flip && !s.again && !before.flip && !before.again && s.corner == 0)
        d_change = static_cast<int>(i);
    }
  const char* tool = v == 3 ? "T1 D0" : v == 4 ? "T0 D1" : v == 5 ? "T1 D2" : "T1 D1";  // TRC-SEL-5/6/7
  p += fmt::format("N{} G{} G90 {}G0 {}{} {}{} {}{} {}\n", n, c.plane, per_revolution ? "G95 " : "", a,
                   fixed(c.start_x, c.decimals), b, fixed(c.start_y, c.decimals), h,
                   fixed(sar.approach ? sar.start_h : 0, c.decimals), tool);
  n += 10;
  if (c.rotation_mdeg != 0) p += fmt::format("N{} ROT RPL={}\n", n - 5, fixed(c.rotation_mdeg, 3));  // NC-FRAME-4
  if (v == 2 && !sar.approach) {  // TRC-SEL-4: G41/G42 first in a block without a plane axis
    p += fmt::format("N{} G1 {} {}-0.5 F500\n", n, c.right ? "G42" : "G41", h);
    n += 10;
  }
  std::string modes = fmt::format("{} {} {} G{} {}", c.right ? "G42" : "G41", c.kont_select ? "KONT" : "NORM",
                                  c.g451_select ? "G451" : "G450", c.edge_select, c.cdon ? "CDON" : "CDOF");
  std::string first = fmt::format("{}{} {}{}", a, fixed(c.first_x, c.decimals), b, fixed(c.first_y, c.decimals));
  if (v == 1 && !sar.approach)  // TRC-SEL-3: the ordinate stays where it is (the contour starts there)
    first = fmt::format("{}{}", a, fixed(c.first_x, c.decimals));
  if (!sar.approach) {
    p += fmt::format("N{} {} {} {} F500\n", n, rapid_ends ? "G0" : "G1", modes, first);
  } else {
    std::string words = sar_words(sar.side_in, sar.seg_in, sar.disr_in, sar.discl_in, sar.discl_in_ac, sar.discl_in_v,
                                  sar.fad_in, c.decimals);
    if (v == 12 || v == 13) words += v == 12 ? " DISRP=5" : " DISRP=-5";  // SAR-DISRP-1/2
    // SAR-STOP-1 / SAR-AGAIN-1: a STOPRE or a second SAR block before the direction block.
    std::string between = v == 14   ? fmt::format("N{} STOPRE\n", n + 2)
                          : v == 15 ? fmt::format("N{} G1 G147 DISR=1 F500\n", n + 2)
                                    : "";
    // SAR-P4-1: P4 in the SAR block, or (the manual's E1 variants) from the next block.
    if (sar.p4_mode == 0) {
      p += fmt::format("N{} G1 G{} {} {} {} {}0 F500\n{}", n, sar.contour_in, words, modes, first, h, between);
    } else if (sar.p4_mode == 1) {
      p += fmt::format("N{} G1 G{} {} {} {}0 F500\n{}N{} {}\n", n, sar.contour_in, words, modes, h, between, n + 1,
                       first);
    } else {
      p += fmt::format("N{} G1 G{} {} {} F500\n{}N{} {} {}0\n", n, sar.contour_in, words, modes, between, n + 1, first,
                       h);
    }
  }
  std::int64_t x = c.first_x, y = c.first_y;
  bool right = c.right;
  int depth = 0;
  for (std::size_t i = 0; i < c.steps.size(); ++i) {
    const Step& s = c.steps[i];
    const bool last = i + 1 == c.steps.size();
    if (v == 10 && i == 0) {  // TRC-DUMMY-2: one block without plane motion too many (MD20250 = 5)
      for (int k = 0; k < 6; ++k) n += 10, p += fmt::format("N{} M{}\n", n, 8 + k % 2);
    }
    if (v == 11 && i == c.steps.size() / 2) {  // TRC-DUMMY-3: a plane position that does not move
      n += 10;
      p += fmt::format("N{} G1 {}{} {}{}\n", n, a, fixed(x, c.decimals), b, fixed(y, c.decimals));
    }
    for (int k = 0; k < s.dummies; ++k) {
      n += 10;
      p += k % 2 == 0 ? fmt::format("N{} G1 {}-{}\n", n, h, ++depth) : fmt::format("N{} M8\n", n);
    }
    x += s.dx, y += s.dy;
    if (s.flip) right = !right;
    n += 10;
    if (s.arc && s.cr != 0) {
      p += fmt::format("N{} {} {}{} {}{} CR={} {}\n", n, s.ccw ? "G3" : "G2", a, fixed(x, c.decimals), b,
                       fixed(y, c.decimals), fixed(s.cr, c.decimals), side_word(s, right));
    } else if (s.arc) {
      // Centre words of the plane: I/J (G17), K/I (G18), J/K (G19).
      const char* ci = c.plane == 17 ? "I" : c.plane == 18 ? "K" : "J";
      const char* cj = c.plane == 17 ? "J" : c.plane == 18 ? "I" : "K";
      // TRC-DESEL-2: the variant deselects in the last circle (without a side change there).
      std::string words = v == 7 && last ? side_word(Step{s.dx, s.dy, s.g451}, right) + " G40" : side_word(s, right);
      p += fmt::format("N{} {} {}{} {}{} {}{} {}{} {}\n", n, s.ccw ? "G3" : "G2", a, fixed(x, c.decimals), b,
                       fixed(y, c.decimals), ci, fixed(s.ci, c.decimals), cj, fixed(s.cj, c.decimals), words);
    } else if (s.polar) {  // NC-POLAR-2: the same end point in polar coordinates, 9 decimals
      double xa = static_cast<double>(x), yb = static_cast<double>(y);
      double scale = std::pow(10.0, -c.decimals);
      p += fmt::format("N{} G1 AP={:.9f} RP={:.9f} {}\n", n, std::atan2(yb, xa) * 180.0 / M_PI,
                       std::hypot(xa, yb) * scale, side_word(s, right));
    } else {
      p += fmt::format("N{} G1 {}{} {}{} {}{}\n", n, a, fixed(x, c.decimals), b, fixed(y, c.decimals),
                       side_word(s, right), v == 9 && i == 0 ? " DISC=1" : "");  // TRC-DISC-1
    }
    if (s.corner != 0) {  // NC-CONTOUR-1: appended to the block just written
      p.pop_back();
      p += fmt::format(" {}={}\n",
                       s.corner == 1   ? "RND"
                       : s.corner == 2 ? "CHR"
                                       : "CHF",
                       fixed(s.corner_value, c.decimals));
    }
    if (i % 3 == 1) {  // PROP-DIFF-3: the feed changes along the contour (no random draw: the seed's geometry stays)
      p.pop_back();
      p += fmt::format(" F{}\n", 300 + 100 * static_cast<int>(i % 5));
    }
    if (static_cast<int>(i) == d_change) {  // D2 of twice the radius (a scaled case scales it), its data
      // just before it: the header stays as it was. Every other such case changes the tool (T2 D1)
      // instead, which the blend takes as it takes a D change.
      bool tool_change = (key / 5) % 2 == 1;
      std::size_t block = p.rfind('\n', p.size() - 2) + 1;
      p.insert(block, fmt::format("$TC_DP1[{0}]=120\n$TC_DP6[{0}]={1}\n", tool_change ? "2,1" : "1,2",
                                  fixed(2 * c.radius_um, c.decimals)));
      p.pop_back();
      p += tool_change ? " T2 D1\n" : " D2\n";
    }
    // PROP-DIFF-3: actions on contour blocks, and blocks that also move the applicate (a slanted
    // line, a helix), so that where actions run and the heights of inserted circles are compared;
    // no random draw either, and the plane geometry stays that of the seed.
    if (i % 4 == 1 && !c.plane_only) {
      p.pop_back();
      p += fmt::format(" M{}\n", i % 8 == 1 ? 8 : 9);
    }
    if (i % 4 == 3 && s.corner == 0 && !s.polar && !c.plane_only) {
      p.pop_back();
      p += fmt::format(" {}-{}\n", h, ++depth);
    }
  }
  if (v == 7 && (c.steps.empty() || !c.steps.back().arc || c.steps.back().cr != 0)) {
    // TRC-DESEL-2 when the contour does not end in a centre circle: a half circle deselecting.
    std::int64_t one = 1;
    for (int k = 0; k < c.decimals; ++k) one *= 10;
    const char* ci = c.plane == 17 ? "I" : c.plane == 18 ? "K" : "J";
    const char* cj = c.plane == 17 ? "J" : c.plane == 18 ? "I" : "K";
    n += 10;
    p += fmt::format("N{} G2 {}{} {}{} {}{} {}0 G40\n", n, a, fixed(x + 20 * one, c.decimals), b, fixed(y, c.decimals),
                     ci, fixed(10 * one, c.decimals), cj);
  }
  if (v == 6) {  // TRC-PLANE-1: a plane change while selected (only a straight block follows)
    n += 10;
    p += fmt::format("N{} G{}\n", n, c.plane == 17 ? 18 : 17);
  }
  if (v == 8 && !sar.retraction) {  // TRC-DESEL-3: G40 first in a block without a plane axis
    n += 10;
    p += fmt::format("N{} G1 G40 {}-0.5\n", n, h);
    if (key % 2 == 0) {  // then G41/G42 again before the retraction: a selection from where the tool is
      n += 10;
      p += fmt::format("N{} G1 {} {}{} {}{} {}-0.25\n", n, c.right ? "G42" : "G41", a,
                       fixed((x + c.end_x) / 2, c.decimals), b, fixed((y + c.end_y) / 2, c.decimals), h);
    }
  }
  n += 10;
  std::string end = fmt::format("{}{} {}{}", a, fixed(c.end_x, c.decimals), b, fixed(c.end_y, c.decimals));
  std::string modes_out =
      fmt::format("{} {} G{}", c.kont_deselect ? "KONT" : "NORM", c.g451_deselect ? "G451" : "G450", c.edge_deselect);
  if (!sar.retraction) {
    p += fmt::format("N{} {} G40 {} {}\n", n, rapid_ends ? "G0" : "G1", modes_out, end);
  } else {
    // SAR-END-1: the ways the retraction block gives (or does not give) its end point.
    std::string axes = sar.end_case == 3   ? end + " " + h + fixed(sar.end_h, c.decimals)
                       : sar.end_case == 4 ? end
                       : sar.end_case == 2 ? h + fixed(sar.end_h, c.decimals)
                                           : "";
    p += fmt::format("N{} G1 {} G{} {} {} {}\n", n, sar.deselect ? "G40" : "", sar.contour_out,
                     sar_words(sar.side_out, sar.seg_out, sar.disr_out, sar.discl_out, sar.discl_out_ac,
                               sar.discl_out_v, false, c.decimals),
                     modes_out, axes);
    if (sar.follow) {  // SAR-END-1/3: the next block starts where the retraction ended (P2's level, P3 or P0)
      n += 10;
      p += fmt::format("N{} G0 {}{}\n", n, h, fixed(40000, c.decimals));
    }
  }
  p += fmt::format("N{} M30\n", n + 10);
  return p;
}

ContourCase reversed_contour(const ContourCase& c) {
  ContourCase r = c;
  r.right = !c.right;
  std::int64_t ex = c.first_x, ey = c.first_y;
  for (const Step& s : c.steps) ex += s.dx, ey += s.dy;
  r.start_x = c.end_x, r.start_y = c.end_y, r.first_x = ex, r.first_y = ey, r.end_x = c.start_x, r.end_y = c.start_y;
  r.kont_select = c.kont_deselect, r.kont_deselect = c.kont_select;
  r.g451_select = c.g451_deselect, r.g451_deselect = c.g451_select;
  r.edge_select = c.edge_deselect, r.edge_deselect = c.edge_select;
  r.steps.clear();
  for (std::size_t k = c.steps.size(); k-- > 0;) {
    const Step& s = c.steps[k];
    Step t = s;
    t.dx = -s.dx, t.dy = -s.dy;
    if (s.arc) t.ccw = !s.ccw, t.ci = s.ci - s.dx, t.cj = s.cj - s.dy;  // the same centre, from the other end
    // The corner (k, k+1) is decided by the mode of its second block, k+1; backwards that is k.
    t.g451 = k + 1 < c.steps.size() ? c.steps[k + 1].g451 : s.g451;
    r.steps.push_back(t);
  }
  return r;
}

void showValue(const ContourCase& c, std::ostream& os) {
  os << "style " << c.style << ", MD20210=" << c.md20210 << " MD20230=" << c.md20230 << " MD20240=" << c.md20240
     << (c.md20250 == ContourCase::kMd20250 ? "" : " MD20250=" + std::to_string(c.md20250)) << "\n"
     << to_program(c);
}

}  // namespace cutcom::props
