// ncoffset command line: the contract of docs/cli.md (design.md "Command-line contract").
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "file_identity.hpp"
#include "limit_option.hpp"
#include "message_sinks.hpp"
#include "ncoffset/channel.hpp"
#include "ncoffset/version.hpp"
#include "out/html_report.hpp"
#include "out/mpf_writer.hpp"
#include "out/svg_writer.hpp"
#include "out/writers.hpp"
#include "output_file.hpp"
#include "progress_line.hpp"
#include "start_option.hpp"
#include "terminal_text.hpp"

namespace {

// What the progress line reads from the channel besides the segments.
ncoffset::cli::ProgressSource progressSource(const ncoffset::Channel& channel) {
  ncoffset::cli::ProgressSource p;
  p.file_name = [&channel](int i) -> const std::string& { return channel.fileName(i); };
  p.file_text = [&channel](int i) { return channel.fileText(i); };
  p.blocks = [&channel] { return channel.blocksExecuted(); };
  return p;
}

std::string extensionFormat(const std::string& path) {
  auto dot = path.rfind('.');
  if (dot == std::string::npos) return "csv";
  std::string ext = path.substr(dot + 1);
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "jsonl" || ext == "svg" || ext == "html" || ext == "mpf") return ext;
  return "csv";
}

// What the command line asks for, besides the run options.
struct Args {
  std::string program, output, format, coords = "mcs", view = "xy", vars;
  std::vector<std::string> inits;
  std::vector<std::string> path;  // --path: where subprograms and cycles are searched
  int decimals = -1;              // --decimals: -1 the shortest round-trip text
  bool diameter = false;
  bool quiet = false;  // -q: no progress line
  std::string start;   // --start X,Y,Z (empty: machine zero, assumed)
};

// What the HTML report reads from the channel: the files of the run, the offset memory and the
// axis dynamics of the time estimate (MD32000, MD32300).
ncoffset::out::ReportContext reportContext(const ncoffset::Channel& channel) {
  ncoffset::out::ReportContext c;
  c.file_count = [&channel] { return channel.fileCount(); };
  c.file_name = [&channel](int i) -> const std::string& { return channel.fileName(i); };
  c.file_text = [&channel](int i) { return channel.fileText(i); };
  c.edge = [&channel](int t, int d) { return channel.toolEdge(t, d); };
  c.dynamics = [&channel] {
    ncoffset::out::AxisDynamics dyn;
    for (int i = 0; i < 3; ++i) {
      dyn.max_velocity[static_cast<size_t>(i)] = channel.axisMachineData("$MA_MAX_AX_VELO", i);
      dyn.max_acceleration[static_cast<size_t>(i)] = channel.axisMachineData("$MA_MAX_AX_ACCEL", i);
    }
    return dyn;
  };
  return c;
}

// The writer of --format, printing MSG texts and warnings on stderr (message_sinks.hpp).
std::unique_ptr<ncoffset::PathSink> makeWriter(const Args& a, std::FILE* out,
                                               const ncoffset::Channel& channel) {
  using ncoffset::cli::Printing;
  auto names = [&channel](int i) -> const std::string& { return channel.fileName(i); };
  const int d = a.decimals;
  if (a.format == "jsonl")
    return std::make_unique<Printing<ncoffset::out::JsonLinesWriter>>(out, names, d);
  // Without --start the machine position at the start is assumed: drawings and statistics leave
  // out the move from it (docs/output-formats.md "Start position").
  const bool assumed = a.start.empty();
  if (a.format == "svg") {
    auto w = std::make_unique<Printing<ncoffset::out::SvgWriter>>(
        out, ncoffset::out::viewFromName(a.view), true, d);
    if (assumed) w->leaveOutFirstMove();
    return w;
  }
  if (a.format == "html") {
    auto w = std::make_unique<Printing<ncoffset::out::HtmlReport>>(
        out, ncoffset::out::viewFromName(a.view), a.program, a.coords, d, reportContext(channel));
    if (assumed) w->leaveOutFirstMove();
    return w;
  }
  if (a.format == "mpf")
    return std::make_unique<Printing<ncoffset::out::MpfWriter>>(out, a.coords, names, d,
                                                                a.diameter);
  if (d >= 0) return std::make_unique<Printing<ncoffset::out::RoundedCsvWriter>>(out, d);
  return std::make_unique<Printing<ncoffset::out::CsvWriter>>(out);
}

