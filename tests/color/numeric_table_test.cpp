#include <irid/color/numeric_table.h>
#include <irid/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <charconv>
#include <sstream>
#include <streambuf>
#include <string_view>
#include <vector>

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
    ASSERT_EQ(t.rows(), 2u);
    EXPECT_EQ(t.row(1)[2], 6.0);
    EXPECT_EQ(t.line_numbers[1], 3);
    EXPECT_FALSE(parse("1,2,3\n").header.has_value());
}

TEST(NumericTable, AcceptsSpacesCrlfExponentsAndBlankLines) {
    const NumericTable t = parse(" 1.5 , -2e-3,+4\r\n\n  \n7,8,9");
    ASSERT_EQ(t.rows(), 2u);
    EXPECT_EQ(t.row(0)[1], -2e-3);
    EXPECT_EQ(t.row(0)[2], 4.0);
    EXPECT_EQ(t.line_numbers[1], 4);
}

TEST(NumericTable, NamesTheLineAndFieldOfBadData) {
    // A bad field of line 1 also says what line 1 may hold.
    const std::string line_1 = "; line 1 holds numbers separated by commas, or a header of names (each beginning with a letter)";
    EXPECT_EQ(error_of("X,Y,Z\n1,2,3\n1,two,3\n"), "input.csv:3: field 2 'two' is not a number");
    EXPECT_EQ(error_of("1,2,3\n1,2\n", 3), "input.csv:2: expected 3 comma-separated numbers, found 2");
    EXPECT_NE(error_of("1,2,3\n1,2\n").find("input.csv:2:"), std::string::npos);
    // A first line is a header only when none of its fields is a number: one bad field among
    // numbers is data, and an error (it was once dropped silently as a header).
    EXPECT_EQ(error_of("0.1,abc,0.3\n"), "input.csv:1: field 2 'abc' is not a number" + line_1);
    EXPECT_EQ(error_of("1,x,3\n"), "input.csv:1: field 2 'x' is not a number" + line_1);
    EXPECT_EQ(error_of("R,1,B\n"), "input.csv:1: field 1 'R' is not a number" + line_1);
    EXPECT_EQ(error_of("R,G,B\n1,2,3\n"), "no error");
    EXPECT_EQ(error_of("wavelength_nm,reflectance 1,R (%)\n400,0.5,3\n"), "no error");
    EXPECT_NE(error_of("1,2,3\n1,x,3\n").find("input.csv:2: field 2 'x'"), std::string::npos);
    // A line of empty fields names nothing: data, and an error.
    EXPECT_EQ(error_of(",,\n"), "input.csv:1: field 1 '' is not a number" + line_1);
    // A first line of number-like fields is data, so a typo there is reported, not skipped.
    EXPECT_EQ(error_of("1e400,0,0\n"), "input.csv:1: field 1 '1e400' is out of the range of a double");
    EXPECT_EQ(error_of("0x10,0,0\n"), "input.csv:1: field 1 '0x10' is not a number" + line_1);
    EXPECT_EQ(error_of("1,,0\n"), "input.csv:1: field 2 '' is not a number" + line_1);
    EXPECT_EQ(error_of("1,0,0,\n"), "input.csv:1: field 4 '' is not a number" + line_1);
    EXPECT_EQ(error_of("+-1,0,0\n"), "input.csv:1: field 1 '+-1' is not a number" + line_1);
    EXPECT_NE(error_of("1,nan,3\n").find("not a finite number"), std::string::npos);
    EXPECT_NE(error_of("1,inf,3\n").find("input.csv:1:"), std::string::npos);
    EXPECT_NE(error_of("1,2,3\nX,Y,Z\n").find("input.csv:2:"), std::string::npos);
    EXPECT_NE(error_of("1,2,3\n1,,3\n").find("field 2"), std::string::npos);
    EXPECT_NE(error_of("1,2,3\n1,2 3,3\n").find("field 2"), std::string::npos);
}

