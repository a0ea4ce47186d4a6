#include "drivers/sweep_table.h"

#include "opf/core/metrics.h"
#include "opf/io/atomic_file.h"
#include "opf/io/csv.h"
#include "opf/io/input_error.h"

#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <string_view>

namespace opf::experiments {
namespace {

constexpr std::array<std::string_view, 9> kMetrics = {"translation_error",
                                                      "rotation_error_paper",
                                                      "rotation_error_geodesic",
                                                      "translation_error_unobserved",
                                                      "frames",
                                                      "unobserved_frames",
                                                      "payload_released",
                                                      "payload_landed",
                                                      "miss_distance"};

// The metric fields of the one row of `estimator` and `seed` in a run's result file.
std::vector<std::string> read_metrics(const std::filesystem::path& file, const SweepRun& run) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), 0, "", "cannot read the run's result file");
  std::vector<std::string_view> required = {"estimator", "seed"};
  required.insert(required.end(), kMetrics.begin(), kMetrics.end());
  csv::Reader reader(in, file.string(), required);
  while (reader.next()) {
    if (reader.field(reader.column("estimator")) != run.estimator ||
        reader.field(reader.column("seed")) != std::to_string(run.seed_index))
      continue;
    std::vector<std::string> fields;
    for (std::string_view metric : kMetrics) fields.push_back(reader.field(reader.column(metric)));
    return fields;
  }
  throw InputError(
      file.string(), 0, "",
      "no row for estimator " + run.estimator + " and seed " + std::to_string(run.seed_index));
}

}  // namespace

std::size_t write_sweep_table(const SweepSpec& spec, const std::vector<SweepRun>& runs,
                              const std::filesystem::path& out, const std::filesystem::path& csv) {
  std::size_t ok = 0;
  write_file_atomically(csv, [&](std::ostream& table) {
    table << "experiment,estimator,variant";
    for (const SweepParameter& parameter : spec.parameters)
      table << ',' << csv::quote_if_needed(parameter.key);
    table << ",seed";
    for (std::string_view metric : kMetrics) table << ',' << metric;
    table << ",status\n";
    for (const SweepRun& run : runs) {
      table << csv::quote_if_needed(run.experiment) << ',' << run.estimator << ','
            << csv::quote_if_needed(run.variant);
      for (const SweepSetting& value : run.point) table << ',' << csv::quote_if_needed(value.value);
      table << ',' << run.seed_index;
      const std::filesystem::path result = out / run.result_file();
      if (std::filesystem::exists(result)) {
        for (const std::string& field : read_metrics(result, run)) table << ',' << field;
        table << ",ok\n";
        ++ok;
      } else {
        table << std::string(kMetrics.size(), ',') << ",missing\n";
      }
    }
  });
  return ok;
}

void print_sweep_summary(std::ostream& out, const std::filesystem::path& csv) {
  std::ifstream in(csv, std::ios::binary);
  const std::array<std::string_view, 6> required = {
      "experiment", "estimator", "seed", "translation_error", "rotation_error_geodesic", "status"};
  csv::Reader reader(in, csv.string(), required);
  const std::size_t seed = reader.column("seed");
  // Every column before seed identifies the configuration.
  std::vector<std::string> order;
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> groups;
  std::map<std::string, std::size_t> missing;
  while (reader.next()) {
    std::string key;
    for (std::size_t c = 0; c < seed; ++c) key += (c ? "  " : "") + reader.field(c);
    if (!groups.count(key)) order.push_back(key);
    auto& group = groups[key];
    if (reader.field(reader.column("status")) != "ok") {
      ++missing[key];
      continue;
    }
    group.first.push_back(reader.number(reader.column("translation_error")));
    group.second.push_back(reader.number(reader.column("rotation_error_geodesic")));
  }
  std::string header;
  for (std::size_t c = 0; c < seed; ++c) header += (c ? "  " : "") + reader.header()[c];
  out << header
      << "  ->  translation [m], rotation geodesic [rad] (mean +- std over the N seeds of each "
         "row)\n";
  for (const std::string& key : order) {
    const auto& [translation, rotation] = groups[key];
    char line[128] = "no finished run";
    if (!translation.empty()) {
      const MeanStd t = mean_std(translation), r = mean_std(rotation);
      if (t.has_spread())
        std::snprintf(line, sizeof line, "%.5f +- %.2e   %.5f +- %.2e  (%zu seeds)", t.mean, t.std,
                      r.mean, r.std, translation.size());
      else
        std::snprintf(line, sizeof line, "%.5f   %.5f  (1 seed: no spread)", t.mean, r.mean);
    }
    out << "  " << key << "  ->  " << line;
    if (missing.count(key)) out << "  [" << missing[key] << " missing]";
    out << "\n";
  }
}

}  // namespace opf::experiments
