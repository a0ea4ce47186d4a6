#include "drivers/results_files.h"

#include "opf/core/metrics.h"
#include "opf/core/pose_conversion.h"
#include "opf/io/atomic_file.h"
#include "opf/io/csv.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>

namespace opf::experiments {
namespace {

struct PaperRow {
  MeanStd opf_translation, pf_translation, opf_rotation, pf_rotation;
};

// Table I of the paper (5 runs, mean +- std; metres and radians).
const std::map<std::string, PaperRow>& paper_table() {
  static const std::map<std::string, PaperRow> table = {
      {"general_op",
       {{0.01138, 7.253e-4}, {0.06289, 6.498e-4}, {0.06869, 2.947e-3}, {0.3870, 1.270e-3}}},
      {"sugar_drop",
       {{0.02129, 5.872e-4}, {0.05018, 6.936e-4}, {0.003411, 4.629e-4}, {0.01456, 2.274e-3}}},
  };
  return table;
}

enum class Metric { kTranslation, kRotationPaper, kRotationGeodesic, kTranslationUnobserved };

MeanStd metric_of(const std::vector<RunErrors>& runs, Metric metric) {
  std::vector<double> values;
  for (const RunErrors& r : runs) {
    switch (metric) {
      case Metric::kTranslation:
        values.push_back(r.translation);
        break;
      case Metric::kRotationPaper:
        values.push_back(r.rotation_paper);
        break;
      case Metric::kRotationGeodesic:
        values.push_back(r.rotation_geodesic);
        break;
      case Metric::kTranslationUnobserved:
        values.push_back(r.translation_unobserved);
        break;
    }
  }
  return mean_std(values);
}

// Over one run there is no spread to print: the mean alone.
std::string cell(const MeanStd& m) {
  char buffer[64];
  if (m.has_spread())
    std::snprintf(buffer, sizeof buffer, "%.5f +- %.2e", m.mean, m.std);
  else
    std::snprintf(buffer, sizeof buffer, "%.5f", m.mean);
  return buffer;
}

std::string number(double v) {
  return csv::format_double(v);
}

}  // namespace

void write_runs_csv(const std::filesystem::path& path, const ExperimentResults& results) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "experiment,estimator,seed,translation_error,rotation_error_paper,"
           "rotation_error_geodesic,translation_error_unobserved,frames,unobserved_frames,"
           "payload_released,payload_landed,miss_distance\n";
    for (const std::string& estimator : results.estimators) {
      const auto runs = results.runs.find(estimator);
      if (runs == results.runs.end()) continue;
      const auto drops = results.drops.find(estimator);
      for (std::size_t k = 0; k < runs->second.size(); ++k) {
        const RunErrors& e = runs->second[k];
        out << csv::quote_if_needed(results.experiment) << ',' << estimator << ','
            << results.first_seed + k << ',' << number(e.translation) << ','
            << number(e.rotation_paper) << ',' << number(e.rotation_geodesic) << ','
            << number(e.translation_unobserved) << ',' << e.frames << ',' << e.unobserved_frames;
        if (drops != results.drops.end() && k < drops->second.size()) {
          const DropOutcome& d = drops->second[k];
          out << ',' << (d.released ? 1 : 0) << ',' << (d.landed ? 1 : 0) << ','
              << (d.released ? number(d.miss_distance) : "");
        } else {
          out << ",,,";
        }
        out << '\n';
      }
    }
  });
}

void write_records_csv(const std::filesystem::path& path, const ExperimentResults& results) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "frame,t,object,estimator,seed,true_x,true_y,true_z,true_qx,true_qy,true_qz,true_qw,"
           "x,y,z,qx,qy,qz,qw,trace,mode,visible,hypothesis,probability,alert,model\n";
    for (const FrameRecord& r : results.records) {
      Eigen::Quaterniond q = orientation_of(r.estimate.pose.mean);
      if (q.w() < 0) q.coeffs() *= -1.0;
      Eigen::Quaterniond tq = r.truth.orientation;
      if (tq.w() < 0) tq.coeffs() *= -1.0;
      const auto& p = r.truth.position;
      const auto& m = r.estimate.pose.mean;
      out << r.frame << ',' << number(r.estimate.t) << ','
          << csv::quote_if_needed(r.estimate.object) << ',' << r.estimator << ',' << r.seed_index
          << ',' << number(p.x()) << ',' << number(p.y()) << ',' << number(p.z()) << ','
          << number(tq.x()) << ',' << number(tq.y()) << ',' << number(tq.z()) << ','
          << number(tq.w()) << ',' << number(m.x()) << ',' << number(m.y()) << ',' << number(m.z())
          << ',' << number(q.x()) << ',' << number(q.y()) << ',' << number(q.z()) << ','
          << number(q.w()) << ',' << number(r.estimate.observation_trace) << ','
          << mode_column(r.estimate.mode, r.estimate.recovery) << ',' << (r.visible ? 1 : 0) << ','
          << r.estimate.hypothesis << ',' << number(r.estimate.probability) << ','
          << (safety_alert(r.estimate, results.epsilon_safe) ? 1 : 0) << ','
          << csv::quote_if_needed(r.estimate.motion_model) << '\n';
    }
  });
}

