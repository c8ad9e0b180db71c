// The clip report's sets made where films are known (include/irid/figures/clip_sets.h): the
// interference set from the exact film optics, and the catalogue of the report's sets by name,
// which hands the spectrum and rec2020 sets of irid_gamut through unchanged.

#include <irid/color/adaptation.h>
#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/figures/clip_sets.h>
#include <irid/gamut/report.h>
#include <irid/optics/film_color.h>
#include <irid/optics/material.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace irid::figures {
namespace {

bool outside(const RgbSpace& space, const Xyz& c) {
    const Rgb r = space.from_xyz(c);
    const double tol = 1e-9;
    return r.r < -tol || r.g < -tol || r.b < -tol || r.r > 1 + tol || r.g > 1 + tol ||
           r.b > 1 + tol;
}

void expect_same_colours(const ColorSet& a, const ColorSet& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.description, b.description);
    ASSERT_EQ(a.colors.size(), b.colors.size());
    for (std::size_t i = 0; i < a.colors.size(); ++i) {
        EXPECT_EQ(a.colors[i].X, b.colors[i].X) << i;
        EXPECT_EQ(a.colors[i].Y, b.colors[i].Y) << i;
        EXPECT_EQ(a.colors[i].Z, b.colors[i].Z) << i;
    }
}

TEST(ClipReportSets, NamesAndAll) {
    for (const ClipReportSet s : clip_report_sets()) {
        const auto parsed = parse_clip_report_sets(clip_report_set_name(s));
        ASSERT_EQ(parsed.size(), 1u);
        EXPECT_EQ(parsed[0], s);
    }
    EXPECT_EQ(parse_clip_report_sets("all").size(), 4u);
    EXPECT_EQ(parse_clip_report_sets("ramps"), std::vector<ClipReportSet>{ClipReportSet::ramps});
    try {
        (void)parse_clip_report_sets("gamut");
        FAIL();
    } catch (const Error& e) {
        const std::string message = e.what();
        for (const char* name : {"spectrum", "interference", "rec2020", "ramps", "all"}) {
            EXPECT_NE(message.find(name), std::string::npos) << name;
        }
    }
}

TEST(ClipReportSets, InterferenceIsTwoFilmsThreeAnglesAndAThicknessGrid) {
    const ColorSet set = interference_color_set(srgb());
    EXPECT_EQ(set.name, "interference");
    ASSERT_EQ(set.colors.size(), 2u * 3u * 301u);
    // Zero thickness: air | air (no reflection) for the soap film, so black at every angle.
    for (int angle = 0; angle < 3; ++angle) {
        EXPECT_NEAR(set.colors[static_cast<std::size_t>(angle) * 301].Y, 0.0, 1e-12);
    }
    std::size_t out = 0, above = 0;
    for (const Xyz& c : set.colors) {
        // The exposure keeps every film below the white's luminance (a reflectance < 1 / 5).
        EXPECT_GE(c.Y, -1e-12);
        EXPECT_LT(c.Y, 1.0);
        out += outside(srgb(), c) ? 1 : 0;
        const Rgb r = srgb().from_xyz(c);
        above += (r.r > 1.0 || r.g > 1.0 || r.b > 1.0) ? 1 : 0;
    }
    EXPECT_GT(out, 0u);
    EXPECT_GT(above, 0u);  // bright enough to cross the upper faces too
    EXPECT_LT(out, set.colors.size());
}

TEST(ClipReportSets, InterferenceColoursAreTheExactFilmColoursTimesTheExposure) {
    // Independently of the set's loop: the oil film (the second film, after the soap film's
    // 3 × 301 colours) at 30° (the second angle) and 700 nm (the 141st thickness), through the
    // optics API directly.
    const Colorimeter colorimeter(illuminant_d65(), Observer::cie1931_2deg, srgb(),
                                  ChromaticAdaptation::bradford);
    const SingleFilm oil{*find_material("air"), *find_material("mineral-oil"),
                         *find_material("water")};
    const Rgb c =
        exact_film_color(oil, 700.0, 30.0 * std::numbers::pi / 180.0, colorimeter).rgb_linear;
    const Xyz want =
        srgb().to_xyz({c.r * interference_set_exposure, c.g * interference_set_exposure,
                       c.b * interference_set_exposure});
    const Xyz got = interference_color_set(srgb()).colors.at(3 * 301 + 301 + 140);
    EXPECT_NEAR(got.X, want.X, 1e-12);
    EXPECT_NEAR(got.Y, want.Y, 1e-12);
    EXPECT_NEAR(got.Z, want.Z, 1e-12);
    EXPECT_GT(want.Y, 0.0);
}

TEST(ClipReportSets, TheCatalogueHandsOnTheGamutLibrarysSetsAndTheFilms) {
    for (const RgbSpace* destination : {&srgb(), &display_p3()}) {
        SCOPED_TRACE(destination->name());
        expect_same_colours(clip_report_color_set(ClipReportSet::spectrum, *destination),
                            spectrum_color_set());
        expect_same_colours(clip_report_color_set(ClipReportSet::rec2020, *destination),
                            rec2020_color_set(*destination));
        expect_same_colours(clip_report_color_set(ClipReportSet::interference, *destination),
                            interference_color_set(*destination));
        const ColorSet ramps = clip_report_color_set(ClipReportSet::ramps, *destination);
        expect_same_colours(ramps, ramps_color_set(*destination));
        EXPECT_EQ(ramps.ramps.size(), 144u);
    }
}

TEST(ClipReportSets, TheReportMeasuresTheInterferenceSetItIsGiven) {
    // The report counts out-of-gamut colours by its own rule (a channel beyond 1e-9 of the cube).
    const ColorSet set = interference_color_set(srgb());
    std::size_t out = 0;
    for (const Xyz& c : set.colors) out += outside(srgb(), c) ? 1 : 0;
    const ClipReport report = measure_clip_report(set, Gamut(srgb()), ClipReportOptions{0.0});
    EXPECT_EQ(report.set_name, "interference");
    EXPECT_EQ(report.size, set.colors.size());
    EXPECT_EQ(report.out_of_gamut, out);
    EXPECT_EQ(report.methods.size(), clip_methods().size());
}

}  // namespace
}  // namespace irid::figures
