// Stream (include/ncoffset/stream.hpp): the channel runs the fed program on a worker thread that
// takes turns with the caller. The worker runs only while the caller waits in feed()/finish();
// it stops at the end of the fed text (lang::SourceFile::growable -> ProgramFlow::nextLineFed) or
// after kBatch records, and the caller writes the records to the sink on its own thread.
// GCC 12 reports the vectors of an AxesEvent record moved through the variant as maybe
// uninitialised (a known false positive of -Wmaybe-uninitialized with std::variant).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "ncoffset/stream.hpp"

#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

#include "interp/channel_impl.hpp"

namespace ncoffset {

namespace {
struct Abandoned {};  // unwinds the worker when a stream is destroyed unfinished

struct Programmed {
  Segment s;
};
struct Message {
  SourceLoc where;
  std::string text;
};
struct Warning {
  SourceLoc where;
  int number;
  std::string text;
};
struct AxisNames {
  std::vector<std::string> names;
};
using Record = std::variant<Segment, Programmed, Message, Warning, ToolEvent, MFunctionEvent,
                            DwellEvent, SpindleEvent, FeedEvent, FrameEvent, AxesEvent, AxisNames>;
}  // namespace

struct Stream::Impl {
  // The worker's sink: keeps the records for the caller, hands over every kBatch of them.
  class Recorder final : public PathSink {
   public:
    explicit Recorder(Impl& s) : s_(s) {}
    void segment(const Segment& x) override { add(x); }
    void programmed(const Segment& x) override { add(Programmed{x}); }
    void message(const SourceLoc& l, const std::string& t) override { add(Message{l, t}); }
    void warning(const SourceLoc& l, int n, const std::string& t) override {
      add(Warning{l, n, t});
    }
    bool wantsProgrammed() const override { return s_.wants_programmed; }
    bool wantsEvents() const override { return s_.wants_events; }
    void tool(const ToolEvent& e) override { add(e); }
    void mFunction(const MFunctionEvent& e) override { add(e); }
    void dwell(const DwellEvent& e) override { add(e); }
    void spindle(const SpindleEvent& e) override { add(e); }
    void feed(const FeedEvent& e) override { add(e); }
    void frame(const FrameEvent& e) override { add(e); }
    void axisNames(const std::vector<std::string>& n) override { add(AxisNames{n}); }
    void axes(const AxesEvent& e) override { add(e); }
    void finish(const Alarm*) override {}  // the stream finishes the sink on the caller's side

   private:
    void add(Record r) {
      s_.records.push_back(std::move(r));
      if (s_.records.size() >= kBatch) s_.handOver(false);
    }
    Impl& s_;
  };

  Impl(Channel& c, PathSink& out, std::string name) : channel(c), sink(out), recorder(*this) {
    wants_programmed = out.wantsProgrammed();
    wants_events = out.wantsEvents();
    source = lang::SourceFile::growable(std::move(name), kMaxText, [this] { return more(); });
    worker = std::thread([this] { work(); });
  }

  // --- worker side ---
  void work() {
    try {
      {
        std::unique_lock<std::mutex> l(mu);
        cv.wait(l, [this] { return worker_turn; });
        if (abandon) throw Abandoned{};
      }
      result = channel.impl_->run(source, recorder, false, false);
    } catch (const Abandoned&) {
    } catch (...) {
      failure = std::current_exception();  // rethrown on the caller's side, as runText would
    }
    std::lock_guard<std::mutex> l(mu);
    done = true;
    worker_turn = false;
    cv.notify_all();
  }
  // The turn goes to the caller until it gives it back; `for_text`: the worker needs text.
  void handOver(bool for_text) {
    std::unique_lock<std::mutex> l(mu);
    waiting_text = for_text;
    worker_turn = false;
    cv.notify_all();
    cv.wait(l, [this] { return worker_turn; });
    waiting_text = false;
    if (abandon) throw Abandoned{};
  }
  // lang::SourceFile::growable's `more`: true once text was appended, false when complete.
  bool more() {
    const size_t before = source->text().size();
    for (;;) {
      if (source->text().size() > before) return true;
      if (closed) return false;
      handOver(true);
    }
  }

