#include "out/writers.hpp"

#include <charconv>

#include "out/shortest_number.hpp"

namespace ncoffset::out {

namespace {
// The longest CSV row: a line number (11), motion (2), 7 numbers of at most 32 characters
// (writeShortest), 8 commas and the newline.
constexpr size_t kMaxRow = 320;
}  // namespace

void appendJsonString(fmt::memory_buffer& b, std::string_view s) {
  b.push_back('"');
  for (char c : s) {
    auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      b.push_back('\\');
      b.push_back(c);
    } else if (u < 0x20 || u >= 0x7f) {
      fmt::format_to(fmt::appender(b), "\\u{:04x}", u);
    } else {
      b.push_back(c);
    }
  }
  b.push_back('"');
}

CsvWriter::CsvWriter(std::FILE* f) : w_(f) {
  fmt::format_to(fmt::appender(w_.buf()), "line,motion,x,y,z,cx,cy,cz,feed\n");
}

void CsvWriter::segment(const Segment& s) {
  // Written in place at the end of the buffer: room for 9 fields of at most 32 characters is
  // made first, the unused part is cut off after the row.
  auto& b = w_.buf();
  const size_t used = b.size();
  b.resize(used + kMaxRow);
  char* const row = b.data() + used;
  char* p = s.line >= 0 ? writeUnsigned(row, static_cast<unsigned>(s.line))
                        : std::to_chars(row, row + 11, s.line).ptr;
  const char* m = motionName(s.motion);
  *p++ = ',';
  *p++ = m[0];
  *p++ = m[1];
  for (double v : {s.end.x, s.end.y, s.end.z}) {
    *p++ = ',';
    p = writeShortest(p, v);
  }
  if (s.motion == Motion::G2 || s.motion == Motion::G3) {
    for (double v : {s.centre.x, s.centre.y, s.centre.z}) {
      *p++ = ',';
      p = writeShortest(p, v);
    }
  } else {
    *p++ = ',';
    *p++ = ',';
    *p++ = ',';
  }
  *p++ = ',';
  if (s.has_feed) p = writeShortest(p, s.feed);  // shortest round trip, as {fmt}'s "{}"
  *p++ = '\n';
  b.resize(used + static_cast<size_t>(p - row));
  w_.lineDone();
}

void CsvWriter::finish(const Alarm*) {
  w_.flush();
}

void JsonLinesWriter::segment(const Segment& s) {
  auto& b = w_.buf();
  auto it = fmt::appender(b);
  fmt::format_to(it, "{{\"line\":{},\"file\":", s.line);
  appendJsonString(b, names_(s.file));
  fmt::format_to(it, ",\"motion\":\"{}\",\"x\":{},\"y\":{},\"z\":{}", motionName(s.motion),
                 s.end.x + 0.0, s.end.y + 0.0, s.end.z + 0.0);
  if (s.motion == Motion::G2 || s.motion == Motion::G3)
    fmt::format_to(it, ",\"cx\":{},\"cy\":{},\"cz\":{},\"normal\":[{},{},{}],\"turns\":{}",
                   s.centre.x + 0.0, s.centre.y + 0.0, s.centre.z + 0.0, s.normal.x + 0.0,
                   s.normal.y + 0.0, s.normal.z + 0.0, s.turns);
  if (s.has_feed) fmt::format_to(it, ",\"feed\":{}", s.feed);
  fmt::format_to(it, "}}\n");
  w_.lineDone();
}

void JsonLinesWriter::message(const SourceLoc& where, const std::string& text) {
  auto& b = w_.buf();
  fmt::format_to(fmt::appender(b), "{{\"message\":");
  appendJsonString(b, text);
  fmt::format_to(fmt::appender(b), ",\"file\":");
  appendJsonString(b, where.file);
  fmt::format_to(fmt::appender(b), ",\"line\":{}}}\n", where.line);
  w_.lineDone();
}

void JsonLinesWriter::warning(const SourceLoc& where, int number, const std::string& text) {
  auto& b = w_.buf();
  fmt::format_to(fmt::appender(b), "{{\"warning\":{},\"file\":", number);
  appendJsonString(b, where.file);
  fmt::format_to(fmt::appender(b), ",\"line\":{},\"text\":", where.line);
  appendJsonString(b, text);
  fmt::format_to(fmt::appender(b), "}}\n");
  w_.lineDone();
}

void JsonLinesWriter::finish(const Alarm* alarm) {
  if (alarm) {
    auto& b = w_.buf();
    fmt::format_to(fmt::appender(b), "{{\"alarm\":{},\"file\":", alarm->number);
    appendJsonString(b, alarm->where.file);
    fmt::format_to(fmt::appender(b), ",\"line\":{},\"column\":{},\"text\":", alarm->where.line,
                   alarm->where.column);
    appendJsonString(b, alarm->text);
    fmt::format_to(fmt::appender(b), "}}\n");
  }
  w_.flush();
}

}  // namespace ncoffset::out
