#include "support/golden_cases.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace ncoffset::golden {
namespace {

// The options of the case's "# args:" line that change a run.
void parseArgs(const std::string& args, const fs::path& dir, GoldenCase& c) {
  std::istringstream in(args);
  std::vector<std::string> a;
  for (std::string w; in >> w;) a.push_back(w);
  Limits& l = c.options.limits;
  for (size_t i = 0; i + 1 < a.size(); ++i) {
    const std::string& k = a[i];
    const std::string& v = a[i + 1];
    if (k == "--init") c.inits.push_back(dir / v);
    if (k == "--coords") c.options.coords = v == "wcs" ? CoordSystem::WCS : CoordSystem::MCS;
    if (k == "--max-blocks") l.max_blocks = std::stoll(v);
    if (k == "--max-blocks-without-motion") l.max_blocks_without_motion = std::stoll(v);
    if (k == "--max-expression-depth") l.max_expression_depth = std::stoi(v);
    if (k == "--max-line-length") l.max_line_length = std::stoul(v);
    if (k == "--max-program-levels") l.max_program_levels = std::stoi(v);
    if (k == "--max-total-elements") l.max_total_elements = std::stoul(v);
    if (k == "--max-variables") l.max_variables = std::stoul(v);
  }
}

class Ignore final : public PathSink {
 public:
  void segment(const Segment&) override {}
  void finish(const Alarm*) override {}
};

}  // namespace

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<GoldenCase> discoverGoldenCases(const fs::path& root) {
  std::vector<GoldenCase> cases;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    if (!e.is_regular_file() || e.path().extension() != ".expected") continue;
    GoldenCase c;
    fs::path stem = e.path();
    stem.replace_extension("");
    for (const char* ext : {".MPF", ".mpf"}) {
      fs::path p = stem;
      p += ext;
      if (fs::exists(p)) c.program = p;
    }
    if (c.program.empty()) continue;
    c.name = fs::relative(stem, root).string();
    for (auto& ch : c.name)
      if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    std::istringstream in(readAll(e.path()));
    for (std::string l; std::getline(in, l);)
      if (l.rfind("# args:", 0) == 0) parseArgs(l.substr(7), stem.parent_path(), c);
    cases.push_back(c);
  }
  std::sort(cases.begin(), cases.end(),
            [](const GoldenCase& a, const GoldenCase& b) { return a.name < b.name; });
  return cases;
}

bool runGoldenInits(Channel& ch, const GoldenCase& c) {
  for (const auto& f : c.inits) {
    Ignore ignored;
    if (ch.runInit(f, ignored).status != RunResult::Status::Ok) return false;
  }
  return true;
}

}  // namespace ncoffset::golden
