// Character classes and name lists of the block parser (src/lang/lexical.hpp).
#include "lang/lexical.hpp"

#include <gtest/gtest.h>

namespace ncoffset::lang {
namespace {

TEST(Lexical, PackName) {
  EXPECT_EQ(packName(""), 0u);
  EXPECT_EQ(packName("A"), static_cast<std::uint64_t>('A'));
  EXPECT_NE(packName("AB"), packName("BA"));
  EXPECT_NE(packName("ENDWHILE"), 0u);          // eight characters still pack
  EXPECT_EQ(packName("ENDWHILE1"), 0u);         // nine do not
  EXPECT_FALSE(isControlKeyword("ENDWHILE1"));  // and match no keyword
}

TEST(Lexical, Keywords) {
  for (const char* kw : {"DEF",    "IF",     "ELSE",  "ENDIF", "WHILE",   "ENDWHILE", "FOR",
                         "ENDFOR", "REPEAT", "UNTIL", "LOOP",  "ENDLOOP", "GOTOF",    "GOTOB",
                         "GOTO",   "GOTOC",  "CASE",  "PROC",  "REPEATB", "DEFINE"})
    EXPECT_TRUE(isControlKeyword(kw)) << kw;
  EXPECT_FALSE(isControlKeyword("DEFINED"));
  EXPECT_FALSE(isControlKeyword("I"));
  EXPECT_EQ(jumpKind("GOTOF"), JumpKind::Gotof);
  EXPECT_EQ(jumpKind("GOTOB"), JumpKind::Gotob);
  EXPECT_EQ(jumpKind("GOTO"), JumpKind::Goto);
  EXPECT_EQ(jumpKind("GOTOC"), JumpKind::Gotoc);
  EXPECT_EQ(jumpKind("GOTOX"), JumpKind::None);
}

TEST(Lexical, ExtendedAddresses) {
  for (const char* a : {"X", "CR", "DISC", "I1", "SPOS", "SCC"})
    EXPECT_TRUE(isExtendedAddress(a)) << a;
  for (const char* a : {"$", "_", "CRX", "R1", "VAR", "DISCLX"})
    EXPECT_FALSE(isExtendedAddress(a)) << a;
}

TEST(Lexical, CharacterClasses) {
  EXPECT_TRUE(isAlpha('A') && isAlpha('_') && isAlpha('$'));
  EXPECT_FALSE(isAlpha('a'));  // the parser sees normalised (upper-case) text
  EXPECT_FALSE(isAlpha('1'));
  EXPECT_TRUE(isIdentChar('9'));
  EXPECT_FALSE(isIdentChar('.'));
}

}  // namespace
}  // namespace ncoffset::lang
