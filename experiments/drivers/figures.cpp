#include "drivers/figures.h"

#include "drivers/line_chart.h"
#include "drivers/observe_experiment.h"
#include "opf/core/metrics.h"
#include "opf/core/pose_conversion.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

namespace opf::experiments {
namespace {

// The paper's colours: OPF red, PF blue; the other baselines green and orange.
std::array<std::uint8_t, 3> colour_of(const std::string& estimator) {
  static const std::map<std::string, std::array<std::uint8_t, 3>> colours = {
      {"opf", {220, 30, 30}},
      {"pf", {30, 60, 220}},
      {"cvkf", {30, 160, 60}},
      {"oapf", {240, 140, 0}}};
  const auto it = colours.find(estimator);
  return it == colours.end() ? std::array<std::uint8_t, 3>{90, 90, 90} : it->second;
}

}  // namespace

std::vector<std::filesystem::path> write_figures(const std::filesystem::path& dir,
                                                 const sim::ExperimentConfig& config,
                                                 const Observation& observation,
                                                 const ExperimentResults& results) {
  std::vector<std::filesystem::path> written;
  for (const std::string& object : config.objects_of_interest) {
    const std::string seed = " (seed " + std::to_string(results.first_seed + 1) + ")";
    LineChart translation{config.name + ": " + object + " translation error" + seed,
                          "frame",
                          "m",
                          {},
                          false,
                          900,
                          420};
    LineChart rotation{config.name + ": " + object + " rotation error, geodesic" + seed,
                       "frame",
                       "rad",
                       {},
                       false,
                       900,
                       420};
    LineChart trace{config.name + ": " + object + " trace of Q~" + seed,
                    "frame",
                    "m^2 + rad^2",
                    {},
                    true,
                    900,
                    420};
    for (const std::string& estimator : results.estimators) {
      const auto [r, g, b] = colour_of(estimator);
      ChartSeries t{estimator, {}, {}, r, g, b}, q{estimator, {}, {}, r, g, b},
          u{estimator, {}, {}, r, g, b};
      for (const FrameRecord& record : results.records) {
        if (record.seed_index != results.first_seed || record.estimator != estimator ||
            record.estimate.object != object || record.estimate.hypothesis != 0)
          continue;
        const auto truth = make_pose(record.truth.position, record.truth.orientation);
        const double frame = record.frame;
        t.x.push_back(frame);
        t.y.push_back(translation_error(record.estimate.pose.mean, truth));
        q.x.push_back(frame);
        q.y.push_back(rotation_error_geodesic(record.estimate.pose.mean, truth));
        u.x.push_back(frame);
        u.y.push_back(record.estimate.observation_trace);
      }
      translation.series.push_back(std::move(t));
      rotation.series.push_back(std::move(q));
      trace.series.push_back(std::move(u));
    }
    for (auto [chart, name] :
         {std::pair{&translation, "translation_error"}, std::pair{&rotation, "rotation_error"},
          std::pair{&trace, "trace"}}) {
      written.push_back(dir / (config.name + "_" + object + "_" + name + ".png"));
      write_line_chart(written.back(), *chart);
    }
  }

  // Where an estimator followed more than one hypothesis (two equally likely occluders): a top
  // view of each hypothesis's track beside the truth's, from the first seed.
  for (const std::string& object : config.objects_of_interest) {
    for (const std::string& estimator : results.estimators) {
      std::map<int, ChartSeries> tracks;
      ChartSeries truth{"truth", {}, {}, 0, 0, 0};
      for (const FrameRecord& record : results.records) {
        if (record.seed_index != results.first_seed || record.estimator != estimator ||
            record.estimate.object != object)
          continue;
        const int h = record.estimate.hypothesis;
        if (!tracks.count(h)) {
          // The main hypothesis in the estimator's colour, the others in grey shades.
          const auto [r, g, b] = colour_of(estimator);
          const auto shade = static_cast<std::uint8_t>(std::min(200, 60 + 50 * h));
          tracks[h] = h == 0
                          ? ChartSeries{"main", {}, {}, r, g, b}
                          : ChartSeries{"hyp. " + std::to_string(h), {}, {}, shade, shade, shade};
        }
        const Eigen::Vector3d p = translation_of(record.estimate.pose.mean);
        tracks[h].x.push_back(p.x());
        tracks[h].y.push_back(p.y());
        if (h == 0) {
          truth.x.push_back(record.truth.position.x());
          truth.y.push_back(record.truth.position.y());
        }
      }
      if (tracks.size() < 2) continue;
      LineChart top{config.name + ": " + object + ", " + estimator +
                        " hypotheses, top view (seed " + std::to_string(results.first_seed + 1) +
                        ")",
                    "x [m]",
                    "y [m]",
                    {},
                    false,
                    900,
                    560};
      top.series.push_back(std::move(truth));
      for (auto& [h, series] : tracks) top.series.push_back(std::move(series));
      written.push_back(dir / (config.name + "_" + object + "_" + estimator + "_hypotheses.png"));
      write_line_chart(written.back(), top);
    }
  }

  // The snapshot: the rendered frame with each estimator's estimate of the objects of interest
  // (filled circles) and the truth (black cross).
  if (!observation.snapshot_bgr.empty()) {
    cv::Mat image = observation.snapshot_bgr.clone();
    const sim::CameraModel camera = camera_of(config);
    const int k = observation.snapshot_frame;
    int legend_y = 20;
    for (const std::string& estimator : results.estimators) {
      const auto [r, g, b] = colour_of(estimator);
      const cv::Scalar colour(b, g, r);
      for (const FrameRecord& record : results.records) {
        if (record.frame != k || record.seed_index != results.first_seed ||
            record.estimator != estimator)
          continue;
        if (std::find(config.objects_of_interest.begin(), config.objects_of_interest.end(),
                      record.estimate.object) == config.objects_of_interest.end())
          continue;
        const auto pixel = camera.project(translation_of(record.estimate.pose.mean));
        if (pixel)
          cv::circle(image, cv::Point2d(pixel->x(), pixel->y()), 7, colour, cv::FILLED,
                     cv::LINE_AA);
        const auto truth = camera.project(record.truth.position);
        if (truth)
          cv::drawMarker(image, cv::Point2d(truth->x(), truth->y()), cv::Scalar(0, 0, 0),
                         cv::MARKER_CROSS, 16, 2);
      }
      cv::circle(image, {15, legend_y - 4}, 6, colour, cv::FILLED, cv::LINE_AA);
      cv::putText(image, estimator, {28, legend_y}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
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
  return written;
}

}  // namespace opf::experiments
