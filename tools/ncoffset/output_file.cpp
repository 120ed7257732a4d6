#include "output_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "file_identity.hpp"

namespace ncoffset::cli {

namespace fs = std::filesystem;

bool OutputFile::fail(std::string& error, int number) {
  error = fmt::format("ncoffset: {}: cannot write: {}", name_, std::strerror(number));
  discard();
  return false;
}

bool OutputFile::open(const std::string& target, std::string& error) {
  name_ = target.empty() ? "stdout" : target;
  if (target.empty()) {
    fd_ = STDOUT_FILENO;
    own_fd_ = false;
    return makeStream(error);
  }
  target_ = target;
  struct stat st {};
  bool exists = ::stat(target.c_str(), &st) == 0;
  if (!exists && errno != ENOENT) return fail(error, errno);
  if (exists && !S_ISREG(st.st_mode)) return openDirect(error);
  // The file is replaced by a rename, which a read-only file would not stop: refuse it as
  // opening it for writing would.
  if (exists && ::access(target.c_str(), W_OK) != 0) return fail(error, errno);
  std::error_code ec;
  fs::path real = followLinks(target, ec);
  if (ec) return fail(error, ec.value());
  struct stat real_st {};
  if (exists && (::stat(real.c_str(), &real_st) != 0 || real_st.st_dev != st.st_dev ||
                 real_st.st_ino != st.st_ino))
    return openDirect(error);  // e.g. /proc/self/fd/1 of a deleted file: no name to replace
  return openTemporary(real, exists ? &st : nullptr, error);
}

bool OutputFile::openDirect(std::string& error) {
  fd_ = ::open(target_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOCTTY | O_CLOEXEC, 0666);
  if (fd_ < 0) return fail(error, errno);
  return makeStream(error);
}

bool OutputFile::openTemporary(const fs::path& real, const struct stat* existing,
                               std::string& error) {
  target_ = real;
  static unsigned counter = 0;
  fs::path dir = real.parent_path();
  for (int attempt = 0; attempt < 100; ++attempt) {
    // Hidden, unique per process and output; O_EXCL never reuses a name left by a killed run.
    // The target's name is cut to 200 bytes so that the whole stays within NAME_MAX (255).
    fs::path temp =
        dir / fmt::format(".{}.ncoffset-{}-{}.tmp", real.filename().string().substr(0, 200),
                          static_cast<long>(::getpid()), counter++);
    fd_ = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOCTTY | O_CLOEXEC, 0666);
    if (fd_ >= 0) {
      temp_ = temp;
      // The replacement keeps the permissions of the file it replaces (best effort: a file
      // system without modes refuses, and the umask's default stays).
      if (existing) (void)::fchmod(fd_, existing->st_mode & 07777);
      return makeStream(error);
    }
    if (errno != EEXIST) return fail(error, errno);
  }
  return fail(error, EEXIST);
}

// A stdio stream over fd_ whose writes go through writeCookie, so the first failing write's
// errno is kept (a plain FILE's error flag loses it).
bool OutputFile::makeStream(std::string& error) {
  cookie_io_functions_t io{nullptr, &OutputFile::writeCookie, nullptr, nullptr};
  stream_ = ::fopencookie(this, "w", io);
  if (!stream_) return fail(error, errno);
  std::setvbuf(stream_, nullptr, _IOFBF, 1 << 16);
  return true;
}

ssize_t OutputFile::writeCookie(void* self, const char* data, size_t size) {
  auto* out = static_cast<OutputFile*>(self);
  if (out->errno_) return 0;  // after the first error nothing more is written
  size_t done = 0;
  while (done < size) {
    ssize_t n = ::write(out->fd_, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      out->errno_ = n < 0 ? errno : EIO;
      return 0;  // fopencookie: 0 reports the error (a negative value is not allowed)
    }
    done += static_cast<size_t>(n);
  }
  return static_cast<ssize_t>(size);
}

bool OutputFile::close(std::string& error) {
  if (stream_) {
    int rc = std::fclose(stream_);
    stream_ = nullptr;
    if (rc != 0 && !errno_) errno_ = EIO;
  }
  if (fd_ >= 0 && own_fd_ && ::close(fd_) != 0 && !errno_) errno_ = errno;
  fd_ = -1;
  if (errno_) return fail(error, errno_);
  return true;
}

// An existing file is exchanged with the temporary one, which then holds the old contents and is
// removed: as atomic as a rename, but a rename onto an existing file makes ext4 write the new
// file's blocks out at once (auto_da_alloc), 2.7 ms for the 2.8 MB CSV of a 100,000-block run,
// a sixth of its time (docs/performance.md §41). Power loss is not covered either way
// (docs/robustness.md). Without a file to replace, or where the file system cannot exchange, a
// rename.
bool OutputFile::publish(std::string& error) {
  if (temp_.empty()) return true;
  if (::renameat2(AT_FDCWD, temp_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
    ::unlink(temp_.c_str());  // the old contents
  } else if (::rename(temp_.c_str(), target_.c_str()) != 0) {
    return fail(error, errno);
  }
  temp_.clear();
  return true;
}

void OutputFile::discard() {
  if (stream_) {
    // Nothing more may reach the target: the error that led here is reported already.
    errno_ = errno_ ? errno_ : ECANCELED;
    std::fclose(stream_);
    stream_ = nullptr;
  }
  if (fd_ >= 0 && own_fd_) ::close(fd_);
  fd_ = -1;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  temp_.clear();
}

StdioStreamBuf::int_type StdioStreamBuf::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  return std::fputc(c, f_) == EOF ? traits_type::eof() : c;
}

std::streamsize StdioStreamBuf::xsputn(const char* s, std::streamsize n) {
  return static_cast<std::streamsize>(std::fwrite(s, 1, static_cast<size_t>(n), f_));
}

}  // namespace ncoffset::cli
