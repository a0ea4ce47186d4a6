// One options schema: the settings reader, the constructors' validate() and the shipped settings
// file all follow the structs' describe_options(). Every bounded field is spoiled once, in a YAML
// file and in the struct, and both must refuse it under the same key path.

#include "opf/estimators/cv_kalman.h"
#include "opf/estimators/imm_kalman.h"
#include "opf/estimators/object_permanence_filter.h"
#include "opf/estimators/random_walk_oapf.h"
#include "opf/io/estimator_settings_yaml.h"
#include "opf/io/input_error.h"
#include "opf/particles/pose_particle_filter.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace opf {
namespace {

/// A field of the description: its key path from the file's top, a value it refuses (as YAML
/// text) and how to write that value into a struct.
struct SpoiledField {
  std::string path;
  std::string bad_yaml;
  std::function<void(EstimatorSettings&)> spoil;
};

/// The values just outside `bounds`, below and above where a limit is finite: the open limit
/// itself, or one past a closed one.
std::vector<double> outside(const Bounds& bounds) {
  std::vector<double> values;
  if (std::isfinite(bounds.low)) values.push_back(bounds.low_open ? bounds.low : bounds.low - 1.0);
  if (std::isfinite(bounds.high))
    values.push_back(bounds.high_open ? bounds.high : bounds.high + 1.0);
  return values;
}

/// Walks the description and lists every field that can be out of range. The spoilers address
/// the field through the same walk on the struct they are given, so they need no member names.
class FieldLister {
 public:
  std::vector<SpoiledField> fields;

  void number(std::string_view key, double&, const Bounds& bounds) {
    for (const double bad : outside(bounds)) add(key, text(bad), [bad](double& x) { x = bad; });
  }
  template <class Integer>
  void integer(std::string_view key, Integer&, const Bounds& bounds) {
    for (const double bad : outside(bounds)) {
      if (bad < 0.0 && std::is_unsigned_v<Integer>) continue;  // the type itself refuses it
      add(key, text(bad), [bad](double& x) { x = bad; });
    }
  }
  void flag(std::string_view, bool&) {}
  template <class Table, class Enum>
  void choice(std::string_view, const Table&, Enum&) {}
  template <class Table, class Enum>
  void choices(std::string_view, const Table&, std::vector<Enum>&) {}
  void numbers(std::string_view key, std::vector<double>&, const Bounds& bounds) {
    for (const double bad : outside(bounds))
      add(key, "[" + text(bad) + "]", [bad](double& x) { x = bad; });
  }
  void vector3(std::string_view key, Eigen::Vector3d&) {
    add(key, "[0, 0, 0]", [](double& x) { x = 0.0; });
  }
  void optional_point(std::string_view key, std::optional<Eigen::Vector4d>&) {
    add(key, "[0, 0, 0, 0]", [](double& x) { x = 0.0; });  // a direction of no length
  }
  template <class Describe>
  void section(std::string_view key, Describe&& describe) {
    path_.enter(key, describe);
  }

 private:
  static std::string text(double value) {
    std::ostringstream out;
    out << std::setprecision(std::numeric_limits<double>::max_digits10) << value;
    return out.str();
  }
  void add(std::string_view key, std::string bad_yaml, std::function<void(double&)> set);

  KeyPath path_;
};

/// Sets the field at `path` by walking the description of `settings` to it.
class FieldSetter {
 public:
  FieldSetter(std::string path, std::function<void(double&)> set)
      : target_(std::move(path)), set_(std::move(set)) {}

  void number(std::string_view key, double& x, const Bounds&) {
    if (here(key)) set_(x);
  }
  template <class Integer>
  void integer(std::string_view key, Integer& x, const Bounds&) {
    double value = static_cast<double>(x);
    if (here(key)) set_(value), x = static_cast<Integer>(value);
  }
  void flag(std::string_view, bool&) {}
  template <class Table, class Enum>
  void choice(std::string_view, const Table&, Enum&) {}
  template <class Table, class Enum>
  void choices(std::string_view, const Table&, std::vector<Enum>&) {}
  void numbers(std::string_view key, std::vector<double>& x, const Bounds&) {
    if (here(key)) set_(x.front());
  }
  void vector3(std::string_view key, Eigen::Vector3d& x) {
    if (here(key))
      for (int i = 0; i < 3; ++i) set_(x(i));
  }
  void optional_point(std::string_view key, std::optional<Eigen::Vector4d>& x) {
    if (!here(key)) return;
    x = Eigen::Vector4d::Ones();
    for (int i = 0; i < 4; ++i) set_((*x)(i));
  }
  template <class Describe>
  void section(std::string_view key, Describe&& describe) {
    path_.enter(key, describe);
  }

