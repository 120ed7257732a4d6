// Shared by the writer tests: segments built by hand, a temporary output file, and a tiny
// check that a document's tags are balanced (SVG, HTML).
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "ncoffset/path.hpp"

namespace ncoffset::out::test {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

inline std::string readAll(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
  return s;
}

inline Segment lineSeg(int no, Motion m, Vec3 start, Vec3 end, double feed = 0) {
  Segment s;
  s.line = no;
  s.motion = m;
  s.start = start;
  s.end = end;
  s.feed = feed;
  s.has_feed = m != Motion::G0;
  return s;
}

inline Segment arcSeg(int no, Motion m, Vec3 start, Vec3 end, Vec3 centre, Vec3 normal,
                      double feed = 100, int turns = 0) {
  Segment s = lineSeg(no, m, start, end, feed);
  s.centre = centre;
  s.normal = normal;
  s.turns = turns;
  return s;
}

// Built member by member (GCC 12 warns falsely on the nested aggregate initialiser).
inline Alarm makeAlarm(int number, const std::string& file, int at, const std::string& text) {
  Alarm a;
  a.number = number;
  a.where.file = file;
  a.where.line = at;
  a.text = text;
  return a;
}

// Empty when every element opened is closed in order (self-closing, comments, <?..?> and
// <!..> skipped); otherwise what went wrong.
inline std::string tagBalance(const std::string& doc, const std::vector<std::string>& voids = {}) {
  std::vector<std::string> open;
  size_t i = 0;
  while ((i = doc.find('<', i)) != std::string::npos) {
    if (doc.compare(i, 4, "<!--") == 0) {
      i = doc.find("-->", i);
      if (i == std::string::npos) return "unterminated comment";
      continue;
    }
    size_t e = doc.find('>', i);
    if (e == std::string::npos) return "unterminated tag at " + std::to_string(i);
    std::string tag = doc.substr(i + 1, e - i - 1);
    i = e + 1;
    if (tag.empty()) return "empty tag";
    if (tag[0] == '?' || tag[0] == '!' || tag.back() == '/') continue;
    bool closing = tag[0] == '/';
    std::string name = tag.substr(closing ? 1 : 0,
                                  tag.find_first_of(" \t\n", closing ? 1 : 0) - (closing ? 1 : 0));
    bool is_void = false;
    for (const auto& v : voids) is_void = is_void || v == name;
    if (is_void) continue;
    if (!closing) {
      open.push_back(name);
      // Raw text elements: their content is no markup.
      if (name == "style" || name == "script") {
        size_t c = doc.find("</" + name + ">", i);
        if (c == std::string::npos) return "unterminated " + name;
        i = c;
      }
    } else if (open.empty() || open.back() != name) {
      return "</" + name + "> closes " + (open.empty() ? "nothing" : "<" + open.back() + ">");
    } else {
      open.pop_back();
    }
  }
  return open.empty() ? "" : "<" + open.back() + "> left open";
}

}  // namespace ncoffset::out::test
