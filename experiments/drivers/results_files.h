#pragma once
// The result files of `opf run` and `opf reproduce`: the per-frame CSV, summary.json, and the
// printed table with the paper's Table I beside our numbers.

#include "drivers/experiment_run.h"

#include <cstddef>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace opf::experiments {

/// frame,t,object,estimator,seed,true_x,...,true_qw,x,...,qw,trace,mode,visible,hypothesis,
/// probability,alert,model
void write_records_csv(const std::filesystem::path& path, const ExperimentResults& results);

/// One row per estimator and seed, the tidy form sweeps aggregate:
/// experiment,estimator,seed,translation_error,rotation_error_paper,rotation_error_geodesic,
/// translation_error_unobserved,frames,unobserved_frames,payload_released,payload_landed,
/// miss_distance (errors in m and rad, means over the frames of the objects of interest; seed is
/// the seed index; the payload columns are empty for open-loop experiments).
void write_runs_csv(const std::filesystem::path& path, const ExperimentResults& results);

/// experiments.<name>.<estimator>.{translation_error, rotation_error_paper,
/// rotation_error_geodesic, translation_error_unobserved}.{mean, std} (std: the sample standard
/// deviation over the seeds, n - 1), plus seeds,
/// dynamics_models (per motion model, the occlusions the dynamics module carried with it, over
/// the seeds and tracked bodies), hypotheses (hidden_frames, with_more, main_hidden_translation,
/// nearest_hidden_translation: see hypothesis_stats), and for closed-loop experiments
/// payload_released and
/// payload_landed (counts over the seeds).
/// Per motion model (Estimate::motion_model), the occlusions `estimator` carried with it.
std::map<std::string, std::size_t> dynamics_model_counts(const std::vector<FrameRecord>& records,
                                                         const std::string& estimator);

/// The hidden frames of the objects of interest where `estimator` followed more than one
/// hypothesis (two equally likely occluders), and the translation error of the hypothesis
/// nearest the truth in every hidden frame against the main hypothesis's (means over the hidden
/// frames of every seed; 0 without hidden frames).
struct HypothesisStats {
  std::size_t hidden_frames = 0;
  std::size_t with_more = 0;
  double nearest_hidden_translation = 0.0;
  double main_hidden_translation = 0.0;
};
HypothesisStats hypothesis_stats(const ExperimentResults& results, const std::string& estimator);

/// `provenance`, when not empty, is a JSON object (how the results were made, see the `opf`
/// program's provenance.h) written first under "provenance".
void write_summary_json(const std::filesystem::path& path,
                        const std::vector<ExperimentResults>& experiments,
                        const std::string& provenance = "");

/// A table's title line: "<experiment>: errors ..., each run's mean over frames (mean +- std over
/// N seeds)", the std the sample standard deviation (n - 1, opf/core/metrics.h).
std::string results_table_title(const std::string& experiment, std::size_t seeds);

/// Per experiment: the title line, each estimator's errors (mean +- sample std over the seeds),
/// the OPF/PF ratios, and the paper's Table I numbers where the paper has them.
void print_results_table(std::ostream& out, const std::vector<ExperimentResults>& experiments);

}  // namespace opf::experiments
