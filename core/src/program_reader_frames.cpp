// NC-PARAM-FRAME-1/2: the frames a program reads and writes as variables ($P_PFRAME, $P_UIFR,
// CTRANS …): a frame shown as its components, and components written back as additive blocks.
#include <fmt/format.h>

#include <cmath>

#include "cutcom/input_error.hpp"
#include "cutcom/reader.hpp"

namespace cutcom {

namespace {
// NC-PARAM-FRAME-1: a programmable frame as additive blocks that build it again: the shift (in the
// program's unit), the rotation, then the factors (a mirror is a factor -1), the order in
// which NC-FRAME-2 applies them. Empty for a shift an inch program cannot write exactly.
std::optional<std::string> frame_blocks(const ProgrammableFrame& f, bool inch) {
  std::string out;
  for (std::size_t a = 0; a < 3; ++a) {
    Decimal v = f.shift[a];
    if (inch) {
      bool exact = true;
      v = v.scaled(10, 254, &exact);
      if (!exact) return std::nullopt;
    }
    if (!v.is_zero()) out += fmt::format(" {}{}", "XYZ"[a], v.to_string());
  }
  if (!out.empty()) out = "ATRANS" + out;  // additive: the frame may be chained after another
  if (f.rotated())
    out += fmt::format("{}AROT {}{}", out.empty() ? "" : "\n", "XYZ"[f.rotation_axis], f.rotation.to_string());
  std::string scale;
  for (std::size_t a = 0; a < 3; ++a)
    if (f.factor[a] != Decimal::from_int(1)) scale += fmt::format(" {}{}", "XYZ"[a], f.factor[a].to_string());
  if (!scale.empty()) out += (out.empty() ? "ASCALE" : "\nASCALE") + scale;
  return out;
}

// NC-PARAM-FRAME-2: the component index [axis, component] of a frame variable; empty if it is not one.
std::optional<std::pair<std::size_t, std::string>> component_index(const std::vector<NcValue>& idx, std::size_t from) {
  if (idx.size() != from + 2 || idx[from].type != NcValue::Type::kString ||
      idx[from + 1].type != NcValue::Type::kString || idx[from].text.size() != 1)
    return std::nullopt;
  int axis = idx[from].text[0] - 'X';
  if (axis < 0 || axis > 2) return std::nullopt;
  return std::pair{static_cast<std::size_t>(axis), idx[from + 1].text};
}
}  // namespace

std::optional<std::string> ProgramReader::programmable_frame() {
  return frame_blocks(frame_, units_ == Units::kG70 || units_ == Units::kG700);
}

// NC-PARAM-FRAME-2: the components as the control shows them: TR the shift, FI the fine shift (0:
// cutcom keeps one shift), RT the rotation about that axis, SC the scale factor, MI 1 when mirrored.
// The programmable frame's shift in the program's unit (as $P_PFRAME), a settable offset's as held.
std::optional<double> ProgramReader::frame_component(std::string_view n, const std::vector<NcValue>& idx) {
  bool inch = units_ == Units::kG70 || units_ == Units::kG700;
  if (n == "$P_PFRAME") {
    auto c = component_index(idx, 0);
    if (!c) return std::nullopt;
    auto [a, comp] = *c;
    if (comp == "TR") return inch ? frame_.shift[a].to_double() / 25.4 : frame_.shift[a].to_double();
    if (comp == "FI") return 0.0;
    if (comp == "RT")
      return frame_.rotated() && frame_.rotation_axis == static_cast<int>(a) ? frame_.rotation.to_double() : 0.0;
    if (comp == "SC") return std::fabs(frame_.factor[a].to_double());
    if (comp == "MI") return frame_.factor[a].sign() < 0 ? 1.0 : 0.0;
    return std::nullopt;
  }
  bool settable = n == "$P_UIFR";
  auto c = component_index(idx, settable ? 1 : 0);
  if (!c) return std::nullopt;
  int index = offset_index_;
  if (settable) {
    if (idx[0].type == NcValue::Type::kString || idx[0].number != std::trunc(idx[0].number) || idx[0].number < 0 ||
        idx[0].number > 99)
      return std::nullopt;
    index = static_cast<int>(idx[0].number);
  }
  auto [a, comp] = *c;
  if (comp == "TR") return coord(offsets_.translation(index), static_cast<int>(a)).to_double();
  if (comp == "FI" || comp == "RT" || comp == "MI") return 0.0;  // settable offsets are translations (NC-OFFSET-2)
  if (comp == "SC") return 1.0;
  return std::nullopt;
}

std::optional<std::string> ProgramReader::settable_frame(int n) {
  Point3 t = offsets_.translation(n < 0 ? offset_index_ : n);
  std::string out;
  for (int a = 0; a < 3; ++a)
    if (!coord(t, a).is_zero()) out += fmt::format(" {}{}", "XYZ"[a], coord(t, a).to_string());
  return out.empty() ? out : "ATRANS" + out;
}

std::optional<std::string> ProgramReader::programmable_frame_with(int axis, std::string_view comp,
                                                                  std::string_view value) {
  auto fail = [](const std::string& what) -> std::optional<std::string> { throw InputError(0, 1, what); };
  auto parsed = Decimal::parse(value);
  if (!parsed.value) return fail(fmt::format("'{}' is not a value a frame holds", value));
  Decimal v = *parsed.value;
  std::size_t a = static_cast<std::size_t>(axis);
  ProgrammableFrame f = frame_;
  if (comp == "TR") {
    f.shift[a] = length(v);
  } else if (comp == "FI") {  // the fine shift adds to the coarse one (as for settable offsets)
    f.shift[a] = f.shift[a] + length(v);
  } else if (comp == "RT") {
    if (f.rotated() && f.rotation_axis != axis && !v.is_zero())
      return fail("rotations in two different planes are SINUMERIK NC that cutcom does not simulate");
    if (!v.is_zero() || f.rotation_axis == axis) f.rotation = v, f.rotation_axis = axis;
  } else if (comp == "SC") {
    if (v.sign() <= 0) return fail(fmt::format("{}: a scale factor must be positive (MI mirrors)", "XYZ"[a]));
    f.factor[a] = f.factor[a].sign() < 0 ? -v : v;
  } else if (comp == "MI") {
    if (!v.is_zero() && v != Decimal::from_int(1)) return fail("a mirror component is 0 or 1");
    if ((f.factor[a].sign() < 0) != !v.is_zero()) f.factor[a] = -f.factor[a];
  } else {
    return fail(fmt::format("'{}' is not a frame component (TR, FI, RT, SC, MI)", comp));
  }
  auto blocks = frame_blocks(f, units_ == Units::kG70 || units_ == Units::kG700);
  if (!blocks) return fail("a translation under inch units G70/G700 that inches cannot write exactly is not simulated");
  return blocks;
}

}  // namespace cutcom
