#include "opf/io/yaml_reader.h"

#include "opf/io/input_error.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace opf {
namespace {

/// The InputError `action` must raise; fails the test (and returns an empty error) when none.
InputError error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", 0, "", "");
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(YamlReader, AssignsOnlyKeysThatArePresent) {
  YamlReader yaml = YamlReader::parse("rate: 2.5\ncount: 12\nflag: yes\nname: abc\n", "s.yaml");
  double rate = 1, missing_double = 7;
  std::size_t count = 0, missing_count = 3;
  bool flag = false, missing_flag = true;
  std::string name, missing_name = "keep";
  yaml.get("rate", rate);
  yaml.get("count", count);
  yaml.get("flag", flag);
  yaml.get("name", name);
  yaml.get("other", missing_double);
  yaml.get("other_count", missing_count);
  yaml.get("other_flag", missing_flag);
  yaml.get("other_name", missing_name);
  EXPECT_NO_THROW(yaml.finish());
  EXPECT_EQ(rate, 2.5);
  EXPECT_EQ(count, 12u);
  EXPECT_TRUE(flag);
  EXPECT_EQ(name, "abc");
  EXPECT_EQ(missing_double, 7.0);
  EXPECT_EQ(missing_count, 3u);
  EXPECT_TRUE(missing_flag);
  EXPECT_EQ(missing_name, "keep");
}

TEST(YamlReader, EmptyDocumentIsAnEmptyMapping) {
  for (const std::string text : {"", "\n# only a comment\n", "~"}) {
    YamlReader yaml = YamlReader::parse(text, "s.yaml");
    double value = 4;
    yaml.child("a").get("b", value);
    EXPECT_NO_THROW(yaml.finish());
    EXPECT_EQ(value, 4.0);
  }
}

TEST(YamlReader, ReadsNestedMappingsInBlockAndFlowStyle) {
  YamlReader yaml = YamlReader::parse("pf:\n  noise: {translation: 0.5, rotation: 1e-2}\n", "s");
  double translation = 0, rotation = 0;
  YamlReader& noise = yaml.child("pf").child("noise");
  EXPECT_EQ(&noise, &yaml.child("pf").child("noise"));  // the same reader on a second call
  noise.get("translation", translation);
  noise.get("rotation", rotation);
  EXPECT_NO_THROW(yaml.finish());
  EXPECT_EQ(translation, 0.5);
  EXPECT_EQ(rotation, 0.01);
  EXPECT_EQ(noise.key_path("rotation"), "pf.noise.rotation");
}

TEST(YamlReader, UnknownKeySuggestsTheClosestKnownOne) {
  YamlReader yaml = YamlReader::parse(
      "pf:\n"
      "  resampling:\n"
      "    every_frame: true\n"
      "    sheme: residual\n",
      "s.yaml");
  std::string scheme;
  bool every_frame = false;
  double ess_threshold = 0.5;
  YamlReader& resampling = yaml.child("pf").child("resampling");
  resampling.get("scheme", scheme);
  resampling.get("every_frame", every_frame);
  resampling.get("ess_threshold", ess_threshold);
  const InputError e = error_of([&] { yaml.finish(); });
  EXPECT_EQ(e.file(), "s.yaml");
  EXPECT_EQ(e.line(), 4u);
  EXPECT_EQ(e.field(), "pf.resampling.sheme");
  EXPECT_TRUE(contains(e.message(), "did you mean 'scheme'?")) << e.what();
  EXPECT_TRUE(contains(e.what(), "key 'pf.resampling.sheme'")) << e.what();
}

TEST(YamlReader, UnknownKeyFarFromAnyListsTheKnownOnes) {
  YamlReader yaml = YamlReader::parse("alpha: 1\nzzzzzzzz: 2\n", "s.yaml");
  double alpha = 0;
  yaml.get("alpha", alpha);
  yaml.child("beta");
  const InputError e = error_of([&] { yaml.finish(); });
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "zzzzzzzz");
  EXPECT_FALSE(contains(e.message(), "did you mean")) << e.what();
  EXPECT_TRUE(contains(e.message(), "expected one of 'alpha', 'beta'")) << e.what();
}

TEST(YamlReader, UnknownTopLevelSectionIsReported) {
  YamlReader yaml = YamlReader::parse("pf: {}\nckvf:\n  acceleration_noise: 1\n", "s.yaml");
  yaml.child("pf");
  yaml.child("cvkf");
  const InputError e = error_of([&] { yaml.finish(); });
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "ckvf");
  EXPECT_TRUE(contains(e.message(), "did you mean 'cvkf'?")) << e.what();
}

TEST(YamlReader, WrongTypesNameKeyAndLine) {
  YamlReader yaml = YamlReader::parse(
      "a:\n"
      "  number: fast\n"
      "  list: [1, 2]\n"
      "  count: -3\n"
      "  fraction: 2.5\n"
      "  flag: maybe\n"
      "  map: {x: 1}\n"
      "  infinite: .inf\n"
      "  empty:\n",
      "s.yaml");
  YamlReader& a = yaml.child("a");
  double d = 0;
  std::size_t n = 0;
  bool b = false;
  std::string s;

  InputError e = error_of([&] { a.get("number", d); });
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "a.number");
  EXPECT_TRUE(contains(e.message(), "expected a finite number, got \"fast\"")) << e.what();

  e = error_of([&] { a.get("list", d); });
  EXPECT_EQ(e.line(), 3u);
  EXPECT_TRUE(contains(e.message(), "expected a number, got [1, 2]")) << e.what();

  e = error_of([&] { a.get("count", n); });
  EXPECT_EQ(e.line(), 4u);
  EXPECT_TRUE(contains(e.message(), "non-negative integer")) << e.what();
  EXPECT_EQ(error_of([&] { a.get("fraction", n); }).line(), 5u);
  EXPECT_EQ(error_of([&] { a.get("flag", b); }).line(), 6u);
  EXPECT_EQ(error_of([&] { a.get("map", s); }).line(), 7u);
  EXPECT_EQ(error_of([&] { a.get("infinite", d); }).line(), 8u);
  e = error_of([&] { a.get("empty", d); });
  EXPECT_EQ(e.line(), 9u);
  EXPECT_TRUE(contains(e.message(), "got nothing")) << e.what();
  EXPECT_EQ(d, 0.0);
  EXPECT_EQ(n, 0u);
}

