// The table of predefined names (lang/predefined_names.*): lookups, prefixes, and that
// docs/names.md lists every row with the same class.
#include "lang/predefined_names.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace ncoffset::lang {
namespace {

TEST(PredefinedNames, FindsExactNamesAndFamilies) {
  const PredefinedName* soft_a = findPredefinedName("SOFTA");
  ASSERT_NE(soft_a, nullptr);
  EXPECT_EQ(soft_a->cls, NameClass::NoPathEffect);
  const PredefinedName* tofflr = findPredefinedName("TOFFLR");
  ASSERT_NE(tofflr, nullptr);
  EXPECT_EQ(tofflr->cls, NameClass::NotModelled);
  EXPECT_TRUE(tofflr->zero_accepted);
  const PredefinedName* toffl = findPredefinedName("TOFFL");  // a reserved name with code
  ASSERT_NE(toffl, nullptr);
  EXPECT_EQ(toffl->cls, NameClass::Modelled);
  const PredefinedName* scp = findPredefinedName("$TC_SCP13");
  ASSERT_NE(scp, nullptr);
  EXPECT_EQ(scp->name, "$TC_SCP");
  // The exact row wins over the family: $AC_TIME has its own sentence.
  ASSERT_NE(findPredefinedName("$AC_TIME"), nullptr);
  EXPECT_EQ(findPredefinedName("$AC_TIME")->name, "$AC_TIME");
  EXPECT_EQ(findPredefinedName("$AC_PATHN")->name, "$AC_");
  EXPECT_EQ(findPredefinedName("FOOBAR"), nullptr);
  EXPECT_EQ(findPredefinedName("CYCLE8"), nullptr);  // no prefix match of CYCLE81
  EXPECT_TRUE(findPredefinedName("CYCLE81")->cycle);
}

// Every row of the table stands in docs/names.md as "| `NAME` | kind | (x) | ..." with the
// same class letter (a row of a family ends in "…").
TEST(PredefinedNames, DocsListEveryRowWithItsClass) {
  std::ifstream in(NCOFFSET_DOCS_DIR "/names.md");
  ASSERT_TRUE(in) << "docs/names.md not found";
  std::map<std::string, char> documented;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| `", 0) != 0) continue;
    const size_t end = line.find('`', 3);
    std::string name = line.substr(3, end - 3);
    const std::string ellipsis = "\u2026";
    if (name.size() > ellipsis.size() &&
        name.compare(name.size() - ellipsis.size(), ellipsis.size(), ellipsis) == 0)
      name.resize(name.size() - ellipsis.size());
    const size_t cls = line.find("| (", end);
    if (cls != std::string::npos) documented[name] = line[cls + 3];
  }
  for (const PredefinedName* p = predefinedNamesBegin(); p != predefinedNamesEnd(); ++p) {
    const std::string name(p->name);
    const char expected = p->cls == NameClass::Modelled       ? 'a'
                          : p->cls == NameClass::NoPathEffect ? 'b'
                                                              : 'c';
    auto it = documented.find(name);
    ASSERT_NE(it, documented.end()) << name << " is missing in docs/names.md";
    EXPECT_EQ(it->second, expected) << name;
  }
}

}  // namespace
}  // namespace ncoffset::lang
