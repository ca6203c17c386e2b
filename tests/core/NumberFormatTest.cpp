// Number text and the CSV reader: exact round trips and located errors.

#include "parksim/core/io/NumberFormat.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "parksim/core/io/Csv.h"
#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

TEST(NumberFormat, ShortestReadsBackExactly) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  for (int i = 0; i < 2000; ++i) {
    const double v = (i % 2 ? -1.0 : 1.0) * std::pow(10.0, exponent(rng));
    double back = 0.0;
    ASSERT_TRUE(parseDouble(formatShortest(v), back)) << formatShortest(v);
    EXPECT_EQ(back, v);
  }
  EXPECT_EQ(formatShortest(0.1), "0.1");
  EXPECT_EQ(formatShortest(-3.0), "-3");
  std::string out = "x=";
  appendShortest(out, 0.25);
  EXPECT_EQ(out, "x=0.25");
}

TEST(NumberFormat, FixedAndGeneralMatchPrintfInTheCLocale) {
  EXPECT_EQ(formatFixed(3.14159, 2), "3.14");
  EXPECT_EQ(formatFixed(2.5, 0), "2");  // round half to even, as printf
  EXPECT_EQ(formatFixed(-0.004, 2), "-0.00");
  EXPECT_EQ(formatGeneral(0.0061), "0.0061");
  EXPECT_EQ(formatGeneral(1234567.0), "1.23457e+06");
  EXPECT_EQ(formatGeneral(0.123456789012, 9), "0.123456789");
  EXPECT_EQ(formatGeneral(29.97), "29.97");
  EXPECT_EQ(padLeft("1.50", 6), "  1.50");
  EXPECT_EQ(padLeft("1234567", 6), "1234567");
  // No 309-digit numbers in messages: the general form of the largest double is short.
  EXPECT_EQ(formatGeneral(std::numeric_limits<double>::max()), "1.79769e+308");
}

TEST(NumberFormat, ParsingTakesTheWholeTextOrNothing) {
  double v = 42.0;
  EXPECT_TRUE(parseDouble("+1.5", v));
  EXPECT_EQ(v, 1.5);
  for (const char* bad : {"", "1,5", "1.5x", " 1", "++1", "+-1", "0x10", "1e999"}) {
    double w = 42.0;
    EXPECT_FALSE(parseDouble(bad, w)) << bad;
    EXPECT_EQ(w, 42.0) << bad;
  }
  long long n = 0;
  EXPECT_TRUE(parseInt("-12", n));
  EXPECT_EQ(n, -12);
  EXPECT_FALSE(parseInt("1.0", n));
  EXPECT_FALSE(parseInt("99999999999999999999", n));
}

TEST(Csv, ReadsQuotedFieldsBlankLinesAndCrlf) {
  const CsvTable csv("a,b,c\r\n1,\"x, \"\"y\"\"\",3\r\n\r\n\" 4\",,\"multi\nline\"\n7,8,9",
                     "t.csv");
  ASSERT_EQ(csv.header(), (std::vector<std::string>{"a", "b", "c"}));
  ASSERT_EQ(csv.rows().size(), 3u);
  EXPECT_EQ(csv.rows()[0].cells, (std::vector<std::string>{"1", "x, \"y\"", "3"}));
  EXPECT_EQ(csv.rows()[1].line, 4);
  EXPECT_EQ(csv.rows()[1].cells, (std::vector<std::string>{" 4", "", "multi\nline"}));
  EXPECT_EQ(csv.rows()[2].line, 6);
  EXPECT_EQ(csv.number(csv.rows()[1], 0), 4.0);  // blanks around a number are ignored
  EXPECT_EQ(csvField("x, \"y\""), "\"x, \"\"y\"\"\"");
  EXPECT_EQ(CsvTable(csvField("x, \"y\"") + "\n", "q").header(),
            (std::vector<std::string>{"x, \"y\""}));
}

TEST(Csv, ErrorsNameFileLineAndColumn) {
  const CsvTable csv("t,x\n0,1\n1,one\n2\n", "f.csv");
  EXPECT_EQ(csv.column("x"), 1u);
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([&] { csv.column("y"); }), "f.csv:1: header lacks column 'y'");
  EXPECT_EQ(message([&] { csv.number(csv.rows()[1], 1); }),
            "f.csv:3: column 'x': 'one' is not a finite number");
  EXPECT_EQ(message([&] { csv.number(csv.rows()[2], 1); }), "f.csv:4: column 'x': missing value");
  EXPECT_EQ(message([] { CsvTable("", "e.csv"); }), "e.csv:1: empty file (expected a header line)");
  EXPECT_EQ(message([] { CsvTable("a\n\"open", "q.csv"); }), "q.csv:2: quoted field is not closed");
  EXPECT_EQ(message([] {
              readCsvFile("/nonexistent/x.csv");
            }).rfind("/nonexistent/x.csv: cannot open", 0),
            0u);
}

}  // namespace
}  // namespace parksim

// The CSV files' digits: printf's %.17g in the C locale, whatever the process locale is.
TEST(NumberFormat, RoundTripWritesSeventeenSignificantDigitsLikePrintf) {
  for (const double v : {0.1, -3.0, 1e-300, 123456.789, 2.0 / 3.0, 1e21, -0.0}) {
    std::string out;
    parksim::appendRoundTrip(out, v);
    char expected[64];
    std::snprintf(expected, sizeof expected, "%.17g", v);
    EXPECT_EQ(out, expected);
    double back = 0.0;
    ASSERT_TRUE(parksim::parseDouble(out, back));
    EXPECT_EQ(back, v);
  }
}
