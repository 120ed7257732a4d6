#include "lang/source_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <new>

namespace ncoffset::lang {

namespace {

// What a path that is not a regular file is, for the error message.
const char* notRegularReason(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISFIFO(mode)) return "not a regular file (a FIFO)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "not a regular file (a device)";
  if (S_ISSOCK(mode)) return "not a regular file (a socket)";
  return "not a regular file";
}

// Reads the whole file from `fd` (when it cannot be mapped); false on a read error.
bool readAll(int fd, std::string& out) {
  char chunk[1 << 16];
  for (;;) {
    ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n == 0) return true;
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return false;
    out.append(chunk, static_cast<size_t>(n));
  }
}

}  // namespace

std::shared_ptr<SourceFile> SourceFile::load(const std::filesystem::path& path,
                                             std::string* error) {
  auto fail = [error](const char* why) -> std::shared_ptr<SourceFile> {
    if (error) *error = why;
    return nullptr;
  };
  // Only regular files are opened: opening a FIFO blocks until a writer comes, and opening a
  // device can have side effects. stat() first keeps them from being opened at all; O_NONBLOCK
  // and the fstat() below cover a file swapped for a FIFO in between.
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return fail(std::strerror(errno));
  if (!S_ISREG(st.st_mode)) return fail(notRegularReason(st.st_mode));
  int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) return fail(std::strerror(errno));
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    int saved = errno;
    ::close(fd);
    return fail(S_ISREG(st.st_mode) ? std::strerror(saved) : notRegularReason(st.st_mode));
  }
  std::shared_ptr<SourceFile> f(new SourceFile());
  f->name_ = path.string();
  f->path_ = path;
  void* p = st.st_size > 0
                ? ::mmap(nullptr, static_cast<size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0)
                : MAP_FAILED;
  if (p != MAP_FAILED) {
    f->map_ = p;
    f->map_size_ = static_cast<size_t>(st.st_size);
    f->text_ = std::string_view(static_cast<const char*>(p), f->map_size_);
  } else if (st.st_size > 0) {
    // Fall back to reading (e.g. on file systems without mmap), from the descriptor already
    // checked rather than by opening the path again.
    if (!readAll(fd, f->owned_)) {
      int saved = errno;
      ::close(fd);
      return fail(std::strerror(saved));
    }
    f->text_ = f->owned_;
  }
  ::close(fd);
  return f;
}

std::shared_ptr<SourceFile> SourceFile::fromString(std::string name, std::string text) {
  std::shared_ptr<SourceFile> f(new SourceFile());
  f->name_ = std::move(name);
  f->path_ = f->name_;
  f->owned_ = std::move(text);
  f->text_ = f->owned_;
  return f;
}

std::shared_ptr<SourceFile> SourceFile::growable(std::string name, size_t capacity,
                                                 std::function<bool()> more) {
  std::shared_ptr<SourceFile> f(new SourceFile());
  f->name_ = std::move(name);
  f->path_ = f->name_;
  // Reserved, not committed: pages are backed by memory as the text reaches them.
  void* p = ::mmap(nullptr, capacity, PROT_READ | PROT_WRITE,
                   MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  f->grow_ = static_cast<char*>(p);
  f->grow_capacity_ = capacity;
  f->text_ = std::string_view(f->grow_, 0);
  f->more_ = std::move(more);
  return f;
}

bool SourceFile::append(std::string_view text) {
  if (!grow_ || text.size() > grow_capacity_ - text_.size()) return false;
  std::memcpy(grow_ + text_.size(), text.data(), text.size());
  text_ = std::string_view(grow_, text_.size() + text.size());
  return true;
}

void SourceFile::releaseBefore(size_t offset) const {
  if (!map_) return;
  const size_t page = static_cast<size_t>(::sysconf(_SC_PAGESIZE));
  size_t end = std::min(offset, map_size_) / page * page;
  if (end <= released_ + (4u << 20)) return;  // in steps of at least 4 MiB
  ::madvise(static_cast<char*>(map_) + released_, end - released_, MADV_DONTNEED);
  released_ = end;
}

void SourceFile::releaseAll() const {
  if (map_) ::madvise(map_, map_size_, MADV_DONTNEED);
  released_ = 0;
}

SourceFile::~SourceFile() {
  if (map_) ::munmap(map_, map_size_);
  if (grow_) ::munmap(grow_, grow_capacity_);
}

}  // namespace ncoffset::lang
