#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string_view>

#include "cutcom/output.hpp"
#include "text_append.hpp"

namespace cutcom {

namespace {
using nlohmann::json;

double clean(double v) { return v == 0 ? 0.0 : v; }  // never print -0

json block_ref(const std::optional<std::int64_t>& b) { return b ? json(*b) : json(nullptr); }

void append(SpillList& list, const json& item) { list.append(item.dump()); }
}  // namespace

JsonWriter::JsonWriter(std::ostream& out, std::string engine, bool with_trace) : out_(out), with_trace_(with_trace) {
  out_ << "{\n  \"format\": \"cutcom-path/1\",\n  \"engine\": " << json(engine).dump()
       << ",\n  \"unit\": \"mm\",\n  \"path\": [";
}

// A path element written straight into the buffer as nlohmann::json's dump() of the same object
// would write it (keys in its sorted order), without building a json object per element: the
// writer emits millions of them (issue "Performance"). Items with numbers are written alike, so
// that every number of the document is the shortest (nlohmann's are not always).
namespace {
// Every number of the document: the shortest that reads back (text::put_shortest), null where it is
// no number (as nlohmann::json writes NaN and infinities), never -0; at most 24 characters.
char* put_shortest_number(char* p, double v) {
  if (!std::isfinite(v)) return text::put(p, "null");
  return text::put_shortest(p, clean(v));
}
using text::put_integer;
// A JSON string: printable ASCII directly, anything else (escapes, UTF-8 checks) by nlohmann.
void append_string(std::string& out, std::string_view s) {
  for (char c : s)
    if (c < 0x20 || c > 0x7e || c == '"' || c == '\\') {
      out += json(std::string(s)).dump();
      return;
    }
  out += '"';
  out.append(s);
  out += '"';
}
void append_key(std::string& out, std::string_view key) {  // "key": after a comma where needed
  if (out.back() != '{') out += ',';
  out += '"';
  out.append(key);
  out += "\":";
}
}  // namespace

char* JsonWriter::put_new_number(char* p, double v, NumberText& keep) {
  char* end = put_shortest_number(p, v);
  std::memcpy(&keep.bits, &v, sizeof keep.bits);
  keep.size = static_cast<std::uint8_t>(end - p);
  std::memcpy(keep.text, p, kNumberCopy);  // whole: the buffer has that room past any number
  return end;
}

char* JsonWriter::put_point(char* p, const PathPoint& q) {  // at most 3 * 26 + 4 characters
  *p++ = '[';
  p = put_number(p, q.x);
  *p++ = ',';
  p = put_number(p, q.y);
  *p++ = ',';
  p = put_number(p, q.z);
  *p++ = ']';
  return p;
}

// cutcom's own names and words (kinds, SAR movements, descriptions): printable ASCII without
// quotes or backslashes, written as JSON strings as they are.
char* put_name(char* p, std::string_view name) {
  *p++ = '"';
  p = text::put(p, name);
  *p++ = '"';
  return p;
}

void JsonWriter::element(const PathElement& e) {
  // One buffer for the element, appended once (a path holds millions of elements): at most
  // 3 points of 82 characters, the description, a feed of at most 40 and the words around them.
  constexpr std::size_t kRoom = 600 + kDescriptionRoom + kNumberCopy;  // put_number copies past the end
  char item[kRoom];
  char* p = text::put(item, first_ ? "\n    {\"block\":" : ",\n    {\"block\":");
  first_ = false;
  const Origin& o = e.origin;
  p = o.block ? put_integer(p, *o.block) : text::put(p, "null");
  bool arc = e.type == ElementType::kArc;
  if (arc) {
    p = text::put(p, e.ccw ? ",\"ccw\":true,\"center\":" : ",\"ccw\":false,\"center\":");
    p = put_point(p, e.center);
  }
  p = text::put(p, ",\"end\":");
  char* end_text = p;
  p = put_point(p, e.end);
  const std::size_t end_size = static_cast<std::size_t>(p - end_text);
  const int spare = last_end_slot_ ^ 1;
  std::memcpy(last_end_text_[spare], end_text, sizeof last_end_text_[spare]);  // whole: a few moves
  if (!e.rapid) {
    if (e.feed != last_feed_ || last_feed_text_.empty()) {  // one feed runs over many elements
      last_feed_ = e.feed;
      last_feed_text_.clear();
      append_string(last_feed_text_, e.feed.to_string());
    }
    p = text::put(p, ",\"feed\":");
    p = text::put(p, std::string_view(last_feed_text_).substr(0, 40));  // a decimal's text: at most 33 characters
    if (e.feed_type == FeedType::kG95) p = text::put(p, ",\"feed_type\":\"G95\"");
  }
  p = text::put(p, ",\"line\":");
  p = put_integer(p, o.line);
  p = text::put(p, ",\"origin\":{");
  // The origin's keys in nlohmann's sorted order, each after a comma but the first.
  const char* first_key = p;
  auto key = [&](std::string_view k) {
    if (p != first_key) *p++ = ',';
    *p++ = '"';
    p = text::put(p, k);
    *p++ = '"', *p++ = ':';
  };
  bool inserted = o.insert.kind != InsertKind::kNone;  // NC-CONTOUR-*: an element the reader inserted
  if (inserted && o.insert.kind != InsertKind::kTurn) key("corner_next_line"), p = put_integer(p, o.insert.next_line);
  if (inserted) key("inserted"), p = put_name(p, insert_kind_name(o.insert.kind));
  key("kind");
  p = put_name(p, origin_kind_name(o.kind));
  key("line");
  p = put_integer(p, o.line);
  if (o.kind == OriginKind::kTransitionCircle) key("next_line"), p = put_integer(p, o.next_line);
  if (o.sar != SarMove::kNone) key("sar"), p = put_name(p, sar_move_name(o.sar));
  if (o.source != 0 && sources_) {  // NC-PARAM-SUB-3: a file's name, of any length
    key("source");
    buffer_.append(item, p);
    append_string(buffer_, sources_(o.source));
    p = item, first_key = nullptr;
  }
  key("text");
  *p++ = '"';
  p = put_description(p, o);
  *p++ = '"';
  if (inserted && o.insert.kind == InsertKind::kTurn) key("turn"), p = put_integer(p, o.insert.turn);
  p = text::put(p, e.rapid ? "},\"rapid\":true,\"start\":" : "},\"rapid\":false,\"start\":");
  bool at_last_end = last_end_size_ != 0 && std::memcmp(&e.start, &last_end_, sizeof last_end_) == 0;
  p = at_last_end ? text::put(p, std::string_view(last_end_text_[last_end_slot_], last_end_size_))
                  : put_point(p, e.start);
  p = text::put(p, arc ? ",\"type\":\"arc\"}" : ",\"type\":\"line\"}");
  last_end_ = e.end, last_end_size_ = end_size, last_end_slot_ = spare;
  buffer_.append(item, p);
  written();
}

void JsonWriter::written() {
  if (buffer_.size() < (std::size_t{1} << 16)) return;
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

void JsonWriter::action(const ActionEvent& a) {
  std::string& item = item_;
  char head[128 + kNumberCopy];  // put_number copies past the end
  char* p = text::put(head, "{\"at\":");
  p = put_point(p, a.at);
  p = text::put(p, ",\"block\":");
  p = a.block ? put_integer(p, *a.block) : text::put(p, "null");
  item.assign(head, p);
  append_key(item, "function");
  append_string(item, a.function.name());
  append_key(item, "line");
  text::append_integer(item, a.line);
  item += '}';
  actions_.append(item);
}

void JsonWriter::decision(const Decision& d) {
  if (!with_trace_) return;
  std::string& item = item_;
  item = "{\"branch\":";
  append_string(item, d.branch);
  append_key(item, "clause");
  append_string(item, d.clause);
  append_key(item, "line");
  text::append_integer(item, d.line);
  if (d.has_margin && !d.margin_exact.empty()) {
    append_key(item, "margin_exact");
    append_string(item, d.margin_exact);
  } else if (d.has_margin) {
    append_key(item, "margin");
    char number[kNumberCopy + 1];  // put_number copies that many
    item.append(number, put_number(number, d.margin));
  }
  item += '}';
  decisions_.append(item);
}

void JsonWriter::alarm(const Alarm& a) {
  json j{{"number", a.number}, {"line", a.line}, {"block", block_ref(a.block)}, {"clause", a.clause}, {"text", a.text}};
  if (a.source != 0 && sources_) j["source"] = sources_(a.source);  // NC-PARAM-SUB-3
  append(alarms_, j);
}

void JsonWriter::notice(const Notice& n) {
  json j{{"line", n.line}, {"clause", n.clause}, {"text", n.text}};
  if (n.source != 0 && sources_) j["source"] = sources_(n.source);  // NC-PARAM-SUB-3
  append(notices_, j);
}

void JsonWriter::sar_variables(const SarVariables& v) {
  char item[256 + kNumberCopy];  // put_number copies past the end
  char* p = text::put(item, "{\"$P_AEP\":");
  p = put_point(p, v.p_aep);
  p = text::put(p, ",\"$P_APDV\":");
  p = put_integer(p, v.p_apdv);
  p = text::put(p, ",\"$P_APR\":");
  p = put_point(p, v.p_apr);
  p = text::put(p, ",\"block\":");
  p = v.block ? put_integer(p, *v.block) : text::put(p, "null");
  p = text::put(p, ",\"line\":");
  p = put_integer(p, v.line);
  *p++ = '}';
  variables_.append(std::string(item, p));
}

void JsonWriter::error(const std::string& file, int line, int column, const std::string& message) {
  error_ = nlohmann::json{{"file", file}, {"line", line}, {"column", column}, {"message", message}}.dump();
}

void JsonWriter::finish() {
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
  out_ << (first_ ? "]" : "\n  ]");
  auto list = [&](const char* key, const SpillList& items) {
    out_ << ",\n  \"" << key << "\": [";
    if (!items.empty()) {
      out_ << "\n    ";
      items.write_to(out_, ",\n    ");
      out_ << "\n  ";
    }
    out_ << "]";
  };
  list("actions", actions_);
  list("alarms", alarms_);
  list("notices", notices_);
  list("variables", variables_);
  if (with_trace_) list("decisions", decisions_);
  if (!error_.empty()) out_ << ",\n  \"error\": " << error_;
  out_ << "\n}\n";
}

}  // namespace cutcom
