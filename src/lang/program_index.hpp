// Per-file index built by one pass over the text before a program runs: its labels and the
// partner lines of its control structures (IF/ELSE/ENDIF, WHILE, FOR, REPEAT, LOOP). This is
// what lets jumps and loops work without keeping a structure per block: memory grows with the
// number of labels and control statements only (PM-JP "Program flow control").
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "lang/source_file.hpp"

namespace ncoffset::lang {

struct ControlLink {
  TextPos partner;  // IF: its ELSE (or ENDIF); ELSE: ENDIF; WHILE/FOR/REPEAT/LOOP: closing line;
                    // closing lines: the opening line
  TextPos end;      // IF: its ENDIF
};

struct StringHash {
  using is_transparent = void;
  size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
};

class ProgramIndex {
 public:
  // Scans `file`. Throws AlarmError with the offending line on invalid nesting (12640) or
  // nesting deeper than `max_depth` (12641).
  // A growable file (a Stream) is indexed as far as it has text; extend() indexes what was
  // appended since, finish() checks the nesting once the text is complete.
  ProgramIndex(const SourceFile& file, int max_depth, size_t max_line_length);
  void extend(const SourceFile& file);
  void finish() const;

  const ControlLink* link(size_t line_offset) const {
    auto it = links_.find(line_offset);
    return it == links_.end() ? nullptr : &it->second;
  }
  const TextPos* label(std::string_view name) const {
    auto it = labels_.find(name);
    return it == labels_.end() ? nullptr : &it->second;
  }

 private:
  struct Open {
    std::string_view keyword;  // IF, WHILE, FOR, REPEAT, LOOP
    TextPos pos;
    TextPos else_pos;
    bool has_else = false;
  };
  void scanLine(TextPos here, std::string_view line, std::string& norm);

  int max_depth_;
  size_t max_line_length_;
  TextPos scanned_;          // where the next extend() starts
  std::vector<Open> stack_;  // structures open at scanned_
  std::unordered_map<size_t, ControlLink> links_;
  std::unordered_map<std::string, TextPos, StringHash, std::equal_to<>> labels_;
};

}  // namespace ncoffset::lang
