// renderer-films: ΔE2000 maps (thickness × angle) of the thesis' single film and the renderers'
// thin-film models (glTF KHR_materials_iridescence, Belcour & Barla 2017, Blender Cycles) against
// the exact Airy film, side by side on one colour scale (what irid film-error --model summarises).

#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/optics/renderer_films.h>

#include "figure_support.h"
#include "plot.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace irid::figures::detail {

FigureResult draw_renderer_films(const FigureRequest& request) {
    const Options options(request, {"metal"});
    const std::string metal = options.choice("metal", {"gold", "silver", "none"}, "gold");

    const Material air = *find_material("air");
    struct Row {
        std::string label;
        SingleFilm film;
    };
    std::vector<Row> rows{{"soap 1.33 in air", {air, Material::constant("soap", 1.33), air}}};
    if (metal != "none") {
        rows.push_back({"1.5 on " + metal,
                        {air, Material::constant("film", 1.5), *find_material(metal)}});
    }
    // The columns: the thesis' model, the three renderers', and irid's Fourier film colour.
    enum class Column { thesis, gltf, belcour, cycles, fourier };
    const std::vector<Column> models{Column::thesis, Column::gltf, Column::belcour, Column::cycles,
                                     Column::fourier};
    const std::vector<std::string> titles{"thesis", "glTF", "Belcour–Barla", "Cycles", "irid Fourier"};
    const auto renderer_of = [](Column c) {
        return c == Column::gltf ? RendererFilmModel::gltf
                                 : (c == Column::belcour ? RendererFilmModel::belcour : RendererFilmModel::cycles);
    };
    const std::vector<std::string> keys{"thesis", "gltf", "belcour", "cycles", "fourier"};

    ErrorStudyOptions grid;
    grid.max_thickness_nm = 2000.0;
    grid.thickness_step_nm = 10.0;
    grid.max_angle_deg = 85.0;
    grid.angle_step_deg = 1.0;
    // One fixed scale for every map: ΔE2000 0–20 (larger values saturate, and are counted).
    constexpr double top = 20.0;

    Canvas canvas(image_format_for(request.output), request.width_px, request.height_px);
    const double s = canvas.scale();
    const Rect page = page_area(canvas);
    const double bar_width = 80.0 * s;
    const double cell_w = (page.width - bar_width) / static_cast<double>(models.size());
    const double cell_h = page.height / static_cast<double>(rows.size());
    PlotOptions plot_options;
    plot_options.font_size = 9.0 * s;

    FigureResult result;
    Rect last_frame{};
    for (std::size_t r = 0; r < rows.size(); ++r) {
        for (std::size_t m = 0; m < models.size(); ++m) {
            const Rect area{page.x + cell_w * static_cast<double>(m), page.y + cell_h * static_cast<double>(r),
                            cell_w, cell_h};
            Axis x{.min = 0.0, .max = grid.max_thickness_nm, .title = "thickness (nm)"};
            // The film names its row on the first column's axis; the model titles each map.
            Axis y{.min = 0.0, .max = grid.max_angle_deg, .title = m == 0 ? rows[r].label + ": angle (degrees)" : ""};
            x.grid = false;
            y.grid = false;
            x.max_ticks = 4;
            y.max_ticks = 5;
            Plot plot(canvas, area, x, y, titles[m], plot_options);
            std::string key = keys[m];
            key += ", ";
            key += rows[r].label;
            const bool metal_row = !rows[r].film.substrate.is_lossless();
            if (models[m] == Column::thesis && metal_row) {
                plot.text({0.5 * grid.max_thickness_nm, 0.5 * grid.max_angle_deg},
                          "n/a (the metal absorbs)",
                          {.size = 9.0 * s, .halign = HAlign::center, .valign = VAlign::middle});
                plot.finish(LegendPosition::none);
                result.measurements.push_back({key, "n/a"});
                continue;
            }
            const FilmErrorMap map =
                models[m] == Column::thesis    ? thesis_film_error_map(rows[r].film, grid)
                : models[m] == Column::fourier ? fourier_film_error_map(rows[r].film, grid)
                                               : renderer_film_error_map(renderer_of(models[m]), rows[r].film, grid);
            std::vector<Color> cells;
            cells.reserve(map.delta_e.size());
            for (const double d : map.delta_e) cells.push_back(sequential_color(std::min(d / top, 1.0)));
            plot.raster(-0.5 * grid.thickness_step_nm, grid.max_thickness_nm + 0.5 * grid.thickness_step_nm,
                        -0.5 * grid.angle_step_deg, grid.max_angle_deg + 0.5 * grid.angle_step_deg,
                        static_cast<int>(map.thickness_count), static_cast<int>(map.angle_count), cells);
            if (models[m] == Column::fourier && metal_row) {
                // FourierFilm::uses_sum: the metal's tabulated index is summed at 1 nm.
                plot.text({0.5 * grid.max_thickness_nm, 0.5 * grid.max_angle_deg}, "summed at 1 nm (metal table)",
                          {.size = 8.0 * s, .color = Color{0.85, 0.85, 0.85}, .halign = HAlign::center,
                           .valign = VAlign::middle});
            }
            plot.finish(LegendPosition::none);
            last_frame = plot.frame();
            const FilmErrorRegions e = summarize_film_error(key, map);
            result.measurements.push_back(
                {key, "mean " + fixed(e.summary.mean, 2) + ", median " + fixed(e.summary.median, 2) + ", p95 " +
                          fixed(e.summary.p95, 2) + ", max " + fixed(e.summary.max, 1) + " (" +
                          fixed(100.0 * e.above_5, 1) + " % above 5)"});
        }
    }
    draw_color_bar(canvas, {page.right() - bar_width + 24.0 * s, page.y + 30.0 * s, 16.0 * s, last_frame.height},
                   0.0, top, "ΔE2000", [](double t) { return sequential_color(t); });
    canvas.save(request.output);
    result.caption =
        "CIEDE2000 between each model's colour and the exact Airy film (Fresnel amplitudes of both "
        "faces, all internal reflections, unpolarised, the 1 nm sum under D65 with CIE 1931 2°), over "
        "film thickness 0–2000 nm every 10 nm and angle of incidence 0–85° every 1°, on one scale "
        "(0–20; larger values show as the top colour). The renderers' RGB is read as a linear "
        "Rec.709 reflectance (white = D65). Thesis: eq. 21/22 with eq. 24, K matched at normal "
        "incidence. glTF: Schlick faces, phases 0/π, m ≤ 2, Gaussian CMF fits. Belcour & Barla: "
        "exact Fresnel, m ≤ 3, the same fits. Cycles: exact Fresnel, m ≤ 3, the FFT table of the "
        "CIE 1931 functions. Metals take one n + ik per RGB channel (at the Rec.709 primaries' "
        "dominant wavelengths); glTF takes the metal's exact F0 colour. irid Fourier: the exact Airy "
        "series summed to convergence against the transform of the tabulated CIE functions "
        "(irid/optics/fourier_film.h; a metal's table is summed at 1 nm). Options: metal=" + metal + ".";
    return result;
}

}  // namespace irid::figures::detail
