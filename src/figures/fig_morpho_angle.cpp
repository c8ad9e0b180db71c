// morpho-angle: the colour of the Morpho wing against viewing angle (Smits 1990, eq. 29 with
// eq. 25, and the blend over mullion thicknesses of §3.7), beside the exact transfer-matrix stack
// of the same geometry, with the wavelength of the reflectance peak against angle.

#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/optics/film.h>
#include <irid/optics/material.h>
#include <irid/optics/multilayer.h>

#include "figure_support.h"
#include "film_clip_data.h"
#include "plot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace irid::figures::detail {
double dominant_peak_nm(const DenseSpectrum& spectrum) noexcept {
    int best = 0;
    for (int i = 1; i < dense_sample_count; ++i) {
        if (spectrum[i] > spectrum[best]) best = i;
    }
    const double nm = DenseSpectrum::wavelength_nm(best);
    return nm >= 380.0 && nm <= 780.0 ? nm : std::numeric_limits<double>::quiet_NaN();
}

FilmStack morpho_exact_stack(const MorphoParameters& wing) {
    validate_morpho(wing);
    // n = 1 as eq. 29 assumes (the dispersive air of find_material differs by 3e-4).
    const Material air = Material::constant("air n=1", 1.0);
    const Material chitin = Material::constant("chitin n=" + format_shortest(wing.n), wing.n);
    std::vector<Layer> layers;
    for (int p = 0; p < wing.periods; ++p) {
        layers.push_back({chitin, wing.d2_nm});
        // The last gap would merge with the air behind the stack.
        if (p + 1 < wing.periods) layers.push_back({air, wing.d1_nm});
    }
    return FilmStack(air, std::move(layers), air);
}

namespace {

/// The exact wing as a film model (irid/optics/film.h); no mullions: a bare interface.
ExactFilm morpho_exact_film(const MorphoParameters& wing) {
    const FilmStack s = morpho_exact_stack(wing);
    std::vector<Layer> layers = s.layers();
    if (layers.empty()) layers.push_back({s.ambient(), 0.0});
    return ExactFilm(s.ambient(), std::move(layers), s.substrate());
}

/// A model's reflectance on the 1 nm grid at an angle (its own thickness).
DenseSpectrum spectrum_of(const FilmModel& film, double theta_rad) {
    DenseValues r;
    film.at_angle(theta_rad)->reflectance(film.thickness_nm(), r);
    return DenseSpectrum(r);
}

}  // namespace

