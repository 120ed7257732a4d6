// The inside of Channel, shared by channel.cpp and stream.cpp: the chain of stages and the sink
// switch that orders events against the segments (docs/architecture.md "Events").
#pragma once

#include <deque>
#include <memory>
#include <variant>

#include "core/inline_step.hpp"
#include "interp/diameter_sink.hpp"
#include "interp/interpreter.hpp"
#include "ncoffset/channel.hpp"
#include "place/placement.hpp"
#include "trc/radius_compensation.hpp"
#include "trc/smooth_approach.hpp"

namespace ncoffset {

// Forwards to whichever sink the current run writes to. Events come from the interpreter when
// it executes a block, segments from the end of the chain, which holds blocks back (the
// compensation's look-ahead, a smooth approach waiting for its contour): an event waits here
// until the segments of the motions before it are written. Only runs with events pay for this.
class SwitchSink final : public PathSink {
 public:
  PathSink* target = nullptr;
  const place::Placement* placement = nullptr;
  const trc::RadiusCompensation* trc = nullptr;
  const trc::SmoothApproach* sar = nullptr;
  const interp::Interpreter* interp = nullptr;

  // (NCOFFSET_ONE_CALL: GCC speculated that the target is another SwitchSink and unrolled the
  // forwarding several levels deep, 13 instructions more per segment in the benchmark.)
  NCOFFSET_ONE_CALL void segment(const Segment& s) override {
    if (waiting_) [[unlikely]]
      release(placement->seq());
    target->segment(s);
  }
  // MSG comes from the interpreter like the events and waits with them.
  void message(const SourceLoc& l, const std::string& t) override { post(Message{l, t}); }
  void warning(const SourceLoc& l, int n, const std::string& t) override {
    target->warning(l, n, t);
  }
  void programmed(const Segment& s) override { target->programmed(s); }
  bool wantsProgrammed() const override { return target && target->wantsProgrammed(); }
  bool wantsEvents() const override { return target && target->wantsEvents(); }
  void tool(const ToolEvent& e) override { post(e); }
  void mFunction(const MFunctionEvent& e) override { post(e); }
  void dwell(const DwellEvent& e) override { post(e); }
  void spindle(const SpindleEvent& e) override { post(e); }
  void feed(const FeedEvent& e) override { post(e); }
  void frame(const FrameEvent& e) override { post(e); }
  void axisNames(const std::vector<std::string>& n) override { target->axisNames(n); }
  void axes(const AxesEvent& e) override { post(e); }
  void finish(const Alarm* a) override { target->finish(a); }
  // Writes the events still waiting (end of a run: nothing is held back any more).
  void releaseAll() { release(-1); }
  // For Placement::bypass: segment() is target->segment() while nothing waits.
  const bool* waiting() const { return &waiting_; }

 private:
  struct Message {
    SourceLoc where;
    std::string text;
  };
  using Event = std::variant<ToolEvent, MFunctionEvent, DwellEvent, SpindleEvent, FeedEvent,
                             FrameEvent, AxesEvent, Message>;
  struct Pending {
    long long after;  // the motions sent before the event
    Event event;
  };
  template <typename E>
  void post(const E& e) {
    const long long sent = interp->motionsSent();
    // Nothing held back and the last motion written: the event goes out at once.
    if (pending_.empty() && !trc->active() && sar->idle() && placement->seq() == sent) {
      deliver(Event(e));
      return;
    }
    pending_.push_back({sent, Event(e)});
    waiting_ = true;
  }
  // Writes the events that follow motions before `seq` (all of them for -1). Out of line: the
  // segment() fast path stays a flag test and the forwarding call.
  [[gnu::noinline]] void release(long long seq) {
    while (!pending_.empty() && (seq < 0 || pending_.front().after < seq)) {
      deliver(pending_.front().event);
      pending_.pop_front();
    }
    waiting_ = !pending_.empty();
  }
  void deliver(const Event& e) {
    std::visit(
        [this](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, ToolEvent>) target->tool(v);
          if constexpr (std::is_same_v<T, MFunctionEvent>) target->mFunction(v);
          if constexpr (std::is_same_v<T, DwellEvent>) target->dwell(v);
          if constexpr (std::is_same_v<T, SpindleEvent>) target->spindle(v);
          if constexpr (std::is_same_v<T, FeedEvent>) target->feed(v);
          if constexpr (std::is_same_v<T, FrameEvent>) target->frame(v);
          if constexpr (std::is_same_v<T, AxesEvent>) target->axes(v);
          if constexpr (std::is_same_v<T, Message>) target->message(v.where, v.text);
        },
        e);
  }
  std::deque<Pending> pending_;
  bool waiting_ = false;  // !pending_.empty(), the one test per segment
};

// The chain of stages (docs/architecture.md): interpreter -> smooth approach -> radius
// compensation -> placement -> sink. Each stage knows only the one after it.
struct Channel::Impl {
  explicit Impl(const RunOptions& o)
      : diameter_output(o.diameter_output),
        placement(sink, o.coords, o.start.value_or(Vec3{})),
        trc(placement),
        sar(trc),
        interp(o, sink, sar) {
    sink.placement = &placement;
    sink.trc = &trc;
    sink.sar = &sar;
    sink.interp = &interp;
    placement.bypass(&sink.target, sink.waiting());
  }
  bool diameter_output;
  DiameterSink diameter;  // between the sink switch and the output, with --diameter only
  SwitchSink sink;
  place::Placement placement;
  trc::RadiusCompensation trc;
  trc::SmoothApproach sar;
  interp::Interpreter interp;

  RunResult run(std::shared_ptr<lang::SourceFile> src, PathSink& out, bool init, bool finish);
};

}  // namespace ncoffset
