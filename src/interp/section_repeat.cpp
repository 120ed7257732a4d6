// Program section repetition (PM-JP "Program section repetition": REPEAT, REPEATB, ENDLABEL,
// P): a section of the current program runs P times as a program level of its own, then the
// program continues after the REPEAT line. Decisions and their sources: docs/language.md
// "Program section repetition".
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::TextPos;

// --- ProgramFlow ----------------------------------------------------------------------------

void ProgramFlow::repeatSection(const Section& s, long long count) {
  if (static_cast<int>(levels_.size()) >= limits_.max_program_levels)
    raise(AlarmNumber::SubprogramDepth,
          fmt::format("maximum subprogram level exceeded: {} program levels (--max-program-levels; "
                      "each program section repetition takes one)",
                      limits_.max_program_levels));
  if (count < 1 || count > 9999)
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: P={} (pass count 1..9999)", count));
  ProgramLevel lvl(*levels_.back().program);
  lvl.pos = s.start;
  lvl.repeat_left = count - 1;
  lvl.defs_allowed = false;
  lvl.section = true;
  lvl.section_start = s.start;
  // The section's text ends before its end line, or (inclusive) after it: reading past it ends
  // the pass, like the end of a file ends a subprogram.
  size_t end = s.end;
  if (s.inclusive) {
    TextPos after{s.end, 0};
    std::string_view skip;
    lang::nextLine(lvl.program->source->text(), after, skip);
    end = after.offset;
  }
  lvl.text = textUpTo(*lvl.program, std::min(end, lvl.program->end));
  levels_.push_back(lvl);
}

bool ProgramFlow::inMainProgram() const {
  size_t k = levels_.size() - 1;
  while (k > 0 && levels_[k].section) --k;
  return k == 0;
}

const std::vector<TextPos>* ProgramFlow::labelLines(std::string_view label) const {
  return levels_.back().program->index->labels(label);
}

const std::vector<TextPos>* ProgramFlow::labelLinesFrom(std::string_view label, size_t from) const {
  const lang::ProgramIndex& index = *levels_.back().program->index;
  const std::vector<TextPos>* lines = index.labels(label);
  // The index grows while waiting (its vectors may move): looked up again after each wait.
  while (levels_.back().program->source->growing() && !(lines && lines->back().offset >= from) &&
         waitForText())
    lines = index.labels(label);
  return lines;
}

// --- Interpreter ----------------------------------------------------------------------------

namespace {

// The nearest line before `here`, else (both ways) the nearest after it. The lines are in file
// order: binary searches.
const TextPos* nearest(const std::vector<TextPos>* lines, size_t here, bool forward_too) {
  if (!lines) return nullptr;
  auto at = std::lower_bound(lines->begin(), lines->end(), here,
                             [](const TextPos& p, size_t h) { return p.offset < h; });
  if (at != lines->begin()) return &*(at - 1);
  if (at != lines->end() && at->offset == here) ++at;
  return forward_too && at != lines->end() ? &*at : nullptr;
}

// The first line of `lines` at or after `from` (and before `before`).
const TextPos* firstFrom(const std::vector<TextPos>* lines, size_t from, size_t before) {
  if (!lines) return nullptr;
  auto at = std::lower_bound(lines->begin(), lines->end(), from,
                             [](const TextPos& p, size_t h) { return p.offset < h; });
  return at != lines->end() && at->offset < before ? &*at : nullptr;
}

}  // namespace

// REPEATB L [P=n]; REPEAT L [P=n]; REPEAT L1 L2 [P=n] (L2 may be ENDLABEL).
void Interpreter::repeatSection(const lang::Stmt& st, bool& jumped) {
  const lang::Block& b = block_;
  const size_t here = line_pos_.offset;
  const bool single_block = st.name == "REPEATB";
  const bool two_labels = st.expr2 >= 0;
  const std::string_view start_name = b.node(st.target).text;
  // REPEATB and REPEAT A B look for the start towards the program start first, then towards its
  // end; REPEAT A repeats what stands between A and itself, so A must come before it.
  const bool forward_too = single_block || two_labels;
  const TextPos* start = nearest(flow_.labelLines(start_name), here, forward_too);
  if (!start && forward_too)  // a fed program: the forward search waits for the start
    start = nearest(flow_.labelLinesFrom(start_name, here + 1), here, true);
  if (!start)
    raise(AlarmNumber::JumpNotFound,
          fmt::format("jump destination {} not found ({} search for the start of the repeated "
                      "section)",
                      start_name, forward_too ? "backward, then forward" : "backward"));
  Section s;
  s.start = *start;
  if (single_block) {
    s.end = start->offset;
    s.inclusive = true;
  } else if (two_labels) {
    const std::string_view end_name = b.node(st.expr2).text;
    const TextPos* end =
        firstFrom(flow_.labelLinesFrom(end_name, start->offset), start->offset, kNoOffset);
    if (!end)
      raise(AlarmNumber::JumpNotFound,
            fmt::format("jump destination {} not found (the end of the repeated section is "
                        "searched forward from {} on line {})",
                        end_name, start_name, start->line));
    s.end = end->offset;
    s.inclusive = true;
  } else if (const TextPos* end = firstFrom(flow_.labelLines("ENDLABEL"), start->offset, here)) {
    s.end = end->offset;  // an ENDLABEL between the start and the REPEAT ends the section
    s.inclusive = true;
  } else {
    s.end = here;  // the section ends before the REPEAT line
  }
  long long count = 1;
  if (st.expr >= 0) {
    double p = lang::toNumber(eval_.eval(b, st.expr), "pass count P");
    if (p != std::floor(p))
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: P={} (the pass count is an integer)", p));
    count = std::fabs(p) > 1e9 ? 0 : static_cast<long long>(p);
  }
  finishBlock();
  if (ended_) return;
  flow_.repeatSection(s, count);
  jumped = true;
}

// M17/RET and M2/M30 (PM-JP "Program section repetition": M17 or RET in a repeated section ends
// the repetition, the program continues after the REPEAT line).
void Interpreter::endWord(bool program_end) {
  if (flow_.level().section) {
    if (program_end && flow_.inMainProgram())
      endProgram();
    else
      flow_.abortSection();
    return;
  }
  if (flow_.depth() > 1)
    returnFromSubprogram();                      // M2/M30 in a subprogram act like M17
  else if (!init_file_ || !flow_.nextSection())  // an init archive goes on with its next section
    endProgram();
}

}  // namespace ncoffset::interp
