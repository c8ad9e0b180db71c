// The colour core for Python: spaces and conversions, colour differences, observers,
// illuminants, spectra to XYZ and the thesis' primaries (Figure 2).

#include "arrays.h"

#include <irid/color.h>

#include <pybind11/stl.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <functional>

#include <optional>
#include <string>
#include <utility>

namespace irid::python {
namespace {

/// A dense spectrum (360-830 nm at 1 nm) as (wavelengths, values).
py::tuple dense_arrays(const DenseSpectrum& s) {
    py::array_t<double> w(dense_sample_count), v(dense_sample_count);
    auto wm = w.mutable_unchecked<1>();
    auto vm = v.mutable_unchecked<1>();
    for (int i = 0; i < dense_sample_count; ++i) {
        wm(i) = DenseSpectrum::wavelength_nm(i);
        vm(i) = s[i];
    }
    return py::make_tuple(w, v);
}

template <class T>
py::array convert_rows(const py::handle& a, const Converter& c, const py::object& out) {
    Rows<T> in = rows_of<T>(a, 3, "colours");
    py::array_t<T> result = result_array<T>(out, in.shape);
    std::span<T> dst = mutable_values(result);
    {
        py::gil_scoped_release release;
        // Pieces of 64 Ki colours on every core (Converter is const and thread-safe). xyY
        // sources stay whole: a refused colour must stop the call before anything is written.
        const std::span<const T> src = in.values();
        constexpr std::size_t piece = std::size_t{3} << 16;
        const std::less<const T*> less;
        if (src.size() <= piece || c.from().family == SpaceFamily::xyy) {
            c.convert(src, dst);
        } else if (src.data() != dst.data() && less(src.data(), dst.data() + dst.size()) &&
                   less(dst.data(), src.data() + src.size())) {
            throw Error("convert: input and output overlap; they must be the same array or disjoint");
        } else {
            tbb::parallel_for(std::size_t{0}, (src.size() + piece - 1) / piece, [&](std::size_t k) {
                const std::size_t b = k * piece, e = std::min(src.size(), b + piece);
                c.convert(src.subspan(b, e - b), dst.subspan(b, e - b));
            });
        }
    }
    return result;
}

}  // namespace

void add_colour(py::module_& m) {
    m.def("color_space_names", &color_space_names);
    m.def("rgb_color_space_names", &rgb_color_space_names);
    // A space's canonical name, from a name in any case; None when no space has it.
    m.def("canonical_space_name", [](const std::string& name) -> std::optional<std::string> {
        if (const std::optional<ColorSpace> s = find_color_space(name)) return color_space_name(*s);
        return std::nullopt;
    });
    m.def("white_point", [](const std::string& name) {
        const Xy w = white_point_xy(name);
        return py::make_tuple(w.x, w.y);
    });
    m.def("white_point_names", &white_point_names);
    m.def("check_white", [](double x, double y) { check_white_chromaticity({x, y}, "white"); });
    m.def(
        "convert",
        [](const py::handle& a, const std::string& source, const std::string& target, double wx,
           double wy, const std::string& adaptation, const py::object& out) -> py::array {
            const Converter c(color_space(source), color_space(target), Xy{wx, wy},
                              parse_chromatic_adaptation(adaptation));
            const py::array numbers = numeric_array(a, "colours");
            if (is_float32(numbers)) return convert_rows<float>(numbers, c, out);
            return convert_rows<double>(numbers, c, out);
        },
        py::arg("a"), py::arg("source"), py::arg("target"), py::arg("wx"), py::arg("wy"),
        py::arg("adaptation"), py::arg("out"));

    m.def(
        "delta_e",
        [](const py::handle& a, const py::handle& b, const std::string& metric_name) {
            const DeltaEMetric metric = parse_delta_e_metric(metric_name);
            Rows<double> x = rows_of<double>(a, 3, "a");
            Rows<double> y = rows_of<double>(b, 3, "b");
            if (x.shape != y.shape) throw py::value_error("a and b: shapes differ after broadcasting");
            std::vector<py::ssize_t> shape(x.shape.begin(), x.shape.end() - 1);
            py::array_t<double> result(shape);
            std::span<double> dst = mutable_values(result);
            const std::span<const double> xs = x.values(), ys = y.values();
            {
                py::gil_scoped_release release;
                for (std::size_t i = 0; i < x.count; ++i) {
                    dst[i] = delta_e(metric, {xs[3 * i], xs[3 * i + 1], xs[3 * i + 2]},
                                     {ys[3 * i], ys[3 * i + 1], ys[3 * i + 2]});
                }
            }
            return result;
        },
        py::arg("a"), py::arg("b"), py::arg("metric"));

    m.def("cmfs", [](const std::string& name) {
        const ColorMatchingFunctions& c = color_matching_functions(parse_observer(name));
        py::array_t<double> w(dense_sample_count);
        py::array_t<double> v({py::ssize_t{dense_sample_count}, py::ssize_t{3}});
        auto wm = w.mutable_unchecked<1>();
        auto vm = v.mutable_unchecked<2>();
        for (int i = 0; i < dense_sample_count; ++i) {
            wm(i) = DenseSpectrum::wavelength_nm(i);
            vm(i, 0) = c.x[i];
            vm(i, 1) = c.y[i];
            vm(i, 2) = c.z[i];
        }
        return py::make_tuple(w, v);
    });
    m.def("illuminant", [](const std::string& name) { return dense_arrays(illuminant_by_name(name)); });
    m.def("daylight", [](double cct) { return dense_arrays(daylight_illuminant(cct)); });
    m.def("blackbody", [](double t) { return dense_arrays(blackbody(t)); });

    m.def(
        "spectrum_to_xyz",
        [](const py::handle& wavelengths, const py::handle& values, const std::string& illuminant,
           const std::string& observer_name) {
            const DenseSpectrum light = illuminant_by_name(illuminant);
            const Observer observer = parse_observer(observer_name);
            const auto w = contiguous_of<double>(wavelengths, "wavelengths");
            if (w.ndim() != 1) throw py::value_error("wavelengths: expected a 1-D array of numbers (nm)");
            const std::span<const double> ws(w.data(), static_cast<std::size_t>(w.size()));
            check_sample_wavelengths(ws);
            const Rows<double> v = rows_of<double>(values, w.size(), "values");
            std::vector<py::ssize_t> shape = v.shape;
            shape.back() = 3;
            py::array_t<double> result(shape);
            std::span<double> dst = mutable_values(result);
            const std::span<const double> vs = v.values();
            const std::size_t n = ws.size();
            {
                py::gil_scoped_release release;
                for (std::size_t i = 0; i < v.count; ++i) {
                    try {
                        const Xyz c = sampled_reflectance_to_xyz(ws, vs.subspan(i * n, n), light, observer);
                        dst[3 * i] = c.X;
                        dst[3 * i + 1] = c.Y;
                        dst[3 * i + 2] = c.Z;
                    } catch (const Error& e) {
                        throw Error("spectrum " + std::to_string(i) + ": " + e.what());
                    }
                }
            }
            return result;
        },
        py::arg("wavelengths"), py::arg("values"), py::arg("illuminant"), py::arg("observer"));

    m.def(
        "primary_matching_functions",
        [](double red, double green, double blue, const std::string& observer) {
            const PrimaryMatchingFunctions p =
                monochromatic_primary_matching_functions(red, green, blue, parse_observer(observer));
            py::array_t<double> w(dense_sample_count);
            py::array_t<double> v({py::ssize_t{dense_sample_count}, py::ssize_t{3}});
            py::array_t<double> m3({py::ssize_t{3}, py::ssize_t{3}});
            auto wm = w.mutable_unchecked<1>();
            auto vm = v.mutable_unchecked<2>();
            auto mm = m3.mutable_unchecked<2>();
            for (int i = 0; i < dense_sample_count; ++i) {
                wm(i) = DenseSpectrum::wavelength_nm(i);
                vm(i, 0) = p.r[i];
                vm(i, 1) = p.g[i];
                vm(i, 2) = p.b[i];
            }
            for (py::ssize_t i = 0; i < 3; ++i) {
                for (py::ssize_t j = 0; j < 3; ++j) mm(i, j) = p.xyz_to_rgb[static_cast<int>(i)][static_cast<std::size_t>(j)];
            }
            return py::make_tuple(w, v, m3);
        },
        py::arg("red"), py::arg("green"), py::arg("blue"), py::arg("observer"));
}

}  // namespace irid::python
