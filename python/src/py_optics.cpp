// Optics for Python: materials, the film models (irid/optics/film.h) with their spectra and
// colours over arrays of thicknesses and angles, the thesis' closed forms (eq. 19–29) as numpy
// ufunc-like functions, and the colour tables with their lookups.

#include "arrays.h"

#include <irid/color.h>
#include <irid/io/output_file.h>
#include <irid/optics/film.h>
#include <irid/optics/film_builder.h>
#include <irid/optics/film_color.h>
#include <irid/optics/film_shader.h>
#include <irid/optics/fourier_film.h>
#include <irid/optics/material.h>
#include <irid/optics/renderer_films.h>
#include <irid/optics/thesis_models.h>

#include <pybind11/complex.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <filesystem>
#include <cctype>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace irid::python {
namespace {

using FilmPtr = std::shared_ptr<FilmModel>;

/// A Python int as the number of periods: one outside C's int is out of the thesis' range too.
int periods_of(const py::int_& value) {
    long long periods = thesis_max_periods + 1LL;
    try {
        periods = value.cast<long long>();
    } catch (const py::cast_error&) {
        // Beyond 64 bits: out of range all the same.
    }
    if (periods < thesis_min_periods || periods > thesis_max_periods) {
        throw Error("periods " + py::repr(value).cast<std::string>() + " must be in " +
                    std::to_string(thesis_min_periods) + ".." + std::to_string(thesis_max_periods) +
                    " (l, the number of films of eq. 25)");
    }
    return static_cast<int>(periods);
}

Colorimeter colorimeter_of(const std::string& illuminant, const std::string& observer, const std::string& rgb) {
    const RgbSpace* space = find_rgb_space(rgb);
    if (space == nullptr) {
        throw UnknownNameError("rgb '" + rgb + "' is unknown; valid: srgb, display-p3, rec2020, adobe-rgb, smpte-c, ntsc1953",
                               {"srgb", "display-p3", "rec2020", "adobe-rgb", "smpte-c", "ntsc1953"});
    }
    return Colorimeter(illuminant_by_name(illuminant), parse_observer(observer), *space);
}

std::vector<double> doubles(const py::handle& value, const char* what) {
    const auto a = contiguous_of<double>(value, what);
    return {a.data(), a.data() + a.size()};
}

void check_finite(const std::vector<double>& v, const char* what, double lo, double hi, bool hi_open) {
    for (std::size_t i = 0; i < v.size(); ++i) {
        const double x = v[i];
        if (!(std::isfinite(x) && x >= lo && (hi_open ? x < hi : x <= hi))) {
            throw Error(std::string(what) + "[" + std::to_string(i) + "] = " + format_shortest(x) +
                        " must be finite and in [" + format_shortest(lo) + ", " + format_shortest(hi) +
                        (hi_open ? ")" : "]"));
        }
    }
}

/// Colours of a film at n (thickness, angle) pairs, prepared once per run of equal angles: the
/// pairs are visited in the order of their angles, in blocks on every core.
void film_colors(const FilmModel& film, const Colorimeter& colorimeter, const std::vector<double>& t,
                 const std::vector<double>& angle_rad, double* xyz, double* rgb) {
    const std::size_t n = t.size();
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return angle_rad[a] < angle_rad[b]; });
    constexpr std::size_t block = 256;
    tbb::parallel_for(std::size_t{0}, (n + block - 1) / block, [&](std::size_t k) {
        std::unique_ptr<FilmAtAngle> row;
        double row_angle = -1.0;
        for (std::size_t j = k * block; j < std::min(n, (k + 1) * block); ++j) {
            const std::size_t i = order[j];
            if (!row || angle_rad[i] != row_angle) {
                row = film.at_angle(angle_rad[i]);
                row_angle = angle_rad[i];
            }
            const FilmColor c = row->color(t[i], colorimeter);
            xyz[3 * i] = c.xyz.X, xyz[3 * i + 1] = c.xyz.Y, xyz[3 * i + 2] = c.xyz.Z;
            rgb[3 * i] = c.rgb_linear.r, rgb[3 * i + 1] = c.rgb_linear.g, rgb[3 * i + 2] = c.rgb_linear.b;
        }
    });
}

