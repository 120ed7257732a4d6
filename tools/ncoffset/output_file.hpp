// An output of the run (-o, --vars, or stdout), written so that a failed run never destroys
// the file it would replace: a regular (or not yet existing) target is written to a temporary
// file beside it and renamed onto it at the end; a device or a pipe (/dev/null, /dev/stdout)
// is written directly. Every write is checked and the first error is kept with its errno.
#pragma once

#include <sys/stat.h>
#include <sys/types.h>

#include <cstdio>
#include <filesystem>
#include <streambuf>
#include <string>

namespace ncoffset::cli {

class OutputFile {
 public:
  OutputFile() = default;
  ~OutputFile() { discard(); }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Opens `target` ("" is stdout). False with a message naming the target when it cannot be
  // written (e.g. a missing folder, a read-only file, a directory).
  bool open(const std::string& target, std::string& error);
  std::FILE* stream() const { return stream_; }
  // Flushes and closes: false with the reason when any write, the flush or the close failed
  // (the temporary file is then removed and the target left as it was).
  bool close(std::string& error);
  // Renames the closed temporary file onto the target (nothing to do for a direct output).
  bool publish(std::string& error);
  // Removes the temporary file, if any, leaving the target untouched.
  void discard();

 private:
  static ssize_t writeCookie(void* self, const char* data, size_t size);
  bool openDirect(std::string& error);
  bool openTemporary(const std::filesystem::path& real, const struct stat* existing,
                     std::string& error);
  bool makeStream(std::string& error);
  bool fail(std::string& error, int number);

  std::string name_;              // the target as given, for messages
  std::filesystem::path target_;  // where the temporary file goes (links followed)
  std::filesystem::path temp_;    // empty for a direct output or once renamed
  int fd_ = -1;
  bool own_fd_ = true;  // false for stdout, which stays open
  int errno_ = 0;       // the first write error
  std::FILE* stream_ = nullptr;
};

// Lets an std::ostream (the --vars JSON) write through an output's stdio stream, so its writes
// are checked like the others.
class StdioStreamBuf final : public std::streambuf {
 public:
  explicit StdioStreamBuf(std::FILE* f) : f_(f) {}

 protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char* s, std::streamsize n) override;

 private:
  std::FILE* f_;
};

}  // namespace ncoffset::cli
