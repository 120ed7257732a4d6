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
  ProgramIndex(const SourceFile& file, int max_depth, size_t max_line_length, TextPos begin = {},
               size_t end = static_cast<size_t>(-1));

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
  std::unordered_map<size_t, ControlLink> links_;
  std::unordered_map<std::string, std::vector<TextPos>, StringHash, std::equal_to<>> labels_;
};

}  // namespace ncoffset::lang
