// Character classes and the name lists the block parser decides by (PM-NC "Fundamentals of NC
// programming", "Addresses"; PM-JP "Flexible NC programming" for the control keywords). All
// inline: the plain-word fast path asks them for every word, and they must cost no call.
#pragma once

#include <cstdint>
#include <string_view>

#include "lang/block.hpp"

namespace ncoffset::lang {

// After normalisation (upper case): letters, '_' and '$' may start a name.
inline bool isAlpha(char c) {
  return (c >= 'A' && c <= 'Z') || c == '_' || c == '$';
}
inline bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
inline bool isIdentChar(char c) {
  return isAlpha(c) || isDigit(c);
}
// PM-JP "Program jumps": a label name starts with two letters or underscores (`MARK1:`,
// `_A:`); `L12:` or `X1:` is no label.
inline bool isLabelStart(char first, char second) {
  auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || c == '_'; };
  return letter(first) && letter(second);
}

// Up to eight characters packed into one integer (first character lowest), so that a name is
// looked up in a keyword list by one switch instead of string comparisons; names longer than
// eight characters pack to 0, which matches no keyword.
constexpr std::uint64_t packName(std::string_view w) {
  if (w.empty() || w.size() > 8) return 0;
  std::uint64_t v = 0;
  for (size_t i = 0; i < w.size(); ++i)
    v |= static_cast<std::uint64_t>(static_cast<unsigned char>(w[i])) << (8 * i);
  return v;
}

// Keywords that open or continue statements with their own syntax.
inline bool isControlKeyword(std::string_view w) {
  switch (packName(w)) {
    case packName("DEF"):
    case packName("IF"):
    case packName("ELSE"):
    case packName("ENDIF"):
    case packName("WHILE"):
    case packName("ENDWHILE"):
    case packName("FOR"):
    case packName("ENDFOR"):
    case packName("REPEAT"):
    case packName("REPEATB"):
    case packName("DEFINE"):
    case packName("UNTIL"):
    case packName("LOOP"):
    case packName("ENDLOOP"):
    case packName("GOTOF"):
    case packName("GOTOB"):
    case packName("GOTO"):
    case packName("GOTOC"):
    case packName("CASE"):
    case packName("PROC"):
    case packName("EXTERN"):
    case packName("MCALL"):
    case packName("CALL"):
    case packName("PCALL"):
    case packName("EXTCALL"):
      return true;
    default:
      return false;
  }
}

// The jump a keyword stands for (JumpKind::None for any other word).
inline JumpKind jumpKind(std::string_view w) {
  if (w == "GOTOF") return JumpKind::Gotof;
  if (w == "GOTOB") return JumpKind::Gotob;
  if (w == "GOTO") return JumpKind::Goto;
  if (w == "GOTOC") return JumpKind::Gotoc;
  return JumpKind::None;
}

// Addresses that take a value after '=' (CR=10, DISC=50) besides the single letters.
// Predefined procedures written with an axis in brackets and no '=' (PM-NC "Axis-specific
// diameter programming": DIAMONA[X]): a procedure call, not an indexed variable.
inline bool isAxisProcedure(std::string_view name) {
  return name == "DIAMONA" || name == "DIAM90A" || name == "DIAMOFA" || name == "DIACYCOFA" ||
         name == "DIAMCHANA";
}

inline bool isExtendedAddress(std::string_view name) {
  if (name.size() == 1) return name[0] != '$' && name[0] != '_';
  switch (packName(name)) {
    case packName("CR"):
    case packName("AR"):
    case packName("TURN"):
    case packName("DISR"):
    case packName("DISC"):
    case packName("OFFN"):
    case packName("DISCL"):
    case packName("DISRP"):
    case packName("FAD"):
    case packName("RPL"):
    case packName("RND"):
    case packName("RNDM"):
    case packName("CHF"):
    case packName("CHR"):
    case packName("SPOS"):
    case packName("SPOSA"):
    case packName("FRC"):
    case packName("FRCM"):
    case packName("ANG"):
    case packName("AP"):
    case packName("RP"):
    case packName("DISPR"):
    case packName("I1"):
    case packName("J1"):
    case packName("K1"):
    case packName("CT"):
    case packName("SF"):
    case packName("FA"):
    case packName("POS"):
    case packName("POSA"):
    case packName("ACC"):
    case packName("OVR"):
    case packName("LIMS"):
    case packName("MOVT"):
    case packName("PM"):
    case packName("PR"):
    case packName("STOLF"):
    case packName("DITS"):
    case packName("DITE"):
    case packName("SCC"):
      return true;
    default:
      return false;
  }
}

}  // namespace ncoffset::lang
