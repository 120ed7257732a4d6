// Strict parsing of the --max-* limit options (docs/limits.md): decimal digits only, within a
// documented range. CLI11 alone reads "0x10" as 16, "010" as 8 and clamps or wraps numbers
// beyond the type, which could turn a guard such as --max-blocks off.
#pragma once

#include <CLI/CLI.hpp>

namespace ncoffset::cli {

// The largest value of most limit options (the range of an int).
inline constexpr unsigned long long kLimitMax = 2147483647ULL;
// The largest --max-blocks: about a day of execution even for fast programs.
inline constexpr unsigned long long kMaxBlocksMax = 1000000000000ULL;

// A transform for a limit option: accepts min..max written in decimal digits and hands the
// number on in canonical form (no leading zeros, which CLI11 would read as octal).
CLI::Validator limitValue(unsigned long long max, unsigned long long min = 1);

}  // namespace ncoffset::cli
