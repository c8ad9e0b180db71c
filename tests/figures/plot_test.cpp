// The drawing toolkit (src/figures/plot.h) and the option reader (src/figures/figure_support.h):
// tick generation, number formatting, colour maps, coordinate mapping, the files a canvas writes.

#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/figures/figures.h>

#include "figure_support.h"
#include "plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

namespace irid::figures {
namespace {

/// True when step is 1, 2 or 5 times a power of ten (to 1e-9 relative).
bool is_nice(double step) {
    const double magnitude = std::pow(10.0, std::floor(std::log10(step) + 1e-12));
    const double m = step / magnitude;
    for (const double n : {1.0, 2.0, 5.0, 10.0}) {
        if (std::abs(m - n) < 1e-9 * n) return true;
    }
    return false;
}

/// The nice step just below `step` in the 1-2-5 sequence.
double smaller_nice(double step) {
    const double magnitude = std::pow(10.0, std::floor(std::log10(step) + 1e-12));
    const double m = std::round(step / magnitude);
    if (m == 1.0) return 0.5 * magnitude;
    if (m == 2.0) return magnitude;
    return 2.0 * magnitude;
}

TEST(Ticks, NiceStepKnownCases) {
    EXPECT_DOUBLE_EQ(nice_step(10.0, 5), 2.0);
    EXPECT_DOUBLE_EQ(nice_step(1.0, 10), 0.1);
    EXPECT_DOUBLE_EQ(nice_step(0.8, 8), 0.1);  // exactly 8 intervals of 0.1
    EXPECT_DOUBLE_EQ(nice_step(7.0, 8), 1.0);
    EXPECT_DOUBLE_EQ(nice_step(450.0, 8), 100.0);  // 56.25 per tick → 100
    EXPECT_DOUBLE_EQ(nice_step(2.3, 8), 0.5);      // 0.2875 → 0.5
    EXPECT_DOUBLE_EQ(nice_step(1e-6, 4), 5e-7);
}

TEST(Ticks, NiceStepIsTheSmallestNiceStepWithinTheTickBudget) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> exponent(-6.0, 6.0);
    std::uniform_int_distribution<int> ticks(1, 12);
    for (int trial = 0; trial < 5000; ++trial) {
        const double span = std::pow(10.0, exponent(rng));
        const int max_ticks = ticks(rng);
        const double step = nice_step(span, max_ticks);
        ASSERT_TRUE(is_nice(step)) << step;
        EXPECT_LE(span / step, max_ticks * (1.0 + 1e-9)) << span << " " << max_ticks;
        EXPECT_GT(span / smaller_nice(step), max_ticks * (1.0 - 1e-9)) << span << " " << max_ticks;
    }
}

TEST(Ticks, TicksCoverTheRangeAtEqualNiceSpacing) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> centre(-1000.0, 1000.0);
    std::uniform_real_distribution<double> exponent(-3.0, 3.0);
    for (int trial = 0; trial < 3000; ++trial) {
        const double lo = centre(rng);
        const double hi = lo + std::pow(10.0, exponent(rng));
        const std::vector<Tick> ticks = nice_ticks(lo, hi, 8);
        const double step = nice_step(hi - lo, 8);
        ASSERT_FALSE(ticks.empty()) << lo << " " << hi;
        EXPECT_LE(ticks.size(), 9U);
        // Inside the range, and none missing at either end.
        EXPECT_GE(ticks.front().value, lo - 1e-9 * step);
        EXPECT_LE(ticks.back().value, hi + 1e-9 * step);
        EXPECT_LT(ticks.front().value - step, lo);
        EXPECT_GT(ticks.back().value + step, hi);
        for (std::size_t i = 0; i < ticks.size(); ++i) {
            // Integer multiples of the step, strictly increasing by one step.
            const double k = ticks[i].value / step;
            EXPECT_NEAR(k, std::round(k), 1e-6) << ticks[i].value;
            if (i > 0) {
                EXPECT_NEAR(ticks[i].value - ticks[i - 1].value, step, 1e-9 * step);
            }
            // The label reads back as the value (with U+2212 for a minus).
            std::string label = ticks[i].label;
            if (label.rfind("\u2212", 0) == 0) label.replace(0, 3, "-");
            EXPECT_NEAR(std::stod(label), ticks[i].value, 1e-9 * std::max(1.0, step)) << label;
        }
    }
}

