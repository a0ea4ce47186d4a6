// Tracks a cup that slides along x at 0.2 m/s and is hidden for 0.3 s, with the default OPF, and
// prints one line per frame: time, mode (measured / dynamics / ...), estimated x and the trace
// of the position covariance.
#include <opf/opf.h>

#include <cstdio>
#include <string>

int main() {
  opf::EstimatorSettings settings;  // default-constructed: the toolkit's defaults
  opf::Tracker tracker(opf::make_estimator_factory("opf", settings), /*seed=*/7);

  const double dt = 1.0 / 30.0;
  for (int k = 0; k < 45; ++k) {
    opf::Frame frame;
    frame.t = k * dt;
    const bool hidden = frame.t >= 0.8 && frame.t < 1.1;  // an absent detection: unobserved
    if (!hidden)
      frame.detections.push_back({"cup", mrpt::poses::CPose3D(0.2 * frame.t, 0, 0.5, 0, 0, 0)});
    for (const opf::Estimate& estimate : tracker.step(frame)) {
      const auto& cov = estimate.pose.cov;
      std::printf("%.3f %-9s x=%.4f trace=%.2e\n", frame.t,
                  std::string(opf::to_string(estimate.mode)).c_str(), estimate.pose.mean.x(),
                  cov(0, 0) + cov(1, 1) + cov(2, 2));
    }
  }
  return 0;
}
