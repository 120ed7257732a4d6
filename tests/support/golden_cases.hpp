// The golden cases (tests/programs/**/NAME.MPF with NAME.expected) as the library runs them: the
// program, the options of the case's "# args:" line that change a run, and its init files. Used
// by the tests that run every golden program through the library (tests/stream/).
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "ncoffset/channel.hpp"

namespace ncoffset::golden {

struct GoldenCase {
  std::filesystem::path program;
  std::string name;  // the path below tests/programs, every other character than [A-Za-z0-9] '_'
  RunOptions options;
  std::vector<std::filesystem::path> inits;
};

inline void PrintTo(const GoldenCase& c, std::ostream* os) {
  *os << c.name;
}

std::string readAll(const std::filesystem::path& p);
// Every case below `root`, sorted by name.
std::vector<GoldenCase> discoverGoldenCases(const std::filesystem::path& root);
// Runs the case's init files on `ch`; false if one failed (the case is then about the init file).
bool runGoldenInits(Channel& ch, const GoldenCase& c);

}  // namespace ncoffset::golden
