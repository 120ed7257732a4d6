#include "interp/program_flow.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "cycles/builtin_cycles.hpp"
#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::TextPos;

LoadedProgram& ProgramFlow::load(std::shared_ptr<lang::SourceFile> source, bool programs) {
  if (programs)
    if (LoadedProgram* first = loadArchive(source, main_archive_)) {
      indexed(*first);
      return *first;
    }
  return indexed(loadRange(std::move(source), TextPos{}, kNoOffset));
}

// The control structures of a program are checked before it runs (alarms 12640/12641); the
// programs of an archive only when they are called, like files of their own.
LoadedProgram& ProgramFlow::indexed(LoadedProgram& prog) {
  if (!prog.index) {
    failed_file_ = prog.file_id;
    prog.index = std::make_unique<lang::ProgramIndex>(
        *prog.source, limits_.max_control_depth, limits_.max_line_length, prog.begin, prog.end);
    failed_file_ = -1;
  }
  return prog;
}

LoadedProgram& ProgramFlow::loadRange(std::shared_ptr<lang::SourceFile> source, TextPos begin,
                                      size_t end) {
  auto p = std::make_unique<LoadedProgram>();
  p->file_id = static_cast<int>(files_.size());
  p->source = std::move(source);
  p->begin = begin;
  p->end = end;
  files_.push_back(std::move(p));
  return *files_.back();
}

void ProgramFlow::setSearchDir(std::filesystem::path dir) {
  search_dir_ = std::move(dir);
}

void ProgramFlow::begin(LoadedProgram& main) {
  levels_.clear();
  levels_.emplace_back(main);
}

LoadedProgram* ProgramFlow::find(std::string_view name) {
  std::string key(name);
  if (auto it = by_name_.find(key); it != by_name_.end()) return it->second;
  LoadedProgram* prog = nullptr;
  if (auto it = main_archive_.find(key); it != main_archive_.end()) prog = it->second;
  if (!prog) prog = findIn(search_dir_, key);
  for (size_t k = 0; !prog && k < search_path_.size(); ++k) prog = findIn(search_path_[k], key);
  if (!prog) prog = findInFedArchive(key);
  if (!prog) prog = findBuiltin(key);
  if (!prog) return nullptr;
  indexed(*prog);  // every caller gets a program it can run
  by_name_.emplace(key, prog);
  return prog;
}

LoadedProgram* ProgramFlow::findInFedArchive(const std::string& key) {
  if (levels_.empty() || fed_archive_loaded_) return nullptr;
  LoadedProgram& main = *levels_.front().program;
  if (!main.source->fed()) return nullptr;
  while (waitForTextOf(main)) {
  }
  fed_archive_loaded_ = true;
  const size_t first = files_.size();
  loadArchive(main.source, main_archive_);
  if (files_.size() > first) {
    // The archive's first program is the one running (the fed program from its top): one file,
    // one id, numbered as when the whole archive is loaded.
    for (auto& named : main_archive_)
      if (named.second == files_[first].get()) named.second = &main;
    files_.erase(files_.begin() + static_cast<std::ptrdiff_t>(first));
    for (size_t k = first; k < files_.size(); ++k) files_[k]->file_id = static_cast<int>(k);
  }
  auto it = main_archive_.find(key);
  return it == main_archive_.end() ? nullptr : it->second;
}

// The user's program of a cycle's name comes first (found above), as a cycle file in the
// control's user cycle directory replaces the standard one (docs/cycles.md).
LoadedProgram* ProgramFlow::findBuiltin(const std::string& key) {
  const std::string_view text = cycles::builtinCycleText(key);
  if (text.empty()) return nullptr;
  auto source = lang::SourceFile::fromString(key + ".SPF (built-in)", std::string(text));
  LoadedProgram& prog = loadRange(std::move(source), {}, kNoOffset);
  prog.builtin = true;
  return &prog;
}

