// Runs a part program through ncoffset::Channel and prints what a PathSink receives: one line
// per segment (source line, motion, end point, arc centre, feed), the tool changes (T, D, M6 with
// the edge's radius and length vector), MSG texts, warnings and the alarm that stopped the run,
// then the final variables (with the active tool, $P_TOOLNO). The program is streamed: read in
// chunks of 4 KiB and fed to an ncoffset::Stream, which writes only final segments, as a
// simulation fed from a network or a control would use it.
//
//   embed_example [--init FILE]... PROGRAM
//
// Exit status: 0 ran to the end, 1 file error, 2 stopped by an alarm.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <ncoffset/channel.hpp>
#include <ncoffset/stream.hpp>
#include <ncoffset/version.hpp>
#include <string>
#include <vector>

namespace {

class PrintingSink final : public ncoffset::PathSink {
 public:
  void segment(const ncoffset::Segment& s) override {
    std::cout << "segment line " << s.line << ' ' << ncoffset::motionName(s.motion) << " to "
              << s.end.x << ' ' << s.end.y << ' ' << s.end.z;
    if (s.motion == ncoffset::Motion::G2 || s.motion == ncoffset::Motion::G3)
      std::cout << " centre " << s.centre.x << ' ' << s.centre.y << ' ' << s.centre.z;
    if (s.has_feed) std::cout << " F" << s.feed;
    std::cout << '\n';
  }
  bool wantsEvents() const override { return true; }
  void tool(const ncoffset::ToolEvent& t) override {
    static constexpr const char* kWord[] = {"T", "D", "M6"};
    std::cout << "tool line " << t.line << ' ' << kWord[static_cast<int>(t.word)] << ": T" << t.tool
              << " D" << t.edge << " radius " << t.radius << " length " << t.length.x << ' '
              << t.length.y << ' ' << t.length.z << '\n';
  }
  void message(const ncoffset::SourceLoc& where, const std::string& text) override {
    std::cout << "message line " << where.line << ": " << text << '\n';
  }
  void warning(const ncoffset::SourceLoc& where, int number, const std::string& text) override {
    std::cout << "warning " << number << " line " << where.line << ": " << text << '\n';
  }
  void finish(const ncoffset::Alarm* alarm) override {
    if (alarm)
      std::cout << "alarm " << alarm->number << " at " << alarm->where.file << ':'
                << alarm->where.line << ": " << alarm->text << '\n';
    else
      std::cout << "end\n";
  }
};

// 0 for Ok; prints a file error.
int status(const ncoffset::RunResult& r) {
  if (r.status == ncoffset::RunResult::Status::FileError) {
    std::cerr << r.file_error << '\n';
    return 1;
  }
  return r.status == ncoffset::RunResult::Status::Alarm ? 2 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> inits;
  std::string program;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--init" && i + 1 < argc)
      inits.push_back(argv[++i]);
    else
      program = arg;
  }
  if (program.empty()) {
    std::cerr << "usage: embed_example [--init FILE]... PROGRAM\n";
    return 1;
  }
  std::cout << "ncoffset " << NCOFFSET_VERSION_STRING << '\n';
  ncoffset::RunOptions options;
  options.coords = ncoffset::CoordSystem::MCS;
  ncoffset::Channel channel(options);
  PrintingSink sink;
  for (const auto& init : inits)
    if (int s = status(channel.runInit(init, sink))) return s;
  std::ifstream file(program, std::ios::binary);
  if (!file) {
    std::cerr << "cannot read " << program << '\n';
    return 1;
  }
  const std::filesystem::path path(program);
  ncoffset::Stream stream(channel, sink, path.filename().string(), path.parent_path());
  char chunk[4096];
  while (file.read(chunk, sizeof chunk) || file.gcount() > 0)
    if (!stream.feed(std::string_view(chunk, static_cast<size_t>(file.gcount())))) break;
  int s = status(stream.finish());
  if (s == 1) return s;
  channel.writeVariablesJson(std::cout);  // R parameters, user variables, $P_TOOLNO, ...
  std::cout << '\n';
  return s;
}
