#pragma once
// The one description of an options struct. Beside each struct, a describe_options(visitor,
// options) names every field by its settings-file key, with the values it admits, once; visitors
// walk that description to check a struct (check_options below, behind every validate()), to read
// a settings file (io/yaml_option_reader.h), to dump the effective settings and to list the fields
// (tests). A range is therefore written in one place, and the reader, the constructors and the
// shipped settings file cannot disagree about it.
//
// A visitor has these members (duck-typed, so the walk is inlined for each):
//   number(key, double&, Bounds)             integer(key, std::size_t& or int&, Bounds)
//   flag(key, bool&)                         choice(key, EnumNames table, Enum&)
//   choices(key, EnumNames table, std::vector<Enum>&)   a non-empty list of distinct names
//   numbers(key, std::vector<double>&, Bounds)   a non-empty list, every element within Bounds
//   vector3(key, Eigen::Vector3d&)           a non-zero, finite vector
//   optional_point(key, std::optional<Eigen::Vector4d>&)   homogeneous (homogeneous_point.h)
//   section(key, fn)                         fn() describes the nested mapping `key`

#include "opf/core/homogeneous_point.h"

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace opf {

/// The admissible values of a number: a finite value between two limits, each open or closed,
/// and the words an error message uses for it ("a positive number of s").
struct Bounds {
  double low = -std::numeric_limits<double>::infinity();
  bool low_open = false;
  double high = std::numeric_limits<double>::infinity();
  bool high_open = false;
  std::string_view expectation = "a finite number";

  constexpr bool admits(double x) const {
    return std::isfinite(x) && (low_open ? x > low : x >= low) &&
           (high_open ? x < high : x <= high);
  }
};

constexpr Bounds positive(std::string_view expectation = "a positive number") {
  return {0.0, true, std::numeric_limits<double>::infinity(), false, expectation};
}
constexpr Bounds non_negative(std::string_view expectation = "a number >= 0") {
  return {0.0, false, std::numeric_limits<double>::infinity(), false, expectation};
}
constexpr Bounds at_least(double low, std::string_view expectation) {
  return {low, false, std::numeric_limits<double>::infinity(), false, expectation};
}
constexpr Bounds greater_than(double low, std::string_view expectation) {
  return {low, true, std::numeric_limits<double>::infinity(), false, expectation};
}
constexpr Bounds between(double low, double high, std::string_view expectation) {
  return {low, false, high, false, expectation};
}
/// The largest noise standard deviation, intensity or spread a setting admits, in its own unit
/// (m, rad, m/sqrt(s), rad/s^2/sqrt(Hz), ...). A million metres or radians is beyond any scene a
/// camera tracks, and the filters' covariances (squares and products of these with times and
/// particle offsets) stay well inside double precision below it; far larger values (from 1e8 on
/// for some estimators) turn the estimates into NaN.
inline constexpr double kMaxNoise = 1e6;
/// (0, kMaxNoise]: a noise standard deviation or intensity; `expectation` names the unit and the
/// limit ("a positive number (m) up to 1e6").
constexpr Bounds noise_scale(std::string_view expectation) {
  return {0.0, true, kMaxNoise, false, expectation};
}
/// The `observation_noise:` section every filter's settings share: a standard deviation per
/// axis of the position (m) and of the rotation (rad, tangent space).
template <class Visitor>
void describe_observation_noise(Visitor& v, double& translation, double& rotation) {
  v.section("observation_noise", [&] {
    v.number("translation", translation, noise_scale("a positive number (m) up to 1e6"));
    v.number("rotation", rotation, noise_scale("a positive number (rad) up to 1e6"));
  });
}
/// (0, 1]: a probability that may not be zero, an ESS fraction.
constexpr Bounds unit_fraction(std::string_view expectation = "a number in (0, 1]") {
  return {0.0, true, 1.0, false, expectation};
}

/// Where a visitor is in a description: the sections entered, as a settings file spells them.
class KeyPath {
 public:
  /// Runs `describe` inside the section `key`.
  template <class Describe>
  void enter(std::string_view key, Describe&& describe) {
    const std::size_t size = prefix_.size();
    prefix_.append(key).append(".");
    describe();
    prefix_.resize(size);
  }
  /// `key` in the current section: "resampling" + "scheme" -> "resampling.scheme".
  std::string of(std::string_view key) const { return prefix_ + std::string(key); }

 private:
  std::string prefix_;  ///< the sections entered, each followed by '.'
};

/// Walks a description and throws std::invalid_argument for the first field out of range:
/// "<owner> option <key path> must be <expectation>, got <value>", the key path as a settings
/// file spells it below the owner's section (e.g. "resampling.ess_threshold").
class OptionChecker {
 public:
  explicit OptionChecker(std::string owner) : owner_(std::move(owner)) {}

  void number(std::string_view key, double value, const Bounds& bounds) const {
    if (!bounds.admits(value)) fail(key, bounds.expectation, value);
  }
  template <class Integer>
  void integer(std::string_view key, Integer value, const Bounds& bounds) const {
    if (!bounds.admits(static_cast<double>(value))) fail(key, bounds.expectation, value);
  }
  void flag(std::string_view, bool) const {}
  template <class Table, class Enum>
  void choice(std::string_view, const Table&, Enum) const {}
  template <class Table, class Enum>
  void choices(std::string_view key, const Table&, const std::vector<Enum>& values) const {
    if (values.empty()) fail(key, "a non-empty list", "an empty list");
    for (std::size_t i = 0; i < values.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (values[i] == values[j]) fail(key, "a list of distinct names", "a name twice");
  }
  void numbers(std::string_view key, const std::vector<double>& values,
               const Bounds& bounds) const {
    if (values.empty()) fail(key, "a non-empty list", "an empty list");
    for (const double v : values)
      if (!bounds.admits(v))
        fail(key, std::string("a list of ") + std::string(bounds.expectation), v);
  }
  void vector3(std::string_view key, const Eigen::Vector3d& value) const {
    if (!value.allFinite() || !(value.norm() > 0.0))
      fail(key, "a non-zero vector", value.transpose());
  }
  void optional_point(std::string_view key, const std::optional<Eigen::Vector4d>& value) const {
    if (value && !homogeneous_point(std::span<const double>(value->data(), 4)))
      fail(key, "a finite point, or a direction at infinity", value->transpose());
  }
  template <class Describe>
  void section(std::string_view key, Describe&& describe) {
    path_.enter(key, describe);
  }

 private:
  template <class Expectation, class Value>
  [[noreturn]] void fail(std::string_view key, const Expectation& expectation,
                         const Value& value) const {
    std::ostringstream message;
    message << owner_ << " option " << path_.of(key) << " must be " << expectation << ", got "
            << value;
    throw std::invalid_argument(message.str());
  }

  std::string owner_;
  KeyPath path_;
};

/// validate() of a struct with a describe_options(): throws std::invalid_argument naming the
/// first field out of range, prefixed with `owner` ("particle filter", "oapf").
template <class Options>
void check_options(const Options& options, std::string owner) {
  OptionChecker checker(std::move(owner));
  Options copy = options;  // the description takes a mutable struct, for the readers
  describe_options(checker, copy);
}

}  // namespace opf
