// The reflectance spectra of single thin films (soap films, oil on water, ...) by the exact
// Airy model and by the thesis' closed form (Smits 1990, eq. 21/22 with eq. 24), with the
// colour each spectrum gives.

#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/optics/film_builder.h>
#include <irid/optics/film_color.h>
#include <irid/optics/material.h>

#include "figure_data.h"
#include "figure_support.h"
#include "plot.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace irid::figures::detail {

FilmSpec parse_film_spec(std::string_view item) {
    const std::size_t at = item.find('@');
    const std::string_view number = item.substr(0, at);
    FilmSpec spec;
    const char* first = number.data();
    const char* last = number.data() + number.size();
    const auto [end, ec] = std::from_chars(first, last, spec.thickness_nm);
    if (number.empty() || ec != std::errc() || end != last || !std::isfinite(spec.thickness_nm) ||
        spec.thickness_nm < 0.0 || spec.thickness_nm > 10000.0) {
        throw Error("film \"" + std::string(item) +
                    "\": the thickness must be a number of nm in [0, 10000]");
    }
    if (at != std::string_view::npos) {
        spec.material = std::string(item.substr(at + 1));
        if (spec.material.empty()) {
            throw Error("film \"" + std::string(item) + "\": a material name must follow '@'");
        }
    }
    return spec;
}

DenseValues film_reflectance(const SingleFilm& film, double thickness_nm, double angle_rad,
                             bool thesis, double k) {
    // Through the film models every command uses: the thesis' eq. 21/22 or the exact Airy film.
    irid::FilmSpec spec = single_film_spec(thesis ? FilmModelKind::thesis : FilmModelKind::exact, film, thickness_nm);
    if (thesis) spec.k = k;
    const std::shared_ptr<FilmModel> model = build_film(spec);
    DenseValues r;
    model->at_angle(angle_rad)->reflectance(thickness_nm, r);
    return r;
}

Series film_reflectance_series(const SingleFilm& film, double thickness_nm, double angle_rad,
                               bool thesis, double k, double lo_nm, double hi_nm) {
    const DenseValues r = film_reflectance(film, thickness_nm, angle_rad, thesis, k);
    Series s;
    for (int i = 0; i < dense_sample_count; ++i) {
        const double nm = DenseSpectrum::wavelength_nm(i);
        if (nm < lo_nm || nm > hi_nm) continue;
        s.x.push_back(nm);
        s.y.push_back(r[i]);
    }
    return s;
}