/// The same colours by the Fourier series (irid/optics/fourier_film.h) of an exact single film.
void fourier_film_colors(const SingleFilm& single, const Colorimeter& colorimeter, const std::vector<double>& t,
                         const std::vector<double>& angle_rad, double* xyz, double* rgb) {
    const FourierFilm fourier(single, fourier_colorimeter_for(single, colorimeter));
    tbb::parallel_for(std::size_t{0}, t.size(), [&](std::size_t i) {
        const FilmColor c = fourier.color(t[i], std::cos(angle_rad[i]));
        xyz[3 * i] = c.xyz.X, xyz[3 * i + 1] = c.xyz.Y, xyz[3 * i + 2] = c.xyz.Z;
        rgb[3 * i] = c.rgb_linear.r, rgb[3 * i + 1] = c.rgb_linear.g, rgb[3 * i + 2] = c.rgb_linear.b;
    });
}

py::array_t<double> triples(std::size_t n) {
    return py::array_t<double>(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), 3});
}

void put(double* p, const Xyz& c) { p[0] = c.X, p[1] = c.Y, p[2] = c.Z; }
void put(double* p, const Rgb& c) { p[0] = c.r, p[1] = c.g, p[2] = c.b; }

Polarization parse_polarization(const std::string& name) {
    if (name == "s") return Polarization::s;
    if (name == "p") return Polarization::p;
    if (name == "unpolarized") return Polarization::unpolarized;
    throw UnknownNameError("polarization '" + name + "' is unknown; valid: s, p, unpolarized",
                           {"s", "p", "unpolarized"});
}

/// A thesis kernel's scalar argument checked per element (the kernels are noexcept and assume
/// valid values).
void need(bool ok, const char* what, double value, const char* allowed) {
    if (!ok) throw Error(std::string(what) + " " + format_shortest(value) + " must be " + allowed);
}

}  // namespace

