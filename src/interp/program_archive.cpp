// Text archives (PM-NC "Program name": files in punched-tape format begin with `%` and the
// control-internal name, e.g. `%_N_SHAFT_MPF`, `%_N_DRILL_SPF`; an archive written by the HMI
// holds several such programs, each followed by a `;$PATH=/_N_xxx_DIR` comment line). Each
// `%` header begins a program that runs up to the next header: its lines keep their line
// numbers in the archive, so alarms point into the file the user has.
#include <cctype>

#include "interp/program_flow.hpp"

namespace ncoffset::interp {

namespace {

struct Header {
  lang::TextPos at;  // the `%` line
  std::string name;  // upper case, without `_N_` and the type suffix
  bool is_program = false;
  bool is_main = false;
};

// `%_N_NAME_MPF` -> NAME (main program); `%NAME_SPF` -> NAME (subprogram); other types
// (`_DEF`, `_INI`, ...) are data, no programs.
Header parseHeader(std::string_view line, lang::TextPos at) {
  Header h;
  h.at = at;
  std::string s;
  for (char c : line.substr(1)) {
    if (c == ' ' || c == '\t' || c == ';' || c == '\r') break;
    s.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  if (s.rfind("_N_", 0) == 0) s.erase(0, 3);
  if (s.size() > 4 &&
      (s.compare(s.size() - 4, 4, "_MPF") == 0 || s.compare(s.size() - 4, 4, "_SPF") == 0)) {
    h.is_program = true;
    h.is_main = s[s.size() - 3] == 'M';
    s.resize(s.size() - 4);
  }
  h.name = s;
  return h;
}

}  // namespace

LoadedProgram* ProgramFlow::loadArchive(const std::shared_ptr<lang::SourceFile>& source,
                                        std::map<std::string, LoadedProgram*>& into) {
  const std::string_view text = source->text();
  // Only a file that begins with a header can be an archive: a plain program costs one look.
  size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos || text[first] != '%') return nullptr;
  std::vector<Header> headers;
  lang::TextPos pos;
  std::string_view line;
  while (true) {
    lang::TextPos at = pos;
    if (!lang::nextLine(text, pos, line)) break;
    if (!line.empty() && line.front() == '%') headers.push_back(parseHeader(line, at));
  }
  source->releaseAll();
  if (headers.size() < 2) return nullptr;  // one program with its header: runs as a whole
  LoadedProgram* main = nullptr;
  LoadedProgram* any = nullptr;
  for (size_t k = 0; k < headers.size(); ++k) {
    const Header& h = headers[k];
    if (!h.is_program) continue;
    lang::TextPos begin = h.at;
    lang::nextLine(text, begin, line);  // the program starts after its header
    size_t end = k + 1 < headers.size() ? headers[k + 1].at.offset : kNoOffset;
    LoadedProgram& prog = loadRange(source, begin, end);
    into.emplace(h.name, &prog);
    if (!any) any = &prog;
    if (h.is_main && !main) main = &prog;
  }
  return main ? main : any;
}

bool ProgramFlow::nextSection() {
  ProgramLevel& lvl = levels_.back();
  lang::TextPos pos = lvl.pos;
  std::string_view line;
  while (true) {
    const lang::TextPos at = pos;
    if (!lang::nextLine(lvl.text, pos, line)) return false;
    if (!line.empty() && line.front() == '%') {
      lvl.pos = at;
      lvl.defs_allowed = true;
      return true;
    }
  }
}

}  // namespace ncoffset::interp
