// The public Channel: wires the stages and turns AlarmError into an Alarm value.
#include "ncoffset/channel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "interp/channel_impl.hpp"

namespace ncoffset {

RunResult Channel::Impl::run(std::shared_ptr<lang::SourceFile> src, PathSink& out, bool init,
                             bool finish) {
  sink.target = &out;
  placement.beginRun([this](int id) -> const std::string& { return interp.fileName(id); });
  trc.passProgrammed(placement.wantsProgrammed());
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
  sink.releaseAll();
  if (finish || r.alarm) out.finish(r.alarm ? &*r.alarm : nullptr);
  return r;
}

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

int Channel::fileCount() const {
  return static_cast<int>(impl_->interp.fileCount());
}

std::string_view Channel::fileText(int index) const {
  return impl_->interp.fileText(index);
}

double Channel::axisMachineData(std::string_view name, int axis) const {
  const interp::MachineData& md = impl_->interp.machineData();
  int id = md.find(name);
  if (id < 0 || !md.isAxisData(id) || axis < 0 || axis > 2)
    return std::numeric_limits<double>::quiet_NaN();
  return md.get(id, axis);
}

long long Channel::blocksExecuted() const {
  return impl_->interp.blocksExecuted();
}

std::optional<EdgeData> Channel::toolEdge(int tool, int edge) const {
  const EdgeData* e = impl_->interp.toolStore().edge(tool, edge);
  if (!e) return std::nullopt;
  return *e;
}

void Channel::writeVariablesJson(std::ostream& out) const {
  impl_->interp.writeVariablesJson(out);
}

}  // namespace ncoffset
