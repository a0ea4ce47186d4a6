#include "opf/io/measurement_log.h"

#include "opf/io/input_error.h"
#include "opf/io/input_file.h"

#include <algorithm>
#include <fstream>
#include <utility>

namespace opf {
namespace {

[[noreturn]] void refuse_without_detections(const std::string& source) {
  throw InputError(source, 0, "",
                   "no detections: the log has no row with a pose (a header only, or every "
                   "object unobserved), so there is nothing to track or compare");
}

}  // namespace

MeasurementLog parse_measurement_log(std::istream& in, const std::string& source_name,
                                     const LogReadOptions& options) {
  LogRowReader reader(in, source_name, options);
  std::vector<LogRow> rows;
  for (LogRow row; reader.next(row);) rows.push_back(row);
  if (std::none_of(rows.begin(), rows.end(), [](const LogRow& row) { return row.pose; }))
    refuse_without_detections(source_name);
  // A file may list its rows in any order: by time, keeping the row order within a time.
  std::stable_sort(rows.begin(), rows.end(),
                   [](const LogRow& a, const LogRow& b) { return a.t < b.t; });

  MeasurementLog log;
  FrameAssembler assembler(source_name, options);
  const auto collect = [&] {
    while (std::optional<Frame> frame = assembler.pop()) {
      for (const Detection& detection : frame->detections)
        if (std::find(log.objects.begin(), log.objects.end(), detection.object) ==
            log.objects.end())
          log.objects.push_back(detection.object);
      log.frames.push_back(std::move(*frame));
    }
  };
  for (LogRow& row : rows) {
    assembler.push(std::move(row));
    collect();
  }
  assembler.finish();
  collect();
  log.report = assembler.report();
  log.states_orientation = reader.states_orientation();
  return log;
}

MeasurementLog read_measurement_log(const std::filesystem::path& path,
                                    const LogReadOptions& options) {
  std::ifstream in = open_input_file(path, "measurement log");
  return parse_measurement_log(in, path.string(), options);
}

MeasurementStream::MeasurementStream(std::istream& in, const std::string& source_name,
                                     const LogReadOptions& options)
    : rows_(in, source_name, options), assembler_(source_name, options), source_(source_name) {}

std::optional<Frame> MeasurementStream::next() {
  while (true) {
    if (std::optional<Frame> frame = assembler_.pop()) return frame;
    if (finished_) return std::nullopt;
    LogRow row;
    if (rows_.next(row)) {
      any_detection_ = any_detection_ || row.pose.has_value();
      assembler_.push(std::move(row));
    } else {
      finished_ = true;
      if (!any_detection_) refuse_without_detections(source_);
      assembler_.finish();
    }
  }
}

}  // namespace opf
