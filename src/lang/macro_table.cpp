#include "lang/macro_table.hpp"

#include <fmt/format.h>

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
std::string upper(std::string_view s) {
  std::string u(s);
  for (auto& c : u)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return u;
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
}

void MacroTable::endRun() {
  for (const auto& n : local_) macros_.erase(n);
  local_.clear();
}

bool MacroTable::expand(std::string_view line, std::string& out, size_t max_length) const {
  out.clear();
  bool replaced = false, head = true;
  size_t i = 0;
  const size_t n = line.size();
  while (i < n) {
    const char c = line[i];
    if (c == ';') break;  // the comment is kept as written
    size_t j = i + 1;
    if (c == '"' || c == '\'') {
      while (j < n && line[j] != c) ++j;  // strings and quoted constants as written
      j = j < n ? j + 1 : n;
    } else if (c == '$' || (c >= '0' && c <= '9') || c == '.') {
      while (j < n && (identChar(line[j]) || line[j] == '.')) ++j;  // $NAME, numbers
    } else if (identStart(c)) {
      while (j < n && identChar(line[j])) ++j;
      std::string_view word = line.substr(i, j - i);
      const bool label = j < n && line[j] == ':' && (j + 1 >= n || line[j + 1] != '=');
      if (head && !label && !isBlockNumber(word)) {
        head = false;
        if (upper(word) == "DEFINE") return false;  // a definition's text is not expanded
      }
      auto it = label ? macros_.end() : macros_.find(upper(word));
      if (it != macros_.end()) {
        out += it->second;
        replaced = true;
        i = j;
        if (out.size() > max_length) break;
        continue;
      }
    }
    out.append(line, i, j - i);
    i = j;
  }
  if (!replaced) return false;
  out.append(line, i, n - i);
  if (out.size() > max_length)
    raise(AlarmNumber::LineTooLong,
          fmt::format("block with its macros expanded is longer than the limit of {} characters "
                      "(--max-line-length)",
                      max_length));
  return true;
}

}  // namespace ncoffset::lang
