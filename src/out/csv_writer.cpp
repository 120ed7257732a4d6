// The CSV writers (the contract of design.md), in their own translation unit: CsvWriter's row
// is the hot path of `ncoffset PROGRAM`, and GCC inlines writeShortest and writeUnsigned into
// it only while little else here calls them (keep it so: docs/performance.md).
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

#include "core/inline_step.hpp"
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
// both "0", NaN never equals). The memo's 16 bytes are copied both ways, one fixed-size move
// instead of a loop: the row has room for them (kMaxRow) and what lies past the number is
// overwritten by the next field or cut off. A longer number is not kept (the memo then equals
// no value; 16 bytes rather than writeShortest's 32: one move each way, §43).
inline char* CsvWriter::writeMemo(char* p, double v, Memo& m) {
  if (v == m.value) {
    std::memcpy(p, m.text, sizeof m.text);
    return p + m.len;
  }
  char* const end = writeShortest(p, v);
  m.len = static_cast<size_t>(end - p);
  m.value = m.len <= sizeof m.text ? v : std::numeric_limits<double>::quiet_NaN();
  std::memcpy(m.text, p, sizeof m.text);
  return end;
}

// The memo's next line: its last digit incremented in place; "199" + 1 -> "200", and all nines
// ("999") became zeros and get a leading one ("1000"). Inline, no call (§43).
inline void CsvWriter::increment(LineMemo& m) {
  ++m.value;
  char* d = m.text + m.len - 1;
  if (*d != '9') [[likely]] {
    ++*d;
    return;
  }
  while (*d == '9' && d != m.text) *d-- = '0';
  if (*d != '9') {
    ++*d;
    return;
  }
  *d = '1';
  m.text[m.len++] = '0';
}

