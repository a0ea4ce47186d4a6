#include "opf/io/yaml_option_reader.h"

#include "opf/io/csv.h"

#include <cmath>
#include <exception>

namespace opf {

void YamlOptionReader::numbers(std::string_view key, std::vector<double>& out,
                               const Bounds& bounds) {
  // A list of any length: read as words, so that one message covers every malformed element.
  std::vector<std::string> words;
  for (const double value : out) words.push_back(csv::format_double(value));
  yaml().get(key, words);
  const std::string expectation = "a list of " + std::string(bounds.expectation);
  std::vector<double> values;
  for (const std::string& word : words) {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(word, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    yaml().require(key, used == word.size() && bounds.admits(value), expectation);
    values.push_back(value);
  }
  out = std::move(values);
}

void YamlOptionReader::vector3(std::string_view key, Eigen::Vector3d& out) {
  std::vector<double> values = {out.x(), out.y(), out.z()};
  yaml().get(key, values, 3);
  out = Eigen::Vector3d(values[0], values[1], values[2]);
  yaml().require(key, out.norm() > 0.0, "a non-zero vector");
}

void YamlOptionReader::optional_vector3(std::string_view key, std::optional<Eigen::Vector3d>& out) {
  std::vector<double> values;
  if (out) values = {out->x(), out->y(), out->z()};
  yaml().get(key, values, 3);
  if (!values.empty()) out = Eigen::Vector3d(values[0], values[1], values[2]);
}

}  // namespace opf