namespace {

std::string hex_color(const Color& c) {
    std::array<char, 8> buffer{};
    const auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
    std::snprintf(buffer.data(), buffer.size(), "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    return buffer.data();
}

}  // namespace

FigureResult draw_film_spectra(const FigureRequest& request) {
    const Options options(request, {"films", "film", "substrate", "ambient", "angle", "model"});
    const std::string material_allowed =
        "a material name (" + join(material_names(), ", ") + ") or an index n or n+ki";
    const auto material = [&](std::string_view key, const std::string& text) {
        try {
            return parse_material(text);
        } catch (const Error&) {
            options.fail(key, text, "unknown material", material_allowed);
        }
    };
    const std::string film_name = options.text("film", "soap-film");
    const Material film_material = material("film", film_name);
    const std::string substrate_name = options.text("substrate", "air");
    const Material substrate = material("substrate", substrate_name);
    const std::string ambient_name = options.text("ambient", "air");
    const Material ambient = material("ambient", ambient_name);
    if (!ambient.is_lossless()) {
        options.fail("ambient", ambient_name, "the ambient must not absorb", "a lossless medium (k = 0)");
    }
    const double angle_deg = options.number("angle", 0.0, 0.0, 89.0);
    const std::string model = options.choice("model", {"exact", "thesis", "both"}, "exact");

    const std::string films_text = options.text("films", "100,300,500,1000");
    std::vector<FilmSpec> specs;
    std::vector<SingleFilm> films;
    for (const std::string& item : options.list("films", "100,300,500,1000")) {
        FilmSpec spec;
        try {
            spec = parse_film_spec(item);
        } catch (const Error& e) {
            options.fail("films", films_text, e.what(),
                         "a comma-separated list of thickness_nm[@material], thickness in "
                         "[0, 10000], material " + material_allowed);
        }
        Material m = film_material;
        if (!spec.material.empty()) {
            try {
                m = parse_material(spec.material);
            } catch (const Error&) {
                options.fail("films", films_text,
                             "unknown material \"" + spec.material + "\" in \"" + item + "\"",
                             material_allowed);
            }
        }
        films.push_back({ambient, m, substrate});
        specs.push_back(std::move(spec));
    }
    if (specs.size() > 8) {
        options.fail("films", films_text, "too many films", "at most 8 films");
    }

    const double angle_rad = angle_deg * std::numbers::pi / 180.0;
    const Colorimeter colorimeter;  // D65, CIE 1931, sRGB
    const GamutClipper clipper(ClipMethod::smits, Gamut(srgb()));
    constexpr double lo_nm = 380.0, hi_nm = 780.0;

    struct Curve {
        Series series;
        Color color;
        bool thesis;
        Xyz xyz;   // the spectrum's colour under D65, white Y = 1
        double k;  // the thesis model's K (1 for the exact model)
    };
    std::vector<Curve> curves;
    std::vector<std::pair<std::string, Color>> swatches;
    FigureResult result;
    const bool mixed = std::any_of(specs.begin(), specs.end(),
                                   [](const FilmSpec& f) { return !f.material.empty(); });
    for (std::size_t k = 0; k < specs.size(); ++k) {
        const SingleFilm& film = films[k];
        const std::string name = shortest(specs[k].thickness_nm) + " nm" +
                                 (mixed ? " " + film.film.name() : std::string());
        const Color line_color = series_color(k);
        for (const bool thesis : {false, true}) {
            if (thesis && model == "exact") continue;
            if (!thesis && model == "thesis") continue;
            const double k_used = thesis ? thesis_matched_k(film) : 1.0;
            Series s = film_reflectance_series(film, specs[k].thickness_nm, angle_rad, thesis,
                                               k_used, lo_nm, hi_nm);
            s.label = name + (model == "both" ? (thesis ? " thesis" : " exact") : "");
            // The colour integrates the whole 360–830 nm spectrum, not only the plotted part.
            const DenseValues r = film_reflectance(film, specs[k].thickness_nm, angle_rad, thesis, k_used);
            const Xyz xyz = colorimeter.xyz_of([&](double nm) {
                return r[static_cast<std::size_t>(std::lround(nm)) - lambda_min_nm];
            });
            curves.push_back({std::move(s), line_color, thesis, xyz, k_used});
        }
    }
    // The swatches are shown brighter by one common factor, the reciprocal of the largest
    // reflectance plotted (a film reflects only a few percent: at its own level every colour
    // would be a dark grey), so they compare with each other as the spectra do.
    double top = 0.0;
    for (const Curve& c : curves) top = std::max(top, series_peak(c.series).y);
    const double exposure = top > 0.0 ? 1.0 / top : 1.0;
    for (const Curve& c : curves) {
        const Xyz bright{c.xyz.X * exposure, c.xyz.Y * exposure, c.xyz.Z * exposure};
        const Color shown = display_color(clipper.clip(colorimeter.linear_rgb(bright)));
        const Peak peak = series_peak(c.series);
        result.measurements.emplace_back(
            c.series.label, "Y = " + fixed(c.xyz.Y, 4) + ", x, y = " +
                                fixed(xyz_to_xy(c.xyz).x, 4) + ", " + fixed(xyz_to_xy(c.xyz).y, 4) +
                                ", swatch " + hex_color(shown) + "; R max " + fixed(peak.y, 4) +
                                " at " + fixed(peak.x, 0) + " nm" +
                                (c.thesis ? ", K = " + fixed(c.k, 4) : std::string()));
        swatches.emplace_back(c.series.label, shown);
    }

    std::vector<std::string> legend_labels;
    for (const Curve& c : curves) legend_labels.push_back(c.series.label);
    for (const auto& sw : swatches) legend_labels.push_back("colour, " + sw.first);
    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    const double sc = canvas.scale();
    Plot plot(canvas, page_area(canvas), {.min = lo_nm, .max = hi_nm, .title = "wavelength λ (nm)"},
              {.min = 0.0, .max = nice_range(0.0, std::max(top, 1e-3) * 1.05, 8).second,
               .title = "reflectance R"},
              "Reflectance of single films: " +
                  (mixed ? std::string("films") : film_material.name()) +
                  (substrate.name() == ambient.name() ? " in " + ambient.name()
                                                      : " on " + substrate.name() + " in " +
                                                            ambient.name()) +
                  ", " + shortest(angle_deg) + "° incidence",
              {.right_reserve = Plot::outside_legend_width(canvas, legend_labels)});
    for (const Curve& c : curves) {
        plot.line(c.series.x, c.series.y,
                  {c.color, 2.0 * sc, c.thesis ? Dash::dashed : Dash::solid}, c.series.label);
    }
    for (const auto& [label, color] : swatches) plot.add_legend_swatch("colour, " + label, color);
    plot.finish(LegendPosition::outside_right);
    canvas.save(request.output);

    std::string thickness_list;
    for (const FilmSpec& f : specs) {
        // Appended piece by piece: "@" + string here trips g++ 12's false -Wrestrict.
        if (!thickness_list.empty()) thickness_list += ',';
        thickness_list += shortest(f.thickness_nm);
        if (!f.material.empty()) {
            thickness_list += '@';
            thickness_list += f.material;
        }
    }
    result.caption =
        "Reflectance spectra of single films of " + film_material.name() + " (thicknesses " +
        thickness_list + " nm) between " + ambient.name() + " and " + substrate.name() + " at " +
        shortest(angle_deg) + "° incidence, unpolarised, " +
        (model == "exact" ? std::string("by the exact Airy model (all internal reflections, "
                                        "Fresnel amplitudes, dispersion)")
         : model == "thesis"
             ? std::string("by the thesis' closed form (Smits 1990, eq. 21/22 with the effective "
                           "thickness of eq. 24; K = |r01| + |r12| at 555 nm)")
             : std::string("by the exact Airy model (solid) and the thesis' closed form "
                           "(dashed; Smits 1990, eq. 21/22 with eq. 24, K = |r01| + |r12| at "
                           "555 nm)")) +
        ". The swatches are the colours of the spectra under D65 (CIE 1931 observer), made "
        "brighter by a common factor of " + fixed(exposure, 1) +
        " (the reciprocal of the largest reflectance shown) and clipped into sRGB by the smits "
        "method. Options: films=" + thickness_list + ", film=" +
        film_name + ", substrate=" + substrate_name + ", ambient=" + ambient_name +
        ", angle=" + shortest(angle_deg) + ", model=" + model + ".";
    return result;
}

}  // namespace irid::figures::detail
