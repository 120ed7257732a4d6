// Program flow of the channel (PM-JP "Program flow control", PM-NC "Subprograms"): the loaded
// programs, the stack of program levels (main program, subprograms with their pass counts), where
// each level reads next, and the search for jump destinations (labels and block numbers) and for
// subprogram files. What a control statement means (IF, WHILE, FOR, ...) is decided by the
// interpreter; this object moves the read positions.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "lang/program_index.hpp"
#include "lang/source_file.hpp"
#include "ncoffset/channel.hpp"

namespace ncoffset::interp {

inline constexpr size_t kNoOffset = static_cast<size_t>(-1);

struct LoadedProgram {
  std::shared_ptr<lang::SourceFile> source;
  // The program's lines: the whole file, or one program of a text archive (the lines after
  // its `%_N_NAME_SPF` header up to the next header; docs/language.md "Text archives").
  lang::TextPos begin;
  size_t end = kNoOffset;
  std::unique_ptr<lang::ProgramIndex> index;
  int file_id = 0;
  // A standard cycle built into ncoffset (src/cycles/, docs/cycles.md): its blocks report the
  // line of the block that called it.
  bool builtin = false;
  // Positions of block numbers used as jump targets, found on demand (N number -> lines).
  std::unordered_map<long long, std::vector<lang::TextPos>> block_numbers;
};

// One program level: the main program (level 0) or an active subprogram.
// The text of `prog` up to (not including) the line at offset `end`.
inline std::string_view textUpTo(const LoadedProgram& prog, size_t end) {
  const std::string_view all = prog.source->text();
  return end < all.size() ? all.substr(0, end) : all;
}

struct ProgramLevel {
  // A level always starts at its program's first line and reads only its program's text (so
  // there is no default constructor: a level without its text would end at once).
  explicit ProgramLevel(LoadedProgram& p) : program(&p), pos(p.begin), text(textUpTo(p, p.end)) {}
  LoadedProgram* program = nullptr;
  lang::TextPos pos;  // next line to read
  long long repeat_left = 0;
  bool defs_allowed = true;
  // The text this level reads: the file, cut after the last line of its archived program or of
  // its repeated section, so that the end-of-text test of nextLine ends the level there too
  // (no extra test per block).
  std::string_view text;
  // A program section repetition (REPEAT/REPEATB; PM-JP "Program section repetition"): a level
  // of its own over the same program, without variables of its own.
  bool section = false;
  lang::TextPos section_start;
  // A built-in cycle's level: the file, line and text of the calling block, which its blocks
  // report (report_file -1: the level's own lines).
  int report_file = -1;
  int report_line = 0;
  std::string_view report_text;
};

// A program section to repeat: its first line and the line it ends at.
struct Section {
  lang::TextPos start;
  size_t end = kNoOffset;  // offset of the end line
  bool inclusive = false;  // the end line belongs to the section
};

// Which way a jump searches (GOTOF, GOTOB, GOTO/GOTOC: forward first, then backward).
struct JumpSearch {
  bool forward = true;
  bool backward = false;
  bool here_too = false;  // GOTO/GOTOC: the jumping line itself is a destination
};

class ProgramFlow {
 public:
  explicit ProgramFlow(const Limits& limits) : limits_(limits) {}

  // Loads a program and indexes its control structures (alarms 12640/12641 from the index).
  // A text archive of several programs given as the program: its programs are found first by
  // the subprogram search, and the first main program (_MPF) in it runs (`programs` false for
  // an init file, which runs as a whole).
  LoadedProgram& load(std::shared_ptr<lang::SourceFile> source, bool programs = true);
  size_t fileCount() const { return files_.size(); }
  // The characters of program text loaded in this run (each file or archive once): the
  // automatic --max-blocks grows with it.
  size_t loadedBytes() const;
  // The file whose control structures were being checked when an alarm came (-1: none);
  // asking forgets it.
  int takeFailedFile() { return std::exchange(failed_file_, -1); }
  const std::string& fileName(int id) const {
    return files_[static_cast<size_t>(id)]->source->name();
  }
  std::string_view text(int id) const { return files_[static_cast<size_t>(id)]->source->text(); }
  // Where subprograms are searched: beside the main program.
  void setSearchDir(std::filesystem::path dir);

  // --- levels ---
  void begin(LoadedProgram& main);
  void clear() { levels_.clear(); }
  ProgramLevel& level() { return levels_.back(); }
  size_t depth() const { return levels_.size(); }
  // Reads the next line of the current level: its text and where it starts. False at the end
  // of the file.
  bool nextLine(std::string_view& text, lang::TextPos& at) {
    ProgramLevel& lvl = levels_.back();
    at = lvl.pos;
    if (lang::nextLine(lvl.text, lvl.pos, text)) return true;
    return nextLineFed(text);  // out of line: only at the end of a level's text
  }
  // A subprogram call with pass count P (alarms 14012 too deep, 12160 pass count, 14011 not
  // found).
  void call(std::string_view name, long long repeat);
  // A level that runs `prog` once from its start (CALL .. BLOCK: the caller then moves it to
  // the section's first line; alarm 14012 too deep).
  void callProgram(LoadedProgram& prog);
  // The current level ends: true if it runs again (pass count), false if it was left.
  bool leave();

