// The predefined names (lang/reserved_names.hpp). The list follows what ncoffset reads: the
// parser's keywords and addresses (lang/lexical.hpp), the evaluator's functions, and the names
// the interpreter takes as commands (Interpreter::namedWord, its procedure calls) or refuses as
// not modelled; a name added there belongs here too.
#include "lang/reserved_names.hpp"

#include <algorithm>
#include <iterator>

#include "lang/lexical.hpp"
#include "lang/predefined_names.hpp"

namespace ncoffset::lang {
namespace {

// Sorted (std::binary_search).
constexpr std::string_view kPredefined[] = {
    "ABS",      "AC",        "ACOS",     "AMIRROR", "AND",      "AROT",      "AROTS",     "ASCALE",
    "ASIN",     "ASPLINE",   "ATAN2",    "ATRANS",  "AXIS",     "BOOL",      "BRISK",     "BSPLINE",
    "B_AND",    "B_NOT",     "B_OR",     "B_XOR",   "CALL",     "CDOF",      "CDOF2",     "CDON",
    "CFC",      "CFIN",      "CFINE",    "CFTCP",   "CHAN",     "CHANDATA",  "CHAR",      "CIP",
    "CMIRROR",  "COS",       "CROT",     "CROTS",   "CSCALE",   "CSPLINE",   "CTRANS",    "DAC",
    "DEFAULT",  "DIACYCOFA", "DIAM90",   "DIAM90A", "DIAMCHAN", "DIAMCHANA", "DIAMCYCOF", "DIAMOF",
    "DIAMOFA",  "DIAMON",    "DIAMONA",  "DIC",     "DISPLOF",  "DISPLON",   "DIV",       "DRIVE",
    "EXP",      "EXTCALL",   "FALSE",    "FFWOF",   "FFWON",    "FRAME",     "GETTCOR",   "IC",
    "INT",      "INVCCW",    "INVCW",    "KONT",    "KONTC",    "KONTT",     "LENTOAX",   "LN",
    "MAXVAL",   "MCALL",     "MINVAL",   "MIRROR",  "MOD",      "MSG",       "NCK",       "NORM",
    "NOT",      "OEMIPO1",   "OEMIPO2",  "OF",      "OR",       "PAROT",     "PAROTOF",   "PCALL",
    "POLY",     "POT",       "RAC",      "REAL",    "REP",      "RET",       "RIC",       "ROT",
    "ROTS",     "ROUND",     "ROUNDUP",  "SAVE",    "SCALE",    "SET",       "SETMS",     "SETTCOR",
    "SIN",      "SOFT",      "SQRT",     "STOPRE",  "STRING",   "STRLEN",    "SUPA",      "TAN",
    "TCARR",    "TCOABS",    "TCOFR",    "TCOFRX",  "TCOFRY",   "TCOFRZ",    "TO",        "TOFRAME",
    "TOFRAMEX", "TOFRAMEY",  "TOFRAMEZ", "TOROT",   "TOROTOF",  "TOROTX",    "TOROTY",    "TOROTZ",
    "TOWBCS",   "TOWKCS",    "TOWMCS",   "TOWSTD",  "TOWTCS",   "TOWWCS",    "TRAANG",    "TRACYL",
    "TRAFOOF",  "TRANS",     "TRANSMIT", "TRAORI",  "TRUE",     "TRUNC",     "WAITM",     "XOR",
};
static_assert(std::is_sorted(std::begin(kPredefined), std::end(kPredefined)));

bool isLetter(char c) {
  return c >= 'A' && c <= 'Z';
}

// X1, R5, G17, MD20270, SD42940: an address letter (or MD/SD) with a number.
bool isAddressWithNumber(std::string_view name) {
  size_t digits = 1;
  if (name.size() >= 3 && (name.substr(0, 2) == "MD" || name.substr(0, 2) == "SD")) digits = 2;
  if (name.size() <= digits || !isLetter(name[0])) return false;
  for (char c : name.substr(digits))
    if (!isDigit(c)) return false;
  return true;
}

}  // namespace

bool isPredefinedName(std::string_view name) {
  if (name.size() == 1) return isLetter(name[0]);  // address letters
  return isAddressWithNumber(name) || isExtendedAddress(name) || isControlKeyword(name) ||
         jumpKind(name) != lang::JumpKind::None ||
         std::binary_search(std::begin(kPredefined), std::end(kPredefined), name) ||
         findPredefinedName(name) != nullptr;  // SOFTA, ADIS, TOFFL, CYCLE81, ... (names.md)
}

const char* variableNameProblem(std::string_view name) {
  auto letterOrUnderscore = [](char c) { return isLetter(c) || c == '_'; };
  if (name.size() < 2 || !letterOrUnderscore(name[0]) || !letterOrUnderscore(name[1]))
    return "variable names start with two letters or underscores";
  for (char c : name)
    if (!isIdentChar(c) || c == '$') return "variable names hold letters, digits and underscores";
  if (name.size() > 31) return "variable names have at most 31 characters";
  return nullptr;
}

}  // namespace ncoffset::lang
