#include <irid/color/numeric_table.h>
#include <irid/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <charconv>
#include <sstream>

namespace irid {
namespace {

NumericTable parse(const std::string& text, int columns = 0, int min_columns = 1) {
    std::istringstream in(text);
    return read_numeric_table(in, "input.csv", columns, min_columns);
}

std::string error_of(const std::string& text, int columns = 0) {
    try {
        (void)parse(text, columns);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(NumericTable, SkipsANonNumericFirstLineAsHeader) {
    const NumericTable t = parse("X,Y,Z\n1,2,3\n4,5,6\n");
    ASSERT_TRUE(t.header.has_value());
    EXPECT_EQ(*t.header, "X,Y,Z");
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[1][2], 6.0);
    EXPECT_EQ(t.line_numbers[1], 3);
    EXPECT_FALSE(parse("1,2,3\n").header.has_value());
}

TEST(NumericTable, AcceptsSpacesCrlfExponentsAndBlankLines) {
    const NumericTable t = parse(" 1.5 , -2e-3,+4\r\n\n  \n7,8,9");
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0][1], -2e-3);
    EXPECT_EQ(t.rows[0][2], 4.0);
    EXPECT_EQ(t.line_numbers[1], 4);
}

TEST(NumericTable, NamesTheLineAndFieldOfBadData) {
    EXPECT_EQ(error_of("X,Y,Z\n1,2,3\n1,two,3\n"), "input.csv:3: field 2 'two' is not a number");
    EXPECT_EQ(error_of("1,2,3\n1,2\n", 3), "input.csv:2: expected 3 comma-separated numbers, found 2");
    EXPECT_NE(error_of("1,2,3\n1,2\n").find("input.csv:2:"), std::string::npos);
    // A first line with a name in it is a header, not an error; the same line later is.
    EXPECT_EQ(error_of("1,x,3\n"), "no error");
    EXPECT_NE(error_of("1,2,3\n1,x,3\n").find("input.csv:2: field 2 'x'"), std::string::npos);
    // A first line of number-like fields is data, so a typo there is reported, not skipped.
    EXPECT_EQ(error_of("1e400,0,0\n"), "input.csv:1: field 1 '1e400' is out of the range of a double");
    EXPECT_EQ(error_of("0x10,0,0\n"), "input.csv:1: field 1 '0x10' is not a number");
    EXPECT_EQ(error_of("1,,0\n"), "input.csv:1: field 2 '' is not a number");
    EXPECT_EQ(error_of("1,0,0,\n"), "input.csv:1: field 4 '' is not a number");
    EXPECT_EQ(error_of("+-1,0,0\n"), "input.csv:1: field 1 '+-1' is not a number");
    EXPECT_NE(error_of("1,nan,3\n").find("not a finite number"), std::string::npos);
    EXPECT_NE(error_of("1,inf,3\n").find("input.csv:1:"), std::string::npos);
    EXPECT_NE(error_of("1,2,3\nX,Y,Z\n").find("input.csv:2:"), std::string::npos);
    EXPECT_NE(error_of("1,2,3\n1,,3\n").find("field 2"), std::string::npos);
    EXPECT_NE(error_of("1,2,3\n1,2 3,3\n").find("field 2"), std::string::npos);
}

TEST(NumericTable, IgnoresAByteOrderMarkAndUnderflowsTinyNumbersToZero) {
    const NumericTable t = parse("\xEF\xBB\xBFX,Y\n1e-400,2\n");
    ASSERT_TRUE(t.header.has_value());
    EXPECT_EQ(*t.header, "X,Y");
    ASSERT_EQ(t.rows.size(), 1u);
    EXPECT_EQ(t.rows[0][0], 0.0);
    EXPECT_EQ(parse("\xEF\xBB\xBF" "1,2\n").rows.size(), 1u);
}

TEST(NumericTable, EmptyInputHasNoRows) {
    EXPECT_TRUE(parse("").rows.empty());
    EXPECT_TRUE(parse("a,b\n").rows.empty());
}

TEST(FormatShortest, RoundTripsWithTheFewestDigits) {
    EXPECT_EQ(format_shortest(0.1), "0.1");
    EXPECT_EQ(format_shortest(-0.0), "0");
    EXPECT_EQ(format_shortest(100.0), "100");
    for (const double v : {1.0 / 3.0, 1e-300, -2.5e17, 0.95047}) {
        const std::string s = format_shortest(v);
        double back = 0.0;
        std::from_chars(s.data(), s.data() + s.size(), back);
        EXPECT_EQ(back, v) << s;
    }
}

}  // namespace
}  // namespace irid