MorphoAngleData morpho_angle_data(double step_deg, Brightness brightness, const Colorimeter& colorimeter,
                                  int exact_blend_samples) {
    const double cells = 90.0 / step_deg;
    if (!(step_deg > 0.0 && step_deg <= 45.0 && std::abs(cells - std::round(cells)) < 1e-9)) {
        throw Error("morpho-angle: step " + format_shortest(step_deg) + "° must divide 90 and lie in (0, 45]");
    }
    if (exact_blend_samples < 2 || exact_blend_samples > 1001) {
        throw Error("morpho-angle: exact blend samples " + std::to_string(exact_blend_samples) +
                    " must be in [2, 1001]");
    }
    MorphoAngleData d;
    d.brightness = brightness;
    d.wing.K = 2.0 / ((d.wing.periods + 1.0) * (d.wing.periods + 1.0));
    const auto n = static_cast<int>(std::round(cells));
    for (int j = 0; j < n; ++j) d.angle_deg.push_back((j + 0.5) * step_deg);

    MorphoRowData single{"thesis eq. 29", {}, {}, {}};
    MorphoRowData blended{"thesis eq. 29, blend", {}, {}, {}};
    MorphoRowData exact{"exact stack", {}, {}, {}};
    MorphoRowData exact_blended{"exact stack, blend", {}, {}, {}};

    // The exact blend: the same varied thickness and range as the thesis' blend.
    std::vector<ExactFilm> blend_stacks;
    for (int i = 0; i < exact_blend_samples; ++i) {
        MorphoParameters w = d.wing;
        const double v = d.blend.min_nm + (d.blend.max_nm - d.blend.min_nm) * i / (exact_blend_samples - 1.0);
        (d.blend.varies == MorphoBlendThickness::d1 ? w.d1_nm : w.d2_nm) = v;
        blend_stacks.push_back(morpho_exact_film(w));
    }
    const ExactFilm stack = morpho_exact_film(d.wing);
    const MorphoFilm thesis_wing(d.wing), thesis_blend(d.wing, d.blend);

    for (const double angle : d.angle_deg) {
        const double theta = angle * std::numbers::pi / 180.0;
        const DenseSpectrum a = spectrum_of(thesis_wing, theta);
        const DenseSpectrum b = spectrum_of(thesis_blend, theta);
        const DenseSpectrum c = spectrum_of(stack, theta);
        DenseSpectrum e(0.0);
        for (const ExactFilm& s : blend_stacks) e += spectrum_of(s, theta);
        e *= 1.0 / exact_blend_samples;
        const std::pair<MorphoRowData*, const DenseSpectrum*> pairs[] = {
            {&single, &a}, {&blended, &b}, {&exact, &c}, {&exact_blended, &e}};
        for (const auto& [row, spectrum] : pairs) {
            row->raw.push_back(colorimeter.xyz(*spectrum));
            row->peak_nm.push_back(dominant_peak_nm(*spectrum));
        }
    }
    for (MorphoRowData* row : {&single, &blended, &exact, &exact_blended}) {
        row->shown = row->raw;
        normalise_brightness(row->shown, brightness);
        d.rows.push_back(std::move(*row));
    }
    return d;
}

