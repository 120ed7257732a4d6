// A SINUMERIK channel: runs init files and a part program and emits the path (the library's
// main entry point). Streaming: memory is bounded by the limits below, not by program length.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncoffset/alarm.hpp"
#include "ncoffset/path.hpp"
#include "ncoffset/tool.hpp"

namespace ncoffset {

// Explicit resource limits (docs/limits.md). Exceeding one ends the run with an alarm.
struct Limits {
  size_t max_line_length = 65536;  // characters in one block
  // Executed blocks of one run before alarm 99002 (the endless-loop guard). 0, the default, is
  // automatic: max_blocks_auto_base and 2 more for each byte of program text the run has loaded
  // (main program or init file, subprograms, cycles; docs/limits.md "Endless loops"), so that a
  // long CAM program never meets it and a short loop that never ends stops within a second.
  long long max_blocks = 0;
  long long max_blocks_auto_base = 5000000;
  // Blocks executed since the last motion: ends a loop without motion (WHILE TRUE, a jump
  // back, pass counts of a subprogram that only computes) in about a second.
  long long max_blocks_without_motion = 10000000;
  int max_expression_depth = 64;        // operator / parenthesis nesting in one expression
  int max_program_levels = 16;          // main program + 15 subprogram levels (PM-NC p493)
  int max_control_depth = 16;           // nested control structures per program level
  size_t max_variables = 10000;         // user variables (DEF) alive at once
  size_t max_array_elements = 1000000;  // elements of one array
  size_t max_total_elements = 4000000;  // elements of all live arrays together
  size_t max_tool_edges = 32000;        // cutting edges in the tool offset memory

  // The largest values the two limits may take (docs/limits.md): the parser and the evaluator
  // recurse once per nesting level (at this depth about 0.7 MB of stack, 1.9 MB under
  // AddressSanitizer), and one block's expression nodes grow with its length. Channel clamps
  // larger values to these; the command line refuses them.
  static constexpr int kMaxExpressionDepth = 1000;
  static constexpr size_t kMaxLineLength = size_t{1} << 22;  // 4 MiB
};

enum class CoordSystem { MCS, WCS };

struct RunOptions {
  CoordSystem coords = CoordSystem::MCS;
  Limits limits;
  // The transverse axis (MD20100) of the program's path as diameter values (positions and arc
  // centres times 2): --diameter, docs/turning.md. Default: radius values, as the machine
  // moves.
  bool diameter_output = false;
  // Where the machine stands when the channel starts: the tool carrier reference point in machine
  // coordinates (MCS, mm; `--start X,Y,Z`). The first segment starts here, and each segment
  // starts where the one before ended (docs/tool-offsets.md section 5). Not given: machine zero
  // 0,0,0, an assumed position: the CLI's drawings and statistics leave out the move from it
  // (docs/output-formats.md "Start position").
  std::optional<Vec3> start = std::nullopt;
};

// How a run ended.
struct RunResult {
  enum class Status { Ok, FileError, Alarm } status = Status::Ok;
  std::optional<Alarm> alarm;  // when status == Alarm
  std::string file_error;      // when status == FileError
};

class Stream;

class Channel {
 public:
  explicit Channel(RunOptions options = {});
  ~Channel();
  Channel(const Channel&) = delete;
  Channel& operator=(const Channel&) = delete;

  // Runs an init file (TO_INI, setting data, frames: NC syntax, ends with M17 or at its end).
  RunResult runInit(const std::filesystem::path& file, PathSink& sink);
  // Runs the part program. Subprograms are searched beside it.
  RunResult runProgram(const std::filesystem::path& file, PathSink& sink);
  // Runs program text held in memory (tests, fuzzing); `dir` is where subprograms are searched.
  // Each call is a whole program: its end flushes radius compensation's look-ahead (the modal
  // state stays). To feed one program piece by piece, use ncoffset::Stream (stream.hpp).
  RunResult runText(const std::string& name, const std::string& text, PathSink& sink,
                    const std::filesystem::path& dir = {});

  // Runs init-file text held in memory (fuzzing, tests).
  RunResult runInitText(const std::string& name, const std::string& text, PathSink& sink);

  // Where subprograms and cycles are searched after the main program's directory, in order
  // (`--path`): directories, or text archives holding several programs.
  void setSearchPath(std::vector<std::filesystem::path> path);

  // The file name of a Segment::file index.
  const std::string& fileName(int index) const;
  // The files loaded so far (Segment::file indices 0..fileCount()-1) and their text, as the
  // program was read (the HTML report lists them beside the drawing).
  int fileCount() const;
  std::string_view fileText(int index) const;
  // An axis machine datum of geometry axis 0 X, 1 Y, 2 Z by its name ("$MA_MAX_AX_VELO");
  // NaN for a name ncoffset does not know.
  double axisMachineData(std::string_view name, int axis) const;
  // The blocks executed so far (the progress line of the command line).
  long long blocksExecuted() const;
  // The cutting edge T, D of the offset memory as it is now (nullopt: none).
  std::optional<EdgeData> toolEdge(int tool, int edge) const;
  // R parameters that were written and the main program's user variables, as JSON (the
  // `--vars` contract of design.md).
  void writeVariablesJson(std::ostream& out) const;

 private:
  friend class Stream;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ncoffset
