#include "opf/io/csv.h"

#include "opf/io/input_error.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace opf::csv {
namespace {

using Fields = std::vector<std::string>;

Fields split(std::string_view text) {
  return split_line(text, "f.csv", 7);
}

TEST(CsvSplitLine, TrimsUnquotedFields) {
  EXPECT_EQ(split(" a ,b,\t c\t,"), (Fields{"a", "b", "c", ""}));
  EXPECT_EQ(split(""), (Fields{""}));
  EXPECT_EQ(split(",,"), (Fields{"", "", ""}));
}

TEST(CsvSplitLine, KeepsQuotedContentVerbatim) {
  EXPECT_EQ(split(R"( "a, b" ,"say ""hi""",""," x ")"), (Fields{"a, b", "say \"hi\"", "", " x "}));
}

TEST(CsvSplitLine, RejectsMalformedQuotes) {
  try {
    split("1,\"open");
    FAIL() << "no error for an unterminated quote";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "f.csv");
    EXPECT_EQ(e.line(), 7u);
    EXPECT_NE(e.message().find("unterminated"), std::string::npos) << e.what();
  }
  EXPECT_THROW(split("\"a\"b,c"), InputError);
}

TEST(CsvParseDouble, AcceptsOnlyWholeNumbers) {
  EXPECT_EQ(parse_double("0.033333"), 0.033333);
  EXPECT_EQ(parse_double("-1e-3"), -1e-3);
  EXPECT_EQ(parse_double("+2.5"), 2.5);
  EXPECT_EQ(parse_double(".5"), 0.5);
  for (const char* bad : {"", "abc", "1.0abc", "1,5", " 1", "0x10", "+-1", "+", "1e400"})
    EXPECT_FALSE(parse_double(bad).has_value()) << bad;
  EXPECT_TRUE(std::isnan(*parse_double("nan")));
  EXPECT_TRUE(std::isinf(*parse_double("-inf")));
}

TEST(CsvFormatDouble, IsShortestRoundTrip) {
  EXPECT_EQ(format_double(0.033333), "0.033333");
  EXPECT_EQ(format_double(2.0), "2");
  EXPECT_EQ(format_double(-0.5), "-0.5");
  for (const double value :
       {1.0 / 3.0, 1e-300, 6.02214076e23, -0.1 - 0.2, std::numeric_limits<double>::denorm_min()})
    EXPECT_EQ(parse_double(format_double(value)), value) << format_double(value);
}

TEST(CsvFormatTime, IsShortestRoundTripWithoutAnExponent) {
  // Where format_double would take an exponent (shorter), a time keeps its digits.
  EXPECT_EQ(format_double(1600000000.0), "1.6e+09");
  EXPECT_EQ(format_time(1600000000.0), "1600000000");
  EXPECT_EQ(format_time(1600000000.033), "1600000000.033");
  EXPECT_EQ(format_time(1e-4), "0.0001");
  EXPECT_EQ(format_time(100000.0), "100000");
  EXPECT_EQ(format_time(0.033333), "0.033333");
  EXPECT_EQ(format_time(-2.5), "-2.5");
  EXPECT_EQ(format_time(0.0), "0");
  for (const double value : {1.0 / 3.0, 1e-300, 6.02214076e23, std::numeric_limits<double>::max(),
                             -std::numeric_limits<double>::denorm_min()}) {
    const std::string text = format_time(value);
    EXPECT_EQ(text.find_first_of("eE"), std::string::npos) << text;
    EXPECT_EQ(parse_double(text), value) << text;
  }
}

TEST(CsvQuoteIfNeeded, RoundTripsThroughSplitLine) {
  EXPECT_EQ(quote_if_needed("ball"), "ball");
  EXPECT_EQ(quote_if_needed("a,b"), "\"a,b\"");
  for (const std::string text : {"plain", "a,b", "say \"hi\"", " padded ", ""})
    EXPECT_EQ(split(quote_if_needed(text) + ",x"), (Fields{text, "x"})) << text;
  EXPECT_THROW(quote_if_needed("two\nlines"), std::invalid_argument);
}

constexpr std::array<std::string_view, 2> kRequired = {"a", "b"};

TEST(CsvReader, ReadsRowsWithLineNumbers) {
  std::istringstream in("\xEF\xBB\xBF b , a ,c\r\n\r\n1,2,3\r\n   \n4,5,6");
  Reader reader(in, "f.csv", kRequired);
  EXPECT_EQ(reader.header(), (Fields{"b", "a", "c"}));
  EXPECT_EQ(reader.column("a"), 1u);
  EXPECT_THROW(reader.column("zzz"), std::out_of_range);
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.line(), 3u);
  EXPECT_EQ(reader.number(reader.column("a")), 2.0);
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.line(), 5u);
  EXPECT_EQ(reader.field(2), "6");
  EXPECT_FALSE(reader.next());
}

TEST(CsvReader, ABinaryFileIsRefusedWithoutEchoingItsBytes) {
  std::istringstream header(
      std::string("\x7f"
                  "ELF\x02,\x01\n",
                  8));
  try {
    Reader reader(header, "image.bin", kRequired);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 1u);
    EXPECT_EQ(e.message(), "not a text file: control byte 0x7f at byte 1 of the line");
  }
  // In a row after a good header: the line and the byte's place; UTF-8 and tabs are text.
  std::istringstream row(std::string("a,b,c\n1,\tcaf\xC3\xA9,3\n4,5\0,6\n", 24));
  Reader reader(row, "f.csv", kRequired);
  ASSERT_TRUE(reader.next());
  EXPECT_EQ(reader.field(1), "caf\xC3\xA9");
  try {
    reader.next();
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.message(), "not a text file: control byte 0x00 at byte 4 of the line");
  }
}

TEST(CsvReader, ReportsMissingAndDuplicateColumns) {
  std::istringstream missing("c,d\n");
  try {
    Reader reader(missing, "f.csv", kRequired);
    FAIL() << "no error for missing columns";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 1u);
    EXPECT_NE(e.message().find("'a', 'b'"), std::string::npos) << e.what();
  }
  std::istringstream twice("a,b,a\n");
  EXPECT_THROW(Reader(twice, "f.csv", kRequired), InputError);
  std::istringstream empty(" \n\n");
  try {
    Reader reader(empty, "f.csv", kRequired);
    FAIL() << "no error for an empty file";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 0u);
    EXPECT_NE(e.message().find("empty"), std::string::npos) << e.what();
  }
}

TEST(CsvReader, NumberErrorsNameTheColumn) {
  std::istringstream in("a,b\n1,x\n1,inf\n1\n");
  Reader reader(in, "f.csv", kRequired);
  ASSERT_TRUE(reader.next());
  try {
    reader.number(1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "f.csv:2: column 'b': expected a number, got \"x\"");
  }
  ASSERT_TRUE(reader.next());
  EXPECT_THROW(reader.number(1), InputError);
  EXPECT_TRUE(std::isinf(reader.number_or_non_finite(1)));
  try {
    reader.next();
    FAIL() << "no error for a short row";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 4u);
    EXPECT_EQ(e.field(), "");
  }
}

}  // namespace
}  // namespace opf::csv
