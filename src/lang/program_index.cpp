#include "lang/program_index.hpp"

#include <fmt/format.h>

#include <bit>
#include <vector>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "core/cpu_features.hpp"
#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {
namespace {

std::string_view closerOf(std::string_view opener) {
  if (opener == "IF") return "ENDIF";
  if (opener == "WHILE") return "ENDWHILE";
  if (opener == "FOR") return "ENDFOR";
  if (opener == "REPEAT") return "UNTIL";
  return "ENDLOOP";
}

// The normalized line buffer is reused, so openers are kept as views of static strings.
std::string_view staticKeyword(std::string_view kw) {
  static constexpr std::string_view kOpeners[] = {"IF", "WHILE", "FOR", "REPEAT", "LOOP"};
  for (auto o : kOpeners)
    if (o == kw) return o;
  return {};
}

bool isLetter(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
bool isDigitChar(char c) {
  return c >= '0' && c <= '9';
}

// Fast rejection without normalising: a block whose first word (after "/", the block number)
// is a letter followed by a digit (G1, X10, N20) cannot start with a label or a control
// keyword, which both begin with two letters or an underscore. Nor can an empty or comment line.
bool mayHoldHead(std::string_view s) {
  size_t i = 0, n = s.size();
  // The usual line first (G1 X10): an upper-case letter other than N, then a digit.
  if (n >= 2 && s[0] >= 'A' && s[0] <= 'Z' && s[0] != 'N' && isDigitChar(s[1])) return false;
  auto spaces = [&] {
    while (i < n && (s[i] == ' ' || s[i] == '\t')) ++i;
  };
  spaces();
  if (i < n && s[i] == '/') {
    ++i;
    if (i < n && isDigitChar(s[i])) ++i;
    spaces();
  }
  if (i + 1 < n && (s[i] == 'N' || s[i] == 'n' || s[i] == ':') && isDigitChar(s[i + 1])) {
    ++i;
    while (i < n && isDigitChar(s[i])) ++i;
    spaces();
  }
  if (i >= n || s[i] == ';') return false;
  if (isLetter(s[i]) && i + 1 < n && isDigitChar(s[i + 1])) return false;
  return true;
}

// mayHoldHead's answer for a line that starts with a block number (N10 G1 X10): false when a
// letter and a digit follow the number and its blanks, which the vector scan of
// program_index_scan.inc checks for the lines it cannot pass over (a block number's length
// varies). Reads no further than `end` and stops at the line's end, which is no digit, blank
// or letter: a line it passes over is one mayHoldHead passes over.
[[gnu::always_inline]] inline bool numberedUsualLine(const char* p, const char* end) {
  if (end - p < 2 || p[0] != 'N' || !isDigitChar(p[1])) return false;
  p += 2;
  while (p < end && isDigitChar(*p)) ++p;
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  return end - p >= 2 && isLetter(p[0]) && isDigitChar(p[1]);
}

#if defined(__SSE2__)
// The vector operations of the usual-line scan, for 16 characters (SSE2) and, where the processor
// has it, 32 (AVX2): the scan below is written once for both.
struct Sse2 {
  using V = __m128i;
  static constexpr size_t kWidth = 16;
  static V load(const char* p) { return _mm_loadu_si128(reinterpret_cast<const V*>(p)); }
  static V set(char c) { return _mm_set1_epi8(c); }
  static V zero() { return _mm_setzero_si128(); }
  static V eq(V a, V b) { return _mm_cmpeq_epi8(a, b); }
  static V sub(V a, V b) { return _mm_sub_epi8(a, b); }
  static V add(V a, V b) { return _mm_add_epi8(a, b); }
  static V min(V a, V b) { return _mm_min_epu8(a, b); }
  static V andV(V a, V b) { return _mm_and_si128(a, b); }
  static V andNot(V a, V b) { return _mm_andnot_si128(a, b); }
  static unsigned mask(V a) { return static_cast<unsigned>(_mm_movemask_epi8(a)); }
  // The sum of the bytes of -a (the lanes count newlines as -1 each).
  static long long sumNegated(V a) {
    const V s8 = _mm_sad_epu8(sub(zero(), a), zero());
    return _mm_cvtsi128_si32(s8) + _mm_cvtsi128_si32(_mm_srli_si128(s8, 8));
  }
};

#if defined(__x86_64__) && defined(__GNUC__)
#define NCOFFSET_AVX2 [[gnu::target("avx2")]]
struct Avx2 {
  using V = __m256i;
  static constexpr size_t kWidth = 32;
  NCOFFSET_AVX2 static V load(const char* p) {
    return _mm256_loadu_si256(reinterpret_cast<const V*>(p));
  }
  NCOFFSET_AVX2 static V set(char c) { return _mm256_set1_epi8(c); }
  NCOFFSET_AVX2 static V zero() { return _mm256_setzero_si256(); }
  NCOFFSET_AVX2 static V eq(V a, V b) { return _mm256_cmpeq_epi8(a, b); }
  NCOFFSET_AVX2 static V sub(V a, V b) { return _mm256_sub_epi8(a, b); }
  NCOFFSET_AVX2 static V add(V a, V b) { return _mm256_add_epi8(a, b); }
  NCOFFSET_AVX2 static V min(V a, V b) { return _mm256_min_epu8(a, b); }
  NCOFFSET_AVX2 static V andV(V a, V b) { return _mm256_and_si256(a, b); }
  NCOFFSET_AVX2 static V andNot(V a, V b) { return _mm256_andnot_si256(a, b); }
  NCOFFSET_AVX2 static unsigned mask(V a) { return static_cast<unsigned>(_mm256_movemask_epi8(a)); }
  NCOFFSET_AVX2 static long long sumNegated(V a) {
    const V s8 = _mm256_sad_epu8(sub(zero(), a), zero());
    return _mm256_extract_epi64(s8, 0) + _mm256_extract_epi64(s8, 1) + _mm256_extract_epi64(s8, 2) +
           _mm256_extract_epi64(s8, 3);
  }
};
#endif

// The scan itself (program_index_scan.inc), once for each width: the AVX2 one must carry the
// target attribute on each of its functions, which a template cannot take from its argument.
#define NCOFFSET_SCAN_WIDTH Sse2
#define NCOFFSET_SCAN_TARGET
#define NCOFFSET_SCAN_NAME skipUsualLinesSse2
#define NCOFFSET_SCAN_UNUSUAL unusualLineStartsSse2
#include "lang/program_index_scan.inc"
#if defined(NCOFFSET_AVX2)
#define NCOFFSET_SCAN_WIDTH Avx2
#define NCOFFSET_SCAN_TARGET NCOFFSET_AVX2
#define NCOFFSET_SCAN_NAME skipUsualLinesAvx2
#define NCOFFSET_SCAN_UNUSUAL unusualLineStartsAvx2
#include "lang/program_index_scan.inc"
#endif
#endif

// The usual lines passed over 32 characters at a time where the processor has AVX2 (asked
// once), otherwise 16;
// without SSE2 no line is skipped here (extend tests each one).
TextPos skipUsualLines(std::string_view text, TextPos pos) {
#if defined(NCOFFSET_AVX2)
  static const bool avx2 = core::cpuHasAvx2();
  if (avx2 && ProgramIndex::wide_scan) return skipUsualLinesAvx2(text, pos);
#endif
#if defined(__SSE2__)
  return skipUsualLinesSse2(text, pos);
#else
  static_cast<void>(text);
  return pos;
#endif
}

}  // namespace

ProgramIndex::ProgramIndex(const SourceFile& file, int max_depth, size_t max_line_length,
                           TextPos begin, size_t end)
    : max_depth_(max_depth), max_line_length_(max_line_length), scanned_(begin), end_(end) {
  extend(file);
  if (!file.growing()) finish();
}

void ProgramIndex::extend(const SourceFile& file) {
  std::string_view text = file.text();
  if (end_ < text.size()) text = text.substr(0, end_);
  std::string_view line;
  std::string norm;
  while (true) {
    // The usual lines up to the next MiB (the released pages follow it), at once.
    const size_t mib = (scanned_.offset | 0xFFFFF) + 1;
    const TextPos skipped =
        skipUsualLines(text.substr(0, std::min(text.size(), mib + 34)), scanned_);
    if (skipped.offset >= mib) file.releaseBefore(mib);
    scanned_ = skipped;
    TextPos here = scanned_;
    if (!nextLine(text, scanned_, line)) break;
    if ((scanned_.offset & 0xFFFFF) < line.size() + 1) file.releaseBefore(here.offset);
    if (line.size() > max_line_length_) continue;  // reported when executed
    if (!mayHoldHead(line)) continue;              // the usual line: no call
    if (line.front() == '%' && here.offset > 0 && file.fed()) {
      // A fed text archive: the program ends before its second header, as the archived
      // program's range does when the whole text is loaded (docs/architecture.md "Streaming").
      end_ = here.offset;
      break;
    }
    scanLine(here, line, norm);
  }
  file.releaseAll();
}

void ProgramIndex::finish() const {
  if (!stack_.empty()) {
    const Open& o = stack_.back();
    throw AlarmError(AlarmNumber::ControlNesting,
                     fmt::format("invalid nesting of control structures: {} without {}", o.keyword,
                                 closerOf(o.keyword)),
                     o.pos.line);
  }
}

void ProgramIndex::scanLine(TextPos here, std::string_view line, std::string& norm) {
  std::vector<Open>& stack = stack_;
  // Only the head of a line matters, except for IF (which may be a jump).
  std::string_view head = line.substr(0, 96);
  if (!normalizeLine(head, norm, nullptr)) return;
  LineHead h = scanLineHead(norm);
  if (h.keyword == "IF" && line.size() > head.size()) {
    if (!normalizeLine(line, norm, nullptr)) return;
    h = scanLineHead(norm);
  }
  if (!h.label.empty()) {
    auto it = labels_.find(h.label);
    if (it == labels_.end())
      it = labels_.emplace(std::string(h.label), std::vector<TextPos>{}).first;
    it->second.push_back(here);
  }
  std::string_view kw = h.keyword;
  if (kw.empty()) return;
  if (kw == "IF" && h.has_goto) return;
  // REPEAT with a label after it repeats a program section (PM-JP "Program section
  // repetition"); only the bare REPEAT opens a REPEAT..UNTIL loop.
  if (kw == "REPEAT" && h.has_arguments) return;
  if (kw == "IF" || kw == "WHILE" || kw == "FOR" || kw == "REPEAT" || kw == "LOOP") {
    if (static_cast<int>(stack.size()) >= max_depth_)
      throw AlarmError(
          AlarmNumber::ControlDepth,
          fmt::format("nesting depth of control structures exceeded (limit {})", max_depth_),
          here.line);
    stack.push_back({staticKeyword(kw), here, {}, false});
    return;
  }
  if (kw == "ELSE") {
    if (stack.empty() || stack.back().keyword != "IF" || stack.back().has_else)
      throw AlarmError(AlarmNumber::ControlNesting,
                       "invalid nesting of control structures: ELSE without IF", here.line);
    stack.back().has_else = true;
    stack.back().else_pos = here;
    return;
  }
  if (kw == "ENDIF" || kw == "ENDWHILE" || kw == "ENDFOR" || kw == "UNTIL" || kw == "ENDLOOP") {
    if (stack.empty() || closerOf(stack.back().keyword) != kw)
      throw AlarmError(
          AlarmNumber::ControlNesting,
          fmt::format("invalid nesting of control structures: {} {}", kw,
                      stack.empty() ? std::string("without opening statement")
                                    : fmt::format("closes {} of line {}", stack.back().keyword,
                                                  stack.back().pos.line)),
          here.line);
    Open o = stack.back();
    stack.pop_back();
    if (o.keyword == "IF") {
      links_[o.pos.offset] = {o.has_else ? o.else_pos : here, here};
      if (o.has_else) links_[o.else_pos.offset] = {here, here};
    } else {
      links_[o.pos.offset] = {here, here};
    }
    links_[here.offset] = {o.pos, o.pos};
  }
}

}  // namespace ncoffset::lang