std::string error_of_shape(const std::string& text, int columns, int min_columns) {
    try {
        (void)parse(text, columns, min_columns);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(NumericTable, AFirstLineIsAHeaderOnlyWhenItNamesEveryColumn) {
    // Numbers with another separator are one field that is no name: data, and an error that
    // says what line 1 may hold (it was taken as a header over an empty table, issue 37).
    EXPECT_EQ(error_of_shape("0.1;0.2;0.3\n", 3, 1),
              "input.csv:1: field 1 '0.1;0.2;0.3' is not a number; line 1 holds 3 numbers separated by "
              "commas, or a header of 3 names (each beginning with a letter)");
    EXPECT_EQ(error_of("0.1;0.2;0.3\n"),
              "input.csv:1: field 1 '0.1;0.2;0.3' is not a number; line 1 holds numbers separated by "
              "commas, or a header of names (each beginning with a letter)");
    EXPECT_NE(error_of_shape("0.1 0.2 0.3\n", 3, 1).find("input.csv:1: field 1 '0.1 0.2 0.3'"), std::string::npos);
    EXPECT_NE(error_of_shape("400;0.5\n", 0, 2).find("at least 2 numbers separated by commas, or a header of at "
                                                     "least 2 names"),
              std::string::npos);
    // One name where three columns are read, a name that does not begin with a letter, and fewer
    // names than the rows have numbers do not name the columns.
    EXPECT_NE(error_of_shape("R;G;B\n", 3, 1).find("input.csv:1: field 1 'R;G;B' is not a number"), std::string::npos);
    EXPECT_NE(error_of_shape("X,Y\n", 3, 1).find("input.csv:1: field 1 'X' is not a number"), std::string::npos);
    EXPECT_NE(error_of("#R,G,B\n1,2,3\n").find("input.csv:1: field 1 '#R'"), std::string::npos);
    EXPECT_NE(error_of("_x,y\n1,2\n").find("input.csv:1:"), std::string::npos);
    EXPECT_EQ(error_of("X,Y\n1,2,3\n"),
              "input.csv:2: expected 2 comma-separated numbers like the header's names on line 1, found 3");
    // Names: letters first, then anything; UTF-8 letters (λ) too.
    EXPECT_EQ(parse("\xCE\xBB,R (%)\n400,3\n").header, "\xCE\xBB,R (%)");
    EXPECT_EQ(parse("R,G,B\n", 3).header, "R,G,B");
    EXPECT_TRUE(parse("R,G,B\n", 3).empty());
    EXPECT_EQ(parse("R;G;B\n").header, "R;G;B");  // one name, one column
    EXPECT_EQ(parse("wavelength_nm,a,b\n400,1,2\n", 0, 2).header, "wavelength_nm,a,b");
    // nan and inf are numbers (not finite ones), never names.
    EXPECT_NE(error_of("nan,inf,x\n").find("input.csv:1: field 3 'x' is not a number"), std::string::npos);
    EXPECT_NE(error_of("nan,inf\n").find("input.csv:1: field 1 'nan' is not a finite number"), std::string::npos);
}

TEST(NumericTable, IgnoresAByteOrderMarkAndUnderflowsTinyNumbersToZero) {
    const NumericTable t = parse("\xEF\xBB\xBFX,Y\n1e-400,2\n");
    ASSERT_TRUE(t.header.has_value());
    EXPECT_EQ(*t.header, "X,Y");
    ASSERT_EQ(t.rows(), 1u);
    EXPECT_EQ(t.row(0)[0], 0.0);
    EXPECT_EQ(parse("\xEF\xBB\xBF" "1,2\n").rows(), 1u);
}

TEST(NumericTable, EmptyInputHasNoRows) {
    EXPECT_TRUE(parse("").empty());
    EXPECT_TRUE(parse("a,b\n").empty());
    EXPECT_TRUE(read_numeric_table(std::string_view("\n\n"), "text").empty());
}

TEST(NumericTable, RowsAreStoredFlatWithTheirColumnCount) {
    const NumericTable t = read_numeric_table(std::string_view("1,2\n3,4\n5,6\n"), "text");
    EXPECT_EQ(t.columns, 2u);
    EXPECT_EQ(t.values, (std::vector<double>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(t.row(2)[1], 6.0);
    EXPECT_EQ(t.line_numbers, (std::vector<int>{1, 2, 3}));
}

TEST(NumericTable, UntrustedBytesAreQuotedShortAndEscaped) {
    // A terminal escape sequence in a field is shown escaped, never sent to the terminal.
    EXPECT_EQ(error_of("1,\x1b[31mred,3\n").rfind("input.csv:1: field 2 '\\x1b[31mred' is not a number", 0), 0U);
    // A 10 MB field is shown by its first 40 characters.
    const std::string message = error_of("1," + std::string(10'000'000, 'z') + ",3\n");
    EXPECT_EQ(message.rfind("input.csv:1: field 2 '" + std::string(40, 'z') + "...' is not a number", 0), 0U);
    // NUL bytes (from /dev/zero) too.
    EXPECT_EQ(error_of(std::string("1,\0\0,3\n", 8)).rfind("input.csv:1: field 2 '\\x00\\x00' is not a number", 0), 0U);
}

TEST(NumericTable, MoreThanTheLimitIsRefusedWithoutGrowingWithoutBound) {
    // Just above max_table_values numbers: one short line repeated.
    std::string text;
    const std::size_t lines = max_table_values / 4 + 1;
    text.reserve(lines * 8);
    for (std::size_t i = 0; i < lines; ++i) text += "1,2,3,4\n";
    const std::string message = [&] {
        try {
            (void)read_numeric_table(std::string_view(text), "big.csv");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    }();
    EXPECT_EQ(message.rfind("big.csv: more than 33554432 numbers", 0), 0u) << message;
    // A stream beyond max_text_input_bytes stops at the limit instead of reading on.
    struct Endless : std::streambuf {
        int_type underflow() override {
            setg(m_zeros, m_zeros, m_zeros + sizeof m_zeros);
            return 0;
        }
        char m_zeros[1 << 16]{};
    } zeros;
    std::istream endless(&zeros);
    EXPECT_THROW((void)read_numeric_table(endless, "<zeros>"), Error);
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