FigureResult draw_morpho_angle(const FigureRequest& request) {
    const Options options(request, {"brightness"});
    const std::string brightness_name = options.choice("brightness", {"strip", "off", "each"}, "strip");
    const Brightness brightness = parse_brightness(brightness_name);
    constexpr double step = 1.0;
    constexpr int exact_samples = 11;
    const Colorimeter colorimeter;  // D65, CIE 1931 2°, sRGB
    const MorphoAngleData d = morpho_angle_data(step, brightness, colorimeter, exact_samples);
    const GamutClipper clipper(ClipMethod::smits, Gamut(srgb()));

    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    const double s = canvas.scale();
    const Rect page = page_area(canvas);
    const Rect top{page.x, page.y, page.width, page.height * 0.45};
    const Rect bottom{page.x, page.y + page.height * 0.47, page.width, page.height * 0.53};
    const std::size_t rows = d.rows.size();

    // The strips.
    Axis sx{.min = 0.0, .max = 90.0, .title = "viewing angle θ (degrees, in air)"};
    sx.max_ticks = 9;
    Axis sy{.min = 0.0, .max = static_cast<double>(rows), .title = ""};
    sy.grid = false;
    for (std::size_t r = 0; r < rows; ++r) sy.ticks.push_back({static_cast<double>(rows - 1 - r) + 0.5, d.rows[r].label});
    Plot strips(canvas, top, sx, sy, "Morpho wing colour against viewing angle");
    constexpr double gap = 0.08;
    for (std::size_t r = 0; r < rows; ++r) {
        std::vector<Color> colors;
        for (const Xyz& c : d.rows[r].shown) colors.push_back(clipped_display_color(c, clipper));
        strips.color_strip(0.0, 90.0, static_cast<double>(rows - 1 - r) + gap, static_cast<double>(rows - r) - gap,
                           colors);
    }
    strips.finish(LegendPosition::none);

    // The peak wavelength: the same horizontal axis, so the plots line up only approximately (the
    // strip labels are wider); each has its own axis.
    Axis px{.min = 0.0, .max = 90.0, .title = "viewing angle θ (degrees, in air)"};
    px.max_ticks = 9;
    Axis py{.min = 380.0, .max = 780.0, .title = "reflectance peak λ (nm)"};
    Plot peaks(canvas, bottom, px, py, "Wavelength of the largest reflectance (while it is visible)");
    static constexpr Dash dashes[] = {Dash::solid, Dash::dashed, Dash::solid, Dash::dashed};
    for (std::size_t r = 0; r < rows; ++r) {
        peaks.line(d.angle_deg, d.rows[r].peak_nm,
                   {series_color(r < 2 ? 0 : 1), (r % 2 == 0 ? 2.2 : 1.6) * s, dashes[r]}, d.rows[r].label);
    }
    // The thesis' first-order peak, λ = 2 t_θ (eq. 25 peaks where sin(2π t_θ/λ) = 0).
    std::vector<double> first_order;
    for (const double angle : d.angle_deg) {
        const double lambda = 2.0 * morpho_effective_thickness_nm(d.wing, angle * std::numbers::pi / 180.0);
        first_order.push_back(lambda >= 380.0 && lambda <= 780.0 ? lambda : std::nan(""));
    }
    peaks.line(d.angle_deg, first_order, {palette::grey, 1.0 * s, Dash::dotted}, "2 t_θ (eq. 29, first order)");
    peaks.finish(LegendPosition::top_left);
    canvas.save(request.output);

    FigureResult result;
    const auto at = [&](double angle) {
        std::size_t best = 0;
        for (std::size_t j = 0; j < d.angle_deg.size(); ++j) {
            if (std::abs(d.angle_deg[j] - angle) < std::abs(d.angle_deg[best] - angle)) best = j;
        }
        return best;
    };
    for (std::size_t r = 0; r < rows; ++r) {
        std::string v;
        for (const double angle : {0.0, 30.0, 60.0}) {
            const std::size_t j = at(angle);
            const double peak = d.rows[r].peak_nm[j];
            v += (v.empty() ? "" : ", ") + (std::isnan(peak) ? std::string("outside 380–780 nm") : fixed(peak, 0) + " nm") +
                 " at " + shortest(d.angle_deg[j]) + "°";
        }
        result.measurements.emplace_back(d.rows[r].label + ": peak", v);
    }
    result.measurements.emplace_back("thesis K", fixed(d.wing.K, 5) + " = 2/(l + 1)², l = " + std::to_string(d.wing.periods));
    result.caption =
        "The Morpho wing against viewing angle θ in air, 0–90° (cells 1° wide, centred at 0.5°, 1.5°, ...). "
        "Strips, from the top: the thesis' wing (Smits 1990, eq. 29 with eq. 25: d₁ = 150 nm of air, "
        "d₂ = 50 nm of chitin n = 1.56, l = 12, K = 2/(l + 1)² so the peak is 1); its blend over d₁ = "
        "50–150 nm (101 samples, irid's reading of §3.7 that keeps the wing blue); the exact "
        "transfer-matrix stack of the same geometry (12 chitin layers of d₂, n = 1.56, separated by air "
        "gaps of d₁, in air of n = 1, unpolarised); and that stack blended over d₁ = 50–150 nm (" +
        std::to_string(exact_samples) +
        " samples). D65, CIE 1931 2°, brightness " +
        (brightness == Brightness::off ? std::string("as reflected")
         : brightness == Brightness::strip ? "scaled per strip so the brightest colour has Y = " + shortest(strip_peak_luminance)
                                           : "scaled to Y = " + shortest(each_luminance) + " everywhere") +
        ", gamut-clipped into sRGB by smits and encoded. Below: the wavelength of each spectrum's largest "
        "reflectance over 360–830 nm, drawn while it lies within 380–780 nm (beyond, the peak has moved "
        "into the ultraviolet), and the thesis' first-order peak 2 t_θ. "
        "Options: brightness=" + brightness_name + ".";
    return result;
}

}  // namespace irid::figures::detail