TEST(Ticks, WavelengthAxis) {
    const std::vector<Tick> ticks = nice_ticks(380.0, 780.0, 8);
    std::vector<double> values;
    for (const Tick& t : ticks) values.push_back(t.value);
    EXPECT_EQ(values, (std::vector<double>{400.0, 450.0, 500.0, 550.0, 600.0, 650.0, 700.0, 750.0}));
    EXPECT_EQ(ticks.front().label, "400");
}

TEST(Ticks, FormatTickUsesTheStepsDecimalsAndATrueMinus) {
    EXPECT_EQ(format_tick(0.30000000000000004, 0.1), "0.3");
    EXPECT_EQ(format_tick(-0.5, 0.5), "\u22120.5");
    EXPECT_EQ(format_tick(-1e-17, 0.1), "0.0");  // never "−0.0"
    EXPECT_EQ(format_tick(500.0, 100.0), "500");
    EXPECT_EQ(format_tick(0.25, 0.05), "0.25");
    EXPECT_EQ(format_tick(2.0, 0.002), "2.000");
}

TEST(Ticks, NiceRangeWidensOutwardToSteps) {
    const auto [lo, hi] = nice_range(0.03, 0.97, 8);
    EXPECT_DOUBLE_EQ(lo, 0.0);
    EXPECT_DOUBLE_EQ(hi, 1.0);
    const auto [a, b] = nice_range(-0.14, 1.87, 8);
    EXPECT_LE(a, -0.14);
    EXPECT_GE(b, 1.87);
    EXPECT_NEAR(a, -0.5, 1e-12);  // 2.01 / 8 → step 0.5
    EXPECT_NEAR(b, 2.0, 1e-12);
    const auto [c, d] = nice_range(3.0, 3.0, 8);  // a degenerate range is widened first
    EXPECT_LT(c, 3.0);
    EXPECT_GT(d, 3.0);
}

TEST(Ticks, BadArgumentsThrow) {
    EXPECT_THROW((void)nice_step(0.0, 5), Error);
    EXPECT_THROW((void)nice_step(1.0, 0), Error);
    EXPECT_THROW((void)nice_step(std::nan(""), 5), Error);
    EXPECT_THROW((void)nice_ticks(1.0, 1.0), Error);
    EXPECT_THROW((void)nice_ticks(2.0, 1.0), Error);
    EXPECT_THROW((void)nice_range(0.0, INFINITY), Error);
}

TEST(Colors, DisplayColorIsTheSrgbEncoding) {
    // IEC 61966-2-1: 1.055 × 0.5^(1/2.4) − 0.055 = 0.735356983...
    const Color c = display_color({0.5, 0.5, 0.5});
    EXPECT_NEAR(c.r, 0.7353569830524495, 1e-12);
    EXPECT_NEAR(c.g, 0.7353569830524495, 1e-12);
    // Linear segment below 0.0031308: 12.92 v.
    EXPECT_NEAR(display_color({0.001, 0.0, 1.0}).r, 0.01292, 1e-12);
    // Rounding left by a clip is clamped away.
    const Color d = display_color({1.0 + 1e-12, -1e-13, 0.0});
    EXPECT_EQ(d.r, 1.0);
    EXPECT_EQ(d.g, 0.0);
}

TEST(Colors, ClippedDisplayColorOfTheWhiteIsWhite) {
    const GamutClipper clipper(ClipMethod::smits, Gamut(srgb()));
    const Color c = clipped_display_color(srgb().white_xyz(), clipper);
    EXPECT_NEAR(c.r, 1.0, 1e-9);
    EXPECT_NEAR(c.g, 1.0, 1e-9);
    EXPECT_NEAR(c.b, 1.0, 1e-9);
}

TEST(Colors, SequentialMapRisesInLightnessAndStaysInGamut) {
    double previous = -1.0;
    for (int i = 0; i <= 200; ++i) {
        const Color c = sequential_color(i / 200.0);
        for (const double v : {c.r, c.g, c.b}) {
            EXPECT_GE(v, 0.0);
            EXPECT_LE(v, 1.0);
        }
        const Oklab lab = xyz_to_oklab(srgb().to_xyz(srgb().decode({c.r, c.g, c.b})));
        EXPECT_GT(lab.L, previous) << "t = " << i / 200.0;
        previous = lab.L;
    }
    // Clamped outside [0, 1], and NaN taken as 0.
    EXPECT_EQ(sequential_color(-3.0).r, sequential_color(0.0).r);
    EXPECT_EQ(sequential_color(7.0).g, sequential_color(1.0).g);
    EXPECT_EQ(sequential_color(std::nan("")).b, sequential_color(0.0).b);
}

