// The Python module `ncoffset` (docs/python.md): ncoffset.run() runs a program with its init files
// and returns the segments as a numpy structured array (pandas.DataFrame takes it as it is), the
// events, the alarm and the variables; ncoffset.Stream mirrors the C++ Stream. An alarm raises
// ncoffset.AlarmError with the number, file, line, column, text and what was produced before it.
#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cstring>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "ncoffset/channel.hpp"
#include "ncoffset/stream.hpp"

namespace py = pybind11;
using namespace ncoffset;

namespace {

// One row of the segments array (field names in docs/python.md).
struct Row {
  int32_t line, file, motion;  // motion: the G number (0..3, 33, 34, 35, 331, 332, 63)
  double sx, sy, sz, x, y, z, cx, cy, cz, nx, ny, nz;
  int32_t turns;
  double feed;
  bool has_feed;
};

// What a run or one feed() produced.
struct Result {
  py::array segments;
  py::list events;       // dicts with a "type" and "segment" (segments before it)
  py::object alarm;      // None or a dict (number, file, line, column, text)
  py::object variables;  // run() and Stream.finish(): R parameters and user variables (dict)
  bool ended = false;    // Stream: the program has ended
};

class Collector final : public PathSink {
 public:
  explicit Collector(const Channel& ch) : ch_(ch) {}
  std::vector<Row> rows;
  py::list events;
  std::optional<Alarm> alarm;
  bool finished = false;

  void segment(const Segment& s) override {
    rows.push_back({s.line, s.file, motionGNumber(s.motion), s.start.x, s.start.y, s.start.z,
                    s.end.x, s.end.y, s.end.z, s.centre.x, s.centre.y, s.centre.z, s.normal.x,
                    s.normal.y, s.normal.z, s.turns, s.feed, s.has_feed});
  }
  void message(const SourceLoc& l, const std::string& t) override {
    add("message", l.file, l.line)["text"] = t;
  }
  void warning(const SourceLoc& l, int n, const std::string& t) override {
    py::dict d = add("warning", l.file, l.line);
    d["number"] = n;
    d["text"] = t;
  }
  bool wantsEvents() const override { return true; }
  void tool(const ToolEvent& e) override {
    static const char* kWord[] = {"T", "D", "M6"};
    py::dict d = add("tool", ch_.fileName(e.file), e.line);
    d["word"] = kWord[static_cast<int>(e.word)];
    d["tool"] = e.tool;
    d["edge"] = e.edge;
    d["radius"] = e.radius;
    d["length"] = py::make_tuple(e.length.x, e.length.y, e.length.z);
    d["changed"] = e.changed;
  }
  void mFunction(const MFunctionEvent& e) override {
    py::dict d = add("m", ch_.fileName(e.file), e.line);
    d["number"] = e.number;
    d["spindle"] = e.spindle;
  }
  void dwell(const DwellEvent& e) override {
    py::dict d = add("dwell", ch_.fileName(e.file), e.line);
    d["seconds"] = e.seconds;
    d["revolutions"] = e.revolutions;
  }
  void spindle(const SpindleEvent& e) override {
    py::dict d = add("spindle", ch_.fileName(e.file), e.line);
    d["speed"] = e.speed;
    d["spindle"] = e.spindle;
  }
  void feed(const FeedEvent& e) override {
    add("feed", ch_.fileName(e.file), e.line)["feed"] = e.feed;
  }
  void frame(const FrameEvent& e) override {
    py::dict d = add("frame", ch_.fileName(e.file), e.line);
    const auto& l = e.map.linear.m;
    d["offset"] = py::make_tuple(e.map.offset.x, e.map.offset.y, e.map.offset.z);
    d["linear"] = py::make_tuple(py::make_tuple(l[0][0], l[0][1], l[0][2]),
                                 py::make_tuple(l[1][0], l[1][1], l[1][2]),
                                 py::make_tuple(l[2][0], l[2][1], l[2][2]));
  }
  void finish(const Alarm* a) override {
    finished = true;
    if (a) alarm = *a;
  }

  // Moves what was collected into a Result (and starts collecting anew).
  Result take() {
    // numpy is imported with the first result, not with the module: `import ncoffset` works
    // without numpy (docs/python.md).
    static bool registered = [] {
      PYBIND11_NUMPY_DTYPE(Row, line, file, motion, sx, sy, sz, x, y, z, cx, cy, cz, nx, ny, nz,
                           turns, feed, has_feed);
      return true;
    }();
    (void)registered;
    Result r;
    py::array_t<Row> a(static_cast<py::ssize_t>(rows.size()));
    if (!rows.empty()) std::memcpy(a.mutable_data(), rows.data(), rows.size() * sizeof(Row));
    r.segments = std::move(a);
    r.events = std::move(events);
    events = py::list();
    rows.clear();
    r.alarm = py::none();
    r.variables = py::none();
    if (alarm) {
      py::dict d;
      d["number"] = alarm->number;
      d["file"] = alarm->where.file;
      d["line"] = alarm->where.line;
      d["column"] = alarm->where.column;
      d["text"] = alarm->text;
      r.alarm = d;
    }
    return r;
  }