// Runs the init files and the program: exit status 0, 1 (file error) or 2 (alarm).
int runAll(const Args& a, ncoffset::Channel& channel, ncoffset::PathSink& writer) {
  // The progress line only where it is shown: otherwise each segment goes straight to the writer.
  std::optional<ncoffset::cli::ProgressForwarder> progress;
  if (!a.quiet && isatty(fileno(stderr)) != 0) progress.emplace(writer, progressSource(channel));
  ncoffset::PathSink& sink = progress ? static_cast<ncoffset::PathSink&>(*progress) : writer;
  auto report = [&](const ncoffset::RunResult& r) -> int {
    if (r.status == ncoffset::RunResult::Status::FileError) {
      writer.finish(nullptr);
      ncoffset::cli::printError("ncoffset: " + r.file_error);
      return 1;
    }
    if (r.status == ncoffset::RunResult::Status::Alarm) {
      const auto& al = *r.alarm;
      ncoffset::cli::printError(
          fmt::format("{}:{}: alarm {}: {}", al.where.file, al.where.line, al.number, al.text));
      ncoffset::cli::printSourceContext(al.where, al.source_line);
      return 2;
    }
    return 0;
  };
  for (const auto& init : a.inits)
    if (int status = report(channel.runInit(init, sink))) return status;
  return report(channel.runProgram(a.program, sink));
}

// An output must be neither an input nor the other output: it would be destroyed (the program
// truncated before it is read) or overwritten.
bool outputsDistinct(const Args& a) {
  std::vector<ncoffset::cli::NamedPath> inputs{{"the program", a.program}};
  for (const auto& init : a.inits) inputs.push_back({"the --init file", init});
  std::vector<ncoffset::cli::NamedPath> outputs;
  if (!a.output.empty()) outputs.push_back({"-o", a.output});
  if (!a.vars.empty()) outputs.push_back({"--vars", a.vars});
  std::string clash = ncoffset::cli::outputClash(inputs, outputs);
  if (!clash.empty()) ncoffset::cli::printError(clash);
  return clash.empty();
}

