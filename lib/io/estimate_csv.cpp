#include "opf/io/estimate_csv.h"

#include "opf/core/pose_conversion.h"
#include "opf/io/csv.h"
#include "opf/io/input_error.h"
#include "opf/io/input_file.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <string_view>
#include <utility>

namespace opf {

namespace {

constexpr std::array<std::string_view, 11> kReadColumns = {
    "t", "object", "x", "y", "z", "qx", "qy", "qz", "qw", "trace", "mode"};
// Written quaternions are unit to rounding; the log reader's tolerance still catches edited files.
constexpr double kQuaternionNormTolerance = 0.01;

constexpr std::array<std::string_view, 6> kPoseAxes = {"x", "y", "z", "yaw", "pitch", "roll"};

}  // namespace

void write_estimate_header(std::ostream& out, EstimateColumns columns) {
  out << "t,object,x,y,z,qx,qy,qz,qw,trace,mode,std_x,std_y,std_z,std_yaw,std_pitch,std_roll,"
         "hypothesis,probability,alert,model";
  if (columns.covariance)
    for (std::size_t i = 0; i < kPoseAxes.size(); ++i)
      for (std::size_t j = i; j < kPoseAxes.size(); ++j)
        out << ",cov_" << kPoseAxes[i] << '_' << kPoseAxes[j];
  out << '\n';
}

void write_estimate_row(std::ostream& out, const Estimate& estimate, double epsilon_safe,
                        EstimateColumns columns) {
  const mrpt::poses::CPose3D& mean = estimate.pose.mean;
  Eigen::Quaterniond q = orientation_of(mean);
  // q and -q are the same rotation; one sign makes files comparable. Adding 0.0 turns -0 into 0.
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const double qw = q.w() + 0.0;

  std::string row = csv::format_time(estimate.t);
  row += ',' + csv::quote_if_needed(estimate.object);
  for (const double value :
       {mean.x(), mean.y(), mean.z(), q.x(), q.y(), q.z(), qw, estimate.observation_trace})
    row += ',' + csv::format_double(value);
  row += ',' + mode_column(estimate.mode, estimate.recovery);
  for (int i = 0; i < 6; ++i) row += ',' + csv::format_double(std::sqrt(estimate.pose.cov(i, i)));
  row += ',' + std::to_string(estimate.hypothesis);
  row += ',' + csv::format_double(estimate.probability);
  row += safety_alert(estimate, epsilon_safe) ? ",1," : ",0,";
  row += csv::quote_if_needed(estimate.motion_model);
  if (columns.covariance)
    for (int i = 0; i < 6; ++i)
      for (int j = i; j < 6; ++j) row += ',' + csv::format_double(estimate.pose.cov(i, j));
  out << row << '\n';
}

std::vector<EstimateRecord> read_estimate_csv(const std::filesystem::path& path) {
  std::ifstream in = open_input_file(path, "estimate file");
  csv::Reader reader(in, path.string(), kReadColumns);
  std::array<std::size_t, kReadColumns.size()> column{};
  for (std::size_t i = 0; i < kReadColumns.size(); ++i) column[i] = reader.column(kReadColumns[i]);

  // Optional columns, written by this toolkit since the OPF landed.
  const auto optional_column = [&](std::string_view name) -> std::optional<std::size_t> {
    const auto& header = reader.header();
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) return std::nullopt;
    return static_cast<std::size_t>(it - header.begin());
  };
  const auto hypothesis_column = optional_column("hypothesis");
  const auto probability_column = optional_column("probability");
  const auto alert_column = optional_column("alert");
  const auto model_column = optional_column("model");

  std::vector<EstimateRecord> records;
  while (reader.next()) {
    EstimateRecord record;
    record.t = reader.number(column[0]);
    record.object = reader.field(column[1]);
    if (record.object.empty())
      reader.fail(column[1], "expected an object name, got an empty field");
    std::array<double, 7> pose{};
    for (std::size_t i = 0; i < pose.size(); ++i) pose[i] = reader.number(column[2 + i]);
    const Eigen::Quaterniond q(pose[6], pose[3], pose[4], pose[5]);
    if (!(std::abs(q.norm() - 1.0) <= kQuaternionNormTolerance))
      throw InputError(reader.source(), reader.line(), "qx,qy,qz,qw",
                       "expected a unit quaternion, got norm " + csv::format_double(q.norm()));
    record.pose = make_pose(Eigen::Vector3d(pose[0], pose[1], pose[2]), q);
    // Non-finite traces are legitimate output (e.g. an estimator with no observation model).
    record.trace = reader.number_or_non_finite(column[9]);
    record.mode = reader.field(column[10]);
    if (!parse_mode_column(record.mode))
      reader.fail(column[10],
                  "expected a mode (measured, predicted, dynamics, carried, left or "
                  "random_walk) optionally followed by +reset, +underflow, +capped, +filled; "
                  "got '" +
                      record.mode + "'");
    if (hypothesis_column) {
      const double h = reader.number(*hypothesis_column);
      // In range before the conversion: a double past an int's range does not convert.
      if (!(h >= 0.0 && h <= std::numeric_limits<int>::max()) || h != std::floor(h))
        reader.fail(*hypothesis_column, "expected a hypothesis number 0, 1, ...");
      record.hypothesis = static_cast<int>(h);
    }
    if (probability_column) {
      record.probability = reader.number(*probability_column);
      if (!(record.probability >= 0.0 && record.probability <= 1.0))
        reader.fail(*probability_column, "expected a probability in [0, 1]");
    }
    if (alert_column) {
      const std::string& a = reader.field(*alert_column);
      if (a != "0" && a != "1") reader.fail(*alert_column, "expected 0 or 1");
      record.alert = a == "1";
    }
    if (model_column) record.model = reader.field(*model_column);
    records.push_back(std::move(record));
  }
  return records;
}

}  // namespace opf
