#include "opf/fit/trajectory_fit.h"

#include "opf/core/so3.h"

#include <ceres/autodiff_cost_function.h>
#include <ceres/loss_function.h>
#include <ceres/problem.h>
#include <ceres/rotation.h>
#include <ceres/solver.h>
#include <ceres/sphere_manifold.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace opf {
namespace {

constexpr int kMaxCoefficients = kMaxTrajectoryOrder + 1;

// Below this total angle over the window the direction of the rotation is rounding noise, so the
// initial axis is arbitrary rather than taken from it.
constexpr double kNoRotation = 1e-9;

using TranslationCoefficients = std::array<double, 3 * kMaxCoefficients>;  // c[3 k + axis]
using RateCoefficients = std::array<double, kMaxTrajectoryOrder>;          // of tau^1 .. tau^n

// The solvers work in tau = (t - t_ref) / window, so tau spans [-1, 0] whatever the frame rate and
// the monomials stay of order one: the normal equations are then well conditioned up to order 5.
struct TimeScale {
  double t_ref = 0.0;
  double window = 1.0;
  double tau(double t) const { return (t - t_ref) / window; }
};

// sum_k c[k * stride] tau^k for k < kCount, by Horner's rule.
template <int kCount, typename T>
T horner(const T* c, int stride, double tau) {
  T value = c[(kCount - 1) * stride];
  for (int k = kCount - 2; k >= 0; --k) value = value * tau + c[k * stride];
  return value;
}

template <int kCoefficients>
struct PolynomialResidual {
  double tau;
  Eigen::Vector3d position;

  template <typename T>
  bool operator()(const T* c, T* residual) const {
    for (int i = 0; i < 3; ++i) residual[i] = horner<kCoefficients>(c + i, 3, tau) - position(i);
    return true;
  }
};

// Residual of one sample against R_last exp(offset) exp(omega(tau) e), with omega(tau) =
// sum_{j=1..kRates} rates[j-1] tau^j: the body-frame rotation vector of the model's error, so the
// loss scale is an angle. `offset` lets the fit move the reference away from the last sample,
// whose own noise would otherwise be copied into every extrapolated orientation.
template <int kRates>
struct RotationResidual {
  double tau;
  std::array<double, 4> relative;  // R_last^-1 R_k as (w, x, y, z), Ceres' order

  template <typename T>
  bool operator()(const T* offset, const T* axis, const T* rates, T* residual) const {
    const T omega = horner<kRates>(rates, 1, tau) * tau;
    const T angle_axis[3] = {omega * axis[0], omega * axis[1], omega * axis[2]};
    T motion[4], correction[4], model[4], error[4];
    ceres::AngleAxisToQuaternion(angle_axis, motion);
    ceres::AngleAxisToQuaternion(offset, correction);
    ceres::QuaternionProduct(correction, motion, model);
    const T model_inverse[4] = {model[0], -model[1], -model[2], -model[3]};
    const T measured[4] = {T(relative[0]), T(relative[1]), T(relative[2]), T(relative[3])};
    ceres::QuaternionProduct(model_inverse, measured, error);
    ceres::QuaternionToAngleAxis(error, residual);
    return true;
  }
};

struct RelativeRotation {
  double tau;
  std::array<double, 4> relative;
};

template <typename... Parts>
void require(bool condition, const Parts&... parts) {
  if (condition) return;
  std::ostringstream message;
  message << "fit_trajectory: ";
  (message << ... << parts);
  throw std::invalid_argument(message.str());
}

void validate(std::span<const TrajectorySample> samples, const TrajectoryFitOptions& options) {
  check_options(options, "fit_trajectory: trajectory");
  // The fit's fixed parameters (not settings) are checked all the same.
  const OptionChecker fixed("fit_trajectory: trajectory");
  fixed.number("translation_loss_scale", options.translation_loss_scale,
               positive("a positive number (m)"));
  fixed.number("rotation_loss_scale", options.rotation_loss_scale,
               positive("a positive number (rad)"));
  fixed.integer("max_iterations", options.max_iterations,
                between(1, 10000, "an integer from 1 to 10000"));
  const std::size_t needed =
      static_cast<std::size_t>(std::max(options.translation_order, options.rotation_order)) + 1;
  require(samples.size() >= needed, "orders ", options.translation_order, " (translation) and ",
          options.rotation_order, " (rotation) need at least ", needed, " samples, got ",
          samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const TrajectorySample& s = samples[k];
    require(std::isfinite(s.t) && s.position.allFinite() && s.orientation.coeffs().allFinite(),
            "sample ", k, " has a non-finite time, position or orientation");
    require(s.orientation.norm() > 0.0, "sample ", k, " has a zero orientation quaternion");
    require(k == 0 || s.t > samples[k - 1].t,
            "sample times must be strictly increasing, but sample ", k, " is at t = ", s.t,
            " after t = ", k == 0 ? 0.0 : samples[k - 1].t);
  }
}

std::unique_ptr<ceres::LossFunction> make_loss(RobustLoss loss, double scale) {
  switch (loss) {
    case RobustLoss::kSquared:
      return nullptr;
    case RobustLoss::kHuber:
      return std::make_unique<ceres::HuberLoss>(scale);
    case RobustLoss::kCauchy:
      return std::make_unique<ceres::CauchyLoss>(scale);
  }
  return nullptr;
}

ceres::Solver::Options solver_options(int max_iterations) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = max_iterations;
  options.num_threads = 1;
  options.minimizer_progress_to_stdout = false;
  options.logging_type = ceres::SILENT;
  // With Ceres' defaults the first Levenberg-Marquardt step is damped (trust region 1e4) and the
  // relative cost-change stop (1e-6) ends the solve before the damping is gone: a cubic fit is
  // left ~1e-6 off the least-squares optimum, which extrapolation magnifies. An undamped first
  // step (Ceres shrinks the region if a step fails, as robust steps may) and a near-machine-
  // precision stop reach the optimum in two iterations for the squared loss.
  options.function_tolerance = 1e-12;
  options.gradient_tolerance = 1e-15;
  options.parameter_tolerance = 1e-13;
  options.initial_trust_region_radius = 1e16;
  return options;
}

