#include "progress_line.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "terminal_text.hpp"

namespace ncoffset::cli {
namespace {
bool g_shown = false;  // one stderr, one progress line
}

ProgressLine::ProgressLine(bool enabled)
    : enabled_(enabled), start_(std::chrono::steady_clock::now()), last_(start_) {}

ProgressLine::~ProgressLine() {
  clearProgressLine();
}

void ProgressLine::update(int line, const std::string& file) {
  using namespace std::chrono;
  auto now = steady_clock::now();
  if (now - start_ < seconds(1) || now - last_ < milliseconds(250)) return;
  last_ = now;
  double elapsed = duration<double>(now - start_).count();
  // \r and erase-to-end-of-line: the line is rewritten in place; the file name is escaped like
  // every program text on stderr.
  std::string text =
      fmt::format("\r\x1b[Kncoffset: {}:{}: {:.1f} M segments, {:.0f} s", terminalSafe(file), line,
                  static_cast<double>(count_) / 1e6, elapsed);
  std::fputs(text.c_str(), stderr);
  std::fflush(stderr);
  g_shown = true;
}

void clearProgressLine() {
  if (!g_shown) return;
  std::fputs("\r\x1b[K", stderr);
  std::fflush(stderr);
  g_shown = false;
}

}  // namespace ncoffset::cli
