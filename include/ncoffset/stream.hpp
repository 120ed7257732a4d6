// Streaming: a part program fed piece by piece (lines, blocks, any chunks of text) to a Channel,
// with the path coming out as it becomes final. The result is the one Channel::runText gives for
// the whole text: segment for segment, event for event (docs/architecture.md "Streaming").
//
// What feed() means for a program with jumps and loops: the stream keeps all text fed so far
// and executes it as far as it goes, as the control reads a program block by block:
//  * at the end of the fed text the program waits for more;
//  * a backward jump (GOTOB, the end of a loop) finds its destination in the text kept;
//  * a forward jump (GOTOF, GOTO, GOTOC) whose destination has not been fed waits for it, and
//    is decided (jump, or alarm 14080 / GOTOC's no-jump) only when the destination was fed or
//    finish() completed the text; likewise IF/WHILE/FOR/LOOP/REPEAT wait for their ELSE/END..;
//  * a structure error (12640/12641, a label defined twice) is found when the offending line is
//    fed, after the segments of the blocks before it were written (runText finds it before
//    running anything: the alarm is the same, the segments before it are not);
//  * the program ends at M2/M30 (text fed after it is ignored) or at the end of the text after
//    finish().
// Segments are final when they come out: radius compensation holds the blocks its look-ahead may
// still change (MD20240 and the open corner), and they come out when later blocks are fed or at
// finish(). Events (PathSink::tool, mFunction, ...) come in order with the segments.
//
// The program runs on a worker thread that runs only while feed() or finish() waits for it; the
// sink's methods are called on the caller's thread, from inside feed() and finish(), at most
// `kBatch` records being held between them. The fed text is kept (backward jumps need it), up to
// kMaxText characters (docs/limits.md).
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "ncoffset/channel.hpp"
#include "ncoffset/path.hpp"

namespace ncoffset {

class Stream {
 public:
  // The characters of program text a stream keeps at most (1 GiB; address space is reserved,
  // memory is used as the text grows). Feeding more throws std::length_error.
  static constexpr size_t kMaxText = size_t{1} << 30;
  // Records (segments, events, messages) held between the worker and the sink at most.
  static constexpr size_t kBatch = 4096;

  // A stream of the main program `name` on `channel` (after its init files), writing to `sink`;
  // subprograms are searched in `dir`. The channel runs nothing else until finish().
  Stream(Channel& channel, PathSink& sink, std::string name = "STREAM.MPF",
         std::filesystem::path dir = {});
  // Without finish(): the program is abandoned (nothing more is written, the sink is not
  // finished).
  ~Stream();
  Stream(const Stream&) = delete;
  Stream& operator=(const Stream&) = delete;

  // Appends program text (complete lines run; a line without its end waits for the rest) and
  // writes what became final. False once the program has ended (M2/M30 or an alarm): the text
  // is then ignored.
  bool feed(std::string_view text);
  // The text is complete: runs the rest, flushes the look-ahead, calls sink.finish() and returns
  // how the run ended (as Channel::runText). Later calls return the same result.
  RunResult finish();
  bool ended() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ncoffset