ceres::Problem::Options problem_options() {
  ceres::Problem::Options options;
  // One loss object is shared by every residual block and owned by the caller.
  options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  return options;
}

FitSummary summarise(const ceres::Solver::Summary& summary, const char* what) {
  if (!summary.IsSolutionUsable()) {
    throw std::runtime_error(std::string("fit_trajectory: the ")
                                 .append(what)
                                 .append(" fit failed: ")
                                 .append(summary.message));
  }
  FitSummary out;
  out.initial_cost = summary.initial_cost;
  out.final_cost = summary.final_cost;
  out.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  return out;
}

template <int kCoefficients>
FitSummary solve_translation(std::span<const TrajectorySample> samples, const TimeScale& time,
                             const TrajectoryFitOptions& options, TranslationCoefficients& c) {
  using Residual = PolynomialResidual<kCoefficients>;
  const auto loss = make_loss(options.loss, options.translation_loss_scale);
  ceres::Problem problem(problem_options());
  for (const TrajectorySample& s : samples) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Residual, 3, 3 * kCoefficients>(
                                 new Residual{time.tau(s.t), s.position}),
                             loss.get(), c.data());
  }
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options(options.max_iterations), &problem, &summary);
  return summarise(summary, "translation");
}

FitSummary fit_translation(std::span<const TrajectorySample> samples, const TimeScale& time,
                           const TrajectoryFitOptions& options, TranslationCoefficients& c) {
  switch (options.translation_order) {
    case 0:
      return solve_translation<1>(samples, time, options, c);
    case 1:
      return solve_translation<2>(samples, time, options, c);
    case 2:
      return solve_translation<3>(samples, time, options, c);
    case 3:
      return solve_translation<4>(samples, time, options, c);
    case 4:
      return solve_translation<5>(samples, time, options, c);
    default:
      return solve_translation<6>(samples, time, options, c);
  }
}

template <int kRates>
FitSummary solve_rotation(const std::vector<RelativeRotation>& data,
                          const TrajectoryFitOptions& options, std::array<double, 3>& offset,
                          std::array<double, 3>& axis, RateCoefficients& rates) {
  using Residual = RotationResidual<kRates>;
  const auto loss = make_loss(options.loss, options.rotation_loss_scale);
  ceres::Problem problem(problem_options());
  problem.AddParameterBlock(axis.data(), 3, new ceres::SphereManifold<3>());
  for (const RelativeRotation& d : data) {
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<Residual, 3, 3, 3, kRates>(new Residual{d.tau, d.relative}),
        loss.get(), offset.data(), axis.data(), rates.data());
  }
  // Order 0 is a constant orientation: only the offset is free (kRates = 1 carries a zero rate).
  if (options.rotation_order == 0) {
    problem.SetParameterBlockConstant(axis.data());
    problem.SetParameterBlockConstant(rates.data());
  }
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options(options.max_iterations), &problem, &summary);
  return summarise(summary, "rotation");
}

