#include "track_command.h"

#include "arguments.h"
#include "command_help.h"
#include "estimator_arguments.h"
#include "log_arguments.h"
#include "opf/core/tracker.h"
#include "opf/estimators/registry.h"
#include "opf/io/atomic_file.h"
#include "opf/io/estimate_csv.h"
#include "opf/io/estimate_tum.h"
#include "opf/io/input_file.h"
#include "opf/io/measurement_log.h"
#include "opf/io/unsized_log_note.h"
#include "output_paths.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace opf::cli {
namespace {

namespace fs = std::filesystem;

// A FIFO, a character device or anything else that exists and is not a regular file is written
// through, not replaced by a new regular file (a FIFO's reader would wait for ever).
bool written_through(const std::string& out) {
  std::error_code ec;
  const fs::file_status status = fs::status(out, ec);
  return !ec && fs::exists(status) && !fs::is_regular_file(status);
}

// Every write is checked: a full disk or a closed pipe ends the run with the output named and
// the system's reason, instead of a report of estimates that were never written. Call it right
// after the write or flush, before anything else can change errno.
void check_written(const std::ostream& os, const std::string& out) {
  if (os) return;
  const int error = errno;
  throw std::runtime_error("cannot write the estimates to " +
                           (out == "-" ? std::string("standard output") : "'" + out + "'") + ": " +
                           (error != 0 ? std::strerror(error) : "write error"));
}

std::vector<OptionSpec> specs() {
  std::vector<OptionSpec> s = {
      {"in", "LOG.csv",
       "measurement log: CSV with columns t,object,x,y,z,qx,qy,qz,qw, or t,object,x,y,z for "
       "positions alone (read at the identity orientation, with a note) (required); - reads "
       "standard input as a stream"},
      {"out", "EST.csv",
       "estimates: t,object,x,y,z,qx,qy,qz,qw,trace,mode,... (required); - writes standard output"},
      {"out-format", "csv|tum",
       "csv: every column and hypothesis; tum: each object's main estimate as a TUM trajectory "
       "(timestamp tx ty tz qx qy qz qw), one file per object, OUT_<object>.tum for several "
       "(default: tum when --out ends in .tum, else csv)"},
      {"estimator", "NAME", "estimator to run: opf (default), pf, cvkf, imm or oapf"},
      {"stream", "",
       "read --in as a stream (as for -): rows in time order, each frame written and flushed as "
       "soon as the next frame's first row arrives"},
      {"quiet", "", "no summary or warnings on stderr (errors still)"},
      {"covariance", "",
       "also write the full pose covariance: its upper triangle as 21 columns cov_x_x ... "
       "cov_roll_roll"},
  };
  for (auto& spec : log_option_specs()) s.push_back(std::move(spec));
  for (auto& spec : estimator_option_specs()) s.push_back(std::move(spec));
  return s;
}

constexpr const char* kSummary =
    "Replays a log of pose detections (AprilTag, motion capture, a pose tracker) through one\n"
    "estimator per object and writes one row per object and frame, from the object's first\n"
    "detection on. Rows close in time form a frame (--frame-tolerance), frames missing inside\n"
    "gaps are filled (--rate, --no-fill); an object with no row (or empty pose fields) in a\n"
    "frame is unobserved there, and the mode column says what the estimator did instead\n"
    "(predicted, dynamics, carried, left, random_walk; +filled in a gap). The OPF treats every\n"
    "object in the log as a possible occluder of every other. Further hypotheses (carried by\n"
    "another occluder, or left) follow as extra rows with hypothesis >= 1, each with its\n"
    "probability; alert is 1 when the row's trace(Q~) reaches epsilon_safe, for any\n"
    "estimator. A file is read whole (rows in any order) and the output written only when\n"
    "the whole run succeeded; a stream (--in - or --stream) is answered frame by frame.\n"
    "The log, estimate and settings formats: docs/formats.md.";

/// Steps the tracker through frames and writes their estimates, counting what it wrote.
class EstimateWriter {
 public:
  EstimateWriter(Tracker& tracker, double epsilon_safe, EstimateColumns columns,
                 std::function<void(std::size_t objects)> on_objects, UnsizedLogWatch& unsized)
      : tracker_(tracker),
        epsilon_safe_(epsilon_safe),
        columns_(columns),
        on_objects_(std::move(on_objects)),
        unsized_(unsized) {}