// Runs with safe outputs (output_file.hpp): the exit status, 1 also when an output cannot be
// written completely (its target is then left as it was).
int run(const Args& a, const ncoffset::RunOptions& options) {
  if (!outputsDistinct(a)) return 1;
  std::string error;
  ncoffset::cli::OutputFile out, vars;
  if (!out.open(a.output, error) || (!a.vars.empty() && !vars.open(a.vars, error))) {
    ncoffset::cli::printError(error);
    return 1;
  }
  ncoffset::Channel channel(options);
  channel.setSearchPath({a.path.begin(), a.path.end()});
  // The writer flushes its last lines into the stream when it goes.
  int status = runAll(a, channel, *makeWriter(a, out.stream(), channel));
  bool ok = out.close(error);
  bool with_vars = ok && !a.vars.empty() && status != 1;
  if (with_vars) {
    ncoffset::cli::StdioStreamBuf buf(vars.stream());
    std::ostream json(&buf);
    channel.writeVariablesJson(json);
    ok = vars.close(error);
  }
  // Both outputs are complete before either replaces its target.
  ok = ok && out.publish(error) && (!with_vars || vars.publish(error));
  if (!ok) {
    ncoffset::cli::printError(error);
    return 1;
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ncoffset: SINUMERIK 840D sl tool offsets (W1) outside the control"};
  Args a;
  ncoffset::RunOptions options;
  app.set_version_flag("--version", "ncoffset " NCOFFSET_VERSION_STRING);
  app.add_option("PROGRAM", a.program, "part program (.MPF)")->required();
  app.add_option("--init", a.inits, "init file run before PROGRAM (repeatable, in order)")
      ->allow_extra_args(false);  // one file per --init, so `--init A PROGRAM` works
  app.add_option("--path", a.path,
                 "directory or text archive searched for subprograms and cycles after the "
                 "program's directory (repeatable, in order)")
      ->allow_extra_args(false)
      ->check(CLI::ExistingPath);
  app.add_option("-o,--output", a.output, "output file (default: stdout)");
  app.add_option("--format", a.format,
                 "csv | jsonl | svg | html | mpf (default: from the output's extension, else csv)")
      ->check(CLI::IsMember({"csv", "jsonl", "svg", "html", "mpf"}));
  app.add_option("--coords", a.coords, "mcs (carrier reference point, default) | wcs (tool tip)")
      ->check(CLI::IsMember({"mcs", "wcs"}));
  app.add_option("--view", a.view, "svg: plane drawn: xy (G17, default) | zx (G18) | yz (G19)")
      ->check(CLI::IsMember({"xy", "zx", "yz"}));
  app.add_option("--vars", a.vars, "write R parameters and user variables as JSON");
  app.add_option("--decimals", a.decimals,
                 "round written numbers to at most N decimals, 0..17 (default: shortest "
                 "round trip; mpf: 6)")
      ->transform(ncoffset::cli::limitValue(17, 0));
  app.add_option("--start", a.start,
                 "X,Y,Z: machine position (MCS) of the tool carrier at the start (default: "
                 "0,0,0, assumed: the move from it is not drawn)");
  app.add_flag("--diameter", a.diameter,
               "csv, jsonl, mpf: the transverse axis (MD20100) as diameter values (default: "
               "radius values)");
  app.add_flag("-q,--quiet", a.quiet, "no progress line on stderr (shown on a terminal otherwise)");
  auto& l = options.limits;
  app.add_option("--max-blocks", l.max_blocks,
                 "executed blocks before alarm 99002 (default: 5,000,000 and 2 per byte of the "
                 "programs loaded)")
      ->transform(ncoffset::cli::limitValue(ncoffset::cli::kMaxBlocksMax));
  app.add_option("--max-blocks-without-motion", l.max_blocks_without_motion,
                 "executed blocks since the last motion before alarm 99006")
      ->capture_default_str()
      ->transform(ncoffset::cli::limitValue(ncoffset::cli::kMaxBlocksMax));
  app.add_option("--max-line-length", l.max_line_length, "characters per block (alarm 99001)")
      ->capture_default_str()
      ->transform(ncoffset::cli::limitValue(ncoffset::Limits::kMaxLineLength));
  app.add_option("--max-expression-depth", l.max_expression_depth,
                 "expression nesting (alarm 99003)")
      ->capture_default_str()
      ->transform(ncoffset::cli::limitValue(ncoffset::Limits::kMaxExpressionDepth));
  app.add_option("--max-program-levels", l.max_program_levels,
                 "main program + subprogram levels (alarm 14012)")
      ->capture_default_str()
      ->transform(ncoffset::cli::limitValue(ncoffset::cli::kLimitMax));
  app.add_option("--max-control-depth", l.max_control_depth,
                 "nested control structures per level (alarm 12641)")
      ->capture_default_str()
      ->transform(ncoffset::cli::limitValue(ncoffset::cli::kLimitMax));
  app.add_option("--max-variables", l.max_variables, "user variables (alarm 99004)")
      ->capture_default_str()
      ->transform(ncoffset::cli::limitValue(ncoffset::cli::kLimitMax));
  app.add_option("--max-total-elements", l.max_total_elements,
                 "array elements of all variables together (alarm 99005)")
      ->capture_default_str()
      ->transform(ncoffset::cli::limitValue(ncoffset::cli::kLimitMax));
  app.add_option("--max-array-elements", l.max_array_elements, "elements per array (alarm 99005)")
      ->capture_default_str()
      ->transform(ncoffset::cli::limitValue(ncoffset::cli::kLimitMax));
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Not app.exit(e): the message quotes the arguments, which are escaped like program text.
    ncoffset::cli::printError(e.what());
    ncoffset::cli::printError("Run with --help for more information.");
    return 1;
  }
  options.coords = a.coords == "wcs" ? ncoffset::CoordSystem::WCS : ncoffset::CoordSystem::MCS;
  if (a.format.empty()) a.format = a.output.empty() ? "csv" : extensionFormat(a.output);
  if (a.diameter && (a.format == "svg" || a.format == "html")) {
    ncoffset::cli::printError("--diameter: drawings (svg, html) show the path as it is (radius)");
    return 1;
  }
  options.diameter_output = a.diameter;
  if (!a.start.empty()) {
    std::string why;
    options.start = ncoffset::cli::parseStart(a.start, why);
    if (!options.start) {
      ncoffset::cli::printError("--start: " + why);
      return 1;
    }
  }
  return run(a, options);
}
