// The per-block fast paths of the interpreter for the blocks CAM systems write (docs/performance.md
// sections 25, 27, 30 and 53): plain blocks (Parser::simpleWords) collected without looking at
// statement kinds, and plain lines of X, Y, Z, G0..G3, F, CR=, I, J and K words collected as they
// are scanned, with no statement at all; the usual plain line is even read by its word scan, which
// finds the line's end itself (lineInPlace, section 44). Each hands whatever it does not know to
// the general path; tests/interp/fast_path_test.cpp compares them with it.

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <new>

#include "core/inline_step.hpp"
#include "interp/interpreter.hpp"
#include "lang/line_copy.hpp"
#include "lang/number_scan.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

// The commonest words of plain blocks collected inline: X, Y, Z, G0..G3, G40..G42, F, CR= and
// I, J, K (a circle's centre), as letterWord, gCode and extendedWord collect them, without the
// call; a G word sets `motion` or `trc` (G group 7, as gCompensation does). False: collectWord
// takes the word (and raises any alarm).
NCOFFSET_INLINE_STEP bool Interpreter::plainWord(std::string_view name, double value, bool is_int,
                                                 Motion& motion, core::TrcMode& trc) {
  if (name.size() != 1) return name == "CR" && plainRadius(value);
  const char c = name[0];
  if (c >= 'X' && c <= 'Z') return plainAxis(c - 'X', value);
  if (c == 'G') return plainG(value, is_int, motion, trc);
  if (c >= 'I' && c <= 'K') return plainCentre(c - 'I', value);
  return c == 'F' && plainFeed(value);
}

// F of plainWord and plainLineWord: false beyond 0..1e9, where collectWord raises the alarm.
NCOFFSET_INLINE_STEP bool Interpreter::plainFeed(double value) {
  if (!(value >= 0 && value <= 1e9)) return false;
  words_.f = value;
  return true;
}

// CR= of plainWord and plainLineWord, the circle radius (extendedWord): false when programmed
// before in the block or when a variable CR exists, for collectWord to decide.
NCOFFSET_INLINE_STEP bool Interpreter::plainRadius(double value) {
  if (words_.cr || vars_.find("CR")) return false;
  words_.cr = value;
  words_.plain_circle = true;
  return true;
}

// I, J or K (0..2) of plainWord, the circle's centre from the start point (or a thread's lead,
// which finishPlainBlock leaves to threadLeadWords as finishBlock does); false if programmed
// before (collectWord's alarm).
NCOFFSET_INLINE_STEP bool Interpreter::plainCentre(int i, double value) {
  if (words_.centre[i]) return false;
  words_.centre[i] = true;
  words_.centre_value[i] = value;
  words_.centre_mode[i] = lang::AxisMode::Default;
  words_.plain_circle = true;
  return true;
}

// An axis word X, Y or Z (axis 0..2) of plainWord; false if the axis was programmed before
// (collectWord's alarm).
NCOFFSET_INLINE_STEP bool Interpreter::plainAxis(int i, double value) {
  if (words_.axis[i]) return false;
  words_.axis[i] = true;
  words_.axis_value[i] = value;
  words_.axis_mode[i] = lang::AxisMode::Default;
  return true;
}

// A G word of plainWord: G0..G3 (group 1) or G40..G42 (group 7), as gMotionPlaneFrame and
// gCompensation set them.
NCOFFSET_INLINE_STEP bool Interpreter::plainG(double value, bool is_int, Motion& motion,
                                              core::TrcMode& trc) {
  if (!is_int) return false;
  if (value >= 0 && value <= 3) {
    motion = static_cast<Motion>(static_cast<int>(value));  // G0 G1 G2 G3
    words_.motion_word = true;
    return true;
  }
  if (value >= 40 && value <= 42) {
    trc = value == 40   ? core::TrcMode::Off
          : value == 41 ? core::TrcMode::Left
                        : core::TrcMode::Right;
    return true;
  }
  return false;
}

// plainG for a code written as digits alone (the plain line).
NCOFFSET_INLINE_STEP bool Interpreter::plainGCode(unsigned long long g, Motion& motion,
                                                  core::TrcMode& trc) {
  if (g <= 3) {
    motion = static_cast<Motion>(g);  // G0 G1 G2 G3
    words_.motion_word = true;
    return true;
  }
  if (g - 40 > 2) return false;
  trc = static_cast<core::TrcMode>(g - 40);  // G40 Off, G41 Left, G42 Right
  return true;
}