std::map<std::string, std::size_t> dynamics_model_counts(const std::vector<FrameRecord>& records,
                                                         const std::string& estimator) {
  // An occlusion's model is counted at its first frame: where a record names a model and the
  // previous record of the same run and body did not name the same.
  std::map<std::string, std::size_t> counts;
  std::map<std::pair<std::size_t, std::string>, std::string> previous;
  for (const FrameRecord& r : records) {
    if (r.estimator != estimator || r.estimate.hypothesis != 0) continue;
    std::string& last = previous[{r.seed_index, r.estimate.object}];
    if (!r.estimate.motion_model.empty() && r.estimate.motion_model != last)
      ++counts[r.estimate.motion_model];
    last = r.estimate.motion_model;
  }
  return counts;
}

HypothesisStats hypothesis_stats(const ExperimentResults& results, const std::string& estimator) {
  // Per (seed, frame, object): the main record's visibility and the smallest error of any
  // hypothesis (the main's first: the tracker reports it before the extra ones).
  struct Frame {
    bool hidden = false;
    std::size_t hypotheses = 0;
    double main = 0.0;
    double nearest = 0.0;
  };
  std::map<std::tuple<std::size_t, int, std::string>, Frame> frames;
  for (const FrameRecord& r : results.records) {
    if (r.estimator != estimator ||
        std::find(results.objects_of_interest.begin(), results.objects_of_interest.end(),
                  r.estimate.object) == results.objects_of_interest.end())
      continue;
    const double error =
        translation_error(r.estimate.pose.mean, make_pose(r.truth.position, r.truth.orientation));
    Frame& f = frames[{r.seed_index, r.frame, r.estimate.object}];
    if (r.estimate.hypothesis == 0) {
      f.hidden = !r.visible;
      f.main = error;
    }
    f.nearest = f.hypotheses == 0 ? error : std::min(f.nearest, error);
    ++f.hypotheses;
  }
  HypothesisStats stats;
  for (const auto& [key, f] : frames) {
    if (!f.hidden) continue;
    ++stats.hidden_frames;
    stats.with_more += f.hypotheses > 1;
    stats.nearest_hidden_translation += f.nearest;
    stats.main_hidden_translation += f.main;
  }
  if (stats.hidden_frames > 0) {
    stats.nearest_hidden_translation /= static_cast<double>(stats.hidden_frames);
    stats.main_hidden_translation /= static_cast<double>(stats.hidden_frames);
  }
  return stats;
}

void write_summary_json(const std::filesystem::path& path,
                        const std::vector<ExperimentResults>& experiments,
                        const std::string& provenance) {
  write_file_atomically(path, [&](std::ostream& out) {
    const auto stat = [&](const char* name, const MeanStd& m, bool last) {
      out << "        \"" << name << "\": {\"mean\": " << number(m.mean)
          << ", \"std\": " << number(m.std) << "}" << (last ? "\n" : ",\n");
    };
    out << "{\n";
    if (!provenance.empty()) out << "  \"provenance\": " << provenance << ",\n";
    out << "  \"experiments\": {\n";
    for (std::size_t e = 0; e < experiments.size(); ++e) {
      const ExperimentResults& x = experiments[e];
      out << "    \"" << x.experiment << "\": {\n";
      for (std::size_t i = 0; i < x.estimators.size(); ++i) {
        const auto& runs = x.runs.at(x.estimators[i]);
        out << "      \"" << x.estimators[i] << "\": {\n";
        out << "        \"seeds\": " << runs.size() << ",\n";
        stat("translation_error", metric_of(runs, Metric::kTranslation), false);
        stat("rotation_error_paper", metric_of(runs, Metric::kRotationPaper), false);
        stat("rotation_error_geodesic", metric_of(runs, Metric::kRotationGeodesic), false);
        const auto drops = x.drops.find(x.estimators[i]);
        const bool closed_loop = drops != x.drops.end();
        stat("translation_error_unobserved", metric_of(runs, Metric::kTranslationUnobserved),
             false);
        // How often the dynamics module chose each model, one count per occlusion it carried
        // (over every seed and tracked body).
        out << "        \"dynamics_models\": {";
        const auto models = dynamics_model_counts(x.records, x.estimators[i]);
        for (auto it = models.begin(); it != models.end(); ++it)
          out << (it == models.begin() ? "" : ", ") << '"' << it->first << "\": " << it->second;
        out << "},\n";
        const HypothesisStats h = hypothesis_stats(x, x.estimators[i]);
        out << "        \"hypotheses\": {\"hidden_frames\": " << h.hidden_frames
            << ", \"with_more\": " << h.with_more
            << ", \"main_hidden_translation\": " << number(h.main_hidden_translation)
            << ", \"nearest_hidden_translation\": " << number(h.nearest_hidden_translation) << "}"
            << (closed_loop ? ",\n" : "\n");
        if (closed_loop) {
          std::size_t released = 0, landed = 0;
          for (const DropOutcome& d : drops->second) {
            released += d.released;
            landed += d.landed;
          }
          out << "        \"payload_released\": " << released << ",\n";
          out << "        \"payload_landed\": " << landed << "\n";
        }
        out << "      }" << (i + 1 < x.estimators.size() ? ",\n" : "\n");
      }
      out << "    }" << (e + 1 < experiments.size() ? ",\n" : "\n");
    }
    out << "  }\n}\n";
  });
}

