#include "file_identity.hpp"

#include <fmt/format.h>
#include <sys/stat.h>

#include <cerrno>

namespace ncoffset::cli {

namespace fs = std::filesystem;

fs::path followLinks(const fs::path& path, std::error_code& ec) {
  fs::path p = path;
  for (int hops = 0; hops < 40; ++hops) {
    if (!fs::is_symlink(fs::symlink_status(p, ec))) {
      ec.clear();  // a missing name is no error here
      return p;
    }
    fs::path next = fs::read_symlink(p, ec);
    if (ec) return p;
    p = next.is_absolute() ? next : p.parent_path() / next;
  }
  ec = std::make_error_code(std::errc::too_many_symbolic_link_levels);
  return p;
}

namespace {

// The name a missing file would get: absolute, normal, links followed (also in its folders).
fs::path normalName(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::absolute(followLinks(path, ec), ec);
  // Absolute first: weakly_canonical leaves a relative name relative when none of it exists.
  fs::path canon = fs::weakly_canonical(p, ec);
  return ec ? p.lexically_normal() : canon;
}

}  // namespace

bool sameFile(const std::string& a, const std::string& b) {
  struct stat sa {};
  struct stat sb {};
  bool a_exists = ::stat(a.c_str(), &sa) == 0;
  bool b_exists = ::stat(b.c_str(), &sb) == 0;
  if (a_exists && b_exists) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  if (a_exists || b_exists) return false;  // a file that exists is none that does not
  return normalName(a) == normalName(b);
}

namespace {

// A device or a pipe (/dev/null, /dev/stdout) can take both outputs and is no input to lose.
bool isSpecial(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

}  // namespace

std::string outputClash(const std::vector<NamedPath>& inputs,
                        const std::vector<NamedPath>& outputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& out = outputs[i];
    if (isSpecial(out.path)) continue;
    for (const NamedPath& in : inputs)
      if (sameFile(out.path, in.path))
        return fmt::format("ncoffset: {} {} is the same file as {} {}: refusing to write over it",
                           out.role, out.path, in.role, in.path);
    for (size_t k = 0; k < i; ++k)
      if (sameFile(out.path, outputs[k].path))
        return fmt::format("ncoffset: {} {} is the same file as {} {}: refusing to write both",
                           out.role, out.path, outputs[k].role, outputs[k].path);
  }
  return {};
}

}  // namespace ncoffset::cli