// finishBlock (block_executor.cpp) for a block whose words plainWord collected alone (X, Y, Z,
// G0..G3, F, CR=, I, J, K), outside a contour definition, a carrier change and a modal call
// (executeBlock): every word the other steps look for is absent, so the feed, the motion and the
// bookkeeping remain, in finishBlock's order. finishBlock is its twin
// (tests/interp/fast_path_test.cpp).
NCOFFSET_INLINE_STEP void Interpreter::finishPlainBlock(int column) {
  column_ = column;  // of the block's first word
  feed_before_ = modal_.feed;
  if (words_.f) modal_.feed = modal_.units == Units::G700 ? *words_.f * 25.4 : *words_.f;
  if (events_) blockEvents(feed_before_);
  const bool is_arc = modal_.motion == Motion::G2 || modal_.motion == Motion::G3;
  const bool circle_words = words_.plain_circle;  // I, J, K, CR=
  if (circle_words && !is_arc) [[unlikely]]
    threadLeadWords();  // I, J, K of a thread; else (and CR=) the circle alarm
  bool moved = false;
  if (words_.axis[0] || words_.axis[1] || words_.axis[2] || (is_arc && circle_words))
    moved = motion_.buildPlain(words_, modal_, line_, file_, feed_before_, motion_before_);
  if (moved) without_motion_ = 0;
  if (events_ && stop_after_) stopEvent();
  if (!moved) motion_.output().blockWithoutMotion();
  motion_before_ = modal_.motion;
}

// executeBlock for a plain block (words_ already cleared): only address words with a plain
// number (G1 X10 CR=5), no definition, jump or expression among them.
void Interpreter::executePlainBlock(const lang::Block& b) {
  flow_.level().defs_allowed = false;
  bool all_plain = true;
  for (const lang::Stmt& st : b.stmts) {
    if (!plainWord(st.name, st.literal_value, st.literal_int, modal_.motion, modal_.trc)) {
      column_ = st.column;  // plainWord raises no alarm: only collectWord needs the column
      all_plain = false;
      collectWord(st);
    }
  }
  // Block end writes to words_ only in a contour definition, a carrier change or MCALL.
  all_plain = all_plain && !contour_active_ && !carrier_.pending && !mcall_.active;
  all_plain ? finishPlainBlock(b.stmts.front().column) : finishBlock();
  words_plain_ = all_plain;
}

namespace {

// The number of a word of a plain line at `p` (its letter or CR= behind): an optional sign and
// at most kExactDigits digits with an optional point, by the parser's own scan; `p` is moved
// behind it. False for anything else (no digits, too many, EX), which the parser then reads.
NCOFFSET_INLINE_STEP bool scanLineNumber(const char*& p, double& value, bool& is_int) {
  bool negative = false;
  if (*p == '-' || *p == '+') negative = *p++ == '-';
  const lang::DecimalDigits digits = lang::scanDigits(p);
  if (digits.digits == 0 || digits.digits > lang::kExactDigits) return false;
  p = digits.end;
  const double v = lang::exactValue(digits);
  value = negative ? -v : v;
  is_int = !digits.point;
  return true;
}

}  // namespace

// One word of a plain line at `p` (no blank before it), scanned and collected as plainWord
// collects it: X, Y, Z, G, F, I, J or K with a number, or CR= with a number; `p` is moved behind
// the blanks after it. Stricter than Parser::simpleWords: what follows a number directly must be
// the next word's letter, which the next call checks (so "1EX3", "X1=2" and "X1;" fail there);
// CR=10 must be followed by a blank or the end, as simpleWords requires.
NCOFFSET_INLINE_STEP bool Interpreter::plainLineWord(const char*& p, Motion& motion,
                                                     core::TrcMode& trc) {
  const char c = *p;
  double value = 0;
  bool is_int = false;
  if (c >= 'X' && c <= 'Z') {
    ++p;
    if (!scanLineNumber(p, value, is_int) || !plainAxis(c - 'X', value)) return false;
  } else if (c == 'G') {
    // The code as an integer (plainG's G0..G3 and G40..G42 written without sign and point;
    // a sign or a point goes to the parser, which reads the same code).
    const lang::DecimalDigits digits = lang::scanDigits(p + 1);
    if (digits.point || digits.digits == 0 || digits.digits > lang::kExactDigits) return false;
    p = digits.end;
    if (!plainGCode(digits.mantissa, motion, trc)) return false;
  } else if (c == 'F') {
    ++p;
    if (!scanLineNumber(p, value, is_int) || !plainFeed(value)) return false;
  } else if (c >= 'I' && c <= 'K') {
    ++p;
    if (!scanLineNumber(p, value, is_int) || !plainCentre(c - 'I', value)) return false;
  } else if (c == 'C' && p[1] == 'R' && p[2] == '=') {
    p += 3;
    if (!scanLineNumber(p, value, is_int)) return false;
    // A blank or the end must follow (any other character up to the blank ends no word, so
    // the next word's scan refuses it).
    if (static_cast<unsigned char>(*p) > ' ' || !plainRadius(value)) return false;
  } else {
    return false;
  }
  // The blanks: the usual single one and a letter behind it (two tests), else the loop; at the
  // line's end no blank (two tests).
  if (*p == ' ') {
    if (*++p < 'A') [[unlikely]]
      while (*p == ' ' || *p == '\t') ++p;
  } else if (*p == '\t') [[unlikely]] {
    while (*p == ' ' || *p == '\t') ++p;
  }
  return true;
}