  // --- program section repetition (section_repeat.cpp) ---
  // Repeats `s` of the current program `count` times as a level of its own (alarms 14012 too
  // deep, 12160 pass count); the caller's level continues after the REPEAT line.
  void repeatSection(const Section& s, long long count);
  // M17/RET in a repeated section: the repetition ends (the level is left at once).
  void abortSection() { levels_.pop_back(); }
  // Whether M2/M30 in the current level ends the whole program: the level is the main
  // program or a section repeated in it.
  bool inMainProgram() const;
  // An init file that is an archive of several sections (`%_N_SGUD_DEF`, `%_N_TO_INI`, ...):
  // after the end (M17/M30) of one section the next `%` header is read. False when none
  // follows.
  bool nextSection();
  // The label lines of `label` in the current program (nullptr if there is none).
  const std::vector<lang::TextPos>* labelLines(std::string_view label) const;
  // The same; in a fed program it first waits until an occurrence at or after offset `from` is
  // fed, or the text is complete (a forward search must not decide on a part of the text).
  const std::vector<lang::TextPos>* labelLinesFrom(std::string_view label, size_t from) const;

  // --- jumps in the current level ---
  // The level reads next from the line after `line`.
  void continueAfter(const lang::TextPos& line);
  // The closing or opening partner of the control statement on the line at `offset` (12640
  // if it stands elsewhere than at the start of its block).
  const lang::ControlLink& link(size_t offset) const;
  // Moves to the line with block number `n` / label `label` (upper case) found from the line at
  // `here`; false if there is none.
  bool jumpToBlockNumber(long long n, size_t here, JumpSearch search);
  bool jumpToLabel(const std::string& label, size_t here, JumpSearch search);

  // The subprogram `name` (upper case), loaded on first use; nullptr if there is none. The one
  // search every call form uses (docs/language.md "Where programs are found"): beside the main
  // program, then each --path entry in order (a directory, or a text archive); in each place
  // NAME.SPF, _N_NAME_SPF, NAME.MPF, _N_NAME_MPF, NAME, case-insensitive. The program comes
  // with its control structures checked (alarms 12640/12641, takeFailedFile() names it).
  LoadedProgram* find(std::string_view name);
  // The --path entries, searched after the main program's directory.
  void setSearchPath(std::vector<std::filesystem::path> path) { search_path_ = std::move(path); }
  // The programs of a text archive (each `%_N_NAME_xxx` section) become known by name; returns
  // the first main program (_MPF) section or else the first section, nullptr if `source` is no
  // archive of several programs.
  LoadedProgram* loadArchive(const std::shared_ptr<lang::SourceFile>& source,
                             std::map<std::string, LoadedProgram*>& into);

 private:
  // A growable program (Stream) at the end of its text (or of the view a level took of it
  // before a wait at a jump or structure fed more): waits for more (the control reads a
  // program block by block in the same way), then reads on. False once the text is complete.
  bool nextLineFed(std::string_view& text);
  // Waits for more text of the current level's program and indexes it; false when complete.
  bool waitForText() const;
  static bool waitForTextOf(LoadedProgram& prog);
  // A call that finds no program in a fed main program: the main program may be a text
  // archive, whose programs are known once its whole text is; waits for it (once).
  LoadedProgram* findInFedArchive(const std::string& key);
  const std::vector<lang::TextPos>& blockNumberLines(LoadedProgram& prog, long long n);
  LoadedProgram* findIn(const std::filesystem::path& dir, const std::string& key);
  // A standard cycle built into ncoffset (src/cycles/builtin_cycles.hpp), searched last.
  LoadedProgram* findBuiltin(const std::string& key);
  LoadedProgram& indexed(LoadedProgram& prog);
  LoadedProgram& loadRange(std::shared_ptr<lang::SourceFile> source, lang::TextPos begin,
                           size_t end);

  Limits limits_;
  std::vector<std::unique_ptr<LoadedProgram>> files_;
  std::map<std::string, LoadedProgram*> by_name_;  // upper-case program name -> program
  std::filesystem::path search_dir_;
  std::vector<std::filesystem::path> search_path_;
  // Per searched directory: upper-case file name -> path (listed once, on first use).
  std::map<std::filesystem::path, std::map<std::string, std::filesystem::path>> dir_entries_;
  // The programs of each archive (the main program's, --path entries), by upper-case name.
  std::map<std::filesystem::path, std::map<std::string, LoadedProgram*>> archives_;
  std::map<std::string, LoadedProgram*> main_archive_;  // the archive given as the program
  bool fed_archive_loaded_ = false;
  std::vector<ProgramLevel> levels_;
  int failed_file_ = -1;
};

}  // namespace ncoffset::interp
