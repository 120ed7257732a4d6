// The public Channel: wires the stages and turns AlarmError into an Alarm value.
#include "ncoffset/channel.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "interp/interpreter.hpp"
#include "place/placement.hpp"
#include "trc/radius_compensation.hpp"
#include "trc/smooth_approach.hpp"

namespace ncoffset {

namespace {
// The transverse axis as diameter values (--diameter, docs/turning.md): positions and centres
// times 2. Lines stay lines; an arc's drawing would be an ellipse, which is why the drawings
// (SVG, HTML) are never asked for it.
Segment asDiameter(Segment s, int axis) {
  s.start[axis] *= 2;
  s.end[axis] *= 2;
  s.centre[axis] *= 2;
  return s;
}

// Forwards to whichever sink the current run writes to.
class SwitchSink final : public PathSink {
 public:
  PathSink* target = nullptr;
  void segment(const Segment& s) override { target->segment(s); }
  void message(const SourceLoc& l, const std::string& t) override { target->message(l, t); }
  void warning(const SourceLoc& l, int n, const std::string& t) override {
    target->warning(l, n, t);
  }
  void programmed(const Segment& s) override { target->programmed(s); }
  bool wantsProgrammed() const override { return target && target->wantsProgrammed(); }
  void finish(const Alarm* a) override { target->finish(a); }
};

// Between SwitchSink and the run's sink with --diameter only (the usual run pays nothing).
class DiameterSink final : public PathSink {
 public:
  PathSink* next = nullptr;
  int axis = 0;
  void segment(const Segment& s) override { next->segment(asDiameter(s, axis)); }
  void message(const SourceLoc& l, const std::string& t) override { next->message(l, t); }
  void warning(const SourceLoc& l, int n, const std::string& t) override { next->warning(l, n, t); }
  void programmed(const Segment& s) override { next->programmed(asDiameter(s, axis)); }
  bool wantsProgrammed() const override { return next && next->wantsProgrammed(); }
  void finish(const Alarm* a) override { next->finish(a); }
};
}  // namespace

// The chain of stages (docs/architecture.md): interpreter -> smooth approach -> radius
// compensation -> placement -> sink. Each stage knows only the one after it.
struct Channel::Impl {
  explicit Impl(const RunOptions& o)
      : diameter_output(o.diameter_output),
        placement(sink, o.coords),
        trc(placement),
        sar(trc),
        interp(o, sink, sar) {}
  bool diameter_output;
  DiameterSink diameter;
  SwitchSink sink;
  place::Placement placement;
  trc::RadiusCompensation trc;
  trc::SmoothApproach sar;
  interp::Interpreter interp;

  RunResult run(std::shared_ptr<lang::SourceFile> src, PathSink& out, bool init, bool finish) {
    sink.target = &out;
    placement.beginRun([this](int id) -> const std::string& { return interp.fileName(id); });
    RunResult r;
    try {
      interp::LoadedProgram& prog = interp.load(std::move(src), init);
      if (diameter_output && !init) {  // after load: the alarm names the program
        diameter.axis = interp.transverseAxis();
        if (diameter.axis < 0)
          raise(AlarmNumber::NoTransverseAxis,
                "no transverse axis for --diameter: MD20100 $MC_DIAMETER_AX_DEF names none");
        diameter.next = &out;
        sink.target = &diameter;
      }
      interp.run(prog, init);
    } catch (const AlarmError& e) {
      r.status = RunResult::Status::Alarm;
      r.alarm = Alarm{e.number(), interp.alarmLoc(e), e.text(), interp.alarmSourceLine(e)};
    } catch (const std::bad_alloc&) {
      r.status = RunResult::Status::Alarm;
      r.alarm = Alarm{toInt(AlarmNumber::ArrayTooLarge), {}, "out of memory", {}};
    }
    if (finish || r.alarm) out.finish(r.alarm ? &*r.alarm : nullptr);
    return r;
  }
};

Channel::Channel(RunOptions options) {
  Limits& l = options.limits;  // what the stack and memory allow (docs/limits.md)
  l.max_expression_depth = std::min(l.max_expression_depth, Limits::kMaxExpressionDepth);
  l.max_line_length = std::min(l.max_line_length, Limits::kMaxLineLength);
  impl_ = std::make_unique<Impl>(options);
}
Channel::~Channel() = default;

static RunResult fileError(const std::filesystem::path& file, const std::string& why) {
  RunResult r;
  r.status = RunResult::Status::FileError;
  r.file_error = fmt::format("{}: cannot read: {}", file.string(), why);
  return r;
}

RunResult Channel::runInit(const std::filesystem::path& file, PathSink& sink) {
  std::string err;
  auto src = lang::SourceFile::load(file, &err);
  if (!src) return fileError(file, err);
  impl_->interp.setSearchDir(file.parent_path());
  return impl_->run(std::move(src), sink, true, false);
}

RunResult Channel::runProgram(const std::filesystem::path& file, PathSink& sink) {
  std::string err;
  auto src = lang::SourceFile::load(file, &err);
  if (!src) return fileError(file, err);
  impl_->interp.setSearchDir(file.parent_path());
  return impl_->run(std::move(src), sink, false, true);
}

RunResult Channel::runText(const std::string& name, const std::string& text, PathSink& sink,
                           const std::filesystem::path& dir) {
  impl_->interp.setSearchDir(dir);
  return impl_->run(lang::SourceFile::fromString(name, text), sink, false, true);
}

RunResult Channel::runInitText(const std::string& name, const std::string& text, PathSink& sink) {
  return impl_->run(lang::SourceFile::fromString(name, text), sink, true, false);
}

void Channel::setSearchPath(std::vector<std::filesystem::path> path) {
  impl_->interp.setSearchPath(std::move(path));
}

const std::string& Channel::fileName(int index) const {
  return impl_->interp.fileName(index);
}

void Channel::writeVariablesJson(std::ostream& out) const {
  impl_->interp.writeVariablesJson(out);
}

}  // namespace ncoffset
