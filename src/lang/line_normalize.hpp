// Line normalisation for the block parser (PM-NC "Fundamentals of NC programming": the language
// is case-insensitive, `;` starts a comment, text in "..." is kept as written). normalizeLine
// (declared in lang/parser.hpp) is the public form; the parser uses normalizeInto, which reuses
// the block's buffer.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace ncoffset::lang {

// normalizeLine into `out` without shrinking it (a std::string that only grows is resized once,
// not for every block): sets `len` to the normalised length (up to a bad byte, for which it
// returns false and sets `bad_column`, 1-based) and, when it succeeds, puts a '\0' after it,
// which the parser's scans rely on (no other '\0' gets through outside strings).
bool normalizeInto(std::string_view text, std::string& out, size_t& len, int* bad_column);

}  // namespace ncoffset::lang
