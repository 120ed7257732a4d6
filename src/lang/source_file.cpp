#include "lang/source_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace ncoffset::lang {

std::shared_ptr<SourceFile> SourceFile::load(const std::filesystem::path& path,
                                             std::string* error) {
  std::shared_ptr<SourceFile> f(new SourceFile());
  f->name_ = path.string();
  f->path_ = path;
  int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) {
    if (error) *error = std::strerror(errno);
    return nullptr;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    if (error) *error = S_ISDIR(st.st_mode) ? "is a directory" : "not a regular file";
    return nullptr;
  }
  if (st.st_size > 0) {
    void* p = ::mmap(nullptr, static_cast<size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    if (p != MAP_FAILED) {
      f->map_ = p;
      f->map_size_ = static_cast<size_t>(st.st_size);
      f->text_ = std::string_view(static_cast<const char*>(p), f->map_size_);
    } else {
      // Fall back to reading (e.g. on file systems without mmap).
      std::ifstream in(path, std::ios::binary);
      std::ostringstream ss;
      ss << in.rdbuf();
      f->owned_ = ss.str();
      f->text_ = f->owned_;
    }
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
}

}  // namespace ncoffset::lang