TEST(YamlReader, PositiveAndRequireChecks) {
  YamlReader yaml = YamlReader::parse("zero: 0\nneg: -1.5\ncount: 0\nratio: 1.5\nok: 2\n", "s");
  double d = 1;
  std::size_t n = 1;
  EXPECT_EQ(error_of([&] { yaml.get_positive("zero", d); }).line(), 1u);
  const InputError e = error_of([&] { yaml.get_positive("neg", d); });
  EXPECT_EQ(e.line(), 2u);
  EXPECT_TRUE(contains(e.message(), "expected a positive number, got \"-1.5\"")) << e.what();
  EXPECT_TRUE(
      contains(error_of([&] { yaml.get_positive("count", n); }).message(), "positive integer"));
  EXPECT_EQ(d, 1.0);
  EXPECT_EQ(n, 1u);

  double ratio = 0.5;
  yaml.get("ratio", ratio);
  const InputError r = error_of([&] { yaml.require("ratio", ratio <= 1.0, "a number in (0, 1]"); });
  EXPECT_EQ(r.line(), 4u);
  EXPECT_EQ(r.message(), "expected a number in (0, 1], got \"1.5\"");
  // Absent keys keep their (valid) defaults and are not checked.
  EXPECT_NO_THROW(yaml.require("absent", false, "anything"));
  yaml.get_positive("ok", d);
  EXPECT_EQ(d, 2.0);
}

TEST(YamlReader, SyntaxErrorsGiveTheLine) {
  const InputError e = error_of([] { YamlReader::parse("a: 1\nb: [1, 2\nc: 3\n", "broken.yaml"); });
  EXPECT_EQ(e.file(), "broken.yaml");
  EXPECT_GE(e.line(), 2u);
  EXPECT_TRUE(contains(e.message(), "invalid YAML")) << e.what();
}

TEST(YamlReader, TopLevelMustBeAMapping) {
  const InputError e = error_of([] { YamlReader::parse("- a\n- b\n", "s.yaml"); });
  EXPECT_EQ(e.line(), 1u);
  EXPECT_TRUE(contains(e.message(), "got [a, b]")) << e.what();
}

// A file of one long line (not YAML at all) is one scalar: the message quotes its start and says
// how long it is, rather than echoing a megabyte to the terminal.
TEST(YamlReader, ALongScalarIsQuotedByItsStart) {
  const std::string line(1 << 20, 'a');
  const InputError e = error_of([&] { YamlReader::parse(line + "\n", "s.yaml"); });
  EXPECT_EQ(e.message(), "expected a mapping of settings at the top level, got \"" +
                             std::string(80, 'a') + "...\" (1048576 characters)");
  double x = 0.0;
  const InputError list = error_of([&] {
    YamlReader::parse("x: [1, " + std::string(100, 'b') + "]\n", "s.yaml").get_positive("x", x);
  });
  EXPECT_TRUE(contains(list.message(), "[1, \"" + std::string(80, 'b') + "...\" (100 characters)]"))
      << list.what();
}

TEST(YamlReader, SectionMustBeAMapping) {
  YamlReader yaml = YamlReader::parse("x: 1\npf: 5\n", "s.yaml");
  const InputError e = error_of([&] { yaml.child("pf"); });
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "pf");
  EXPECT_TRUE(contains(e.message(), "expected a mapping")) << e.what();
}

TEST(YamlReader, DuplicateKeysAreRejected) {
  const InputError e = error_of([] { YamlReader::parse("a: 1\nb: 2\na: 3\n", "s.yaml"); });
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "a");
  EXPECT_TRUE(contains(e.message(), "first on line 1")) << e.what();
}

TEST(YamlReader, SequenceOfMappingsIsReadAndChecked) {
  YamlReader yaml = YamlReader::parse(
      "bodies:\n"
      "  - name: ball\n"
      "    radius: 0.025\n"
      "  - name: mug\n"
      "    radus: 0.04\n",
      "scene.yaml");
  const auto bodies = yaml.sequence("bodies");
  ASSERT_EQ(bodies.size(), 2u);
  std::string name;
  double radius = 0.0;
  bodies[0]->get("name", name);
  bodies[0]->get("radius", radius);
  EXPECT_EQ(name, "ball");
  EXPECT_EQ(radius, 0.025);
  bodies[1]->get("name", name);
  bodies[1]->get("radius", radius);
  try {
    yaml.finish();
    FAIL() << "the misspelt key went unnoticed";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "bodies[1].radus");
    EXPECT_EQ(e.line(), 5u);
  }
  EXPECT_TRUE(YamlReader::parse("", "s.yaml").sequence("bodies").empty());
  YamlReader scalar = YamlReader::parse("bodies: 3\n", "s.yaml");
  EXPECT_THROW(scalar.sequence("bodies"), InputError);
  YamlReader not_maps = YamlReader::parse("bodies: [1, 2]\n", "s.yaml");
  EXPECT_THROW(not_maps.sequence("bodies"), InputError);
}

}  // namespace
}  // namespace opf
