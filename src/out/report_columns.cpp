#include "out/report_columns.hpp"

#include "out/arc_geometry.hpp"
#include "out/shortest_number.hpp"

namespace ncoffset::out {

Spool::~Spool() {
  if (file_) std::fclose(file_);
}

void Spool::spill() {
  if (!file_) file_ = std::tmpfile();
  if (!file_) return;  // no temporary file: keep the data in memory
  std::fwrite(buf_.data(), 1, buf_.size(), file_);
  buf_.clear();
}

void Spool::copyTo(fmt::memory_buffer& b, std::FILE* out) {
  b.push_back('[');
  if (file_) {
    std::fwrite(b.data(), 1, b.size(), out);
    b.clear();
    std::rewind(file_);
    char chunk[1 << 16];
    size_t n = 0;
    while ((n = std::fread(chunk, 1, sizeof chunk, file_)) > 0) std::fwrite(chunk, 1, n, out);
  }
  b.append(buf_.data(), buf_.data() + buf_.size());
  b.push_back(']');
}

void PathColumns::number(fmt::memory_buffer& b, double v) const {
  fmt::format_to(fmt::appender(b), "{}", Number{v + 0.0, decimals_});
}

void PathColumns::add(const Segment& s, int tool, bool same) {
  const long long i = count_++;
  fmt::format_to(fmt::appender(lines_.element()), "{}", s.line - last_line_);
  last_line_ = s.line;
  // The start is written where it is not the end point before (the first segment's always).
  const bool start =
      i == 0 || s.start.x != last_end_.x || s.start.y != last_end_.y || s.start.z != last_end_.z;
  // Bits 0-1 the drawn motion (a thread or tapping line is drawn as G1), 2 feed, 3 start, 4 the
  // same as programmed, 5 a thread line, 6-8 which one (G33 .. G63, docs/threads.md).
  const int m = static_cast<int>(s.motion);
  const int drawn = isThreadMotion(s.motion) ? 1 : m;
  const int thread = isThreadMotion(s.motion) ? 32 + ((m - 4) << 6) : 0;
  int kind = drawn + (s.has_feed ? 4 : 0) + (start ? 8 : 0) + (same ? 16 : 0) + thread;
  fmt::format_to(fmt::appender(kinds_.element()), "{}", kind);
  number(x_.element(), s.end.x);
  number(y_.element(), s.end.y);
  number(z_.element(), s.end.z);
  last_end_ = s.end;
  const double feed = s.has_feed ? s.feed : 0;
  if (s.file != last_file_ || tool != last_tool_ || feed != last_feed_ ||
      s.feed_unit != last_unit_) {
    auto& b = runs_.element();
    fmt::format_to(fmt::appender(b), "[{},{},{},", i, s.file, tool);
    number(b, feed);
    fmt::format_to(fmt::appender(b), ",{}]", static_cast<int>(s.feed_unit));
    last_file_ = s.file, last_tool_ = tool, last_feed_ = feed, last_unit_ = s.feed_unit;
  }
  if (isArc(s)) {
    auto& b = arcs_.element();
    fmt::format_to(fmt::appender(b), "[{}", i);
    for (double v : {s.centre.x, s.centre.y, s.centre.z, s.normal.x, s.normal.y, s.normal.z}) {
      b.push_back(',');
      number(b, v);
    }
    fmt::format_to(fmt::appender(b), ",{}]", s.turns);
  }
  if (start) {
    auto& b = starts_.element();
    fmt::format_to(fmt::appender(b), "[{}", i);
    for (double v : {s.start.x, s.start.y, s.start.z}) {
      b.push_back(',');
      number(b, v);
    }
    b.push_back(']');
  }
}

void PathColumns::copyTo(fmt::memory_buffer& b, std::FILE* out) {
  const char* names[] = {"L", "K", "X", "Y", "Z", "R", "A", "S"};
  Spool* spools[] = {&lines_, &kinds_, &x_, &y_, &z_, &runs_, &arcs_, &starts_};
  b.push_back('{');
  for (size_t k = 0; k < 8; ++k) {
    fmt::format_to(fmt::appender(b), "{}\"{}\":", k ? "," : "", names[k]);
    spools[k]->copyTo(b, out);
  }
  b.push_back('}');
}

void appendScriptString(fmt::memory_buffer& b, std::string_view s, bool quoted) {
  if (quoted) b.push_back('"');
  for (char c : s) {
    auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      b.push_back('\\');
      b.push_back(c);
    } else if (c == '\n') {
      b.append(std::string_view("\\n"));
    } else if (u < 0x20 || c == '<' || u == 0x7f) {
      fmt::format_to(fmt::appender(b), "\\u{:04x}", u);
    } else {
      b.push_back(c);
    }
  }
  if (quoted) b.push_back('"');
}

}  // namespace ncoffset::out
