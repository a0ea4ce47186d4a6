#include "opf/io/input_error.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

TEST(InputError, WhatNamesFileLineColumnAndMessage) {
  const InputError error("log.csv", 12, "qw", "expected a number, got \"abc\"");
  EXPECT_STREQ(error.what(), "log.csv:12: column 'qw': expected a number, got \"abc\"");
  EXPECT_EQ(error.file(), "log.csv");
  EXPECT_EQ(error.line(), 12u);
  EXPECT_EQ(error.field(), "qw");
  EXPECT_EQ(error.message(), "expected a number, got \"abc\"");
}

TEST(InputError, LeavesOutLineZeroAndEmptyField) {
  EXPECT_STREQ(InputError("log.csv", 0, "", "empty file").what(), "log.csv: empty file");
  EXPECT_STREQ(InputError("log.csv", 3, "", "bad row").what(), "log.csv:3: bad row");
  EXPECT_STREQ(InputError("log.csv", 0, "t", "no rows").what(), "log.csv: column 't': no rows");
}

TEST(InputError, NamesYamlKeysAsKeys) {
  const InputError error("pf.yaml", 4, "pf.resampling.sheme", "unknown key",
                         InputError::FieldKind::kKey);
  EXPECT_STREQ(error.what(), "pf.yaml:4: key 'pf.resampling.sheme': unknown key");
}

TEST(InputError, IsARuntimeError) {
  try {
    throw InputError("a.csv", 1, "", "boom");
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "a.csv:1: boom");
    return;
  }
  FAIL() << "not caught as std::runtime_error";
}

}  // namespace
}  // namespace opf
