// A detector piped into `opf track --in - --out -`: a 100 Hz, 10-object log read as a stream
// (rows generated as they are read, never held), every frame stepped through the OPF and its
// estimate rows formatted. Reports the per-frame latency (from the frame being complete to its
// rows written) and the memory: the resident set after a tenth of the stream and at its end, so
// that memory flat in the log's length shows as a growth near zero.

#include "opf/core/random.h"
#include "opf/core/tracker.h"
#include "opf/estimators/registry.h"
#include "opf/io/estimate_csv.h"
#include "opf/io/measurement_log.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

namespace opf {
namespace {

constexpr double kRate = 100.0;
constexpr int kObjects = 10;

/// The log's rows, produced one frame at a time as the reader asks for them. Objects move on
/// circles with 2 mm noise; object 3 is unobserved for 0.5 s of every 7 s.
class GeneratedLog : public std::streambuf {
 public:
  GeneratedLog(double seconds, std::uint64_t seed)
      : frames_(static_cast<long>(seconds * kRate)), noise_(seed) {
    buffer_ = "t,object,x,y,z,qx,qy,qz,qw\n";
    setg(buffer_.data(), buffer_.data(), buffer_.data() + buffer_.size());
  }

 protected:
  int_type underflow() override {
    if (frame_ >= frames_) return traits_type::eof();
    std::ostringstream rows;
    rows.precision(10);
    const double t = static_cast<double>(frame_) / kRate;
    for (int i = 0; i < kObjects; ++i) {
      const double a = 0.7 * t + i;
      const double x = 0.15 * i + 0.1 * std::cos(a) + 0.002 * noise_.normal();
      const double y = 0.1 * std::sin(a) + 0.002 * noise_.normal();
      if (i == 3 && std::fmod(t, 7.0) >= 6.5) {
        rows << t << ",object" << i << ",,,,,,,\n";
        continue;
      }
      rows << t << ",object" << i << ',' << x << ',' << y << ",0.05,0,0," << std::sin(a / 2) << ','
           << std::cos(a / 2) << '\n';
    }
    ++frame_;
    buffer_ = rows.str();
    setg(buffer_.data(), buffer_.data(), buffer_.data() + buffer_.size());
    return traits_type::to_int_type(buffer_.front());
  }

 private:
  long frames_;
  long frame_ = 0;
  Random noise_;
  std::string buffer_;
};

/// A /proc/self/status field in KiB (VmRSS: resident now, VmHWM: the process's peak).
double status_kib(const std::string& field) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind(field + ":", 0) == 0) return std::stod(line.substr(field.size() + 1));
  return 0.0;
}

/// Discards what is written, as a pipe to a fast reader would.
class NullBuffer : public std::streambuf {
 protected:
  int_type overflow(int_type c) override { return c; }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

void BM_LogStream(benchmark::State& state) {
  const double seconds = static_cast<double>(state.range(0));
  EstimatorSettings settings;
  settings.pf.translation_particles = settings.pf.rotation_particles =
      static_cast<std::size_t>(state.range(1));
  std::vector<double> latencies;
  double rss_early = 0.0;
  double rss_end = 0.0;
  for (auto _ : state) {
    GeneratedLog generated(seconds, 7);
    std::istream in(&generated);
    NullBuffer null;
    std::ostream out(&null);
    MeasurementStream stream(in, "<generated>");
    Tracker tracker(make_estimator_factory("opf", settings), 1, 1);
    const auto frames = static_cast<std::size_t>(seconds * kRate);
    // Written in place: filled up front, so that its pages do not count as the stream's growth.
    latencies.assign(frames + 1, 0.0);
    std::size_t done = 0;
    while (const auto frame = stream.next()) {
      const auto start = std::chrono::steady_clock::now();
      for (const Estimate& estimate : tracker.step(*frame))
        write_estimate_row(out, estimate, settings.opf.feedback.epsilon_safe);
      out.flush();
      latencies.at(done++) =
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
              .count();
      if (done == frames / 10) rss_early = status_kib("VmRSS");
    }
    latencies.resize(done);
    rss_end = status_kib("VmRSS");
  }
  std::sort(latencies.begin(), latencies.end());
  double sum = 0.0;
  for (double l : latencies) sum += l;
  state.counters["frames"] = static_cast<double>(latencies.size());
  state.counters["latency_mean_us"] = sum / static_cast<double>(latencies.size());
  state.counters["latency_p99_us"] = latencies[latencies.size() * 99 / 100];
  state.counters["latency_max_us"] = latencies.back();
  state.counters["rss_after_10pct_MiB"] = rss_early / 1024.0;
  state.counters["rss_growth_MiB"] = (rss_end - rss_early) / 1024.0;
  state.counters["peak_rss_MiB"] = status_kib("VmHWM") / 1024.0;
}
// One minute and one hour of the stream: the hour's memory must be the minute's.
BENCHMARK(BM_LogStream)
    ->ArgNames({"seconds", "particles"})
    ->Args({60, 500})
    ->Args({3600, 500})
    ->Iterations(1)
    ->Repetitions(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace
}  // namespace opf
