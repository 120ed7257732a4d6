// A program or init file held in memory (memory-mapped when possible), read line by line.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ncoffset::lang {

class SourceFile {
 public:
  // Loads a regular file; returns nullptr and sets `error` when it cannot be read or is not a
  // regular file (a FIFO, a device or a directory is refused without blocking on it).
  static std::shared_ptr<SourceFile> load(const std::filesystem::path& path, std::string* error);
  static std::shared_ptr<SourceFile> fromString(std::string name, std::string text);
  // An empty text that grows by append() as a Stream is fed. Its characters never move (the
  // address space for `capacity` characters is reserved up front), so views into it stay valid.
  // `more` is called when the reader needs text that has not been appended yet: it returns once
  // text was appended (true) or the text is complete (false).
  static std::shared_ptr<SourceFile> growable(std::string name, size_t capacity,
                                              std::function<bool()> more);
  ~SourceFile();
  SourceFile(const SourceFile&) = delete;
  SourceFile& operator=(const SourceFile&) = delete;

  std::string_view text() const { return text_; }
  // The name used in alarms: the path as the user gave it.
  const std::string& name() const { return name_; }
  const std::filesystem::path& path() const { return path_; }
  // Lets the kernel drop the mapped pages before `offset` (they are read again from the file
  // if a backward jump needs them), so resident memory stays flat in the program's length.
  void releaseBefore(size_t offset) const;
  // Drops all mapped pages and restarts the releaseBefore watermark (after a full scan).
  void releaseAll() const;

  // Growable texts (Stream): more may follow. Appending beyond the capacity returns false.
  bool growing() const { return more_ != nullptr; }
  // Made by growable(): fed piece by piece, complete or not.
  bool fed() const { return grow_ != nullptr; }
  bool append(std::string_view text);
  // Waits for more text (see growable()); false when the text is complete.
  bool waitForMore() const { return more_ && more_(); }
  // No more text follows.
  void complete() { more_ = nullptr; }

 private:
  SourceFile() = default;
  std::string name_;
  std::filesystem::path path_;
  std::string owned_;
  void* map_ = nullptr;
  size_t map_size_ = 0;
  mutable size_t released_ = 0;
  char* grow_ = nullptr;  // growable: the reserved characters
  size_t grow_capacity_ = 0;
  std::function<bool()> more_;
  std::string_view text_;
};

// A position in a file: byte offset of a line start and its 1-based line number.
struct TextPos {
  size_t offset = 0;
  int line = 1;
};

// The first '\n' of the `rest` characters at `begin`, nullptr if there is none. A line of a
// part program is short: the first 32 characters are searched inline (SSE2), without the call
// to memchr (docs/performance.md section 34).
inline const char* findNewline(const char* begin, size_t rest) {
#if defined(__SSE2__)
  const auto newlines = [](const char* p) {
    const __m128i chars = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    return static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(chars, _mm_set1_epi8('\n'))));
  };
  if (rest >= 32) {
    if (const unsigned first = newlines(begin); first != 0) return begin + __builtin_ctz(first);
    if (const unsigned second = newlines(begin + 16); second != 0)
      return begin + 16 + __builtin_ctz(second);
    return std::char_traits<char>::find(begin + 32, rest - 32, '\n');
  }
#endif
  return std::char_traits<char>::find(begin, rest, '\n');
}

// Reads the line at `pos` (without its CR/LF) and advances `pos` to the next line.
// Returns false at the end of the text.
inline bool nextLine(std::string_view text, TextPos& pos, std::string_view& line) {
  if (pos.offset >= text.size()) return false;
  const char* begin = text.data() + pos.offset;
  size_t rest = text.size() - pos.offset;
  const char* nl = findNewline(begin, rest);
  size_t len = nl ? static_cast<size_t>(nl - begin) : rest;
  pos.offset += len + (nl ? 1 : 0);
  ++pos.line;
  if (len > 0 && begin[len - 1] == '\r') --len;
  line = std::string_view(begin, len);
  return true;
}

}  // namespace ncoffset::lang