void add_optics(py::module_& m) {
    // --- Materials -----------------------------------------------------------------------
    py::class_<Material>(m, "Material", "An optical material: its complex index N = n + ik over wavelength.")
        .def(py::init([](const std::string& text) { return parse_material(text); }), py::arg("text"),
             "A material by name ('water', 'silver', ...), a constant index ('1.33') or a complex one "
             "('1.5+0.02i', k >= 0 absorbing).")
        .def_static("constant", &Material::constant, py::arg("name"), py::arg("n"), py::arg("k") = 0.0,
                    "A wavelength-independent index n + ik (n > 0, k >= 0 absorbing).")
        .def_static("cauchy", &Material::cauchy, py::arg("name"), py::arg("a"), py::arg("b_um2"),
                    py::arg("c_um4") = 0.0,
                    "Cauchy's n(λ) = A + B/λ² + C/λ⁴, λ in µm, k = 0 (n > 0 over 360-830 nm).")
        .def_static(
            "sellmeier",
            [](std::string name, const std::vector<std::pair<double, double>>& terms) {
                std::vector<SellmeierTerm> t;
                for (const auto& [b, c] : terms) t.push_back({b, c});
                return Material::sellmeier(std::move(name), std::move(t));
            },
            py::arg("name"), py::arg("terms"),
            "Sellmeier's n²(λ) = 1 + Σ B λ²/(λ² − C), λ in µm: terms [(B, C µm²), ...], poles outside "
            "360-830 nm.")
        .def_static(
            "read_csv",
            [](const std::string& path, const std::string& name) {
                try {
                    return Material::read_csv(path, name);
                } catch (const Error& e) {
                    // "<path>:<line>: ..." is a bad line (ValueError); anything else about the
                    // file (missing, unreadable, not a regular file) is an OSError.
                    const std::string what = e.what();
                    const bool line = what.size() > path.size() + 1 && what.compare(0, path.size(), path) == 0 &&
                                      what[path.size()] == ':' &&
                                      std::isdigit(static_cast<unsigned char>(what[path.size() + 1]));
                    if (line) throw;
                    throw FileError(what);
                }
            },
            py::arg("path"), py::arg("name") = "",
            "Measured n, k from CSV lines wavelength_nm,n,k (a header line is skipped), linear between "
            "samples; named after the file unless a name is given. OSError for a file that cannot be "
            "read, ValueError naming the line for a bad one.")
        .def_property_readonly("name", &Material::name, "The material's name.")
        .def_property_readonly("is_lossless", &Material::is_lossless, "Whether k = 0 at every wavelength.")
        .def(
            "index",
            [](const Material& mat, const py::handle& wavelengths) {
                const auto w = contiguous_of<double>(wavelengths, "wavelengths");
                std::vector<py::ssize_t> shape(w.shape(), w.shape() + w.ndim());
                py::array_t<std::complex<double>> out(shape);
                const double* src = w.data();
                std::complex<double>* dst = out.mutable_data();
                for (py::ssize_t i = 0; i < w.size(); ++i) {
                    if (!(std::isfinite(src[i]) && src[i] > 0.0)) {
                        throw Error("wavelengths[" + std::to_string(i) + "] = " + format_shortest(src[i]) +
                                    " must be finite and > 0 nm");
                    }
                    dst[i] = mat.index(src[i]);
                }
                return out;
            },
            py::arg("wavelengths"), "The complex index N = n + ik at each wavelength [nm], an array of their shape.")
        .def("__repr__", [](const Material& mat) { return "irid.Material('" + mat.name() + "')"; });
    m.def("material_names", &material_names, "The named materials.");

    // --- Films -----------------------------------------------------------------------------
    py::class_<FilmModel, FilmPtr>(m, "FilmModel")
        .def_property_readonly("model", [](const FilmModel& f) { return std::string(f.name()); })
        .def_property_readonly("has_transmittance", &FilmModel::has_transmittance)
        .def_property_readonly("has_thickness", &FilmModel::has_thickness)
        .def_property_readonly("thickness", &FilmModel::thickness_nm)
        .def(
            "spectrum",
            [](const FilmModel& f, const py::handle& wavelengths, double angle_rad, std::optional<double> thickness) {
                const auto w = contiguous_of<double>(wavelengths, "wavelengths");
                std::vector<py::ssize_t> shape(w.shape(), w.shape() + w.ndim());
                const std::vector<double> lambdas(w.data(), w.data() + w.size());
                check_finite(lambdas, "wavelengths", 1.0, 1e6, false);
                f.check_work({{"wavelengths", static_cast<double>(lambdas.size())}}, true,
                             {"layers", "blend"});
                const auto at = f.spectrum(angle_rad, thickness);
                py::array_t<double> r(shape), t(shape);
                double* rp = r.mutable_data();
                double* tp = t.mutable_data();
                {
                    py::gil_scoped_release release;
                    tbb::parallel_for(std::size_t{0}, lambdas.size(), [&](std::size_t i) {
                        const Optics o = at(lambdas[i]);
                        rp[i] = o.R;
                        tp[i] = o.T;
                    });
                }
                return py::make_tuple(r, t);
            },
            py::arg("wavelengths"), py::arg("angle_rad"), py::arg("thickness") = py::none())
        .def(
            "colors",
            [](const FilmModel& f, const py::handle& thickness, const py::handle& angle_rad,
               const std::string& illuminant, const std::string& observer, const std::string& rgb,
               const std::string& integration) {
                // The film the Fourier series needs, checked before any work: the exact single
                // film only.
                std::optional<SingleFilm> single;
                if (parse_film_integration(integration) == FilmIntegration::fourier) {
                    try {
                        single = fourier_single_film(f);
                    } catch (const Error& e) {
                        throw Error(std::string("integration 'fourier': ") + e.what() + "; use 'sum'");
                    }
                }
                const std::vector<double> t = doubles(thickness, "thickness");
                const std::vector<double> a = doubles(angle_rad, "angle");
                if (t.size() != a.size()) throw Error("thickness and angle: sizes differ");
                check_finite(t, "thickness", 0.0, 1e6, false);
                for (std::size_t i = 0; i < a.size(); ++i) check_incidence_angle(a[i]);
                const Colorimeter c = colorimeter_of(illuminant, observer, rgb);
                f.check_work({{"thickness × angle", static_cast<double>(t.size()), "colours"}}, false,
                             {"layers", "blend"});
                py::array_t<double> xyz = triples(t.size()), out_rgb = triples(t.size());
                double* xp = xyz.mutable_data();
                double* rp = out_rgb.mutable_data();
                {
                    py::gil_scoped_release release;
                    if (single) fourier_film_colors(*single, c, t, a, xp, rp);
                    else film_colors(f, c, t, a, xp, rp);
                }
                return py::make_tuple(xyz, out_rgb);
            },
            py::arg("thickness"), py::arg("angle_rad"), py::arg("illuminant"), py::arg("observer"),
            py::arg("rgb"), py::arg("integration") = "sum")
        .def("effective_thickness", &FilmModel::effective_thickness_nm, py::arg("angle_rad"));

    // --- The film colour as a shader chunk and its table (irid shader) --------------------
    m.def(
        "write_film_shader",
        [](const std::filesystem::path& dir, const std::string& lang, const std::string& illuminant,
           const std::string& space) {
            const ShaderLanguage language = parse_shader_language(lang);
            const FilmShaderSetup setup = film_shader_setup(illuminant, space);
            std::vector<std::string> paths;
            py::gil_scoped_release release;
            const FilmShader shader(setup.colorimeter, setup.illuminant, setup.space);
            try {
                for (const auto& p : io::write_output_files(dir, shader.files(language))) paths.push_back(p.string());
            } catch (const Error& e) {
                throw FileError(e.what());
            }
            return paths;
        },
        py::arg("dir"), py::arg("lang"), py::arg("illuminant"), py::arg("space"));

    // --- The renderers' thin-film models (colour only) ------------------------------------
    m.def("renderer_film_models", &renderer_film_model_names,
          "The renderers' thin-film models: gltf, belcour, cycles.");
    m.def(
        "renderer_film_colors",
        [](const std::string& model, const Material& ambient, const Material& film, const Material& substrate,
           const py::handle& thickness, const py::handle& angle_rad) {
            const RendererFilmModel kind = parse_renderer_film_model(model);
            const std::vector<double> t = doubles(thickness, "thickness");
            const std::vector<double> a = doubles(angle_rad, "angle");
            if (t.size() != a.size()) throw Error("thickness and angle: sizes differ");
            check_finite(t, "thickness", 0.0, 1e6, false);
            for (const double v : a) check_incidence_angle(v);
            const RendererFilmInputs inputs = renderer_film_inputs({ambient, film, substrate});
            py::array_t<double> xyz = triples(t.size()), out_rgb = triples(t.size());
            double* xp = xyz.mutable_data();
            double* rp = out_rgb.mutable_data();
            {
                py::gil_scoped_release release;
                tbb::parallel_for(std::size_t{0}, t.size(), [&](std::size_t i) {
                    const FilmColor c = renderer_film_color(kind, inputs, t[i], a[i]);
                    xp[3 * i] = c.xyz.X, xp[3 * i + 1] = c.xyz.Y, xp[3 * i + 2] = c.xyz.Z;
                    rp[3 * i] = c.rgb_linear.r, rp[3 * i + 1] = c.rgb_linear.g, rp[3 * i + 2] = c.rgb_linear.b;
                });
            }
            return py::make_tuple(xyz, out_rgb);
        },
        py::arg("model"), py::arg("ambient"), py::arg("film"), py::arg("substrate"), py::arg("thickness"),
        py::arg("angle_rad"));

    // The films: each class method of irid.Film fills a FilmSpec and builds through the library
    // (film_builder.h), which holds the rules; the names are Python's keywords.
    m.def(
        "film_exact",
        [](const Material& ambient, const std::vector<std::pair<Material, double>>& layers,
           const Material& substrate, const std::string& polarization) -> FilmPtr {
            FilmSpec spec;
            spec.ambient = ambient;
            spec.substrate = substrate;
            for (const auto& [material, t] : layers) spec.layers.push_back({material, t});
            spec.polarization = parse_polarization(polarization);
            return build_film(spec);
        },
        py::arg("ambient"), py::arg("layers"), py::arg("substrate"), py::arg("polarization"));
    m.def(
        "film_thesis",
        [](const Material& ambient, const Material& film, const Material& substrate, double thickness,
           std::optional<double> k, std::optional<bool> phase_change) -> FilmPtr {
            FilmSpec spec;
            spec.model = FilmModelKind::thesis;
            spec.ambient = ambient;
            spec.substrate = substrate;
            spec.layers.push_back({film, thickness});
            spec.k = k;
            spec.phase_change = phase_change;
            FilmSpecNames names;
            names.layer = [](std::size_t) { return std::string("film"); };
            return build_film(spec, names);
        },
        py::arg("ambient"), py::arg("film"), py::arg("substrate"), py::arg("thickness"), py::arg("k"),
        py::arg("phase_change"));
    m.def(
        "film_thesis_multilayer",
        [](const Material& film, double thickness, const py::int_& periods, std::optional<double> k) -> FilmPtr {
            FilmSpec spec;
            spec.model = FilmModelKind::thesis_multilayer;
            spec.layers.push_back({film, thickness});
            spec.periods = periods_of(periods);
            spec.k = k;
            FilmSpecNames names;
            names.layer = [](std::size_t) { return std::string("film"); };
            return build_film(spec, names);
        },
        py::arg("film"), py::arg("thickness"), py::arg("periods"), py::arg("k"));
    m.def(
        "film_morpho",
        [](double d1, double d2, double n, const py::int_& periods, std::optional<double> k, bool blend,
           const std::string& vary, double blend_min, double blend_max, int blend_samples) -> FilmPtr {
            FilmSpec spec;
            spec.model = FilmModelKind::morpho;
            spec.d1_nm = d1;
            spec.d2_nm = d2;
            spec.n = n;
            spec.periods = periods_of(periods);
            spec.k = k;
            spec.blend = blend;
            if (blend) {
                if (vary != "d1" && vary != "d2") {
                    throw UnknownNameError("blend_vary '" + vary + "' is unknown; valid: d1, d2", {"d1", "d2"});
                }
                spec.blend_varies = vary == "d2" ? MorphoBlendThickness::d2 : MorphoBlendThickness::d1;
                spec.blend_min_nm = blend_min;
                spec.blend_max_nm = blend_max;
                spec.blend_samples = blend_samples;
            }
            return build_film(spec);
        },
        py::arg("d1"), py::arg("d2"), py::arg("n"), py::arg("periods"), py::arg("k"), py::arg("blend"),
        py::arg("blend_vary"), py::arg("blend_min"), py::arg("blend_max"), py::arg("blend_samples"));

    // --- The thesis' closed forms, element-wise over broadcast arrays --------------------------
    m.def("thesis_phase_change", py::vectorize([](double n_ambient, double n_film, double n_substrate) {
        return thesis_phase_change(n_ambient, n_film, n_substrate);
    }));
    m.def("thesis_film_reflectance",
          py::vectorize([](double lambda_nm, double thickness_nm, double n_film, bool phase_change, double k) {
              need(std::isfinite(lambda_nm) && lambda_nm > 0.0, "wavelength", lambda_nm, "finite and > 0 nm");
              need(std::isfinite(thickness_nm) && thickness_nm >= 0.0, "thickness", thickness_nm, "finite and >= 0 nm");
              need(std::isfinite(n_film) && n_film > 0.0, "n_film", n_film, "finite and > 0");
              need(std::isfinite(k) && k >= 0.0, "k", k, "finite and >= 0");
              return thesis_film_reflectance(lambda_nm, thickness_nm, n_film, phase_change, k);
          }));
    m.def("thesis_film_angle", py::vectorize([](double theta_rad, double n_film, double n_ambient) {
              need(std::isfinite(theta_rad) && theta_rad >= 0.0 && theta_rad < 1.5707963267948966, "angle",
                   theta_rad, "in [0, pi/2) rad");
              need(std::isfinite(n_film) && n_film > 0.0, "n_film", n_film, "finite and > 0");
              need(std::isfinite(n_ambient) && n_ambient > 0.0, "n_ambient", n_ambient, "finite and > 0");
              return thesis_film_angle_rad(theta_rad, n_film, n_ambient);
          }));
    m.def("thesis_effective_thickness", py::vectorize([](double thickness_nm, double n_film, double theta_film_rad) {
              need(std::isfinite(thickness_nm) && thickness_nm >= 0.0, "thickness", thickness_nm, "finite and >= 0 nm");
              need(std::isfinite(n_film) && n_film > 0.0, "n_film", n_film, "finite and > 0");
              need(std::isfinite(theta_film_rad) && theta_film_rad >= 0.0 && theta_film_rad <= 1.5707963267948966,
                   "angle in the film", theta_film_rad, "in [0, pi/2] rad");
              return thesis_effective_thickness_nm(thickness_nm, n_film, theta_film_rad);
          }));
    m.def("thesis_multilayer_reflectance",
          py::vectorize([](double lambda_nm, double effective_thickness_nm, int periods, double k) {
              need(std::isfinite(lambda_nm) && lambda_nm > 0.0, "wavelength", lambda_nm, "finite and > 0 nm");
              need(std::isfinite(effective_thickness_nm) && effective_thickness_nm >= 0.0, "effective thickness",
                   effective_thickness_nm, "finite and >= 0 nm");
              check_thesis_periods(periods);
              need(std::isfinite(k) && k >= 0.0, "k", k, "finite and >= 0");
              return thesis_multilayer_reflectance(lambda_nm, effective_thickness_nm, periods, k);
          }));
    m.def("thesis_multilayer_effective_thickness",
          py::vectorize([](double thickness_nm, double n, double theta_rad) {
              need(std::isfinite(thickness_nm) && thickness_nm >= 0.0, "thickness", thickness_nm, "finite and >= 0 nm");
              check_thesis_air_index(n, "n");
              need(std::isfinite(theta_rad) && theta_rad >= 0.0 && theta_rad < 1.5707963267948966, "angle",
                   theta_rad, "in [0, pi/2) rad");
              return thesis_multilayer_effective_thickness_nm(thickness_nm, n, theta_rad);
          }));
    m.def("morpho_effective_thickness", py::vectorize([](double theta_rad, double d1, double d2, double n) {
              need(std::isfinite(theta_rad) && theta_rad >= 0.0 && theta_rad < 1.5707963267948966, "angle",
                   theta_rad, "in [0, pi/2) rad");
              const MorphoParameters wing{d1, d2, n, 12, 1.0};
              validate_morpho(wing);
              return morpho_effective_thickness_nm(wing, theta_rad);
          }));
    m.def("thesis_matched_k",
          [](const Material& ambient, const Material& film, const Material& substrate, double lambda_nm) {
              check_thesis_single_film({ambient, film, substrate});
              return thesis_matched_k({ambient, film, substrate}, lambda_nm);
          },
          py::arg("ambient"), py::arg("film"), py::arg("substrate"), py::arg("wavelength"));
    m.def("thesis_unit_peak_k", [](int periods) {
        check_thesis_periods(periods);
        return thesis_unit_peak_k(periods);
    });

    // --- Colour tables --------------------------------------------------------------------
    py::class_<FilmColorTable>(m, "FilmColorTable",
                               "Thickness → colour every step nm, linear between (Film.color_table).")
        .def_property_readonly("min_thickness", &FilmColorTable::min_nm)
        .def_property_readonly("max_thickness", &FilmColorTable::max_nm)
        .def_property_readonly("step", &FilmColorTable::step_nm)
        .def_property_readonly("thickness", [](const FilmColorTable& t) {
            py::array_t<double> a(static_cast<py::ssize_t>(t.size()));
            for (std::size_t i = 0; i < t.size(); ++i) a.mutable_data()[i] = t.thickness_nm(i);
            return a;
        })
        .def_property_readonly("colors", [](const FilmColorTable& t) {
            py::array_t<double> xyz = triples(t.size()), rgb = triples(t.size());
            for (std::size_t i = 0; i < t.size(); ++i) {
                put(xyz.mutable_data() + 3 * i, t.colors()[i].xyz);
                put(rgb.mutable_data() + 3 * i, t.colors()[i].rgb_linear);
            }
            return py::make_tuple(xyz, rgb);
        })
        .def(
            "at",
            [](const FilmColorTable& table, const py::handle& thickness) {
                const std::vector<double> t = doubles(thickness, "thickness");
                for (std::size_t i = 0; i < t.size(); ++i) {
                    if (std::isnan(t[i])) throw Error("thickness[" + std::to_string(i) + "] is NaN");
                }
                py::array_t<double> xyz = triples(t.size()), rgb = triples(t.size());
                for (std::size_t i = 0; i < t.size(); ++i) {
                    const FilmColor c = table.at(t[i]);
                    put(xyz.mutable_data() + 3 * i, c.xyz);
                    put(rgb.mutable_data() + 3 * i, c.rgb_linear);
                }
                return py::make_tuple(xyz, rgb);
            },
            py::arg("thickness"),
            "(xyz, rgb) at each thickness [nm], arrays (n, 3); thicknesses beyond the table clamp to its ends.");
    m.def(
        "film_color_table",
        [](const FilmModel& film, double min_nm, double max_nm, double step_nm, double angle_rad,
           const std::string& illuminant, const std::string& observer, const std::string& rgb) {
            const Colorimeter c = colorimeter_of(illuminant, observer, rgb);
            if (std::isfinite(min_nm) && std::isfinite(max_nm) && std::isfinite(step_nm) && step_nm > 0.0) {
                film.check_work({{"the table", std::floor((max_nm - min_nm) / step_nm) + 1.0, "thicknesses"}},
                                false, {"layers", "blend"});
            }
            const auto row = film.at_angle(angle_rad);
            py::gil_scoped_release release;
            return FilmColorTable(min_nm, max_nm, step_nm, [&](double t) { return row->color(t, c); });
        },
        py::arg("film"), py::arg("min_thickness"), py::arg("max_thickness"), py::arg("step"), py::arg("angle_rad"),
        py::arg("illuminant"), py::arg("observer"), py::arg("rgb"));

    py::class_<FilmColorTable2D>(m, "FilmColorTable2D",
                                 "Thickness × cos θ → colour, bilinear (Film.color_table_2d).")
        .def_property_readonly("thickness_step", &FilmColorTable2D::thickness_step_nm)
        .def_property_readonly("thickness_count", &FilmColorTable2D::thickness_count)
        .def_property_readonly("cos_count", &FilmColorTable2D::cos_count)
        .def_property_readonly("cos_step", &FilmColorTable2D::cos_step)
        .def(
            "at",
            [](const FilmColorTable2D& table, const py::handle& thickness, const py::handle& cos_theta) {
                const std::vector<double> t = doubles(thickness, "thickness");
                const std::vector<double> c = doubles(cos_theta, "cos_theta");
                if (t.size() != c.size()) throw Error("thickness and cos_theta: sizes differ");
                for (std::size_t i = 0; i < t.size(); ++i) {
                    if (std::isnan(t[i]) || std::isnan(c[i])) throw Error("thickness or cos_theta [" + std::to_string(i) + "] is NaN");
                }
                py::array_t<double> xyz = triples(t.size()), rgb = triples(t.size());
                for (std::size_t i = 0; i < t.size(); ++i) {
                    const FilmColor col = table.at(t[i], c[i]);
                    put(xyz.mutable_data() + 3 * i, col.xyz);
                    put(rgb.mutable_data() + 3 * i, col.rgb_linear);
                }
                return py::make_tuple(xyz, rgb);
            },
            py::arg("thickness"), py::arg("cos_theta"),
            "(xyz, rgb) at each (thickness [nm], cos θ) pair, both clamped to the table.");
    m.def(
        "film_color_table_2d",
        [](const FilmModel& film, double max_nm, double step_nm, double max_angle_rad, int cos_steps,
           const std::string& illuminant, const std::string& observer, const std::string& rgb) {
            const Colorimeter c = colorimeter_of(illuminant, observer, rgb);
            check_incidence_angle(max_angle_rad);
            if (std::isfinite(max_nm) && std::isfinite(step_nm) && step_nm > 0.0 && cos_steps > 0) {
                film.check_work({{"the table's thicknesses", std::floor(max_nm / step_nm) + 1.0, "thicknesses"},
                                 {"cos_steps", static_cast<double>(cos_steps) + 1.0, "rows"}},
                                false, {"layers", "blend"});
            }
            // Each row of cos θ prepared once (the constructor fills rows in order).
            std::unique_ptr<FilmAtAngle> row;
            double row_cos = -2.0;
            py::gil_scoped_release release;
            return FilmColorTable2D(max_nm, step_nm, std::cos(max_angle_rad), cos_steps, [&](double t, double cos_theta) {
                if (!row || cos_theta != row_cos) {
                    row = film.at_angle(std::acos(std::clamp(cos_theta, 0.0, 1.0)));
                    row_cos = cos_theta;
                }
                return row->color(t, c);
            });
        },
        py::arg("film"), py::arg("max_thickness"), py::arg("step"), py::arg("max_angle_rad"), py::arg("cos_steps"),
        py::arg("illuminant"), py::arg("observer"), py::arg("rgb"));

    py::class_<ThesisFilmTable>(m, "ThesisFilmTable",
                                "The thesis' §3.3 table: effective thickness t′ → XYZ (thesis_film_table).")
        .def_property_readonly("phase_change", &ThesisFilmTable::phase_change)
        .def_property_readonly("step", &ThesisFilmTable::step_nm)
        .def_property_readonly("max_effective_thickness", &ThesisFilmTable::max_effective_thickness_nm)
        .def(
            "at",
            [](const ThesisFilmTable& table, const py::handle& effective_thickness, double k) {
                const std::vector<double> t = doubles(effective_thickness, "effective_thickness");
                for (std::size_t i = 0; i < t.size(); ++i) {
                    if (std::isnan(t[i])) throw Error("effective_thickness[" + std::to_string(i) + "] is NaN");
                }
                need(std::isfinite(k) && k >= 0.0, "k", k, "finite and >= 0");
                py::array_t<double> xyz = triples(t.size());
                for (std::size_t i = 0; i < t.size(); ++i) put(xyz.mutable_data() + 3 * i, table.at(t[i], k));
                return xyz;
            },
            py::arg("effective_thickness"), py::arg("k"),
            "XYZ (n, 3) at each effective thickness t′ [nm] for amplitude factor K (colours scale by K²).");
    m.def(
        "thesis_film_table",
        [](bool phase_change, double max_nm, double step_nm, const std::string& illuminant,
           const std::string& observer) {
            return ThesisFilmTable(phase_change, max_nm, step_nm, illuminant_by_name(illuminant),
                                   parse_observer(observer));
        },
        py::arg("phase_change"), py::arg("max_effective_thickness"), py::arg("step"), py::arg("illuminant"),
        py::arg("observer"));
}

}  // namespace irid::python