// The words of a plain line from `base` up to where `at_end` says it ends (an optional block
// number first), collected into words_ as plainWord collects them; G groups 1 and 7 go to
// `motion` and `trc`, which takePlainLine stores. The end of the last word, or nullptr when the
// line is not plain, empty or a block number alone. A word stops at the line's end or before the
// next word (a '\0' or CR inside the line is neither: the next word's scan refuses it).
template <class AtEnd>
NCOFFSET_INLINE_STEP const char* Interpreter::plainWords(const char* base, AtEnd at_end,
                                                         Motion& motion, core::TrcMode& trc) {
  const char* p = base;
  if (*p < 'A' || *p == 'N') [[unlikely]] {  // else a word's letter (the usual line), not the end
    while (*p == ' ' || *p == '\t') ++p;
    if (*p == 'N' && lang::isDigit(p[1])) {  // the block number (more than 18 digits: alarm)
      const char* q = p + 1;
      while (lang::isDigit(*q)) ++q;
      if (q - p - 1 > 18) return nullptr;
      p = q;
      while (*p == ' ' || *p == '\t') ++p;
    }
    if (at_end(p)) return nullptr;  // an empty line or a block number alone
  }
  plain_column_ = static_cast<int>(p - base) + 1;
  // Only plainWord's fields now (ten stores): executeBlock clears the rest if the line is not
  // plain after all, takePlainLine if it is.
  words_.clearPlain();
  motion = modal_.motion;
  trc = modal_.trc;
  while (plainLineWord(p, motion, trc))
    if (at_end(p)) return p;
  return nullptr;
}

// The plain line's words are taken: the rest of words_ cleared after a block of other words,
// the modal motion and compensation stored.
NCOFFSET_INLINE_STEP void Interpreter::takePlainLine(Motion motion, core::TrcMode trc) {
  if (!words_plain_) words_.clearExceptPlain();
  modal_.motion = motion;
  modal_.trc = trc;
  flow_.level().defs_allowed = false;
}

// plainLine without the test for lines refused before. The line is scanned where it stands
// when the character after it may be read (a newline, or the '\0' of a macro expansion: no
// digit, sign, blank or letter, so every scan stops there), else in a copy ended by a '\0'.
// Out of line: the usual line is lineInPlace's, and one copy of the scan inlined into the block
// loop leaves room for inlining the number scan there.
[[gnu::noinline]] bool Interpreter::scanPlainLine(std::string_view text, bool ended) {
  const char* const base = ended ? text.data() : lang::copyWritten(text, line_copy_);
  const char* const end = base + text.size();
  Motion motion;
  core::TrcMode trc;
  if (!plainWords(
          base, [end](const char* p) { return p == end; }, motion, trc))
    return false;
  takePlainLine(motion, trc);
  return true;
}