TEST(Colors, SeriesColorsAreDistinctAndCycle) {
    for (std::size_t i = 0; i < 8; ++i) {
        for (std::size_t j = i + 1; j < 8; ++j) {
            const Color a = series_color(i);
            const Color b = series_color(j);
            EXPECT_GT(std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b), 0.1);
        }
        EXPECT_EQ(series_color(i).r, series_color(i + 8).r);
    }
}

// --- canvas files ------------------------------------------------------------------------------

/// Width and height from a PNG's IHDR chunk (big-endian at bytes 16..23), or {-1, -1}.
std::pair<long, long> png_size(const std::string& bytes) {
    static const std::string signature("\x89PNG\r\n\x1a\n", 8);
    if (bytes.size() < 24 || bytes.compare(0, 8, signature) != 0 || bytes.compare(12, 4, "IHDR") != 0) {
        return {-1, -1};
    }
    const auto be32 = [&](std::size_t at) {
        long v = 0;
        for (std::size_t i = 0; i < 4; ++i) v = v * 256 + static_cast<unsigned char>(bytes[at + i]);
        return v;
    };
    return {be32(16), be32(20)};
}

std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Canvas, PngHasExactlyTheRequestedSize) {
    Canvas canvas(ImageFormat::png, 321, 123);
    canvas.fill_rect({10, 10, 50, 50}, series_color(0));
    canvas.text({20, 100}, "λ x̄ ȳ z̄ −0.5 u′v′", {});
    const auto [w, h] = png_size(canvas.finish());
    EXPECT_EQ(w, 321);
    EXPECT_EQ(h, 123);
}

TEST(Canvas, SvgIsAnSvgDocumentOfTheRequestedSize) {
    Canvas canvas(ImageFormat::svg, 200, 100);
    canvas.line({0, 0}, {200, 100}, {});
    const std::string svg = canvas.finish();
    EXPECT_EQ(svg.rfind("<?xml", 0), 0U);
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_NE(svg.find("width=\"200pt\""), std::string::npos);
    EXPECT_NE(svg.find("height=\"100pt\""), std::string::npos);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST(Canvas, SizeLimits) {
    EXPECT_THROW(Canvas(ImageFormat::png, min_size_px - 1, 100), Error);
    EXPECT_THROW(Canvas(ImageFormat::png, 100, max_size_px + 1), Error);
    EXPECT_NO_THROW(Canvas(ImageFormat::svg, min_size_px, min_size_px));
}

TEST(Canvas, SaveWritesAtomicallyAndLeavesNoTemporaryFile) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("irid_plot_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    Canvas canvas(ImageFormat::png, 100, 80);
    canvas.save(dir / "a.png");
    EXPECT_EQ(png_size(read_file(dir / "a.png")), (std::pair<long, long>{100, 80}));
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1U);
    Canvas other(ImageFormat::png, 100, 80);
    EXPECT_THROW(other.save(dir / "missing-folder" / "b.png"), Error);
    std::filesystem::remove_all(dir);
}

TEST(Canvas, ImageFormatFromTheExtension) {
    EXPECT_EQ(image_format_for("a/b.svg"), ImageFormat::svg);
    EXPECT_EQ(image_format_for("B.PNG"), ImageFormat::png);
    try {
        (void)image_format_for("c.jpg");
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(".svg, .png"), std::string::npos) << e.what();
    }
}

// --- plots ------------------------------------------------------------------------------------

TEST(Plot, MapsTheAxisLimitsToTheFrame) {
    Canvas canvas(ImageFormat::png, 400, 300);
    Plot plot(canvas, page_area(canvas), {.min = 380.0, .max = 780.0, .title = "λ (nm)"},
              {.min = -0.5, .max = 2.0, .title = "value"}, "title");
    const Rect f = plot.frame();
    EXPECT_NEAR(plot.to_canvas(380.0, -0.5).x, f.x, 1e-9);
    EXPECT_NEAR(plot.to_canvas(380.0, -0.5).y, f.bottom(), 1e-9);
    EXPECT_NEAR(plot.to_canvas(780.0, 2.0).x, f.right(), 1e-9);
    EXPECT_NEAR(plot.to_canvas(780.0, 2.0).y, f.y, 1e-9);
    EXPECT_NEAR(plot.to_canvas(580.0, 0.75).x, f.x + f.width / 2.0, 1e-9);
    // The frame lies inside the area given.
    const Rect a = page_area(canvas);
    EXPECT_GE(f.x, a.x);
    EXPECT_GE(f.y, a.y);
    EXPECT_LE(f.right(), a.right());
    EXPECT_LE(f.bottom(), a.bottom());
    // Generated ticks are those of nice_ticks.
    EXPECT_EQ(plot.x_ticks().size(), nice_ticks(380.0, 780.0, 8).size());
}

