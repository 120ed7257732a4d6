#include "progress_line.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "terminal_text.hpp"

namespace ncoffset::cli {
namespace {
bool g_shown = false;  // one stderr, one progress line

long long countLines(std::string_view text) {
  long long n = 0;
  for (const char* p = text.data();
       (p = static_cast<const char*>(std::memchr(p, '\n', text.data() + text.size() - p))); ++p)
    ++n;
  return n + (!text.empty() && text.back() != '\n' ? 1 : 0);
}
}  // namespace

ProgressLine::ProgressLine(bool enabled, ProgressSource source)
    : enabled_(enabled),
      source_(std::move(source)),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

ProgressLine::~ProgressLine() {
  clearProgressLine();
}

std::string ProgressLine::percent(int line, int file) {
  if (file < 0 || !source_.file_text) return {};
  if (lines_.size() <= static_cast<size_t>(file)) lines_.resize(static_cast<size_t>(file) + 1, 0);
  long long& total = lines_[static_cast<size_t>(file)];
  if (total == 0) {
    std::string_view text = source_.file_text(file);
    total = text.size() > kLargeFile ? std::max(1LL, countLines(text)) : -1;
  }
  if (total < 0) return {};
  return fmt::format(", {:.0f} % of the file", 100.0 * std::min<double>(line, total) / total);
}

void ProgressLine::update(int line, int file) {
  using namespace std::chrono;
  auto now = steady_clock::now();
  if (now - start_ < seconds(1) || now - last_ < milliseconds(250)) return;
  const double since_last = duration<double>(now - last_).count();
  last_ = now;
  double elapsed = duration<double>(now - start_).count();
  const long long blocks = source_.blocks ? source_.blocks() : 0;
  const double rate = since_last > 0 ? static_cast<double>(blocks - last_blocks_) / since_last : 0;
  last_blocks_ = blocks;
  const std::string name = source_.file_name ? source_.file_name(file) : std::string();
  // \r and erase-to-end-of-line: the line is rewritten in place; the file name is escaped like
  // every program text on stderr.
  std::string text = fmt::format(
      "\r\x1b[Kncoffset: {}:{}: {:.1f} M blocks ({:.2f} M blocks/s), {:.1f} M segments{}, {:.0f} s",
      terminalSafe(name), line, static_cast<double>(blocks) / 1e6, rate / 1e6,
      static_cast<double>(count_) / 1e6, percent(line, file), elapsed);
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
