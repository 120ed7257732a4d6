#include "lang/program_index.hpp"

#include <fmt/format.h>

#include <vector>

#include "lang/parser.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {
namespace {

struct Open {
  std::string_view keyword;  // IF, WHILE, FOR, REPEAT, LOOP
  TextPos pos;
  TextPos else_pos;
  bool has_else = false;
};

std::string_view closerOf(std::string_view opener) {
  if (opener == "IF") return "ENDIF";
  if (opener == "WHILE") return "ENDWHILE";
  if (opener == "FOR") return "ENDFOR";
  if (opener == "REPEAT") return "UNTIL";
  return "ENDLOOP";
}

// The normalized line buffer is reused, so openers are kept as views of static strings.
std::string_view staticKeyword(std::string_view kw) {
  static constexpr std::string_view kOpeners[] = {"IF", "WHILE", "FOR", "REPEAT", "LOOP"};
  for (auto o : kOpeners)
    if (o == kw) return o;
  return {};
}

}  // namespace

ProgramIndex::ProgramIndex(const SourceFile& file, int max_depth, size_t max_line_length) {
  std::string_view text = file.text();
  TextPos pos;
  std::string_view line;
  std::string norm;
  std::vector<Open> stack;
  while (true) {
    TextPos here = pos;
    if (!nextLine(text, pos, line)) break;
    if (line.size() > max_line_length) continue;  // reported when executed
    // Only the head of a line matters, except for IF (which may be a jump).
    std::string_view head = line.substr(0, 96);
    if (!normalizeLine(head, norm, nullptr)) continue;
    LineHead h = scanLineHead(norm);
    if (h.keyword == "IF" && line.size() > head.size()) {
      if (!normalizeLine(line, norm, nullptr)) continue;
      h = scanLineHead(norm);
    }
    if (!h.label.empty()) {
      std::string name(h.label);
      if (labels_.count(name))
        throw AlarmError(alarm_no::kSyntaxError, fmt::format("label {} defined twice", name), here.line);
      labels_.emplace(std::move(name), here);
    }
    std::string_view kw = h.keyword;
    if (kw.empty()) continue;
    if (kw == "IF" && h.has_goto) continue;
    if (kw == "IF" || kw == "WHILE" || kw == "FOR" || kw == "REPEAT" || kw == "LOOP") {
      if (static_cast<int>(stack.size()) >= max_depth)
        throw AlarmError(alarm_no::kControlDepth,
                         fmt::format("nesting depth of control structures exceeded (limit {})", max_depth),
                         here.line);
      stack.push_back({staticKeyword(kw), here, {}, false});
      continue;
    }
    if (kw == "ELSE") {
      if (stack.empty() || stack.back().keyword != "IF" || stack.back().has_else)
        throw AlarmError(alarm_no::kControlNesting, "invalid nesting of control structures: ELSE without IF", here.line);
      stack.back().has_else = true;
      stack.back().else_pos = here;
      continue;
    }
    if (kw == "ENDIF" || kw == "ENDWHILE" || kw == "ENDFOR" || kw == "UNTIL" || kw == "ENDLOOP") {
      if (stack.empty() || closerOf(stack.back().keyword) != kw)
        throw AlarmError(alarm_no::kControlNesting,
                         fmt::format("invalid nesting of control structures: {} {}", kw,
                                     stack.empty() ? std::string("without opening statement")
                                                   : fmt::format("closes {} of line {}",
                                                                 stack.back().keyword,
                                                                 stack.back().pos.line)),
                         here.line);
      Open o = stack.back();
      stack.pop_back();
      if (o.keyword == "IF") {
        links_[o.pos.offset] = {o.has_else ? o.else_pos : here, here};
        if (o.has_else) links_[o.else_pos.offset] = {here, here};
      } else {
        links_[o.pos.offset] = {here, here};
      }
      links_[here.offset] = {o.pos, o.pos};
    }
  }
  if (!stack.empty()) {
    const Open& o = stack.back();
    throw AlarmError(alarm_no::kControlNesting,
                     fmt::format("invalid nesting of control structures: {} without {}", o.keyword,
                                 closerOf(o.keyword)),
                     o.pos.line);
  }
}

}  // namespace ncoffset::lang
