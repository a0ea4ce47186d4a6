#include "drivers/measurement_export.h"

#include "opf/io/atomic_file.h"
#include "opf/io/measurement_log_writer.h"

#include <string>

namespace opf::experiments {

std::vector<std::filesystem::path> write_measurement_logs(const std::filesystem::path& out,
                                                          const sim::ExperimentConfig& config,
                                                          const Observation& observation,
                                                          std::uint64_t base_seed,
                                                          std::size_t first_seed,
                                                          std::size_t seeds) {
  std::vector<std::filesystem::path> written;
  for (std::size_t s = first_seed; s < first_seed + seeds; ++s) {
    const std::vector<Frame> frames = measurement_stream(config, observation, base_seed, s);
    const StatedColumns columns = stated_columns(frames);
    written.push_back(out / (config.name + "_measurements_seed" + std::to_string(s) + ".csv"));
    write_file_atomically(written.back(), [&](std::ostream& file) {
      write_measurement_header(file, columns);
      write_measurement_rows(file, frames, columns);
    });
  }
  written.push_back(out / (config.name + "_truth.csv"));
  write_file_atomically(written.back(), [&](std::ostream& file) {
    write_measurement_header(file);
    for (const sim::SceneSnapshot& truth : observation.truth)
      for (std::size_t i = 0; i < truth.bodies.size(); ++i)
        if (truth.bodies[i].tracked)
          write_measurement_row(file, truth.t, truth.bodies[i].name, truth.poses[i].position,
                                truth.poses[i].orientation);
  });
  return written;
}

}  // namespace opf::experiments
