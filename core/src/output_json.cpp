#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string_view>

#include "cutcom/output.hpp"
#include "text_append.hpp"

namespace cutcom {

namespace {
using nlohmann::json;

double clean(double v) { return v == 0 ? 0.0 : v; }  // never print -0

json point(const PathPoint& p) { return json::array({clean(p.x), clean(p.y), clean(p.z)}); }

json block_ref(const std::optional<std::int64_t>& b) { return b ? json(*b) : json(nullptr); }

void append(SpillList& list, const json& item) { list.append(item.dump()); }
}  // namespace

JsonWriter::JsonWriter(std::ostream& out, std::string engine, bool with_trace) : out_(out), with_trace_(with_trace) {
  out_ << "{\n  \"format\": \"cutcom-path/1\",\n  \"engine\": " << json(engine).dump()
       << ",\n  \"unit\": \"mm\",\n  \"path\": [";
}

// A path element written straight into the buffer, byte for byte as nlohmann::json's dump()
// of the same object would write it (keys in its sorted order, numbers by its own shortest
// round-trip formatter), without building a json object per element: the writer emits
// millions of them (issue "Performance").
namespace {
void append_number(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  char digits[64];
  char* end = nlohmann::detail::to_chars(digits, digits + sizeof digits, clean(v));
  out.append(digits, end);
}
void append_point(std::string& out, const PathPoint& p) {
  out += '[';
  append_number(out, p.x);
  out += ',';
  append_number(out, p.y);
  out += ',';
  append_number(out, p.z);
  out += ']';
}
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
// ,"key": in one append where a key is known to follow another (the writer's hot path).
template <std::size_t N>
void append_next_key(std::string& out, const char (&comma_key_colon)[N]) {
  out.append(comma_key_colon, N - 1);
}
}  // namespace

void JsonWriter::element(const PathElement& e) {
  std::string& b = buffer_;
  b += first_ ? "\n    {" : ",\n    {";
  first_ = false;
  const Origin& o = e.origin;
  b += "\"block\":";
  if (o.block)
    text::append_integer(b, *o.block);
  else
    b += "null";
  bool arc = e.type == ElementType::kArc;
  if (arc) {
    append_next_key(b, ",\"ccw\":");
    b += e.ccw ? "true" : "false";
    append_next_key(b, ",\"center\":");
    append_point(b, e.center);
  }
  append_next_key(b, ",\"end\":");
  append_point(b, e.end);
  if (!e.rapid) {
    append_next_key(b, ",\"feed\":");
    if (e.feed != last_feed_ || last_feed_text_.empty()) {  // one feed runs over many elements
      last_feed_ = e.feed;
      last_feed_text_.clear();
      append_string(last_feed_text_, e.feed.to_string());
    }
    b += last_feed_text_;
    if (e.feed_type == FeedType::kG95) append_key(b, "feed_type"), b += "\"G95\"";
  }
  append_next_key(b, ",\"line\":");
  text::append_integer(b, o.line);
  append_next_key(b, ",\"origin\":");
  b += '{';
  bool inserted = o.insert.kind != InsertKind::kNone;  // NC-CONTOUR-*: an element the reader inserted
  if (inserted && o.insert.kind != InsertKind::kTurn)
    append_key(b, "corner_next_line"), text::append_integer(b, o.insert.next_line);
  if (inserted) append_key(b, "inserted"), append_string(b, insert_kind_name(o.insert.kind));
  append_key(b, "kind");
  append_string(b, origin_kind_name(o.kind));
  append_key(b, "line");
  text::append_integer(b, o.line);
  if (o.kind == OriginKind::kTransitionCircle) append_key(b, "next_line"), text::append_integer(b, o.next_line);
  if (o.sar != SarMove::kNone) append_key(b, "sar"), append_string(b, sar_move_name(o.sar));
  if (o.source != 0 && sources_) append_key(b, "source"), append_string(b, sources_(o.source));  // NC-PARAM-SUB-3
  text_.clear();
  append_description(text_, o);
  append_key(b, "text");
  append_string(b, text_);
  if (inserted && o.insert.kind == InsertKind::kTurn) append_key(b, "turn"), text::append_integer(b, o.insert.turn);
  b += '}';
  append_next_key(b, ",\"rapid\":");
  b += e.rapid ? "true" : "false";
  append_next_key(b, ",\"start\":");
  append_point(b, e.start);
  append_next_key(b, ",\"type\":");
  b += arc ? "\"arc\"" : "\"line\"";
  b += '}';
  written();
}

void JsonWriter::written() {
  if (buffer_.size() < (std::size_t{1} << 16)) return;
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

void JsonWriter::action(const ActionEvent& a) {
  append(actions_,
         json{{"line", a.line}, {"block", block_ref(a.block)}, {"function", a.function.name()}, {"at", point(a.at)}});
}

void JsonWriter::decision(const Decision& d) {
  if (!with_trace_) return;
  json j{{"clause", d.clause}, {"line", d.line}, {"branch", d.branch}};
  if (d.has_margin) {
    if (!d.margin_exact.empty())
      j["margin_exact"] = d.margin_exact;
    else
      j["margin"] = clean(d.margin);
  }
  append(decisions_, j);
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
  append(variables_, json{{"line", v.line},
                          {"block", block_ref(v.block)},
                          {"$P_APR", point(v.p_apr)},
                          {"$P_AEP", point(v.p_aep)},
                          {"$P_APDV", v.p_apdv}});
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