// Parser::parseWritten, Parser::simpleWords and executePlainBlock in one pass, for a line whose
// every word plainWord collects (an optional block number first): the same number scan, the
// same words in the same order, and finishPlainBlock (by finishPlainLine) under the same
// conditions. It accepts no line that simpleWords would not (plainLineWord is stricter). False
// leaves the line to the parser and executeBlock; words_ then holds what it held with
// plainWord's fields changed, which executeBlock clears (words_plain_ as before), and the modal
// motion and compensation are as before.
NCOFFSET_INLINE_STEP bool Interpreter::plainLine(std::string_view text, bool ended) {
  if (contour_active_ || carrier_.pending || mcall_.active) [[unlikely]]
    return false;
  // A line refused before (a loop's lines: refused once, not on every pass), by the address
  // of its text. A stale entry (the text's memory reused) only sends a line to the general
  // path, which is never wrong.
  const char*& refused = refused_[(reinterpret_cast<std::uintptr_t>(text.data()) >> 4) % 32];
  if (refused == text.data()) return false;
  if (scanPlainLine(text, ended)) return true;
  refused = text.data();
  return false;
}

// The state a run starts from.
void Interpreter::startRun(LoadedProgram& program, bool init_file) {
  init_file_ = init_file;
  ended_ = false;
  events_ = sink_.wantsEvents();
  flow_.begin(program);
  vars_.beginRun();
  resetCalls();
  without_motion_ = 0;  // an init file's data blocks do not count against the program
  run_start_ = executed_;
  block_budget_ =
      executed_ + (options_.limits.max_blocks > 0 ? options_.limits.max_blocks
                                                  : options_.limits.max_blocks_auto_base);
  line_stop_ = executed_;          // the first line takes countLine's other way, which sets it
  if (!init_file) announceAxes();  // the output columns of the additional axes
  loop_.reset();
  words_plain_ = false;
  in_place_ = false;
}

// The bookkeeping of every line read: the pages read before released now and then, the block
// budget (lineStop, where executed_ reaches line_stop_: one test a line for both), the blocks
// without motion.
NCOFFSET_INLINE_STEP void Interpreter::countLine(ProgramLevel& lvl) {
  if (executed_ >= line_stop_) [[unlikely]]
    lineStop(lvl);
  else
    ++executed_;
  if (++without_motion_ > options_.limits.max_blocks_without_motion)
    raise(AlarmNumber::NoMotionLimit,
          fmt::format("{} blocks executed without any motion (endless loop?); raise "
                      "--max-blocks-without-motion",
                      options_.limits.max_blocks_without_motion));
}

// countLine's tests of the pages to release (every 65,536 lines) and of the block budget, and
// the next count where one of them may hold again.
void Interpreter::lineStop(ProgramLevel& lvl) {
  if ((executed_ & 0xFFFF) == 0) lvl.program->source->releaseBefore(line_pos_.offset);
  if (++executed_ > block_budget_) [[unlikely]]
    blockBudgetReached();  // raises, or sets a larger budget
  line_stop_ = std::min((executed_ + 0xFFFF) & ~0xFFFFLL, block_budget_);
}

// Where lineInPlace may read lines: the level's text ends with a newline (every scan stops at
// one), its lines are its own (no built-in cycle's), no macro may expand them, and no contour
// definition, carrier change or modal call wants the general block end. Only a line that is not
// plain, a level's change or a section's end changes any of it, so the block loop asks again
// only after those (in_place_).
NCOFFSET_INLINE_STEP bool Interpreter::inPlaceAllowed(const ProgramLevel& lvl) const {
  return !lvl.text.empty() && lvl.text.back() == '\n' && lvl.report_file < 0 && macros_.empty() &&
         !contour_active_ && !carrier_.pending && !mcall_.active;
}

