// ncoffset command line: the contract of docs/cli.md (design.md "Command-line contract").
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <memory>

#include "ncoffset/channel.hpp"
#include "out/html_report.hpp"
#include "out/mpf_writer.hpp"
#include "out/svg_writer.hpp"
#include "out/writers.hpp"

namespace {

// Prints MSG texts to stderr and forwards the path.
class MessagePrinter final : public ncoffset::PathSink {
 public:
  explicit MessagePrinter(ncoffset::PathSink& next) : next_(next) {}
  void segment(const ncoffset::Segment& s) override { next_.segment(s); }
  void message(const ncoffset::SourceLoc& where, const std::string& text) override {
    std::fprintf(stderr, "%s:%d: message: %s\n", where.file.c_str(), where.line, text.c_str());
    next_.message(where, text);
  }
  void warning(const ncoffset::SourceLoc& where, int number, const std::string& text) override {
    std::fprintf(stderr, "%s:%d: warning %d: %s\n", where.file.c_str(), where.line, number,
                 text.c_str());
    next_.warning(where, number, text);
  }
  void programmed(const ncoffset::Segment& s) override { next_.programmed(s); }
  bool wantsProgrammed() const override { return next_.wantsProgrammed(); }
  void finish(const ncoffset::Alarm* alarm) override { next_.finish(alarm); }

 private:
  ncoffset::PathSink& next_;
};

std::string extensionFormat(const std::string& path) {
  auto dot = path.rfind('.');
  if (dot == std::string::npos) return "csv";
  std::string ext = path.substr(dot + 1);
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "jsonl" || ext == "svg" || ext == "html" || ext == "mpf") return ext;
  return "csv";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ncoffset: SINUMERIK 840D sl tool offsets (W1) outside the control"};
  std::string program, output, format, coords = "mcs", view = "xy", vars;
  std::vector<std::string> inits;
  ncoffset::RunOptions options;
  app.add_option("PROGRAM", program, "part program (.MPF)")->required();
  app.add_option("--init", inits, "init file run before PROGRAM (repeatable, in order)")
      ->allow_extra_args(false);  // one file per --init, so `--init A PROGRAM` works
  app.add_option("-o,--output", output, "output file (default: stdout)");
  app.add_option("--format", format,
                 "csv | jsonl | svg | html | mpf (default: from the output's extension, else csv)")
      ->check(CLI::IsMember({"csv", "jsonl", "svg", "html", "mpf"}));
  app.add_option("--coords", coords, "mcs (carrier reference point, default) | wcs (tool tip)")
      ->check(CLI::IsMember({"mcs", "wcs"}));
  app.add_option("--view", view, "svg: plane drawn: xy (G17, default) | zx (G18) | yz (G19)")
      ->check(CLI::IsMember({"xy", "zx", "yz"}));
  app.add_option("--vars", vars, "write R parameters and user variables as JSON");
  auto& l = options.limits;
  app.add_option("--max-blocks", l.max_blocks, "executed blocks before alarm 99002")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--max-line-length", l.max_line_length, "characters per block (alarm 99001)")
      ->capture_default_str()
      ->check(CLI::Range(size_t{1}, ncoffset::Limits::kMaxLineLength));
  app.add_option("--max-expression-depth", l.max_expression_depth,
                 "expression nesting (alarm 99003)")
      ->capture_default_str()
      ->check(CLI::Range(1, ncoffset::Limits::kMaxExpressionDepth));
  app.add_option("--max-program-levels", l.max_program_levels,
                 "main program + subprogram levels (alarm 14012)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--max-control-depth", l.max_control_depth,
                 "nested control structures per level (alarm 12641)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--max-variables", l.max_variables, "user variables (alarm 99004)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--max-total-elements", l.max_total_elements,
                 "array elements of all variables together (alarm 99005)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--max-array-elements", l.max_array_elements, "elements per array (alarm 99005)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 1;
  }
  options.coords = coords == "wcs" ? ncoffset::CoordSystem::WCS : ncoffset::CoordSystem::MCS;
  if (format.empty()) format = output.empty() ? "csv" : extensionFormat(output);
  std::FILE* out = stdout;
  if (!output.empty()) {
    out = std::fopen(output.c_str(), "wb");
    if (!out) {
      std::fprintf(stderr, "ncoffset: %s: cannot write: %s\n", output.c_str(),
                   std::strerror(errno));
      return 1;
    }
  }
  ncoffset::Channel channel(options);
  std::unique_ptr<ncoffset::PathSink> writer;
  if (format == "jsonl")
    writer = std::make_unique<ncoffset::out::JsonLinesWriter>(
        out, [&channel](int i) -> const std::string& { return channel.fileName(i); });
  else if (format == "svg")
    writer = std::make_unique<ncoffset::out::SvgWriter>(out, ncoffset::out::viewFromName(view));
  else if (format == "html")
    writer = std::make_unique<ncoffset::out::HtmlReport>(out, ncoffset::out::viewFromName(view),
                                                         program, coords);
  else if (format == "mpf")
    writer = std::make_unique<ncoffset::out::MpfWriter>(
        out, coords, [&channel](int i) -> const std::string& { return channel.fileName(i); });
  else
    writer = std::make_unique<ncoffset::out::CsvWriter>(out);
  MessagePrinter sink(*writer);

  auto report = [&](const ncoffset::RunResult& r) -> int {
    if (r.status == ncoffset::RunResult::Status::FileError) {
      writer->finish(nullptr);
      std::fprintf(stderr, "ncoffset: %s\n", r.file_error.c_str());
      return 1;
    }
    if (r.status == ncoffset::RunResult::Status::Alarm) {
      const auto& a = *r.alarm;
      std::fprintf(stderr, "%s:%d: alarm %d: %s\n", a.where.file.c_str(), a.where.line, a.number,
                   a.text.c_str());
      return 2;
    }
    return 0;
  };
  int status = 0;
  for (const auto& init : inits) {
    status = report(channel.runInit(init, sink));
    if (status) break;
  }
  if (!status) status = report(channel.runProgram(program, sink));
  writer.reset();
  if (out != stdout) std::fclose(out);
  if (!vars.empty() && status != 1) {
    std::ofstream v(vars);
    if (!v) {
      std::fprintf(stderr, "ncoffset: %s: cannot write\n", vars.c_str());
      return 1;
    }
    channel.writeVariablesJson(v);
  }
  return status;
}
