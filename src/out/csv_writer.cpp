// The CSV writers (the contract of design.md), in their own translation unit: CsvWriter's row
// is the hot path of `ncoffset PROGRAM`, and GCC inlines writeShortest and writeUnsigned into
// it only while little else here calls them (keep it so: docs/performance.md).
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

#include "out/shortest_number.hpp"
#include "out/writers.hpp"

namespace ncoffset::out {

namespace {
// The longest CSV row: a line number (11), motion (at most 4), 7 numbers of at most 32 characters
// (writeShortest), 8 commas and the newline.
constexpr size_t kMaxRow = 320;
// With --decimals: numbers of at most kRoundedRoom characters (writeRounded).
static_assert(24 + 7 * kRoundedRoom <= kMaxRow);

// The byte of ",G0?" that holds the digit, as a 32-bit number's bits / 8 (CsvWriter::segment).
constexpr int kDigitByte = std::endian::native == std::endian::little ? 2 : 1;

constexpr const char* kHeader = "line,motion,x,y,z,cx,cy,cz,feed\n";

// ",v" at p; returns the end.
inline char* writeField(char* p, double v) {
  *p = ',';
  return writeShortest(p + 1, v);
}

}  // namespace

// v as writeShortest writes it; the memo's text when v equals its value (== : -0 and 0 are
// both "0", NaN never equals). The whole 32 bytes are copied both ways, one fixed-size move
// instead of a loop: the row has room for them (kMaxRow) and what lies past the number is
// overwritten by the next field or cut off.
inline char* CsvWriter::writeMemo(char* p, double v, Memo& m) {
  if (v == m.value) {
    std::memcpy(p, m.text, sizeof m.text);
    return p + m.len;
  }
  char* const end = writeShortest(p, v);
  m.value = v;
  m.len = static_cast<size_t>(end - p);
  std::memcpy(m.text, p, sizeof m.text);
  return end;
}

// The 16 bytes of the text are copied at once (the row has room, as for writeMemo). A line
// number is at most 11 characters ("-2147483648"); negative ones are written anew each time.
inline char* CsvWriter::writeLine(char* p, int line) {
  LineMemo& m = line_;
  if (line == m.value + 1) [[likely]] {
    m.value = line;
    char& last = m.text[m.len - 1];
    if (last != '9') [[likely]]
      ++last;
    else
      carry(m);
  } else if (line != m.value) {
    char* const end = line >= 0 ? writeUnsigned(m.text, static_cast<unsigned>(line))
                                : std::to_chars(m.text, m.text + 11, line).ptr;
    m.len = static_cast<size_t>(end - m.text);
    m.value = line >= 0 ? line : LineMemo::kNone;
  }
  const size_t len = m.len;  // (read before the copy: a store through `p` may alias it)
  std::memcpy(p, m.text, sizeof m.text);
  return p + len;
}

void CsvWriter::carry(LineMemo& m) {
  // "199" + 1 -> "200"; all nines ("999") became zeros and get a leading one ("1000").
  char* d = m.text + m.len - 1;
  while (*d == '9' && d != m.text) *d-- = '0';
  if (*d != '9') {
    ++*d;
    return;
  }
  *d = '1';
  m.text[m.len++] = '0';
}

CsvWriter::CsvWriter(std::FILE* f) : w_(f) {
  fmt::format_to(fmt::appender(w_.buf()), kHeader);
  allocateRows();
}

// Room for the rows up to kRowsFlush and one row more (its 9 fields and the axes' fields).
void CsvWriter::allocateRows() {
  rows_.reset(new char[kRowsFlush + kMaxRow + axis_room_]);  // (not zeroed: written before read)
  rows_end_ = rows_.get();
  rows_flush_ = rows_.get() + kRowsFlush;
}

void CsvWriter::flushRows(bool sync) {
  if (rows_end_ == rows_.get()) {
    if (sync) w_.flush();
    return;
  }
  w_.write(rows_.get(), static_cast<size_t>(rows_end_ - rows_.get()), sync);
  rows_end_ = rows_.get();
}

void CsvWriter::segment(const Segment& s) {
  // Written in place at the end of the rows (room for one more: allocateRows).
  char* const row = rows_end_;
  char* p = writeLine(row, s.line);
  // (The motion read once: a store through `p` may alias the segment, §40.)
  const Motion motion = s.motion;
  static_assert(static_cast<int>(Motion::G0) == 0 && static_cast<int>(Motion::G3) == 3);
  if (motion <= Motion::G3) [[likely]] {  // G0..G3: the digit is the enum's value, no call
    // ",G0" and a fourth byte (overwritten by the next field) as one number, the digit added
    // to it: one store (the bytes in memory order, as the row has them).
    const char g0[4] = {',', 'G', '0', 0};
    std::uint32_t field;
    std::memcpy(&field, g0, 4);
    field += static_cast<std::uint32_t>(motion) << (kDigitByte * 8);
    std::memcpy(p, &field, 4);
    p += 3;
  } else {  // G33, G331, G63, ...
    *p++ = ',';
    for (const char* c = motionName(motion); *c; ++c) *p++ = *c;
  }
  // (Written out, not a loop over an initializer list: that copied the three values first.)
  p = writeField(p, s.end.x);
  p = writeField(p, s.end.y);
  *p++ = ',';
  p = writeMemo(p, s.end.z, z_);  // z mostly as in the row before
  if (motion == Motion::G2 || motion == Motion::G3) {
    p = writeField(p, s.centre.x);
    p = writeField(p, s.centre.y);
    *p++ = ',';
    p = writeMemo(p, s.centre.z, z_);  // in the plane: mostly z
  } else {
    *p++ = ',';
    *p++ = ',';
    *p++ = ',';
  }
  *p++ = ',';
  if (s.has_feed) p = writeMemo(p, s.feed, feed_);  // shortest round trip, as {fmt}'s "{}"
  if (axis_room_) [[unlikely]]
    p = writeAxes(p);
  *p++ = '\n';
  rows_end_ = p;
  if (p >= rows_flush_) [[unlikely]]
    flushRows();
}

void CsvWriter::finish(const Alarm*) {
  flushRows(true);
}

bool extendCsvHeader(BufferedWriter& w, AxisColumns& axes, const std::vector<std::string>& names) {
  auto& b = w.buf();
  const std::string_view header(kHeader);
  if (w.wrote() || b.size() != header.size()) return false;  // rows of an init file: keep them
  axes.announce(names);
  b.clear();
  fmt::format_to(fmt::appender(b), "{}{}\n", header.substr(0, header.size() - 1), axes.header());
  return true;
}

void CsvWriter::axisNames(const std::vector<std::string>& names) {
  if (rows_end_ != rows_.get()) return;  // rows of an init file: keep the header
  if (!extendCsvHeader(w_, axes_, names)) return;
  axis_room_ = 33 * names.size();
  allocateRows();
}

char* CsvWriter::writeAxes(char* p) const {
  for (double v : axes_.positions) {
    *p++ = ',';
    p = writeShortest(p, v + 0.0);
  }
  return p;
}

RoundedCsvWriter::RoundedCsvWriter(std::FILE* f, int decimals) : w_(f), decimals_(decimals) {
  fmt::format_to(fmt::appender(w_.buf()), kHeader);
}

void RoundedCsvWriter::segment(const Segment& s) {
  char row[kMaxRow];
  char* p = std::to_chars(row, row + 11, s.line).ptr;
  const char* m = motionName(s.motion);
  *p++ = ',';
  *p++ = m[0];
  *p++ = m[1];
  if (m[2] != 0) [[unlikely]]  // G33, G331, G63, ...
    for (const char* c = m + 2; *c; ++c) *p++ = *c;
  const bool arc = s.motion == Motion::G2 || s.motion == Motion::G3;
  for (int i = 0; i < 6; ++i) {  // the end point; the centre of an arc, else empty fields
    *p++ = ',';
    if (i < 3) p = writeRounded(p, s.end[i], decimals_);
    if (i >= 3 && arc) p = writeRounded(p, s.centre[i - 3], decimals_);
  }
  *p++ = ',';
  if (s.has_feed) p = writeRounded(p, s.feed, decimals_);
  w_.buf().append(row, p);
  for (double v : axes_.positions) {  // the additional axes (none: no loop)
    char field[kRoundedRoom + 1];
    field[0] = ',';
    w_.buf().append(field, writeRounded(field + 1, v + 0.0, decimals_));
  }
  w_.buf().push_back('\n');
  w_.lineDone();
}

void RoundedCsvWriter::finish(const Alarm*) {
  w_.flush();
}

}  // namespace ncoffset::out