 private:
  py::dict add(const char* type, const std::string& file, int line) {
    py::dict d;
    d["type"] = type;
    d["file"] = file;
    d["line"] = line;
    d["segment"] = rows.size();
    events.append(d);
    return d;
  }
  const Channel& ch_;
};

// start=(x, y, z): the machine position (MCS) where the channel starts (RunOptions::start).
using Start = std::optional<std::array<double, 3>>;

RunOptions options(const std::string& coords, const Start& start) {
  RunOptions o;
  if (start) o.start = Vec3{(*start)[0], (*start)[1], (*start)[2]};
  if (coords == "wcs" || coords == "WCS")
    o.coords = CoordSystem::WCS;
  else if (coords != "mcs" && coords != "MCS")
    throw py::value_error("coords must be \"mcs\" or \"wcs\"");
  return o;
}

py::object variables(const Channel& ch) {
  std::ostringstream out;
  ch.writeVariablesJson(out);
  return py::module_::import("json").attr("loads")(out.str());
}

// Raises ncoffset.AlarmError for `r.alarm` (with the result attached).
[[noreturn]] void raiseAlarm(const Result& r) {
  py::object cls = py::module_::import("ncoffset").attr("AlarmError");
  py::dict a = r.alarm;
  py::object e = cls(a["number"], a["file"], a["line"], a["column"], a["text"], py::cast(r));
  PyErr_SetObject(cls.ptr(), e.ptr());
  throw py::error_already_set();
}

// Runs the init files; raises for a file error or an alarm.
void runInits(Channel& ch, const std::vector<std::filesystem::path>& init) {
  for (const auto& f : init) {
    Collector c(ch);
    RunResult rr = ch.runInit(f, c);
    if (rr.status == RunResult::Status::FileError) throw py::value_error(rr.file_error);
    if (rr.alarm) {
      c.alarm = rr.alarm;
      raiseAlarm(c.take());
    }
  }
}

Result run(const std::filesystem::path& program, const std::vector<std::filesystem::path>& init,
           const std::string& coords, std::optional<std::string> text, bool raise,
           const Start& start) {
  Channel ch(options(coords, start));
  runInits(ch, init);
  Collector c(ch);
  RunResult rr = text ? ch.runText(program.string(), *text, c, program.parent_path())
                      : ch.runProgram(program, c);
  if (rr.status == RunResult::Status::FileError) throw py::value_error(rr.file_error);
  Result r = c.take();
  r.variables = variables(ch);
  r.ended = true;
  if (r.alarm.is_none() || !raise) return r;
  raiseAlarm(r);
}

// ncoffset.Stream: owns its channel, the collecting sink and the C++ stream.
class PyStream {
 public:
  PyStream(const std::vector<std::filesystem::path>& init, const std::string& coords,
           const std::string& name, const std::filesystem::path& dir, bool raise,
           const Start& start)
      : channel_(options(coords, start)), collector_(channel_), raise_(raise) {
    runInits(channel_, init);
    stream_ = std::make_unique<Stream>(channel_, collector_, name, dir);
  }
  Result feed(const std::string& text) {
    stream_->feed(text);
    return done(false);
  }
  Result finish() {
    stream_->finish();
    return done(true);
  }

 private:
  Result done(bool finished) {
    Result r = collector_.take();
    r.ended = stream_->ended();
    if (finished) r.variables = variables(channel_);
    if (!r.alarm.is_none() && raise_) raiseAlarm(r);
    return r;
  }
  Channel channel_;
  Collector collector_;
  bool raise_;
  std::unique_ptr<Stream> stream_;
};

}  // namespace

PYBIND11_MODULE(ncoffset, m) {
  m.doc() = "SINUMERIK 840D sl tool offsets outside the control (docs/python.md)";
  py::exec(R"(
class AlarmError(Exception):
    """A run ended with a control alarm: number, file, line, column, text, and result (what was
    produced before it: segments, events, variables)."""
    def __init__(self, number, file, line, column, text, result=None):
        super().__init__(f"{file}:{line}: alarm {number}: {text}")
        self.number, self.file, self.line, self.column, self.text = number, file, line, column, text
        self.result = result
)",
           m.attr("__dict__"));
  py::class_<Result>(m, "Result")
      .def_readonly("segments", &Result::segments, "numpy structured array, one row a segment")
      .def_readonly("events", &Result::events, "list of dicts, each with a 'type'")
      .def_readonly("alarm", &Result::alarm, "None, or a dict: number, file, line, column, text")
      .def_readonly("variables", &Result::variables, "R parameters and user variables (dict)")
      .def_readonly("ended", &Result::ended, "the program has ended")
      .def("__repr__", [](const Result& r) {
        return "<ncoffset.Result " + std::to_string(r.segments.size()) + " segments, " +
               std::to_string(r.events.size()) + " events" +
               (r.alarm.is_none() ? std::string() : ", alarm") + ">";
      });
  m.def("run", &run, py::arg("program"), py::arg("init") = std::vector<std::filesystem::path>{},
        py::arg("coords") = "mcs", py::arg("text") = py::none(), py::arg("raise_on_alarm") = true,
        py::arg("start") = py::none(),
        "Runs a part program (a file, or `text` named `program`) after its init files.");
  py::class_<PyStream>(m, "Stream")
      .def(py::init<const std::vector<std::filesystem::path>&, const std::string&,
                    const std::string&, const std::filesystem::path&, bool, const Start&>(),
           py::arg("init") = std::vector<std::filesystem::path>{}, py::arg("coords") = "mcs",
           py::arg("name") = "STREAM.MPF", py::arg("dir") = std::filesystem::path(),
           py::arg("raise_on_alarm") = true, py::arg("start") = py::none())
      .def("feed", &PyStream::feed, py::arg("text"),
           "Feeds program text; returns what became final")
      .def("finish", &PyStream::finish, "The text is complete: returns the rest");
  m.attr("__version__") = "0.1.0";
}
