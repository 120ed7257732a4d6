// Runs a part program through ncoffset::Channel and prints what a PathSink receives: one line
// per segment (source line, motion, end point, arc centre, feed), MSG texts, warnings and the
// alarm that stopped the run, then the final variables (with the active tool, $P_TOOLNO).
//
//   embed_example [--init FILE]... PROGRAM
//
// Exit status: 0 ran to the end, 1 file error, 2 stopped by an alarm.
#include <iostream>
#include <ncoffset/channel.hpp>
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
  int s = status(channel.runProgram(program, sink));
  if (s == 1) return s;
  channel.writeVariablesJson(std::cout);  // R parameters, user variables, $P_TOOLNO, ...
  std::cout << '\n';
  return s;
}
