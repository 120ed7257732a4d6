// Whether two command-line paths name the same file, so that an output (-o, --vars) is never
// written over an input (the program, an --init file) or over the other output.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ncoffset::cli {

// A path from the command line and what it is for the message ("the program", "-o").
struct NamedPath {
  std::string role;
  std::string path;
};

// `path` with symbolic links in its last component followed (relative links against the link's
// folder), so that a link to a file not yet written leads to that file's name. Sets `ec`
// (ELOOP) after 40 links.
std::filesystem::path followLinks(const std::filesystem::path& path, std::error_code& ec);

// True when `a` and `b` are the same file: the same device and inode when both exist (hard
// links, symbolic links and other spellings alike); otherwise the same absolute, normal name
// once links are followed (two outputs that do not exist yet, or an output and a missing input).
bool sameFile(const std::string& a, const std::string& b);

// The message for the first output that is the same file as an input or an earlier output;
// empty when all are distinct.
std::string outputClash(const std::vector<NamedPath>& inputs,
                        const std::vector<NamedPath>& outputs);

}  // namespace ncoffset::cli