TEST(Plot, EqualAspectGivesEqualScales) {
    Canvas canvas(ImageFormat::svg, 900, 400);
    Plot plot(canvas, page_area(canvas), {.min = 0.0, .max = 0.8}, {.min = 0.0, .max = 0.9}, "",
              {.equal_aspect = true});
    const double sx = plot.frame().width / 0.8;
    const double sy = plot.frame().height / 0.9;
    EXPECT_NEAR(sx, sy, 1e-9 * sx);
}

TEST(Plot, RejectsBadAxesAndGrids) {
    Canvas canvas(ImageFormat::png, 200, 200);
    EXPECT_THROW(Plot(canvas, page_area(canvas), {.min = 1.0, .max = 1.0}, {}), Error);
    EXPECT_THROW(Plot(canvas, page_area(canvas), {}, {.min = 0.0, .max = NAN}), Error);
    EXPECT_THROW(Plot(canvas, {0, 0, 20, 20}, {}, {}), Error);  // no room
    Plot plot(canvas, page_area(canvas), {}, {});
    const std::vector<Color> three(3);
    EXPECT_THROW(plot.cell_grid(0, 1, 0, 1, 2, 2, three), Error);
    EXPECT_THROW(plot.raster(0, 1, 0, 1, 2, 2, three), Error);
    const std::vector<double> xs{0.0, 1.0};
    const std::vector<double> ys{0.0};
    EXPECT_THROW(plot.line(xs, ys, {}), Error);
    EXPECT_NO_THROW(plot.finish());
}

TEST(Plot, DrawsEveryElementIntoAValidFile) {
    for (const ImageFormat format : {ImageFormat::png, ImageFormat::svg}) {
        Canvas canvas(format, 640, 400);
        Plot plot(canvas, page_area(canvas), {.min = 0.0, .max = 10.0, .title = "x"},
                  {.min = -1.0, .max = 1.0, .title = "y"}, "every element",
                  {.right_reserve = 80.0});
        std::vector<double> xs, ys;
        for (int i = 0; i <= 100; ++i) {
            xs.push_back(i / 10.0);
            ys.push_back(std::sin(i / 10.0));
        }
        ys[50] = NAN;  // breaks the line
        plot.line(xs, ys, {series_color(0), 2.0, Dash::dashed}, "sin");
        const std::vector<Point> tri{{1, 0}, {3, 0.5}, {2, -0.5}};
        plot.polygon(tri, with_alpha(series_color(1), 0.3), {series_color(1), 1.0, Dash::dotted},
                     "triangle");
        for (const MarkerShape m : {MarkerShape::circle, MarkerShape::square, MarkerShape::diamond,
                                    MarkerShape::triangle, MarkerShape::cross, MarkerShape::plus}) {
            plot.marker({1.0 + static_cast<int>(m), 0.8}, {.shape = m});
        }
        std::vector<Color> strip;
        for (int i = 0; i < 50; ++i) strip.push_back(sequential_color(i / 49.0));
        plot.color_strip(5.0, 9.0, -0.9, -0.6, strip);
        plot.cell_grid(5.0, 9.0, -0.5, -0.2, 10, 5, std::vector<Color>(50, series_color(2)));
        plot.text({5.0, 0.0}, "label", {.halign = HAlign::center, .halo = true});
        plot.hline(0.0, {palette::grey, 1.0, Dash::dash_dot});
        plot.finish(LegendPosition::bottom_left);
        EXPECT_GT(plot.legend_box().width, 0.0);
        draw_color_bar(canvas, {plot.frame().right() + 10.0, plot.frame().y, 15.0, 200.0}, 0.0,
                       5.0, "ΔE", sequential_color);
        EXPECT_THROW(draw_color_bar(canvas, {0, 0, 10, 10}, 1.0, 1.0, "", sequential_color),
                     Error);
        const std::string bytes = canvas.finish();
        if (format == ImageFormat::png) {
            EXPECT_EQ(png_size(bytes), (std::pair<long, long>{640, 400}));
        } else {
            EXPECT_EQ(bytes.rfind("<?xml", 0), 0U);
            EXPECT_NE(bytes.find("</svg>"), std::string::npos);
        }
    }
}

