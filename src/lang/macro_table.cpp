#include "lang/macro_table.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "lang/lexical.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {
namespace {

bool identStart(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
}
bool identChar(char c) {
  return identStart(c) || (c >= '0' && c <= '9');
}
char upper(char c) {
  return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
}
bool isDefine(std::string_view w) {
  if (w.size() != 6) return false;
  for (size_t k = 0; k < 6; ++k)
    if (upper(w[k]) != "DEFINE"[k]) return false;
  return true;
}
// A block number N10 (not a name).
bool isBlockNumber(std::string_view w) {
  if (w.size() < 2 || (w[0] != 'N' && w[0] != 'n')) return false;
  for (char c : w.substr(1))
    if (c < '0' || c > '9') return false;
  return true;
}

// The words a macro may not stand for: the control structures and labels are indexed from the
// program text before it runs, so a macro cannot make one (ncoffset limit, docs/language.md).
bool structural(std::string_view text) {
  size_t i = 0;
  while (i < text.size() && identChar(text[i])) ++i;
  std::string_view first = text.substr(0, i);
  static constexpr std::string_view kWords[] = {
      "IF",    "ELSE", "ENDIF",   "WHILE", "ENDWHILE", "FOR",  "ENDFOR", "REPEAT",
      "UNTIL", "LOOP", "ENDLOOP", "CASE",  "DEFINE",   "PROC", "DEF",    "REPEATB"};
  for (auto w : kWords)
    if (first == w) return true;
  return i < text.size() && text[i] == ':' && (i + 1 >= text.size() || text[i + 1] != '=');
}

}  // namespace

void MacroTable::define(std::string_view name, std::string_view text, bool global) {
  if (macros_.find(name) != macros_.end())
    raise(AlarmNumber::AlreadyDefined, fmt::format("macro {} defined several times", name));
  if (structural(text))
    raise(AlarmNumber::NotModelled,
          fmt::format("macro {} AS {}: a macro that opens or closes a control structure or "
                      "defines a label is not modelled by ncoffset (the structure of a program "
                      "is indexed before it runs)",
                      name, text));
  if (macros_.size() >= kMaxMacros)
    raise(AlarmNumber::TooManyVariables, fmt::format("more than {} macros", kMaxMacros));
  macros_.emplace(std::string(name), std::string(text));
  if (!global) local_.emplace_back(name);
  index();
}

void MacroTable::endRun() {
  for (const auto& n : local_) macros_.erase(n);
  local_.clear();
  index();
}

void MacroTable::index() {
  first_.fill(false);
  trigger_.fill(false);
  max_length_ = 0;
  for (const auto& [name, text] : macros_) {
    const unsigned char c = static_cast<unsigned char>(name[0]);
    first_[c & 0x7F] = true;
    trigger_[c] = true;
    if (c >= 'A' && c <= 'Z') trigger_[c - 'A' + 'a'] = true;
    max_length_ = std::max(max_length_, name.size());
  }
}

bool MacroTable::expand(std::string_view line, std::string& out, size_t max_length) const {
  size_t any = 0;
  while (any < line.size() && !trigger_[static_cast<unsigned char>(line[any])]) ++any;
  if (any == line.size()) return false;  // no letter a macro name begins with
  bool head = true;
  size_t i = 0, copied = 0;  // line[0, copied) is in `out`
  const size_t n = line.size();
  char name[64];
  while (i < n) {
    const char c = line[i];
    if (c == ';') break;  // the comment is kept as written
    size_t j = i + 1;
    if (c == '"' || c == '\'') {
      while (j < n && line[j] != c) ++j;  // strings and quoted constants as written
      i = j < n ? j + 1 : n;
      continue;
    }
    if (c == '$' || (c >= '0' && c <= '9') || c == '.') {
      while (j < n && (identChar(line[j]) || line[j] == '.')) ++j;  // $NAME, numbers
      i = j;
      continue;
    }
    if (!identStart(c)) {
      i = j;
      continue;
    }
    while (j < n && identChar(line[j])) ++j;
    const std::string_view word = line.substr(i, j - i);
    const bool label = j < n && line[j] == ':' && (j + 1 >= n || line[j + 1] != '=');
    if (head && !label && !isBlockNumber(word)) {
      head = false;
      if (isDefine(word)) return false;  // a definition's text is not expanded
    }
    if (!label && word.size() <= max_length_ && word.size() <= sizeof name &&
        first_[static_cast<unsigned char>(upper(c)) & 0x7F]) {
      for (size_t k = 0; k < word.size(); ++k) name[k] = upper(word[k]);
      auto it = macros_.find(std::string_view(name, word.size()));
      if (it != macros_.end()) {
        if (copied == 0) out.clear();
        out.append(line, copied, i - copied);
        out += it->second;
        copied = j;
        if (out.size() > max_length) break;
      }
    }
    i = j;
  }
  if (copied == 0) return false;
  out.append(line, copied, n - copied);
  if (out.size() > max_length)
    raise(AlarmNumber::LineTooLong,
          fmt::format("block with its macros expanded is longer than the limit of {} characters "
                      "(--max-line-length)",
                      max_length));
  return true;
}

}  // namespace ncoffset::lang