// The next line read and collected in one pass when it is plain (docs/performance.md §44): the
// word scan finds the line's end itself, a newline or CR LF, instead of a search for the newline
// first (lang::nextLine) and the scan after it. Only where inPlaceAllowed says so; whatever it
// refuses (also a line beyond --max-line-length, whose alarm the general way raises) is read
// again by nextLine and plainLine, its twin, as if it had not looked (nothing but the plain
// fields of words_ changed, which both ways clear). Taken: with the bookkeeping of run() done;
// Refused: a line plainLine refused before (by its address), which plainLine need not ask again.
NCOFFSET_INLINE_STEP Interpreter::InPlace Interpreter::lineInPlace(ProgramLevel& lvl,
                                                                   size_t max_len) {
  const std::string_view all = lvl.text;
  const size_t at = lvl.pos.offset;
  if (at >= all.size()) [[unlikely]]
    return InPlace::No;
  const char* const begin = all.data() + at;
  const char* const refused = refused_[(reinterpret_cast<std::uintptr_t>(begin) >> 4) % 32];
  if (!in_place_) [[unlikely]] {
    // After a line that is not plain the refused lines first: a loop of other lines does not
    // ask inPlaceAllowed on every line. After a plain line only when the scan refuses the line
    // (the usual plain line does not look them up).
    if (refused == begin) return InPlace::Refused;
    in_place_ = inPlaceAllowed(lvl);
    if (!in_place_) return InPlace::No;
    // The level's file: while in_place_ holds, only plain lines of this level ran, which keep it
    // (a level's change and every other change of file_ come with a line that is not plain).
    file_ = lvl.program->file_id;
  }
  Motion motion;
  core::TrcMode trc;
  const char* const stop = plainWords(
      begin, [](const char* p) { return *p == '\n' || (*p == '\r' && p[1] == '\n'); }, motion, trc);
  if (stop == nullptr) [[unlikely]]
    return refused == begin ? InPlace::Refused : InPlace::No;
  const auto len = static_cast<size_t>(stop - begin);
  if (len > max_len) return InPlace::No;
  line_pos_ = lvl.pos;
  lvl.pos.offset = at + len + (*stop == '\n' ? 1 : 2);
  ++lvl.pos.line;
  line_ = line_pos_.line;
  line_text_ = std::string_view(begin, len);
  column_ = 0;
  countLine(lvl);
  takePlainLine(motion, trc);
  return InPlace::Taken;
}

// The block loop (here, beside the plain line, which it inlines: a call a line costs the saving
// of six registers).
void Interpreter::run(LoadedProgram& program, bool init_file) {
  startRun(program, init_file);
  std::string_view text;
  const size_t max_len = options_.limits.max_line_length;
  while (!ended_) {
    ProgramLevel& lvl = flow_.level();
    const InPlace in_place = lineInPlace(lvl, max_len);  // sets file_ where it reads
    bool plain = in_place == InPlace::Taken;
    if (!plain) {
      in_place_ = false;  // the line may change what inPlaceAllowed asks, or the level end
      file_ = lvl.program->file_id;
      const bool more = flow_.nextLine(text, line_pos_);
      line_ = line_pos_.line;
      line_text_ = text;
      column_ = 0;
      if (lvl.report_file >= 0) [[unlikely]] {  // a built-in cycle: the calling block's line
        file_ = lvl.report_file;
        line_ = lvl.report_line;
        line_text_ = lvl.report_text;
      }
      if (!more) {
        // End of file: a subprogram returns, the main program (or init file) ends.
        if (flow_.depth() > 1) {
          returnFromSubprogram();
          continue;
        }
        break;
      }
      countLine(lvl);
      if (text.size() > max_len)
        raise(AlarmNumber::LineTooLong,
              fmt::format("block of {} characters is longer than the limit of {} "
                          "(--max-line-length)",
                          text.size(), max_len));
      if (!text.empty() && text.front() == '%') {  // archive header %_N_NAME_MPF
        // A fed text archive (docs/architecture.md "Streaming"): the program ends before the
        // next program's header, as its range ends when the whole archive is loaded.
        if (lvl.program->source->fed() && line_pos_.offset > 0) [[unlikely]] {
          if (flow_.depth() > 1) {
            returnFromSubprogram();
            continue;
          }
          break;
        }
        continue;
      }
      // X Y Z G0..G3 G40..G42 F CR= I J K alone: no parse. Behind the line a newline, or the '\0'
      // of an expansion, may be read (`ended`).
      bool ended = lvl.pos.offset - line_pos_.offset > text.size();
      if (!macros_.empty() && macros_.expand(text, expanded_, max_len)) [[unlikely]] {
        text = expanded_;
        ended = true;
      }
      plain = in_place == InPlace::No && plainLine(text, ended);  // refused: plainLine's too
      if (!plain) lang::parseBlock(text, line_, block_, {options_.limits.max_expression_depth});
    }
    try {
      plain ? finishPlainLine() : executeBlock();
      if (line_pos_.offset == section_end_) [[unlikely]] {
        endSection();  // CALL .. BLOCK .. TO ..
        in_place_ = false;
      }
    } catch (const std::bad_alloc&) {
      raise(AlarmNumber::ArrayTooLarge, "out of memory while executing this block");
    }
  }
  if (!init_file) motion_.flush();  // the last compensated element ends on its normal
  vars_.endRun(!init_file);
  if (!init_file) macros_.endRun();
  flow_.clear();
}

}  // namespace ncoffset::interp
