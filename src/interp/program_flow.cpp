#include "interp/program_flow.hpp"

#include <fmt/format.h>

#include <cctype>

#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::TextPos;

LoadedProgram& ProgramFlow::load(std::shared_ptr<lang::SourceFile> source) {
  auto p = std::make_unique<LoadedProgram>();
  p->file_id = static_cast<int>(files_.size());
  p->source = std::move(source);
  files_.push_back(std::move(p));
  LoadedProgram& prog = *files_.back();
  prog.index = std::make_unique<lang::ProgramIndex>(*prog.source, limits_.max_control_depth,
                                                    limits_.max_line_length);
  return prog;
}

void ProgramFlow::setSearchDir(std::filesystem::path dir) {
  search_dir_ = std::move(dir);
}

void ProgramFlow::begin(LoadedProgram& main) {
  levels_.clear();
  ProgramLevel level;
  level.program = &main;
  levels_.push_back(level);
}

LoadedProgram* ProgramFlow::find(std::string_view name) {
  std::string key(name);
  if (auto it = by_name_.find(key); it != by_name_.end()) return it->second;
  if (!dir_scanned_) {
    dir_scanned_ = true;
    std::error_code ec;
    std::filesystem::path dir = search_dir_.empty() ? std::filesystem::path(".") : search_dir_;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
      std::string fn = e.path().filename().string();
      for (auto& c : fn) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      dir_entries_.emplace(fn, search_dir_.empty() ? e.path().filename() : e.path());
    }
  }
  const std::string candidates[] = {key + ".SPF", "_N_" + key + "_SPF", key + ".MPF",
                                    "_N_" + key + "_MPF", key};
  for (const auto& c : candidates) {
    auto it = dir_entries_.find(c);
    if (it == dir_entries_.end()) continue;
    std::string err;
    auto src = lang::SourceFile::load(it->second, &err);
    if (!src) continue;
    LoadedProgram* prog = &load(std::move(src));
    by_name_.emplace(key, prog);
    return prog;
  }
  return nullptr;
}

void ProgramFlow::call(std::string_view name, long long repeat) {
  if (static_cast<int>(levels_.size()) >= limits_.max_program_levels)
    raise(AlarmNumber::SubprogramDepth,
          fmt::format("maximum subprogram level exceeded: {} program levels (--max-program-levels)",
                      limits_.max_program_levels));
  if (repeat < 1 || repeat > 9999)
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: P{} (pass count 1..9999)", repeat));
  LoadedProgram* prog = find(name);
  if (!prog)
    raise(AlarmNumber::ProgramNotFound,
          fmt::format(
              "program {} not existing (looked for {}.SPF and _N_{}_SPF beside the main program)",
              name, name, name));
  ProgramLevel lvl;
  lvl.program = prog;
  lvl.repeat_left = repeat - 1;
  levels_.push_back(lvl);
}

bool ProgramFlow::leave() {
  ProgramLevel& lvl = levels_.back();
  if (lvl.repeat_left > 0) {
    --lvl.repeat_left;
    lvl.pos = TextPos{};
    lvl.defs_allowed = true;
    return true;
  }
  levels_.pop_back();
  return false;
}

void ProgramFlow::continueAfter(const TextPos& line) {
  ProgramLevel& lvl = levels_.back();
  lvl.pos = line;
  std::string_view skip;
  lang::nextLine(lvl.program->source->text(), lvl.pos, skip);
}

bool ProgramFlow::waitForText() const {
  LoadedProgram& prog = *levels_.back().program;
  if (!prog.source->growing()) return false;
  const bool more = prog.source->waitForMore();
  if (!more) prog.source->complete();
  prog.index->extend(*prog.source);
  prog.block_numbers.clear();  // found again with the new lines
  if (!more) prog.index->finish();
  return more;
}

bool ProgramFlow::nextLineFed(std::string_view& text) {
  ProgramLevel& lvl = levels_.back();
  while (waitForText())
    if (lang::nextLine(lvl.program->source->text(), lvl.pos, text)) return true;
  return false;
}

const lang::ControlLink& ProgramFlow::link(size_t offset) const {
  const lang::ControlLink* l = levels_.back().program->index->link(offset);
  // A structure of a fed program whose end has not been fed yet: wait for it.
  while (!l && waitForText()) l = levels_.back().program->index->link(offset);
  if (!l)
    raise(AlarmNumber::ControlNesting,
          "invalid nesting of control structures: statement must stand at the start of its block");
  return *l;
}

const std::vector<TextPos>& ProgramFlow::blockNumberLines(LoadedProgram& prog, long long n) {
  if (auto it = prog.block_numbers.find(n); it != prog.block_numbers.end()) return it->second;
  // One scan of the file per distinct target number.
  std::vector<TextPos> found;
  TextPos p;
  std::string_view text;
  std::string norm;
  while (true) {
    TextPos at = p;
    if (!lang::nextLine(prog.source->text(), p, text)) break;
    if (!lang::normalizeLine(text.substr(0, 40), norm, nullptr)) continue;
    size_t i = norm.find_first_not_of(' ');
    if (i == std::string::npos) continue;
    if (norm[i] == '/') {
      ++i;
      if (i < norm.size() && norm[i] >= '0' && norm[i] <= '9') ++i;
      i = norm.find_first_not_of(' ', i);
      if (i == std::string::npos) continue;
    }
    if ((norm[i] != 'N' && norm[i] != ':') || i + 1 >= norm.size()) continue;
    size_t j = i + 1;
    long long v = 0;
    while (j < norm.size() && norm[j] >= '0' && norm[j] <= '9' && j - i < 19)
      v = v * 10 + (norm[j++] - '0');
    if (j > i + 1 && v == n) found.push_back(at);
  }
  return prog.block_numbers.emplace(n, std::move(found)).first->second;
}

bool ProgramFlow::jumpToBlockNumber(long long n, size_t here, JumpSearch search) {
  ProgramLevel& lvl = levels_.back();
  if (search.forward && lvl.program->source->growing()) {
    // A fed program: the forward search needs the text up to the destination (or all of it).
    auto ahead = [&] {
      for (const auto& p : blockNumberLines(*lvl.program, n))
        if (p.offset > here) return true;
      return false;
    };
    while (!ahead() && waitForText()) {
    }
  }
  const std::vector<TextPos>& lines = blockNumberLines(*lvl.program, n);
  // The nearest occurrence in the search direction: forward first, then backward.
  if (search.forward)
    for (const auto& p : lines)
      if (p.offset > here) {
        lvl.pos = p;
        return true;
      }
  if (search.backward)
    for (auto r = lines.rbegin(); r != lines.rend(); ++r)
      if (r->offset < here) {
        lvl.pos = *r;
        return true;
      }
  return false;
}

bool ProgramFlow::jumpToLabel(const std::string& label, size_t here, JumpSearch search) {
  ProgramLevel& lvl = levels_.back();
  const TextPos* p = lvl.program->index->label(label);
  // A fed program: a forward search waits for the destination (or the end of the text).
  while (search.forward && !p && waitForText()) p = lvl.program->index->label(label);
  if (p && ((search.forward && p->offset > here) || (search.backward && p->offset < here) ||
            (search.here_too && p->offset == here))) {
    lvl.pos = *p;
    return true;
  }
  return false;
}

}  // namespace ncoffset::interp