// --- options ------------------------------------------------------------------------------

FigureRequest request_with(std::vector<std::pair<std::string, std::string>> options) {
    FigureRequest r;
    r.name = "test-figure";
    r.options = std::move(options);
    return r;
}

/// The message of the FigureRequestError `f` throws ("" when it throws nothing).
template <class F>
std::string request_error(F&& f) {
    try {
        f();
    } catch (const FigureRequestError& e) {
        return e.what();
    }
    return "";
}

TEST(Options, UnknownKeyNamesTheKeyAndTheKnownOnes) {
    const std::string m = request_error([] {
        detail::Options o(request_with({{"colour", "red"}}), {"color", "space"});
    });
    EXPECT_NE(m.find("test-figure"), std::string::npos) << m;
    EXPECT_NE(m.find("\"colour\""), std::string::npos) << m;
    EXPECT_NE(m.find("color, space"), std::string::npos) << m;
}

TEST(Options, ValuesAreValidated) {
    const detail::Options o(
        request_with({{"n", "2.5"}, {"n", "3"}, {"i", "7"}, {"c", "uv"}, {"l", " a , b,c "},
                      {"v", "1,2,3"}, {"bad", "x"}, {"big", "1e9"}, {"hole", "a,,b"}}),
        {"n", "i", "c", "l", "v", "bad", "big", "hole", "absent"});
    EXPECT_DOUBLE_EQ(o.number("n", 0.0, 0.0, 10.0), 3.0);  // the last value wins
    EXPECT_EQ(o.integer("i", 0, 0, 10), 7);
    EXPECT_EQ(o.choice("c", {"xy", "uv"}, "xy"), "uv");
    EXPECT_EQ(o.choice("absent", {"xy", "uv"}, "xy"), "xy");
    EXPECT_EQ(o.list("l", ""), (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_EQ(o.numbers("v", "", 0.0, 5.0, 3), (std::vector<double>{1.0, 2.0, 3.0}));
    EXPECT_DOUBLE_EQ(o.number("absent", 4.5, 0.0, 10.0), 4.5);

    std::string m = request_error([&] { (void)o.number("bad", 0.0, 0.0, 1.0); });
    EXPECT_NE(m.find("bad=x"), std::string::npos) << m;
    EXPECT_NE(m.find("[0, 1]"), std::string::npos) << m;
    m = request_error([&] { (void)o.number("big", 0.0, 0.0, 100.0); });
    EXPECT_NE(m.find("out of range"), std::string::npos) << m;
    m = request_error([&] { (void)o.choice("c", {"lab", "luv"}, "lab"); });
    EXPECT_NE(m.find("lab, luv"), std::string::npos) << m;
    m = request_error([&] { (void)o.list("hole", ""); });
    EXPECT_NE(m.find("empty item"), std::string::npos) << m;
    m = request_error([&] { (void)o.numbers("v", "", 0.0, 5.0, 2); });
    EXPECT_NE(m.find("expected 2 values"), std::string::npos) << m;
    m = request_error([&] { (void)o.numbers("v", "", 0.0, 2.5, 3); });
    EXPECT_NE(m.find("3 is out of range"), std::string::npos) << m;
    m = request_error([&] { (void)o.integer("c", 0, 0, 10); });
    EXPECT_NE(m.find("not an integer"), std::string::npos) << m;
}

TEST(Formatting, FixedAndShortest) {
    EXPECT_EQ(detail::fixed(-0.0004, 3), "0.000");
    EXPECT_EQ(detail::fixed(1.23456, 2), "1.23");
    EXPECT_EQ(detail::shortest(0.1), "0.1");
    EXPECT_EQ(detail::shortest(520.0), "520");
    EXPECT_EQ(detail::lower_extension("x/Fig.SVG"), ".svg");
    EXPECT_EQ(detail::lower_extension("noext"), "");
}

}  // namespace
}  // namespace irid::figures