// One place of the search: a directory, or a text archive holding several programs.
LoadedProgram* ProgramFlow::findIn(const std::filesystem::path& place, const std::string& key) {
  std::error_code ec;
  const std::filesystem::path dir = place.empty() ? std::filesystem::path(".") : place;
  if (std::filesystem::is_regular_file(dir, ec)) {
    auto archive = archives_.find(dir);
    if (archive == archives_.end()) {
      archive = archives_.emplace(dir, std::map<std::string, LoadedProgram*>{}).first;
      std::string err;
      if (auto src = lang::SourceFile::load(dir, &err)) loadArchive(src, archive->second);
    }
    auto it = archive->second.find(key);
    return it == archive->second.end() ? nullptr : it->second;
  }
  auto listed = dir_entries_.find(dir);
  if (listed == dir_entries_.end()) {
    listed = dir_entries_.emplace(dir, std::map<std::string, std::filesystem::path>{}).first;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
      std::string fn = e.path().filename().string();
      for (auto& c : fn) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      listed->second.emplace(fn, place.empty() ? e.path().filename() : e.path());
    }
  }
  const std::string candidates[] = {key + ".SPF", "_N_" + key + "_SPF", key + ".MPF",
                                    "_N_" + key + "_MPF", key};
  for (const auto& c : candidates) {
    auto it = listed->second.find(c);
    if (it == listed->second.end()) continue;
    std::string err;
    auto src = lang::SourceFile::load(it->second, &err);
    if (!src) continue;
    return &load(std::move(src));
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
          fmt::format("program {} not existing (looked for {}.SPF and _N_{}_SPF beside the main "
                      "program{})",
                      name, name, name, search_path_.empty() ? "" : " and in the --path entries"));
  ProgramLevel lvl(*prog);
  lvl.repeat_left = repeat - 1;
  levels_.push_back(lvl);
}

void ProgramFlow::callProgram(LoadedProgram& prog) {
  if (static_cast<int>(levels_.size()) >= limits_.max_program_levels)
    raise(AlarmNumber::SubprogramDepth,
          fmt::format("maximum subprogram level exceeded: {} program levels (--max-program-levels)",
                      limits_.max_program_levels));
  levels_.emplace_back(prog);  // CALL BLOCK: the caller then jumps to the section's start
}

bool ProgramFlow::leave() {
  ProgramLevel& lvl = levels_.back();
  if (lvl.repeat_left > 0) {
    --lvl.repeat_left;
    if (lvl.section) {
      lvl.pos = lvl.section_start;
      return true;
    }
    lvl.pos = lvl.program->begin;
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
  return waitForTextOf(*levels_.back().program);
}

bool ProgramFlow::waitForTextOf(LoadedProgram& prog) {
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
  // A repeated section ends at its end line, an archived program at the next header, both known
  // when the level started; the level over a growing text (never an archive range) reads what
  // was fed since its view was taken: a wait at a jump or a structure may have fed more, and
  // completed the text (then the source is no longer growing).
  const lang::SourceFile& src = *lvl.program->source;
  if (lvl.section || lvl.program->end != kNoOffset) return false;
  if (!src.growing() && lvl.text.size() == src.text().size()) return false;
  do {
    lvl.text = lvl.program->source->text();
    if (lang::nextLine(lvl.text, lvl.pos, text)) return true;
  } while (waitForText());
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
  TextPos p = prog.begin;
  std::string_view text;
  std::string norm;
  const std::string_view all = prog.source->text();
  const std::string_view lines = prog.end < all.size() ? all.substr(0, prog.end) : all;
  while (true) {
    TextPos at = p;
    if (!lang::nextLine(lines, p, text)) break;
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
  // A fed program: a forward search waits until an occurrence after `here` is fed (one before
  // it does not satisfy a forward search), or the text is complete.
  const std::vector<TextPos>* lines =
      search.forward ? labelLinesFrom(label, here + 1) : lvl.program->index->labels(label);
  if (!lines) return false;
  // The first occurrence the search meets (PM-NC "Program jumps": the destination is searched
  // from the jumping block in the jump's direction), so a label may stand more than once. The
  // lines are in file order: a binary search, however often a label is repeated.
  auto after = std::upper_bound(lines->begin(), lines->end(), here,
                                [](size_t h, const TextPos& p) { return h < p.offset; });
  if (search.forward && after != lines->end()) {
    lvl.pos = *after;
    return true;
  }
  if (after != lines->begin()) {
    const TextPos& before = *(after - 1);  // the last line at or before `here`
    if ((search.backward && before.offset < here) || (search.here_too && before.offset == here)) {
      lvl.pos = before;
      return true;
    }
    if (search.backward && before.offset == here && after - 1 != lines->begin()) {
      lvl.pos = *(after - 2);
      return true;
    }
  }
  return false;
}

size_t ProgramFlow::loadedBytes() const {
  size_t bytes = 0;
  const lang::SourceFile* last = nullptr;  // an archive's programs follow each other
  for (const auto& f : files_)
    if (f->source.get() != last) {
      last = f->source.get();
      bytes += last->text().size();
    }
  return bytes;
}

}  // namespace ncoffset::interp
