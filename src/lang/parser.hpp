// Parser for one block of the SINUMERIK NC language (PM-NC "Fundamentals of NC programming",
// "Flexible NC programming"). Case-insensitive; `;` starts a comment; `/` marks a skippable
// block; `N<no>`/`:<no>` block numbers; `NAME:` labels. Knows nothing of geometry.
#pragma once

#include <string_view>

#include "lang/block.hpp"

namespace ncoffset::lang {

// The deepest nesting any caller may allow (Limits::kMaxExpressionDepth): the parser and the
// evaluator recurse once per level, and at this depth they use about 0.7 MB of stack (1.9 MB
// under AddressSanitizer; docs/limits.md). parseBlock clamps larger limits to it.
inline constexpr int kMaxExpressionDepth = 1000;

struct ParseLimits {
  // Nesting of parentheses, calls, unary operators and operators of rising priority in one
  // expression (alarm 99003); at most kMaxExpressionDepth.
  int max_expression_depth = 64;
};

// Parses `text` (one line without its line end) into `out` (cleared first). Throws
// AlarmError (12080 syntax error, 99011 bad character, 99003 expression too deep).
void parseBlock(std::string_view text, int line, Block& out, const ParseLimits& limits = {});

// Upper-cases `text` outside string literals and cuts the `;` comment. Returns false when the
// line contains a byte the language does not allow outside comments and strings (NUL, control
// characters, non-ASCII); `bad_column` then holds its 1-based column.
bool normalizeLine(std::string_view text, std::string& out, int* bad_column);

// The first keyword of a line after block number and label (upper-cased), for the control
// structure pre-scan. Empty when there is none. `label` receives a label definition.
struct LineHead {
  std::string_view keyword;
  std::string_view label;
  bool has_goto = false;       // the line contains GOTOF/GOTOB/GOTO/GOTOC (IF as a jump)
  bool has_arguments = false;  // something follows the keyword (REPEAT LABEL: a section)
};
LineHead scanLineHead(std::string_view normalized);

}  // namespace ncoffset::lang
