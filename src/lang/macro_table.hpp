// Macros (PM-JP "Macro technique (DEFINE ... AS)"): `DEFINE NAME AS text` makes every later
// occurrence of the identifier NAME in a block stand for `text`. The expansion is textual and
// happens before a block is parsed, once (a macro's text is not expanded again: the manual
// allows no nesting). A program without macros never calls into this table (the interpreter
// tests `empty()` once per block).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "lang/program_index.hpp"

namespace ncoffset::lang {

class MacroTable {
 public:
  // The most macros one channel holds (docs/limits.md; alarm 99004 beyond it).
  static constexpr size_t kMaxMacros = 10000;

  bool empty() const { return macros_.empty(); }
  // DEFINE `name` AS `text` (both upper case). `global`: from an init or macro definition file
  // (kept for the following runs), else valid until the end of the current run. Throws 12170
  // (defined twice), 99010 (a text that would open or close a control structure or define a
  // label: the program's structure is indexed before it runs), 99004 (too many macros).
  void define(std::string_view name, std::string_view text, bool global);
  // The current run ended: its own macros go, those of init files stay.
  void endRun();
  // Writes `line` with its macros replaced into `out`; false (and `out` untouched in meaning)
  // when the line holds no macro or is itself a DEFINE. Throws 99001 when the expanded block
  // is longer than `max_length`.
  bool expand(std::string_view line, std::string& out, size_t max_length) const;

 private:
  void index();  // first_ and max_length_ from macros_

  std::unordered_map<std::string, std::string, StringHash, std::equal_to<>> macros_;
  std::vector<std::string> local_;  // macros of the current run
  // Quick rejection, so that a program run with a machine's macro file pays little for the
  // words that are no macros (G1, X10, ...): the first letters of the names, their longest.
  std::array<bool, 128> first_{};
  std::array<bool, 256> trigger_{};  // the first letters in both cases: a line without any
                                     // of them holds no macro
  size_t max_length_ = 0;
};

}  // namespace ncoffset::lang