 private:
  bool here(std::string_view key) const { return path_.of(key) == target_; }

  std::string target_;
  std::function<void(double&)> set_;
  KeyPath path_;
};

void FieldLister::add(std::string_view key, std::string bad_yaml,
                      std::function<void(double&)> set) {
  const std::string path = path_.of(key);
  fields.push_back({path, std::move(bad_yaml), [path, set](EstimatorSettings& settings) {
                      FieldSetter setter(path, set);
                      describe_options(setter, settings);
                    }});
}

std::vector<SpoiledField> spoiled_fields() {
  FieldLister lister;
  EstimatorSettings settings;
  describe_options(lister, settings);
  return lister.fields;
}

/// `path` as a nested YAML mapping holding `value`; the value sits on the last line.
std::string nested_yaml(const std::string& path, const std::string& value, std::size_t& line) {
  std::string yaml, indent;
  std::istringstream keys(path);
  std::string key;
  std::vector<std::string> parts;
  while (std::getline(keys, key, '.')) parts.push_back(key);
  for (std::size_t i = 0; i + 1 < parts.size(); ++i, indent += "  ")
    yaml += indent + parts[i] + ":\n";
  line = parts.size();
  return yaml + indent + parts.back() + ": " + value + "\n";
}

/// What the estimator that owns the section does with the spoiled settings.
void construct_owner(const std::string& path, const EstimatorSettings& s) {
  const std::string section = path.substr(0, path.find('.'));
  if (section == "pf") PoseParticleFilter(s.pf, 1);
  if (section == "cvkf") ConstantVelocityKalman{s.cvkf};
  if (section == "imm") ImmKalman{s.imm};
  if (section == "opf") ObjectPermanenceFilter(s.opf, "x", 1);
  if (section == "oapf") OcclusionAwareParticleFilter(s.oapf, 1);
}

TEST(SettingsSchema, ListsEveryBoundedFieldOfEverySection) {
  const std::vector<SpoiledField> fields = spoiled_fields();
  std::set<std::string> sections;
  for (const SpoiledField& f : fields) sections.insert(f.path.substr(0, f.path.find('.')));
  EXPECT_EQ(sections, (std::set<std::string>{"pf", "cvkf", "imm", "opf", "oapf"}));
  // Every bounded number, list and vector of the five sections: a field dropped from a
  // description shows. 27 of the 44 are bounded on both sides (each side a spoiled value).
  std::set<std::string> paths;
  for (const SpoiledField& f : fields) paths.insert(f.path);
  EXPECT_EQ(paths.size(), 44u);
  EXPECT_EQ(fields.size(), 71u);
}

TEST(SettingsSchema, TheReaderAndTheConstructorsRefuseTheSameValues) {
  for (const SpoiledField& field : spoiled_fields()) {
    SCOPED_TRACE(field.path + " = " + field.bad_yaml);
    std::size_t line = 0;
    const std::string yaml = nested_yaml(field.path, field.bad_yaml, line);
    try {
      parse_estimator_settings(yaml, "settings.yaml");
      ADD_FAILURE() << "the reader took\n" << yaml;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field.path);
      EXPECT_EQ(e.line(), line);
    }
    EstimatorSettings settings;
    field.spoil(settings);
    // The OPF and the OAPF carry the shared particle filter under `particles`, as the registry
    // copies it; a spoiled pf: field must stop them too.
    settings.opf.particles = settings.pf;
    settings.oapf.particles = settings.pf;
    const std::string key = field.path.substr(field.path.find('.') + 1);
    try {
      construct_owner(field.path, settings);
      ADD_FAILURE() << "the constructor took it";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("option " + key + " must be"), std::string::npos)
          << e.what();
    }
  }
}

TEST(SettingsSchema, TheDefaultsAreInsideEveryRange) {
  EstimatorSettings settings;
  EXPECT_NO_THROW(check_options(settings, "settings"));
  for (const SpoiledField& field : spoiled_fields()) {
    EstimatorSettings spoiled;
    field.spoil(spoiled);
    EXPECT_THROW(check_options(spoiled, "settings"), std::invalid_argument) << field.path;
  }
}

}  // namespace
}  // namespace opf