// The 16 bytes of the text are copied at once (the row has room, as for writeMemo). A line
// number is at most 11 characters ("-2147483648"); negative ones are written anew each time, and
// every one while there are additional axes.
inline char* CsvWriter::writeLine(char* p, int line) {
  LineMemo& m = line_;
  if (line == m.value + 1) [[likely]] {
    increment(m);
  } else if (line != m.value) {
    char* const end = line >= 0 ? writeUnsigned(m.text, static_cast<unsigned>(line))
                                : std::to_chars(m.text, m.text + 11, line).ptr;
    m.len = static_cast<size_t>(end - m.text);
    m.value = line >= 0 && axis_room_ == 0 ? line : LineMemo::kNone;  // (row's usual test)
  }
  const size_t len = m.len;  // (read before the copy: a store through `p` may alias it)
  std::memcpy(p, m.text, sizeof m.text);
  return p + len;
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

// "," at p (an empty field); returns the end.
inline char* writeEmpty(char* p) {
  *p = ',';
  return p + 1;
}

// ",v" at p for |v| < 10000 with at most six decimals, else nullptr (no call; a whole number's
// comma from the table, §51).
NCOFFSET_INLINE_STEP char* writeSmallField(char* p, double v) {
  return writeFixed<true, true>(p, v);
}

// writeMemo of a field (",v") for row()'s usual row: a new value by writeSmallField (at most 13
// characters, ",-9999.999999"), else nullptr. (Its own memos: generalRow's hold no comma.)
NCOFFSET_INLINE_STEP char* CsvWriter::writeSmallMemo(char* p, double v, Memo& m) {
  if (v == m.value) {
    std::memcpy(p, m.text, sizeof m.text);
    return p + m.len;
  }
  char* const end = writeSmallField(p, v);
  if (!end) return nullptr;
  m.len = static_cast<size_t>(end - p);
  m.value = v;
  std::memcpy(m.text, p, sizeof m.text);
  return end;
}

// The usual row's end after y for a line (not an arc): ",z,,,,feed\n", the row before's while
// z, the feed and whether there is one are as then (two moves, §51), else written and kept
// (at most 30 characters: 13 + 3 + 13 + 1). nullptr: z or the feed is no small number.
NCOFFSET_INLINE_STEP char* CsvWriter::writeLineTail(char* p, double z, bool has_feed, double feed) {
  TailMemo& t = tail_;
  if (z == t.z && feed == t.feed && has_feed == t.has_feed) {
    std::memcpy(p, t.text, sizeof t.text);
    return p + t.len;
  }
  char* e = writeSmallMemo(p, z, zf_);
  if (!e) return nullptr;
  std::memcpy(e, ",,,,", 4);  // the centre's three empty fields, and the feed's comma
  e = has_feed ? writeSmallMemo(e + 3, feed, feedf_) : e + 4;
  if (!e) return nullptr;
  *e++ = '\n';
  t.len = static_cast<size_t>(e - p);
  t.z = z;
  t.feed = feed;
  t.has_feed = has_feed;
  std::memcpy(t.text, p, sizeof t.text);
  return e;
}

void CsvWriter::segment(const Segment& s) {
  row(s.line, s.motion, s.has_feed, s.end.x, s.end.y, s.end.z, s.centre.x, s.centre.y, s.centre.z,
      s.feed);
}

void CsvWriter::row(int line, Motion motion, bool has_feed, double x, double y, double z, double cx,
                    double cy, double cz, double feed) {
  // The usual row: the line of the row before or the next one, G0..G3, z, an arc
  // centre's z and the feed as in the memos, no additional axes, numbers below 10000 with at
  // most six decimals. Written without a call (so without registers to save: 17 instructions a
  // row, docs/performance.md §43); any other row by generalRow from the row's start.
  const bool arc = motion == Motion::G2 || motion == Motion::G3;
  LineMemo& l = line_;
  const bool next = line == l.value + 1;  // (l.len > 0 then)
  // (With additional axes the line's memo holds no line: never usual, without a test of them.)
  const bool usual = motion <= Motion::G3 && (next || line == l.value);
  if (!usual) [[unlikely]]
    return generalRow(line, motion, has_feed, x, y, z, cx, cy, cz, feed);
  if (next) [[likely]]
    increment(l);
  char* p = rows_end_;
  std::memcpy(p, l.text, sizeof l.text);
  p += l.len;
  p = writeMotion(p, motion);
  p = writeSmallField(p, x);
  if (p) p = writeSmallField(p, y);
  if (!p) [[unlikely]]  // (the line's memo holds this line now: written again as it is)
    return generalRow(line, motion, has_feed, x, y, z, cx, cy, cz, feed);
  if (!arc) {
    p = writeLineTail(p, z, has_feed, feed);
  } else {
    p = writeSmallMemo(p, z, zf_);
    if (p) p = writeSmallField(p, cx);
    if (p) p = writeSmallField(p, cy);
    if (p) p = writeSmallMemo(p, cz, zf_);  // in the plane: mostly z
    if (p) p = has_feed ? writeSmallMemo(p, feed, feedf_) : writeEmpty(p);
    if (p) *p++ = '\n';
  }
  if (!p) [[unlikely]]
    return generalRow(line, motion, has_feed, x, y, z, cx, cy, cz, feed);
  rows_end_ = p;
  if (p >= rows_flush_) [[unlikely]]
    flushRows();
}

// ",G0" ... ",G3" (one store) or ",G33", ",G331", ...
inline char* CsvWriter::writeMotion(char* p, Motion motion) {
  static_assert(static_cast<int>(Motion::G0) == 0 && static_cast<int>(Motion::G3) == 3);
  if (motion <= Motion::G3) [[likely]] {  // G0..G3: the digit is the enum's value, no call
    // ",G0" and a fourth byte (overwritten by the next field) as one number, the digit added
    // to it: one store (the bytes in memory order, as the row has them).
    const char g0[4] = {',', 'G', '0', 0};
    std::uint32_t field;
    std::memcpy(&field, g0, 4);
    field += static_cast<std::uint32_t>(motion) << (kDigitByte * 8);
    std::memcpy(p, &field, 4);
    return p + 3;
  }
  *p++ = ',';  // G33, G331, G63, ...
  for (const char* c = motionName(motion); *c; ++c) *p++ = *c;
  return p;
}

// Any row (row's general twin).
void CsvWriter::generalRow(int line, Motion motion, bool has_feed, double x, double y, double z,
                           double cx, double cy, double cz, double feed) {
  // Written in place at the end of the rows (room for one more: allocateRows).
  char* p = writeLine(rows_end_, line);
  p = writeMotion(p, motion);
  p = writeField(p, x);
  p = writeField(p, y);
  *p++ = ',';
  p = writeMemo(p, z, z_);  // z mostly as in the row before
  if (motion == Motion::G2 || motion == Motion::G3) {
    p = writeField(p, cx);
    p = writeField(p, cy);
    *p++ = ',';
    p = writeMemo(p, cz, z_);  // in the plane: mostly z
  } else {
    *p++ = ',';
    *p++ = ',';
    *p++ = ',';
  }
  *p++ = ',';
  if (has_feed) p = writeMemo(p, feed, feed_);  // shortest round trip, as {fmt}'s "{}"
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
  line_ = LineMemo{};  // (no line while there are axes: row() takes none as usual)
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