  // --- caller side ---
  // Lets the worker run until it needs text or ends, writing what it produced.
  void resume() {
    for (;;) {
      {
        std::unique_lock<std::mutex> l(mu);
        worker_turn = true;
        cv.notify_all();
        cv.wait(l, [this] { return !worker_turn; });
      }
      deliver();
      if (failure) std::rethrow_exception(std::exchange(failure, nullptr));
      if (done || waiting_text) break;
    }
    if (done && !sink_finished) {
      sink_finished = true;
      sink.finish(result.alarm ? &*result.alarm : nullptr);
    }
  }
  void deliver() {
    for (const Record& r : records) std::visit([this](const auto& v) { write(v); }, r);
    records.clear();
  }
  void write(const Segment& s) { sink.segment(s); }
  void write(const Programmed& p) { sink.programmed(p.s); }
  void write(const Message& m) { sink.message(m.where, m.text); }
  void write(const Warning& w) { sink.warning(w.where, w.number, w.text); }
  void write(const ToolEvent& e) { sink.tool(e); }
  void write(const MFunctionEvent& e) { sink.mFunction(e); }
  void write(const DwellEvent& e) { sink.dwell(e); }
  void write(const SpindleEvent& e) { sink.spindle(e); }
  void write(const FeedEvent& e) { sink.feed(e); }
  void write(const FrameEvent& e) { sink.frame(e); }
  void write(const AxesEvent& e) { sink.axes(e); }
  void write(const AxisNames& n) { sink.axisNames(n.names); }

  void append(std::string_view text) {
    if (!source->append(text))
      throw std::length_error("ncoffset::Stream: more than kMaxText characters of program text");
  }

  Channel& channel;
  PathSink& sink;
  Recorder recorder;
  bool wants_programmed = false, wants_events = false;
  std::shared_ptr<lang::SourceFile> source;
  std::string partial;  // a line fed without its end
  std::vector<Record> records;
  RunResult result;
  std::exception_ptr failure;  // an exception other than an alarm, from the worker
  bool sink_finished = false;

  std::mutex mu;
  std::condition_variable cv;
  bool worker_turn = false;   // the worker runs (the caller waits)
  bool waiting_text = false;  // the worker waits for text
  bool done = false;          // the worker ended (the program ended, by an alarm or abandoned)
  bool closed = false;        // finish(): no more text
  bool abandon = false;
  std::thread worker;  // last: starts when everything above is there
};

Stream::Stream(Channel& channel, PathSink& sink, std::string name, std::filesystem::path dir) {
  channel.impl_->interp.setSearchDir(std::move(dir));
  impl_ = std::make_unique<Impl>(channel, sink, std::move(name));
}

Stream::~Stream() {
  if (!impl_->done) {
    std::lock_guard<std::mutex> l(impl_->mu);
    impl_->abandon = true;
    impl_->worker_turn = true;
    impl_->cv.notify_all();
  }
  impl_->worker.join();
}

bool Stream::feed(std::string_view text) {
  Impl& s = *impl_;
  if (s.done || s.closed) return false;
  const size_t nl = text.rfind('\n');
  if (nl == std::string_view::npos) {
    if (s.partial.size() + text.size() > kMaxText)
      throw std::length_error("ncoffset::Stream: a line longer than kMaxText characters");
    s.partial.append(text);
    return true;
  }
  // Complete lines go to the program; the rest waits for its line end.
  if (!s.partial.empty()) {
    s.append(s.partial);
    s.partial.clear();
  }
  s.append(text.substr(0, nl + 1));
  s.partial.assign(text.substr(nl + 1));
  s.resume();
  return !s.done;
}

RunResult Stream::finish() {
  Impl& s = *impl_;
  if (!s.closed) {
    if (!s.done && !s.partial.empty()) s.append(s.partial);
    s.partial.clear();
    s.closed = true;
    if (!s.done) s.resume();
  }
  return s.result;
}

bool Stream::ended() const {
  return impl_->done;
}

}  // namespace ncoffset
