#include <irid/color/adaptation.h>
#include <irid/color/illuminant.h>
#include <irid/color/numeric_table.h>
#include <irid/color/observer.h>
#include <irid/error.h>
#include <irid/text_input.h>
#include <irid/figures/clip_sets.h>
#include <irid/optics/film_color.h>
#include <irid/optics/material.h>

#include <array>
#include <numbers>
#include <string>
#include <utility>

namespace irid::figures {
namespace {

constexpr std::array<ClipReportSet, 4> all_sets{ClipReportSet::spectrum, ClipReportSet::interference,
                                                ClipReportSet::rec2020, ClipReportSet::ramps};

}  // namespace

ColorSet interference_color_set(const RgbSpace& destination) {
    ColorSet set;
    set.name = "interference";
    set.description =
        "Exact thin-film reflections (D65, CIE 1931 2°): soap film air|water|air and "
        "mineral oil on water, 0-1500 nm every 5 nm at 0°, 30°, 60°, XYZ × " +
        format_shortest(interference_set_exposure);
    // The colorimeter adapts from the illuminant's white to the destination's; its linear RGB is
    // then XYZ relative to the destination's white.
    const Colorimeter colorimeter(illuminant_d65(), Observer::cie1931_2deg, destination,
                                  ChromaticAdaptation::bradford);
    const Material air = *find_material("air");
    const Material water = *find_material("water");
    const SingleFilm films[] = {{air, water, air}, {air, *find_material("mineral-oil"), water}};
    for (const SingleFilm& film : films) {
        for (const double angle_deg : {0.0, 30.0, 60.0}) {
            const double angle = angle_deg * std::numbers::pi / 180.0;
            for (int t = 0; t <= 1500; t += 5) {
                const Rgb c = exact_film_color(film, t, angle, colorimeter).rgb_linear;
                const double e = interference_set_exposure;
                set.colors.push_back(destination.to_xyz({c.r * e, c.g * e, c.b * e}));
            }
        }
    }
    return set;
}

std::span<const ClipReportSet> clip_report_sets() noexcept {
    return all_sets;
}

std::string_view clip_report_set_name(ClipReportSet set) noexcept {
    switch (set) {
        case ClipReportSet::spectrum: return "spectrum";
        case ClipReportSet::interference: return "interference";
        case ClipReportSet::rec2020: return "rec2020";
        case ClipReportSet::ramps: return "ramps";
    }
    return "";
}

std::vector<ClipReportSet> parse_clip_report_sets(std::string_view name) {
    if (name == "all") return {all_sets.begin(), all_sets.end()};
    std::string names;
    std::vector<std::string> valid;
    for (const ClipReportSet s : all_sets) {
        if (clip_report_set_name(s) == name) return {s};
        names += std::string(clip_report_set_name(s)) + ", ";
        valid.emplace_back(clip_report_set_name(s));
    }
    valid.emplace_back("all");
    throw UnknownNameError("unknown set " + quote_untrusted(name) + "; valid: " + names + "all",
                           std::move(valid));
}

ColorSet clip_report_color_set(ClipReportSet set, const RgbSpace& destination) {
    switch (set) {
        case ClipReportSet::spectrum: return spectrum_color_set();
        case ClipReportSet::interference: return interference_color_set(destination);
        case ClipReportSet::rec2020: return rec2020_color_set(destination);
        case ClipReportSet::ramps: return ramps_color_set(destination);
    }
    return {};
}

}  // namespace irid::figures
