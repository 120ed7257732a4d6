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
#include <vector>

#include "lang/program_index.hpp"
#include "lang/source_file.hpp"
#include "ncoffset/channel.hpp"

namespace ncoffset::interp {

struct LoadedProgram {
  std::shared_ptr<lang::SourceFile> source;
  std::unique_ptr<lang::ProgramIndex> index;
  int file_id = 0;
  // Positions of block numbers used as jump targets, found on demand (N number -> lines).
  std::unordered_map<long long, std::vector<lang::TextPos>> block_numbers;
};

// One program level: the main program (level 0) or an active subprogram.
struct ProgramLevel {
  LoadedProgram* program = nullptr;
  lang::TextPos pos;  // next line to read
  long long repeat_left = 0;
  bool defs_allowed = true;
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
  LoadedProgram& load(std::shared_ptr<lang::SourceFile> source);
  size_t fileCount() const { return files_.size(); }
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
    if (lang::nextLine(lvl.program->source->text(), lvl.pos, text)) return true;
    return lvl.program->source->growing() && nextLineFed(text);
  }
  // A subprogram call with pass count P (alarms 14012 too deep, 12160 pass count, 14011 not
  // found).
  void call(std::string_view name, long long repeat);
  // The current level ends: true if it runs again (pass count), false if it was left.
  bool leave();

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

  // The subprogram `name` (upper case) beside the main program, loaded on first use; nullptr if
  // there is none.
  LoadedProgram* find(std::string_view name);

 private:
  // A growable program (Stream) at the end of its text: waits for more (the control reads a
  // program block by block in the same way), then reads on. False once the text is complete.
  bool nextLineFed(std::string_view& text);
  // Waits for more text of the current level's program and indexes it; false when complete.
  bool waitForText() const;
  const std::vector<lang::TextPos>& blockNumberLines(LoadedProgram& prog, long long n);

  Limits limits_;
  std::vector<std::unique_ptr<LoadedProgram>> files_;
  std::map<std::string, LoadedProgram*> by_name_;  // upper-case program name -> program
  std::filesystem::path search_dir_;
  std::map<std::string, std::filesystem::path> dir_entries_;  // upper-case file name -> path
  bool dir_scanned_ = false;
  std::vector<ProgramLevel> levels_;
};

}  // namespace ncoffset::interp
