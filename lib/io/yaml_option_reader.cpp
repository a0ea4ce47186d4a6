#include "opf/io/yaml_option_reader.h"

#include "opf/core/homogeneous_point.h"
#include "opf/io/csv.h"

#include <Eigen/Geometry>

#include <cmath>
#include <exception>

namespace opf {
namespace {

/// The whole word as a number, or none.
std::optional<double> number_of(const std::string& word) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(word, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != word.size()) return std::nullopt;
  return value;
}

}  // namespace

void YamlOptionReader::numbers(std::string_view key, std::vector<double>& out,
                               const Bounds& bounds) {
  // A list of any length: read as words, so that one message covers every malformed element.
  std::vector<std::string> words;
  for (const double value : out) words.push_back(csv::format_double(value));
  yaml().get(key, words);
  const std::string expectation = "a list of " + std::string(bounds.expectation);
  std::vector<double> values;
  for (const std::string& word : words) {
    const std::optional<double> value = number_of(word);
    yaml().require(key, value && bounds.admits(*value), expectation);
    values.push_back(*value);
  }
  out = std::move(values);
}

void YamlOptionReader::vector3(std::string_view key, Eigen::Vector3d& out) {
  std::vector<double> values = {out.x(), out.y(), out.z()};
  yaml().get(key, values, 3);
  out = Eigen::Vector3d(values[0], values[1], values[2]);
  yaml().require(key, out.norm() > 0.0, "a non-zero vector");
}

void YamlOptionReader::optional_point(std::string_view key, std::optional<Eigen::Vector4d>& out) {
  // A point is written as three numbers, a direction at infinity as four.
  std::vector<std::string> words;
  if (out) {
    const Eigen::VectorXd written =
        out->w() != 0.0 ? Eigen::VectorXd(out->hnormalized()) : Eigen::VectorXd(*out);
    for (const double x : written) words.push_back(csv::format_double(x));
  }
  yaml().get(key, words);
  if (words.empty()) return;
  std::vector<double> values;
  for (const std::string& word : words)
    if (const std::optional<double> value = number_of(word)) values.push_back(*value);
  // A word that is not a number leaves a count homogeneous_point refuses.
  const std::optional<Eigen::Vector4d> point =
      values.size() == words.size() ? homogeneous_point(values) : std::nullopt;
  yaml().require(key, point.has_value(), std::string(kHomogeneousCameraExpectation));
  out = point;
}

}  // namespace opf
