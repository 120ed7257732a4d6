#include "lang/program_index.hpp"

#include <fmt/format.h>

#include <bit>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

#if defined(__SSE2__)
// The newlines of the 16 characters at `s` whose line is not the usual line of mayHoldHead's
// first test (an upper-case letter other than N, then a digit), as bits; reads s[0..17].
int unusualLineStarts(const char* s, __m128i& newlines) {
  const auto load = [](const char* p) {
    return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  };
  const __m128i after = load(s + 1), second = load(s + 2);
  newlines = _mm_cmpeq_epi8(load(s), _mm_set1_epi8('\n'));
  const __m128i letter = _mm_sub_epi8(after, _mm_set1_epi8('A'));  // 0..25 for A..Z
  const __m128i upper =
      _mm_andnot_si128(_mm_cmpeq_epi8(after, _mm_set1_epi8('N')),
                       _mm_cmpeq_epi8(_mm_min_epu8(letter, _mm_set1_epi8(25)), letter));
  const __m128i digit = _mm_sub_epi8(second, _mm_set1_epi8('0'));  // 0..9 for 0..9
  const __m128i is_digit = _mm_cmpeq_epi8(_mm_min_epu8(digit, _mm_set1_epi8(9)), digit);
  return _mm_movemask_epi8(_mm_andnot_si128(_mm_and_si128(upper, is_digit), newlines));
}
#endif

// From the line at `pos`, the first line that mayHoldHead's first test does not pass over
// (the usual line, G1 X10, which can hold no label and no control keyword), or the last line
// start before the end of `text` that could be told; `pos` itself when its line is not usual.
// Sixteen characters at a time (SSE2) instead of a memchr and a test for every line: the
// pre-scan was 67 instructions a block of the issue 22 contour (docs/performance.md section
// 34). Without SSE2 no line is skipped here (extend tests each one).
TextPos skipUsualLines(std::string_view text, TextPos pos) {
#if defined(__SSE2__)
  const char* const s = text.data();
  const size_t n = text.size(), begin = pos.offset;
  if (begin + 18 > n || s[begin] < 'A' || s[begin] > 'Z' || s[begin] == 'N' ||
      !isDigitChar(s[begin + 1]))
    return pos;
  size_t i = begin;
  long long lines = 0;
  // Newlines passed, per byte lane (-1 each, so at most 255 groups between two sums).
  __m128i lanes = _mm_setzero_si128();
  const auto sum = [&] {
    const __m128i s8 = _mm_sad_epu8(_mm_sub_epi8(_mm_setzero_si128(), lanes), _mm_setzero_si128());
    lines += _mm_cvtsi128_si32(s8) + _mm_cvtsi128_si32(_mm_srli_si128(s8, 8));
    lanes = _mm_setzero_si128();
  };
  __m128i newlines;
  for (int groups = 0; i + 18 <= n; i += 16) {
    if (const int unusual = unusualLineStarts(s + i, newlines); unusual != 0) {
      sum();
      const int at = std::countr_zero(static_cast<unsigned>(unusual));
      const unsigned before = static_cast<unsigned>(_mm_movemask_epi8(newlines)) & ((1u << at) - 1);
      return {i + static_cast<size_t>(at) + 1,
              pos.line + static_cast<int>(lines + std::popcount(before) + 1)};
    }
    lanes = _mm_add_epi8(lanes, newlines);
    if (++groups == 255) {
      sum();
      groups = 0;
    }
  }
  sum();
  // Back to the start of the line that the last group ended in (every newline counted is
  // before it).
  size_t start = i;
  while (start > begin && s[start - 1] != '\n') --start;
  return {start, pos.line + static_cast<int>(lines)};
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
        skipUsualLines(text.substr(0, std::min(text.size(), mib + 18)), scanned_);
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