  void write(std::ostream& out, const Frame& frame) {
    for (const Detection& detection : frame.detections) {
      if (objects_.insert(detection.object).second) on_objects_(objects_.size());
      unsized_.saw(detection);
    }
    // The further hypotheses (the OPF's virtual objects) follow as extra rows, hypothesis >= 1.
    step_into_rows(tracker_, frame, frame_rows_);
    for (const Estimate& row : frame_rows_) {
      write_estimate_row(out, row, epsilon_safe_, columns_);
      unsized_.saw(row);
    }
    rows_ += frame_rows_.size();
    ++frames_;
  }
  std::size_t rows() const { return rows_; }
  std::size_t frames() const { return frames_; }
  std::size_t objects() const { return objects_.size(); }

 private:
  Tracker& tracker_;
  double epsilon_safe_;
  EstimateColumns columns_;
  std::function<void(std::size_t)> on_objects_;
  std::set<std::string> objects_;
  std::vector<Estimate> frame_rows_;  // step_into_rows's, kept from frame to frame
  std::size_t rows_ = 0;
  std::size_t frames_ = 0;
  UnsizedLogWatch& unsized_;
};

// Flushes, then checks, errno still the flush's.
void flush_checked(std::ostream& os, const std::string& out) {
  errno = 0;
  os.flush();
  check_written(os, out);
}

// A frame's rows, formatted first and written in one call, then checked.
void write_checked(EstimateWriter& writer, std::ostream& os, const Frame& frame,
                   const std::string& out) {
  std::ostringstream rows;
  writer.write(rows, frame);
  const std::string text = rows.str();
  errno = 0;
  os.write(text.data(), static_cast<std::streamsize>(text.size()));
  check_written(os, out);
}

bool tum_output(const Arguments& args, const std::string& out) {
  const auto format = args.get("out-format");
  if (!format) return fs::path(out).extension() == ".tum";
  if (*format != "csv" && *format != "tum")
    throw UsageError{"option '--out-format': expected csv or tum, got \"" + *format + "\""};
  return *format == "tum";
}

// The TUM output: each object's main estimates, kept until the whole run succeeded, then one
// file per object (tum_paths), none of them the input. Returns the paths written.
std::vector<fs::path> track_to_tum(Tracker& tracker, const MeasurementLog& log,
                                   const std::string& in, const std::string& out,
                                   UnsizedLogWatch& unsized) {
  if (out == "-" && log.objects.size() > 1)
    throw UsageError{
        "--out-format tum writes one file per object: standard output holds one, "
        "and the log has " +
        std::to_string(log.objects.size())};
  std::map<std::string, std::ostringstream> rows;
  for (const Frame& frame : log.frames) {
    for (const Detection& detection : frame.detections) unsized.saw(detection);
    for (const Estimate& estimate : tracker.step(frame)) {
      write_tum_row(rows[estimate.object], estimate);
      unsized.saw(estimate);
    }
  }
  const std::vector<fs::path> paths = tum_paths(out, log.objects);
  for (const fs::path& path : paths)
    refuse_output_over_input({"--out", path.string()}, {{"--in", in}});
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::string text = rows[log.objects[i]].str();
    const std::string name = paths[i].string();
    const auto write = [&](std::ostream& os) {
      write_tum_header(os);
      errno = 0;
      os.write(text.data(), static_cast<std::streamsize>(text.size()));
      check_written(os, name);
      flush_checked(os, name);
    };
    if (out == "-") {
      write(std::cout);
    } else {
      write_file_atomically(paths[i], write);
    }
  }
  return paths;
}

// A stream: each frame's rows written and flushed as soon as the next frame begins.
FrameAssemblyReport track_stream(const std::string& in, const std::string& out,
                                 const LogReadOptions& log_options, const EstimateColumns& columns,
                                 EstimateWriter& writer, bool quiet) {
  std::optional<std::ifstream> file;
  if (in != "-") file = open_input_file(in, "measurement log");
  std::istream& input = file ? static_cast<std::istream&>(*file) : std::cin;
  const std::string source = in == "-" ? "<stdin>" : in;
  MeasurementStream frames(input, source, log_options);
  if (!quiet && !frames.states_orientation()) note_positions_only("track", source);
  std::optional<std::ofstream> out_file;
  if (out != "-") {
    out_file.emplace(out, std::ios::binary);
    if (!*out_file) throw std::runtime_error("cannot write " + out);
  }
  std::ostream& output = out_file ? static_cast<std::ostream&>(*out_file) : std::cout;
  write_estimate_header(output, columns);
  flush_checked(output, out);
  while (const std::optional<Frame> frame = frames.next()) {
    write_checked(writer, output, *frame, out);
    flush_checked(output, out);  // answered now, not when the input ends
  }
  if (out_file) out_file->close();
  if (out_file) check_written(*out_file, out);
  return frames.report();
}

