// Numbers in the output: the shortest decimal that reads back as the same double, exactly as
// {fmt}'s "{}" writes it, with a fast path for the common case of a value with at most six
// decimals (most coordinates of real programs), which needs no floating-point-to-decimal
// conversion at all.
#pragma once

#include <fmt/format.h>

namespace ncoffset::out {

// Writes v at `out` (room for 32 characters) and returns the end.
char* writeShortest(char* out, double v);

inline void appendShortest(fmt::memory_buffer& b, double v) {
  char text[32];
  b.append(text, writeShortest(text, v));
}

}  // namespace ncoffset::out
