// Golden end-to-end tests. Each case is a program `NAME.MPF` (any folder below
// tests/programs/) with `NAME.expected` beside it:
//
//   # args: --init TOOLS.INI --coords wcs     (optional, extra command-line arguments)
//   # status: 2                               (optional, default 0)
//   # stderr: NAME.MPF:4: alarm 14040: *      (one line each, in order; a trailing * matches
//                                              any rest of the line)
//   line,motion,x,y,z,cx,cy,cz,feed           (expected CSV; numbers compared to 1e-6 mm)
//   ...
//
// The program's header comment explains how the expected values were derived by hand.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Case {
  fs::path program;
  fs::path expected;
  std::string name;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

std::vector<Case> discover() {
  std::vector<Case> cases;
  for (const auto& e : fs::recursive_directory_iterator(NCOFFSET_PROGRAMS)) {
    if (!e.is_regular_file() || e.path().extension() != ".expected") continue;
    fs::path stem = e.path();
    stem.replace_extension("");
    fs::path mpf;
    for (const char* ext : {".MPF", ".mpf"}) {
      fs::path p = stem;
      p += ext;
      if (fs::exists(p)) mpf = p;
    }
    std::string name = fs::relative(stem, NCOFFSET_PROGRAMS).string();
    for (auto& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    cases.push_back({mpf, e.path(), name});
  }
  std::sort(cases.begin(), cases.end(),
            [](const Case& a, const Case& b) { return a.name < b.name; });
  return cases;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string l;
  while (std::getline(in, l)) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    out.push_back(l);
  }
  return out;
}

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else {
      cur.push_back(c);
    }
  }
  out.push_back(cur);
  return out;
}

bool sameField(const std::string& want, const std::string& got) {
  if (want == got) return true;
  if (want.empty() || got.empty()) return false;
  char* e1;
  char* e2;
  double a = std::strtod(want.c_str(), &e1);
  double b = std::strtod(got.c_str(), &e2);
  if (*e1 || *e2) return false;
  return std::fabs(a - b) <= 1e-6;
}

// ` 12 | G1 X1` or `    | ^`: what the CLI prints under an alarm.
bool isSourceContext(const std::string& l) {
  size_t bar = l.find(" | ");
  if (bar == std::string::npos || l.empty() || l[0] != ' ') return false;
  for (size_t i = 0; i < bar; ++i)
    if (l[i] != ' ' && !std::isdigit(static_cast<unsigned char>(l[i]))) return false;
  return true;
}

class Golden : public testing::TestWithParam<Case> {};

TEST_P(Golden, MatchesExpected) {
  const Case& c = GetParam();
  ASSERT_FALSE(c.program.empty()) << "no .MPF beside " << c.expected;
  std::string args;
  int status = 0;
  std::vector<std::string> want_err, want_csv;
  for (const auto& l : lines(readAll(c.expected))) {
    if (l.rfind("# args:", 0) == 0)
      args = l.substr(7);
    else if (l.rfind("# status:", 0) == 0)
      status = std::atoi(l.substr(9).c_str());
    else if (l.rfind("# stderr:", 0) == 0)
      want_err.push_back(l.substr(l.size() > 9 && l[9] == ' ' ? 10 : 9));
    else if (l.rfind("#", 0) == 0 || l.empty())
      continue;
    else
      want_csv.push_back(l);
  }
  fs::path dir = c.program.parent_path();
  // The process id in the name: two builds' test runs (Release and ASan) may run the same case
  // at the same moment.
  fs::path tmp =
      fs::temp_directory_path() / ("ncoffset_golden_" + c.name + "_" + std::to_string(::getpid()));
  std::string cmd = "cd '" + dir.string() + "' && '" NCOFFSET_CLI "' " + args + " -o '" +
                    tmp.string() + ".csv' '" + c.program.filename().string() + "' 2> '" +
                    tmp.string() + ".err' < /dev/null";
  int rc = std::system(cmd.c_str());
  int got_status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  std::string err = readAll(tmp.string() + ".err");
  std::vector<std::string> got_csv = lines(readAll(tmp.string() + ".csv"));
  EXPECT_EQ(got_status, status) << "stderr:\n" << err;
  std::vector<std::string> got_err;
  bool after_alarm = false;
  for (const auto& l : lines(err)) {
    // The source line and the caret under an alarm (` 12 | text`, `    |   ^`): their shape is
    // checked here, their content by the tests of the CLI.
    if (after_alarm && isSourceContext(l)) continue;
    after_alarm = l.find(": alarm ") != std::string::npos;
    if (l.find(": message: ") == std::string::npos || !want_err.empty()) got_err.push_back(l);
  }
  ASSERT_EQ(got_err.size(), want_err.size()) << "stderr:\n" << err;
  for (size_t i = 0; i < want_err.size(); ++i) {
    const std::string& w = want_err[i];
    bool ok = !w.empty() && w.back() == '*' ? got_err[i].rfind(w.substr(0, w.size() - 1), 0) == 0
                                            : got_err[i] == w;
    EXPECT_TRUE(ok) << "stderr line " << i + 1 << "\n  want: " << w << "\n  got:  " << got_err[i];
  }
  ASSERT_EQ(got_csv.size(), want_csv.size()) << "CSV rows differ; got:\n"
                                             << readAll(tmp.string() + ".csv");
  for (size_t i = 0; i < want_csv.size(); ++i) {
    auto w = split(want_csv[i]);
    auto g = split(got_csv[i]);
    bool ok = w.size() == g.size();
    for (size_t k = 0; ok && k < w.size(); ++k) ok = sameField(w[k], g[k]);
    EXPECT_TRUE(ok) << "CSV row " << i << "\n  want: " << want_csv[i] << "\n  got:  " << got_csv[i];
  }
  fs::remove(tmp.string() + ".csv");
  fs::remove(tmp.string() + ".err");
}

INSTANTIATE_TEST_SUITE_P(Programs, Golden, testing::ValuesIn(discover()),
                         [](const testing::TestParamInfo<Case>& i) { return i.param.name; });

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