// A whole log's estimates as CSV: to a file only once the whole run succeeded (a device such as
// a pipe is written through).
void track_whole_log(const MeasurementLog& log, const std::string& out,
                     const EstimateColumns& columns, EstimateWriter& writer) {
  const auto write_all = [&](std::ostream& os) {
    write_estimate_header(os, columns);
    for (const Frame& frame : log.frames) write_checked(writer, os, frame, out);
    flush_checked(os, out);
  };
  if (out == "-") {
    write_all(std::cout);
  } else if (written_through(out)) {
    std::ofstream device(out, std::ios::binary);
    if (!device) throw std::runtime_error("cannot open '" + out + "' for writing");
    write_all(device);
    device.close();
    check_written(device, out);
  } else {
    write_file_atomically(out, write_all);
  }
}

// How the log's gaps were filled, and which were too long to fill.
void report_filled_gaps(const FrameAssemblyReport& assembly) {
  if (assembly.filled_frames > 0)
    std::cerr << "opf track: " << assembly.filled_frames << " frames filled inside "
              << assembly.gaps << (assembly.gaps == 1 ? " gap" : " gaps") << " of the log (at "
              << 1.0 / assembly.frame_period << " Hz; mode +filled; --no-fill keeps only the "
              << "log's frames)\n";
  if (assembly.long_gaps > 0)
    std::cerr << "opf track: warning: " << assembly.long_gaps << " gaps left unfilled: longer than "
              << kMaxFilledGap << " s (a clock jump or a pause) or than " << kMaxFilledFrames
              << " frames at " << 1.0 / assembly.frame_period << " Hz\n";
}

}  // namespace

CommandHelp track_help() {
  return {"track", kSummary, specs()};
}

int track_command(const std::vector<std::string>& raw) {
  const auto option_specs = specs();
  const Arguments args(raw, option_specs);
  if (args.help()) {
    std::cout << usage(track_help());
    return 0;
  }
  const std::string in = args.require("in");
  const std::string out = args.require("out");
  refuse_output_over_input({"--out", out},
                           {{"--in", in}, {"--config", args.get("config").value_or("")}});
  const std::string estimator = args.get("estimator").value_or("opf");
  require_known_estimators("estimator", {estimator});
  const EstimatorSettings settings = settings_from(args);
  require_camera_for_line_of_sight(settings);
  const LogReadOptions log_options = log_options_from(args, in);
  const bool stream = in == "-" || args.has("stream");
  const bool quiet = args.has("quiet");
  // With the estimates on standard output, everything else goes to standard error.
  std::ostream& report = out == "-" ? std::cerr : std::cout;

  const bool warn_camera = !quiet && estimator == "opf" && assumes_top_down_camera(settings);
  Tracker tracker(make_estimator_factory(estimator, settings), seed_from(args), threads_from(args));
  const EstimateColumns columns{.covariance = args.has("covariance")};
  UnsizedLogWatch unsized;  // for unsized_log_note, whichever output is written
  EstimateWriter writer(
      tracker, settings.opf.feedback.epsilon_safe, columns,
      [&](std::size_t objects) {
        if (warn_camera && objects == 2) std::cerr << missing_camera_warning("track");
      },
      unsized);

  FrameAssemblyReport assembly;
  std::string written;  // what the closing line says was written, and where
  if (tum_output(args, out)) {
    if (stream)
      throw UsageError{"--out-format tum is written when the log is read whole, not from a stream"};
    const MeasurementLog log = read_whole_log(in, log_options, "track", quiet);
    assembly = log.report;
    std::string names;
    for (const fs::path& path : track_to_tum(tracker, log, in, out, unsized))
      names += (names.empty() ? "" : ", ") + path.string();
    written = std::to_string(log.frames.size()) + " frames, " + std::to_string(log.objects.size()) +
              " objects: main estimates written as TUM to " + names;
  } else if (stream) {
    assembly = track_stream(in, out, log_options, columns, writer, quiet);
  } else {
    const MeasurementLog log = read_whole_log(in, log_options, "track", quiet);
    assembly = log.report;
    track_whole_log(log, out, columns, writer);
  }
  if (quiet) return 0;
  report_filled_gaps(assembly);
  if (unsized.note_due()) std::cerr << "opf track: note: " << unsized_log_note() << "\n";
  if (written.empty())
    written = std::to_string(writer.frames()) + " frames, " + std::to_string(writer.objects()) +
              " objects: " + std::to_string(writer.rows()) + " estimates written to " + out;
  report << "opf track: " << estimator << " over " << written << "\n";
  return 0;
}

}  // namespace opf::cli