FitSummary fit_rotation(const std::vector<RelativeRotation>& data,
                        const TrajectoryFitOptions& options, std::array<double, 3>& offset,
                        std::array<double, 3>& axis, RateCoefficients& rates) {
  switch (options.rotation_order) {
    case 0:
    case 1:
      return solve_rotation<1>(data, options, offset, axis, rates);
    case 2:
      return solve_rotation<2>(data, options, offset, axis, rates);
    case 3:
      return solve_rotation<3>(data, options, offset, axis, rates);
    case 4:
      return solve_rotation<4>(data, options, offset, axis, rates);
    default:
      return solve_rotation<5>(data, options, offset, axis, rates);
  }
}

}  // namespace

Eigen::Vector3d TrajectoryModel::position(double t) const {
  const double dt = t - t_ref_;
  Eigen::Vector3d p = translation_.col(translation_order_);
  for (int k = translation_order_ - 1; k >= 0; --k) p = p * dt + translation_.col(k);
  return p;
}

Eigen::Vector3d TrajectoryModel::velocity(double t) const {
  const double dt = t - t_ref_;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int k = translation_order_; k >= 1; --k) v = v * dt + k * translation_.col(k);
  return v;
}

double TrajectoryModel::angle(double t) const {
  const double dt = t - t_ref_;
  double omega = 0.0;
  for (int k = rotation_order_; k >= 1; --k) omega = (omega + omega_(k)) * dt;
  return omega;
}

double TrajectoryModel::angular_rate(double t) const {
  const double dt = t - t_ref_;
  double rate = 0.0;
  for (int k = rotation_order_; k >= 1; --k) rate = rate * dt + k * omega_(k);
  return rate;
}

Eigen::Quaterniond TrajectoryModel::orientation(double t) const {
  return (r_ref_ * so3::exp(angle(t) * axis_)).normalized();
}

TrajectoryModel fit_trajectory(std::span<const TrajectorySample> samples,
                               const TrajectoryFitOptions& options) {
  validate(samples, options);
  const std::size_t n = samples.size();
  const TrajectorySample& first = samples.front();
  const TrajectorySample& last = samples.back();
  const TimeScale time{last.t, n > 1 ? last.t - first.t : 1.0};

  TrajectoryModel model;
  model.t_ref_ = time.t_ref;
  model.translation_order_ = options.translation_order;
  model.rotation_order_ = options.rotation_order;

  // Translation, started from the chord through the first and last samples.
  TranslationCoefficients c{};
  for (int i = 0; i < 3; ++i) {
    c[i] = last.position(i);
    if (options.translation_order >= 1) c[3 + i] = last.position(i) - first.position(i);
  }
  model.translation_summary_ = fit_translation(samples, time, options, c);
  double power = 1.0;  // window^k
  for (int k = 0; k <= options.translation_order; ++k, power *= time.window) {
    for (int i = 0; i < 3; ++i) model.translation_(i, k) = c[3 * k + i] / power;
  }

  // Rotation, started from the sum of the per-frame increments: unlike log(R_first^-1 R_last) it
  // does not wrap when the object turns by more than pi over the window.
  const Eigen::Quaterniond last_q = last.orientation.normalized();
  std::vector<RelativeRotation> data;
  data.reserve(n);
  Eigen::Vector3d turned = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Quaterniond q = samples[k].orientation.normalized();
    const Eigen::Quaterniond relative = last_q.conjugate() * q;
    data.push_back(
        {time.tau(samples[k].t), {relative.w(), relative.x(), relative.y(), relative.z()}});
    if (k > 0) turned += so3::difference(samples[k - 1].orientation.normalized(), q);
  }
  std::array<double, 3> offset{0.0, 0.0, 0.0};
  std::array<double, 3> axis{0.0, 0.0, 1.0};
  RateCoefficients rates{};
  if (options.rotation_order >= 1 && turned.norm() > kNoRotation) {
    const Eigen::Vector3d e = turned.normalized();
    axis = {e.x(), e.y(), e.z()};
    rates[0] = turned.norm() / (time.tau(last.t) - time.tau(first.t));
  }
  model.rotation_summary_ = fit_rotation(data, options, offset, axis, rates);

  // exp(omega e) = exp((-omega)(-e)): pick the sign with a non-negative rate at t_ref.
  const auto leading = std::find_if(rates.begin(), rates.end(), [](double r) { return r != 0.0; });
  const double sign = leading != rates.end() && *leading < 0.0 ? -1.0 : 1.0;
  model.axis_ = sign * Eigen::Vector3d(axis[0], axis[1], axis[2]).normalized();
  power = time.window;
  for (int k = 1; k <= options.rotation_order; ++k, power *= time.window) {
    model.omega_(k) = sign * rates[k - 1] / power;
  }
  model.r_ref_ = (last_q * so3::exp(Eigen::Vector3d(offset[0], offset[1], offset[2]))).normalized();
  return model;
}

}  // namespace opf
