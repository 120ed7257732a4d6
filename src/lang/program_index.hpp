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
  // Scans `file` from `begin` up to the line at offset `end` (one program of a text archive;
  // docs/language.md "Text archives"). Throws AlarmError with the offending line on invalid
  // nesting (12640) or nesting deeper than `max_depth` (12641).
  // A growable file (a Stream) is indexed as far as it has text; extend() indexes what was
  // appended since, finish() checks the nesting once the text is complete. A growing file is
  // never an archive range: it is indexed whole (begin and end left at their defaults).
  ProgramIndex(const SourceFile& file, int max_depth, size_t max_line_length, TextPos begin = {},
               size_t end = static_cast<size_t>(-1));
  void extend(const SourceFile& file);
  void finish() const;
  // Tests only: false passes usual lines over 16 characters at a time even where the processor
  // could take 32 (the twin of the AVX2 scan, tests/lang/program_index_test.cpp).
  static inline bool wide_scan = true;

  const ControlLink* link(size_t line_offset) const {
    auto it = links_.find(line_offset);
    return it == links_.end() ? nullptr : &it->second;
  }
  // The first line defining label `name`, nullptr if there is none.
  const TextPos* label(std::string_view name) const {
    auto it = labels_.find(name);
    return it == labels_.end() ? nullptr : &it->second.front();
  }
  // Every line defining label `name`, in file order: the control searches a jump destination
  // from the jumping block in the jump's direction and takes the first it meets, so one label
  // may stand in several places (docs/language.md "Labels"). nullptr if there is none.
  const std::vector<TextPos>* labels(std::string_view name) const {
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
  size_t end_;               // offset of the line after the indexed range (archive program)
  std::vector<Open> stack_;  // structures open at scanned_
  std::unordered_map<size_t, ControlLink> links_;
  std::unordered_map<std::string, std::vector<TextPos>, StringHash, std::equal_to<>> labels_;
};

}  // namespace ncoffset::lang
