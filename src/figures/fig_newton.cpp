// newton: Newton's colour scale, the colour of a film against its thickness, with and without the
// phase change of one reflection (Smits 1990, eq. 21 and eq. 22), by the thesis' model and by the
// exact optics, with the interference orders marked.

#include <irid/color/difference.h>
#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/optics/film.h>
#include <irid/optics/film_builder.h>
#include <irid/optics/material.h>

#include "figure_support.h"
#include "film_clip_data.h"
#include "plot.h"

#include <algorithm>
#include <memory>
#include <cmath>
#include <string>

namespace irid::figures::detail {

Brightness parse_brightness(std::string_view name) {
    if (name == "off") return Brightness::off;
    if (name == "strip") return Brightness::strip;
    if (name == "each") return Brightness::each;
    throw Error("brightness '" + std::string(name) + "' is unknown; valid: off, strip, each");
}

void normalise_brightness(std::vector<Xyz>& colors, Brightness brightness) noexcept {
    const auto scale = [](Xyz& c, double k) { c = {c.X * k, c.Y * k, c.Z * k}; };
    switch (brightness) {
        case Brightness::off: return;
        case Brightness::strip: {
            double top = 0.0;
            for (const Xyz& c : colors) top = std::max(top, c.Y);
            if (top <= 0.0) return;
            for (Xyz& c : colors) scale(c, strip_peak_luminance / top);
            return;
        }
        case Brightness::each:
            for (Xyz& c : colors) {
                if (c.Y < 1e-6) {
                    c = {};
                } else {
                    scale(c, each_luminance / c.Y);
                }
            }
            return;
    }
}

std::vector<double> order_boundaries_nm(double n, bool phase_change, double reference_nm, double max_thickness_nm) {
    if (!(n > 0.0 && reference_nm > 0.0 && std::isfinite(n) && std::isfinite(reference_nm) &&
          std::isfinite(max_thickness_nm))) {
        throw Error("order boundaries: need a finite index > 0 and a reference wavelength > 0");
    }
    std::vector<double> t;
    const double half_wave = reference_nm / (2.0 * n);  // the thickness of one order
    for (int m = 1;; ++m) {
        const double value = (phase_change ? m : m - 0.5) * half_wave;
        if (value > max_thickness_nm + 1e-9) break;
        t.push_back(value);
    }
    return t;
}

SingleFilm newton_film(bool phase_change) {
    const Material air = *find_material("air");
    const Material water = *find_material("water");
    if (phase_change) return {air, water, air};
    // n between the ambient's and the substrate's: both reflections shift by π, so the two beams
    // differ by none.
    return {air, water, Material::constant("substrate n=" + format_shortest(newton_substrate_n), newton_substrate_n)};
}

NewtonData newton_data(double max_thickness_nm, double step_nm, double reference_nm, bool k_matched,
                       Brightness brightness, const Colorimeter& colorimeter) {
    if (!(step_nm > 0.0 && max_thickness_nm > 0.0 && std::isfinite(max_thickness_nm) &&
          max_thickness_nm / step_nm <= 1e6)) {
        throw Error("newton: need 0 < step <= thickness with at most 1e6 steps");
    }
    NewtonData d;
    d.reference_nm = reference_nm;
    d.brightness = brightness;
    const auto count = static_cast<std::size_t>(std::floor(max_thickness_nm / step_nm + 1e-9)) + 1;
    for (std::size_t i = 0; i < count; ++i) d.thickness_nm.push_back(step_nm * static_cast<double>(i));

    const SingleFilm soap = newton_film(true);
    const SingleFilm no_shift = newton_film(false);

    const auto index_at = [&](const SingleFilm& f) { return f.film.index(reference_nm).real(); };
    const auto phase_of = [&](const SingleFilm& f) {
        return thesis_phase_change(f.ambient.index(reference_nm).real(), index_at(f),
                                   f.substrate.index(reference_nm).real());
    };
    d.k = k_matched ? thesis_matched_k(soap) : 1.0;
    struct Spec {
        std::string label;
        const SingleFilm* film;
        bool exact;
    };
    const Spec specs[] = {
        {"thesis eq. 21 (phase change)", &soap, false},
        {"exact: soap film in air", &soap, true},
        {"thesis eq. 22 (no phase change)", &no_shift, false},
        {"exact: water on n = 1.77", &no_shift, true},
    };
    for (const Spec& spec : specs) {
        NewtonStrip strip;
        strip.label = spec.label;
        strip.exact = spec.exact;
        strip.phase_change = phase_of(*spec.film);
        strip.n_at_reference = index_at(*spec.film);
        strip.boundaries_nm = order_boundaries_nm(strip.n_at_reference, strip.phase_change, reference_nm, max_thickness_nm);
        const double k = k_matched ? thesis_matched_k(*spec.film) : 1.0;
        // Through the film models (irid/optics/film.h), prepared once at normal incidence.
        FilmSpec film_spec = single_film_spec(spec.exact ? FilmModelKind::exact : FilmModelKind::thesis, *spec.film);
        if (!spec.exact) {
            film_spec.k = k;
            film_spec.phase_change = strip.phase_change;
        }
        const std::shared_ptr<FilmModel> model = build_film(film_spec);
        const std::unique_ptr<FilmAtAngle> row = model->at_angle(0.0);
        for (const double t : d.thickness_nm) strip.raw.push_back(row->color(t, colorimeter).xyz);
        strip.shown = strip.raw;
        normalise_brightness(strip.shown, brightness);
        d.strips.push_back(std::move(strip));
    }
    return d;
}

FigureResult draw_newton(const FigureRequest& request) {
    const Options options(request, {"brightness", "reference", "k"});
    const std::string brightness_name = options.choice("brightness", {"strip", "off", "each"}, "strip");
    const Brightness brightness = parse_brightness(brightness_name);
    const double reference = options.number("reference", 550.0, 380.0, 780.0);
    const std::string k_name = options.choice("k", {"matched", "1"}, "matched");
    constexpr double max_thickness = 1500.0, step = 1.0;
    const Colorimeter colorimeter;  // D65, CIE 1931 2°, sRGB
    const NewtonData d = newton_data(max_thickness, step, reference, k_name == "matched", brightness, colorimeter);
    const GamutClipper clipper(ClipMethod::smits, Gamut(srgb()));

    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    const double s = canvas.scale();
    const std::size_t rows = d.strips.size();
    // Strip r occupies y in [rows − 1 − r, rows − r] minus a gap; the first strip is on top.
    constexpr double gap = 0.12;
    Axis x{.min = 0.0, .max = max_thickness, .title = "film thickness t (nm)"};
    x.max_ticks = 15;
    Axis y{.min = 0.0, .max = static_cast<double>(rows), .title = ""};
    y.grid = false;
    for (std::size_t r = 0; r < rows; ++r) {
        y.ticks.push_back({static_cast<double>(rows - 1 - r) + 0.5, d.strips[r].label});
    }
    Plot plot(canvas, page_area(canvas), x, y,
              "Newton's colour scale: thin-film colour against thickness (normal incidence)");

    FigureResult result;
    std::size_t clipped = 0, total = 0;
    for (std::size_t r = 0; r < rows; ++r) {
        const NewtonStrip& strip = d.strips[r];
        std::vector<Color> colors;
        for (const Xyz& c : strip.shown) {
            colors.push_back(clipped_display_color(c, clipper));
            const Rgb lin = srgb().from_xyz(c);
            const double lo = -1e-9, hi = 1.0 + 1e-9;
            clipped += (lin.r < lo || lin.g < lo || lin.b < lo || lin.r > hi || lin.g > hi || lin.b > hi) ? 1 : 0;
            ++total;
        }
        const double y0 = static_cast<double>(rows - 1 - r) + gap, y1 = static_cast<double>(rows - r) - gap;
        const double half = 0.5 * (d.thickness_nm[1] - d.thickness_nm[0]);
        plot.color_strip(d.thickness_nm.front() - half, d.thickness_nm.back() + half, y0, y1, colors);
        // Order boundaries: ticks above and below the strip, order numbers between them.
        const LineStyle tick{palette::black, 1.6 * s, Dash::solid};
        double previous = 0.0;
        // With the phase change t = 0 is black and the first band is order 1; without it t = 0 is
        // bright, the zeroth order.
        int order = strip.phase_change ? 1 : 0;
        for (const double t : strip.boundaries_nm) {
            plot.line(std::vector<Point>{{t, y1}, {t, y1 + gap * 0.8}}, tick);
            plot.line(std::vector<Point>{{t, y0 - gap * 0.8}, {t, y0}}, tick);
            if (t - previous > 60.0) {
                plot.text({0.5 * (previous + t), y1 + 0.02}, std::to_string(order),
                          TextStyle{.size = 9.0 * s, .color = palette::dark_grey, .halign = HAlign::center,
                                    .valign = VAlign::bottom});
            }
            previous = t;
            ++order;
        }
        std::string b;
        for (std::size_t i = 0; i < strip.boundaries_nm.size(); ++i) {
            b += (i == 0 ? "" : ", ") + fixed(strip.boundaries_nm[i], 0);
        }
        result.measurements.emplace_back(strip.label + ": order boundaries (nm)",
                                         b + " (n = " + fixed(strip.n_at_reference, 4) + " at " + shortest(reference) + " nm)");
    }
    plot.finish(LegendPosition::none);
    canvas.save(request.output);

    // How far the thesis' strips are from the exact ones (ΔE2000 of the raw colours).
    for (std::size_t pair = 0; pair + 1 < rows; pair += 2) {
        double sum = 0.0, worst = 0.0;
        for (std::size_t i = 0; i < d.thickness_nm.size(); ++i) {
            const double de = delta_e_2000_of(colorimeter, d.strips[pair].raw[i], d.strips[pair + 1].raw[i]);
            sum += de;
            worst = std::max(worst, de);
        }
        result.measurements.emplace_back(d.strips[pair].label + " vs exact: ΔE2000 mean / max",
                                         fixed(sum / static_cast<double>(d.thickness_nm.size()), 2) + " / " + fixed(worst, 2));
    }
    result.measurements.emplace_back("colours outside sRGB before the clip",
                                     std::to_string(clipped) + " of " + std::to_string(total));

    const std::string brightness_text =
        brightness == Brightness::off ? "as reflected (a white reflector at Y = 1)"
        : brightness == Brightness::strip
            ? "each strip scaled by one factor so that its brightest colour has Y = " + shortest(strip_peak_luminance)
            : "every colour scaled to Y = " + shortest(each_luminance) + " (hue and saturation only)";
    result.caption =
        "Newton's colour scale: the reflected colour of a film at normal incidence against its thickness "
        "0–1500 nm (every 1 nm). From the top: the thesis' single film with the phase change of one "
        "reflection (Smits 1990, eq. 21) and the exact soap film in air (air | water | air: Airy sum, "
        "Fresnel amplitudes, dispersion); the thesis' film without a phase change (eq. 22) and an exact "
        "film without one: water on a substrate of index 1.77, so the film's index lies between the "
        "ambient's and the substrate's and both reflections shift by π. Thesis K = " +
        (k_name == "matched" ? "|r01| + |r12| of each film (matched to the exact peak)" : std::string("1")) +
        ". D65, CIE 1931 2°; brightness " + brightness_text +
        "; colours gamut-clipped into sRGB by smits (constant luminance, Smits 1990 §4.3) and encoded. "
        "Ticks mark the order boundaries, where the reference wavelength " + shortest(reference) +
        " nm is extinguished: t = m λ/(2n) with the phase change, (m − ½) λ/(2n) without (n of water at λ); "
        "the numbers are the orders, from 1 with the phase change (t = 0 is black) and from 0 without "
        "(t = 0 is bright). Options: brightness=" + brightness_name + ", reference=" +
        shortest(reference) + ", k=" + k_name + ".";
    return result;
}

}  // namespace irid::figures::detail
