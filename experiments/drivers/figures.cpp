#include "drivers/figures.h"

#include "drivers/coinciding_series.h"
#include "drivers/estimator_style.h"
#include "drivers/line_chart.h"
#include "drivers/observe_experiment.h"
#include "drivers/svg_line_chart.h"
#include "opf/core/metrics.h"
#include "opf/core/pose_conversion.h"
#include "opf/io/csv.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

namespace opf::experiments {
namespace {

/// The snapshot's marker of an estimator: OpenCV's marker of the same shape as in the charts.
int snapshot_marker(Marker marker) {
  switch (marker) {
    case Marker::kDiamond:
      return cv::MARKER_DIAMOND;
    case Marker::kSquare:
      return cv::MARKER_SQUARE;
    case Marker::kTriangleUp:
      return cv::MARKER_TRIANGLE_UP;
    case Marker::kTriangleDown:
      return cv::MARKER_TRIANGLE_DOWN;
    case Marker::kCross:
      return cv::MARKER_TILTED_CROSS;
    case Marker::kCircle:
    case Marker::kNone:
      break;
  }
  return cv::MARKER_STAR;
}

/// Writes the chart as `<stem>.png` and `<stem>.svg` into `dir`, both paths appended to `written`.
void write_chart(const std::filesystem::path& dir, const std::string& stem, const LineChart& chart,
                 std::vector<std::filesystem::path>& written) {
  written.push_back(dir / (stem + ".png"));
  write_line_chart(written.back(), chart);
  written.push_back(dir / (stem + ".svg"));
  write_svg_line_chart(written.back(), chart);
}

// A hypothesis by what it says: "left", or "carried by mug_a".
std::string hypothesis_name(const Estimate& estimate) {
  std::string name(to_string(estimate.mode));
  if (estimate.mode == EstimateMode::kCarried && !estimate.motion_model.empty())
    name += " by " + estimate.motion_model;
  return name;
}

// Appends a point to a track, first a gap (a non-finite value) when the track skipped frames.
void extend(ChartSeries& track, int& last_frame, int frame, const Eigen::Vector3d& p) {
  if (!track.x.empty() && frame != last_frame + 1) {
    track.x.push_back(track.x.back());
    track.y.push_back(std::numeric_limits<double>::quiet_NaN());
  }
  track.x.push_back(p.x());
  track.y.push_back(p.y());
  last_frame = frame;
}

// One of the occluder module's hypotheses of an object, as drawn: its track and its carrier.
struct HypothesisTrack {
  ChartSeries series;
  int last_frame = -1;
  std::string carrier;  ///< empty for `left`
};

// The n-th hypothesis's line: dashed, dash-dotted, dotted, then the same in lighter greys.
ChartSeries hypothesis_series(const std::string& name, std::size_t n) {
  static constexpr std::array<LineStyle, 3> kStyles = {LineStyle::kDashed, LineStyle::kDashDot,
                                                       LineStyle::kDotted};
  const auto shade = static_cast<std::uint8_t>(70 + 55 * ((n / kStyles.size()) % 3));
  ChartSeries series{name, {}, {}, shade, shade, shade};
  series.style = kStyles[n % kStyles.size()];
  return series;
}

// The n-th carrier's main estimate over the frames the object is hidden in, thin, in a light hue
// apart from the estimators' and the greys.
ChartSeries carrier_path(const ExperimentResults& results, const std::string& estimator,
                         const std::string& carrier, const std::set<int>& hidden_frames,
                         std::size_t n) {
  static constexpr std::array<std::array<std::uint8_t, 3>, 4> kHues = {
      {{110, 170, 230}, {230, 170, 90}, {120, 200, 160}, {200, 140, 210}}};
  const auto& hue = kHues[n % kHues.size()];
  ChartSeries path{carrier + " (estimate, while hidden)", {}, {}, hue[0], hue[1], hue[2]};
  path.width = 1;
  int last_frame = -1;
  for (const FrameRecord& record : results.records)
    if (record.seed_index == results.first_seed && record.estimator == estimator &&
        record.estimate.object == carrier && record.estimate.hypothesis == 0 &&
        hidden_frames.count(record.frame))
      extend(path, last_frame, record.frame, translation_of(record.estimate.pose.mean));
  return path;
}

// The top view of an object's hypotheses from the first seed, when the estimator kept more than
// one: the truth, each of the occluder module's hypotheses by what it says (grey, dashed or
// dotted, across the frames it exists in, main or not), the objects carrying them (thin, their main
// estimates while the object is hidden) and the main estimate in the estimator's style on top.
// None when it kept one throughout.
std::optional<LineChart> hypotheses_chart(const ExperimentResults& results,
                                          const std::string& object, const std::string& estimator) {
  ChartSeries truth{"truth", {}, {}, 0, 0, 0};
  truth.width = 4;
  ChartSeries main = estimator_series("main", estimator);
  std::map<std::string, HypothesisTrack> tracks;  // by name
  std::set<int> hidden_frames;                    // the object's
  bool several = false;
  for (const FrameRecord& record : results.records) {
    if (record.seed_index != results.first_seed || record.estimator != estimator ||
        record.estimate.object != object)
      continue;
    const Eigen::Vector3d p = translation_of(record.estimate.pose.mean);
    several = several || record.estimate.hypothesis > 0;
    if (record.estimate.hypothesis == 0) {
      if (!record.visible) hidden_frames.insert(record.frame);
      main.x.push_back(p.x());
      main.y.push_back(p.y());
      truth.x.push_back(record.truth.position.x());
      truth.y.push_back(record.truth.position.y());
    }
    const EstimateMode mode = record.estimate.mode;
    if (mode != EstimateMode::kCarried && mode != EstimateMode::kLeft) continue;
    const std::string name = hypothesis_name(record.estimate);
    auto [it, added] = tracks.try_emplace(name);
    if (added) {
      it->second.series = hypothesis_series(name, tracks.size() - 1);
      if (mode == EstimateMode::kCarried) it->second.carrier = record.estimate.motion_model;
    }
    extend(it->second.series, it->second.last_frame, record.frame, p);
  }
  if (!several) return std::nullopt;
  LineChart top;
  top.x_label = "x [m]";
  top.y_label = "y [m]";
  top.height = 560;
  top.map = true;
  top.series.push_back(std::move(truth));
  std::size_t carriers = 0;
  for (const auto& [name, track] : tracks)
    if (!track.carrier.empty())
      top.series.push_back(
          carrier_path(results, estimator, track.carrier, hidden_frames, carriers++));
  for (auto& [name, track] : tracks) top.series.push_back(std::move(track.series));
  top.series.push_back(std::move(main));
  return top;
}

LineChart time_chart(const std::string& title, const std::string& y_label, bool log_y) {
  LineChart chart;
  chart.title = title;
  chart.x_label = "t [s]";
  chart.y_label = y_label;
  chart.log_y = log_y;
  chart.band_label = "hidden";
  return chart;
}

// The intervals the object was hidden in, from the measurements (the same for every estimator):
// each frame's interval reaches halfway to its neighbours.
std::vector<ChartBand> hidden_bands(const ExperimentResults& results, const std::string& object) {
  std::vector<std::pair<double, bool>> frames;  // t, visible
  for (const FrameRecord& record : results.records)
    if (record.seed_index == results.first_seed && record.estimate.object == object &&
        record.estimate.hypothesis == 0 && record.estimator == results.estimators.front())
      frames.emplace_back(record.estimate.t, record.visible);
  std::vector<ChartBand> bands;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (frames[i].second) continue;
    const double from = i > 0 ? 0.5 * (frames[i - 1].first + frames[i].first) : frames[i].first;
    const double to =
        i + 1 < frames.size() ? 0.5 * (frames[i].first + frames[i + 1].first) : frames[i].first;
    if (!bands.empty() && bands.back().to >= from)
      bands.back().to = to;
    else
      bands.push_back({from, to});
  }
  return bands;
}

// Per object of interest: translation error, rotation error and trace(Q~) over time, a series per
// estimator in figure order, each one's markers a step further along their spacing than the
// previous one's so that lines on the same values show every estimator.
void write_time_charts(const std::filesystem::path& dir, const sim::ExperimentConfig& config,
                       const ExperimentResults& results, const std::string& object,
                       std::vector<std::filesystem::path>& written) {
  const std::size_t seed = results.first_seed;
  LineChart translation =
      time_chart(figure_title(config.name, object, "translation error", seed), "error [m]", false);
  LineChart rotation = time_chart(
      figure_title(config.name, object, "rotation error (geodesic)", seed), "error [rad]", false);
  LineChart trace = time_chart(figure_title(config.name, object, "uncertainty trace(Q~)", seed),
                               "trace(Q~) [m^2 + rad^2]", true);
  trace.references.push_back(
      {results.epsilon_safe, "alert (" + csv::format_double(results.epsilon_safe) + ")"});
  translation.bands = hidden_bands(results, object);
  rotation.bands = trace.bands = translation.bands;
  const std::vector<std::string> estimators = in_figure_order(results.estimators);
  for (std::size_t k = 0; k < estimators.size(); ++k) {
    const std::string& estimator = estimators[k];
    const double phase = static_cast<double>(k) / static_cast<double>(estimators.size());
    ChartSeries t = estimator_series(estimator, estimator, phase), q = t, u = t;
    for (const FrameRecord& record : results.records) {
      if (record.seed_index != seed || record.estimator != estimator ||
          record.estimate.object != object || record.estimate.hypothesis != 0)
        continue;
      const auto truth = make_pose(record.truth.position, record.truth.orientation);
      const double time = record.estimate.t;
      t.x.push_back(time);
      t.y.push_back(translation_error(record.estimate.pose.mean, truth));
      q.x.push_back(time);
      q.y.push_back(rotation_error_geodesic(record.estimate.pose.mean, truth));
      u.x.push_back(time);
      u.y.push_back(record.estimate.observation_trace);
    }
    translation.series.push_back(std::move(t));
    rotation.series.push_back(std::move(q));
    trace.series.push_back(std::move(u));
  }
  for (auto [chart, name] : {std::pair{&translation, "translation_error"},
                             std::pair{&rotation, "rotation_error"}, std::pair{&trace, "trace"}}) {
    merge_coinciding_series(chart->series);
    write_chart(dir, config.name + "_" + object + "_" + name, *chart, written);
  }
}

// The snapshot: the rendered frame with each estimator's estimate of the objects of interest (its
// marker, as in the charts) and the truth (black cross).
void write_snapshot(const std::filesystem::path& dir, const sim::ExperimentConfig& config,
                    const Observation& observation, const ExperimentResults& results,
                    std::vector<std::filesystem::path>& written) {
  cv::Mat image = observation.snapshot_bgr.clone();
  const sim::CameraModel camera = camera_of(config);
  const int k = observation.snapshot_frame;
  int legend_y = 20;
  // Each estimate as its estimator's marker, ringed in white and black so that it stands out on
  // a body of its own colour.
  const auto draw_estimate = [&](cv::Point2d at, const EstimatorStyle& style) {
    const cv::Scalar colour(style.rgb[2], style.rgb[1], style.rgb[0]);
    const int marker = snapshot_marker(style.marker);
    cv::drawMarker(image, at, cv::Scalar(0, 0, 0), marker, 19, 6, cv::LINE_AA);
    cv::drawMarker(image, at, cv::Scalar(255, 255, 255), marker, 17, 4, cv::LINE_AA);
    cv::drawMarker(image, at, colour, marker, 15, 2, cv::LINE_AA);
  };
  for (const std::string& estimator : in_figure_order(results.estimators)) {
    const EstimatorStyle style = estimator_style(estimator);
    for (const FrameRecord& record : results.records) {
      if (record.frame != k || record.seed_index != results.first_seed ||
          record.estimator != estimator)
        continue;
      if (std::find(config.objects_of_interest.begin(), config.objects_of_interest.end(),
                    record.estimate.object) == config.objects_of_interest.end())
        continue;
      const auto pixel = camera.project(translation_of(record.estimate.pose.mean));
      if (pixel) draw_estimate(cv::Point2d(pixel->x(), pixel->y()), style);
      const auto truth = camera.project(record.truth.position);
      if (truth)
        cv::drawMarker(image, cv::Point2d(truth->x(), truth->y()), cv::Scalar(0, 0, 0),
                       cv::MARKER_CROSS, 16, 2);
    }
    draw_estimate(cv::Point2d(15, legend_y - 4), style);
    cv::putText(image, estimator, {30, legend_y}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
    legend_y += 20;
  }
  cv::putText(image, config.name + ", frame " + std::to_string(k) + " (x: truth)",
              {10, image.rows - 12}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(255, 255, 255), 1,
              cv::LINE_AA);
  written.push_back(dir / (config.name + "_snapshot.png"));
  if (!cv::imwrite(written.back().string(), image))
    throw std::runtime_error("cannot write the figure " + written.back().string());
}

}  // namespace

std::string figure_title(const std::string& experiment, const std::string& object,
                         const std::string& what, std::size_t seed) {
  const std::string subject = object == experiment ? experiment : experiment + ": " + object;
  return subject + ", " + what + " (seed " + std::to_string(seed) + ")";
}

std::vector<std::filesystem::path> write_figures(const std::filesystem::path& dir,
                                                 const sim::ExperimentConfig& config,
                                                 const Observation& observation,
                                                 const ExperimentResults& results) {
  std::vector<std::filesystem::path> written;
  for (const std::string& object : config.objects_of_interest)
    write_time_charts(dir, config, results, object, written);
  // Where an estimator kept more than one hypothesis: a top view of each one's track.
  for (const std::string& object : config.objects_of_interest)
    for (const std::string& estimator : in_figure_order(results.estimators)) {
      std::optional<LineChart> top = hypotheses_chart(results, object, estimator);
      if (!top) continue;
      top->title = figure_title(config.name, object, estimator + " hypotheses, top view",
                                results.first_seed);
      write_chart(dir, config.name + "_" + object + "_" + estimator + "_hypotheses", *top, written);
    }
  if (!observation.snapshot_bgr.empty()) write_snapshot(dir, config, observation, results, written);
  return written;
}

}  // namespace opf::experiments
