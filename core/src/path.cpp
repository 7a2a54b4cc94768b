#include "cutcom/path.hpp"

#include "text_append.hpp"

namespace cutcom {

std::string_view origin_kind_name(OriginKind k) {
  switch (k) {
    case OriginKind::kProgrammed:
      return "programmed";
    case OriginKind::kApproach:
      return "approach";
    case OriginKind::kOffset:
      return "offset";
    case OriginKind::kTransitionCircle:
      return "transition_circle";
    case OriginKind::kRetraction:
      return "retraction";
    case OriginKind::kInfeed:
      return "infeed";
  }
  return "?";
}

namespace {
// The description is written into a char buffer, not appended piece by piece to a string: the
// writers describe every element of the path (issue "Performance").
using text::put_integer;

char* put_block_name(char* p, int line, const std::optional<std::int64_t>& n) {
  if (n) {
    *p++ = 'N';
    return put_integer(p, *n);
  }
  return put_integer(text::put(p, "line "), line);
}

// "N40", or for an inserted element "(rounding of N40/N50)", "(turn 2 of N60)" (NC-CONTOUR-*).
char* put_inserted_name(char* p, int line, const std::optional<std::int64_t>& block, const ContourInsert& insert) {
  switch (insert.kind) {
    case InsertKind::kNone:
      return put_block_name(p, line, block);
    case InsertKind::kRounding:
    case InsertKind::kChamfer:
      p = text::put(p, insert.kind == InsertKind::kRounding ? "(rounding of " : "(chamfer of ");
      p = put_block_name(p, line, block);
      *p++ = '/';
      p = put_block_name(p, insert.next_line, insert.next_block);
      *p++ = ')';
      return p;
    case InsertKind::kTurn:
      p = put_integer(text::put(p, "(turn "), insert.turn);
      p = put_block_name(text::put(p, " of "), line, block);
      *p++ = ')';
      return p;
  }
  return p;
}

char* put_kind_description(char* p, const Origin& o) {
  switch (o.kind) {
    case OriginKind::kProgrammed:
      return text::put(put_inserted_name(p, o.line, o.block, o.insert), " without compensation");
    case OriginKind::kApproach:
      p = text::put(p, "approach ");
      break;
    case OriginKind::kOffset:
      p = text::put(p, "offset of ");
      break;
    case OriginKind::kTransitionCircle:
      p = put_inserted_name(text::put(p, "transition circle at corner "), o.line, o.block, o.insert);
      *p++ = '/';
      return put_inserted_name(p, o.next_line, o.next_block, o.next_insert);
    case OriginKind::kRetraction:
      p = text::put(p, "retraction ");
      break;
    case OriginKind::kInfeed:
      return text::put(put_inserted_name(p, o.line, o.block, o.insert), " at the corner point");
  }
  return put_inserted_name(p, o.line, o.block, o.insert);
}
}  // namespace

std::string_view sar_move_name(SarMove m) {
  switch (m) {
    case SarMove::kNone:
      return "";
    case SarMove::kLead:
      return "lead";
    case SarMove::kFastInfeed:
      return "fast_infeed";
    case SarMove::kSlowInfeed:
      return "slow_infeed";
    case SarMove::kElement:
      return "element";
    case SarMove::kEndPath:
      return "end_path";
  }
  return "?";
}

// At most two inserted names of three block names of 20 digits each, and the words around them:
// within kDescriptionRoom.
char* put_description(char* p, const Origin& o) {
  p = put_kind_description(p, o);
  if (o.sar != SarMove::kNone) {
    p = text::put(text::put(p, " (SAR "), sar_move_name(o.sar));
    *p++ = ')';
  }
  return p;
}

void append_description(std::string& out, const Origin& o) {
  char buffer[kDescriptionRoom];
  out.append(buffer, put_description(buffer, o));
}

std::string describe(const Origin& o) {
  std::string text;
  append_description(text, o);
  return text;
}

std::string_view insert_kind_name(InsertKind k) {
  switch (k) {
    case InsertKind::kNone:
      return "";
    case InsertKind::kRounding:
      return "rounding";
    case InsertKind::kChamfer:
      return "chamfer";
    case InsertKind::kTurn:
      return "turn";
  }
  return "?";
}

}  // namespace cutcom