std::string results_table_title(const std::string& experiment, std::size_t seeds) {
  const std::string prefix =
      experiment + ": errors of the objects of interest, each run's mean over frames ";
  if (seeds == 1) return prefix + "(1 seed: no spread)";
  return prefix + "(mean +- std over " + std::to_string(seeds) + " seeds)";
}

namespace {

// One experiment's block of the printed table, section by section.
void print_error_rows(std::ostream& out, const ExperimentResults& x) {
  char line[256];
  std::snprintf(line, sizeof line, "  %-10s %-22s %-22s %-22s %-22s\n", "estimator",
                "translation [m]", "rotation paper [rad]", "rotation geodesic",
                "transl. hidden [m]");
  out << line;
  for (const std::string& name : x.estimators) {
    const auto& runs = x.runs.at(name);
    std::snprintf(line, sizeof line, "  %-10s %-22s %-22s %-22s %-22s\n", name.c_str(),
                  cell(metric_of(runs, Metric::kTranslation)).c_str(),
                  cell(metric_of(runs, Metric::kRotationPaper)).c_str(),
                  cell(metric_of(runs, Metric::kRotationGeodesic)).c_str(),
                  cell(metric_of(runs, Metric::kTranslationUnobserved)).c_str());
    out << line;
  }
}

void print_drops_and_hypotheses(std::ostream& out, const ExperimentResults& x) {
  char line[256];
  for (const std::string& name : x.estimators) {
    const auto drops = x.drops.find(name);
    if (drops == x.drops.end()) continue;
    std::size_t released = 0, landed = 0;
    for (const DropOutcome& d : drops->second) {
      released += d.released;
      landed += d.landed;
    }
    std::snprintf(line, sizeof line,
                  "  %-10s cube released in %zu of %zu runs, landed in the mug in %zu\n",
                  name.c_str(), released, drops->second.size(), landed);
    out << line;
  }
  for (const std::string& name : x.estimators) {
    const HypothesisStats h = hypothesis_stats(x, name);
    if (h.with_more == 0) continue;
    std::snprintf(
        line, sizeof line,
        "  %-10s more than one hypothesis in %zu of %zu hidden frames; hidden error of the one "
        "nearest the truth %.5f m (the main one's %.5f m)\n",
        name.c_str(), h.with_more, h.hidden_frames, h.nearest_hidden_translation,
        h.main_hidden_translation);
    out << line;
  }
}

void print_paper_rows_and_ratios(std::ostream& out, const ExperimentResults& x) {
  char line[256];
  const auto paper = paper_table().find(x.experiment);
  if (paper != paper_table().end()) {
    const PaperRow& p = paper->second;
    std::snprintf(line, sizeof line, "  %-10s %-22s %-22s (Table I, 5 runs)\n", "paper opf",
                  cell(p.opf_translation).c_str(), cell(p.opf_rotation).c_str());
    out << line;
    std::snprintf(line, sizeof line, "  %-10s %-22s %-22s (Table I, 5 runs)\n", "paper pf",
                  cell(p.pf_translation).c_str(), cell(p.pf_rotation).c_str());
    out << line;
  }
  if (!x.runs.count("opf") || !x.runs.count("pf")) return;
  const auto ratio = [&](Metric m) {
    return metric_of(x.runs.at("opf"), m).mean / metric_of(x.runs.at("pf"), m).mean;
  };
  std::snprintf(line, sizeof line, "  OPF/PF ratio: translation %.3f, rotation (paper) %.3f",
                ratio(Metric::kTranslation), ratio(Metric::kRotationPaper));
  out << line;
  if (paper != paper_table().end()) {
    const PaperRow& p = paper->second;
    std::snprintf(line, sizeof line, "   [paper: %.3f, %.3f]",
                  p.opf_translation.mean / p.pf_translation.mean,
                  p.opf_rotation.mean / p.pf_rotation.mean);
    out << line;
  }
  out << "\n";
}

}  // namespace

void print_results_table(std::ostream& out, const std::vector<ExperimentResults>& experiments) {
  for (const ExperimentResults& x : experiments) {
    out << "\n" << results_table_title(x.experiment, x.seeds) << "\n";
    print_error_rows(out, x);
    print_drops_and_hypotheses(out, x);
    print_paper_rows_and_ratios(out, x);
  }
}

}  // namespace opf::experiments
