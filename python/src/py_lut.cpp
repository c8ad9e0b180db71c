// 3D LUTs for Python: a ClipPipeline baked at size³ nodes (irid/exchange/lut.h), its table as a
// numpy view, the files for OpenColorIO, Resolve and ffmpeg, and the LUT evaluated as a client
// evaluates it.

#include "arrays.h"

#include <irid/error.h>
#include <irid/exchange/display_lut.h>
#include <irid/exchange/lut.h>
#include <irid/exchange/ocio_config.h>
#include <irid/color/adaptation.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/pipeline.h>
#include <irid/io/output_file.h>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace irid::python {
namespace {

LutShaper parse_shaper(const std::string& name) {
    if (name == "none") return LutShaper::none;
    if (name == "log2") return LutShaper::log2;
    throw UnknownNameError("unknown shaper '" + name + "'; valid: none, log2", {"none", "log2"});
}

/// The table as a read-only (size, size, size, 3) view indexed [r, g, b, channel] of the
/// values (stored red fastest), kept alive by the Lut object.
py::array table_view(const std::shared_ptr<Lut3D>& lut, py::handle owner) {
    const auto n = static_cast<py::ssize_t>(lut->size);
    const py::ssize_t f = sizeof(float);
    py::array a(py::dtype::of<float>(), {n, n, n, py::ssize_t{3}},
                {3 * f, 3 * f * n, 3 * f * n * n, f}, lut->values.data(), owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

}  // namespace

void add_lut(py::module_& m) {
    py::class_<Lut3D, std::shared_ptr<Lut3D>>(m, "Lut", R"(A 3D LUT baked by bake_lut: a clip method sampled at size³ nodes.

size: nodes per axis. shaper: "none" (nodes uniform over domain) or "log2" (uniform in stops
below the domain's top, `stops` of them). domain: (lo, hi), the values covered on every axis of
the cube; inputs beyond clamp to it. matrix: None, or the (3, 3) matrix that takes an input to
the cube's space first (a display LUT over light: to AP1), cube_space that space's name (the
source's without a matrix). title: the line the files carry (irid's version, the method, its
parameters and both spaces). source, target: the spaces of the input and the output.
table: a read-only float32 view (size, size, size, 3) indexed [r, g, b, channel].
nodes: the value of each node along an axis of the cube (float64, size).)")
        .def_property_readonly("size", [](const Lut3D& l) { return l.size; })
        .def_property_readonly("shaper",
                               [](const Lut3D& l) { return std::string(l.domain.shaper == LutShaper::log2 ? "log2" : "none"); })
        .def_property_readonly("domain", [](const Lut3D& l) { return py::make_tuple(l.domain.min, l.domain.max); })
        .def_property_readonly("stops", [](const Lut3D& l) { return l.domain.stops; })
        .def_property_readonly("matrix", [](const Lut3D& l) -> py::object {
            if (!l.domain.matrix) return py::none();
            py::array_t<double> a({3, 3});
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j) a.mutable_at(i, j) = (*l.domain.matrix)[i][j];
            }
            return a;
        })
        .def_property_readonly("cube_space", [](const Lut3D& l) {
            return l.domain.matrix ? l.domain.matrix_space : l.source;
        })
        .def_property_readonly("title", [](const Lut3D& l) { return l.title; })
        .def_property_readonly("source", [](const Lut3D& l) { return l.source; })
        .def_property_readonly("target", [](const Lut3D& l) { return l.destination; })
        .def_property_readonly("table", [](const py::object& self) {
            return table_view(self.cast<std::shared_ptr<Lut3D>>(), self);
        })
        .def_property_readonly("nodes", [](const Lut3D& l) {
            py::array_t<double> a(l.size);
            for (int i = 0; i < l.size; ++i) a.mutable_at(i) = l.node(i);
            return a;
        })
        .def("text", [](const Lut3D& l, const std::string& format) {
                 return lut_text(l, lut_format_for("lut." + format));
             }, py::arg("format"),
             "The text of the LUT's file in a format: 'cube', 'clf' or 'spi3d'.")
        .def("write", [](const Lut3D& l, const std::filesystem::path& path) {
                 const LutFormat format = lut_format_for(path);
                 std::string text;
                 try {
                     text = lut_text(l, format);
                 } catch (const UnknownNameError&) {
                     throw;
                 } catch (const Error& e) {
                     throw Error(path.string() + ": " + e.what());
                 }
                 py::gil_scoped_release release;
                 try {
                     io::write_output_file(path, text);
                 } catch (const Error& e) {
                     throw FileError(e.what());
                 }
             }, py::arg("path"),
             "Writes the LUT as .cube, .clf or .spi3d by the extension, whole or not at all: OSError "
             "when it cannot be written, ValueError when the format cannot carry the domain, KeyError "
             "for another extension.")
        .def("apply", [](const Lut3D& l, const py::handle& a, const std::string& interpolation) {
                 const LutInterpolation how = parse_lut_interpolation(interpolation);
                 Rows<double> in = rows_of<double>(a, 3, "colours");
                 py::array_t<double> result(in.shape);
                 double* out = result.mutable_data();
                 const double* src = in.array.data();
                 {
                     py::gil_scoped_release release;
                     for (std::size_t i = 0; i < in.count; ++i) {
                         const Rgb c = apply_lut(l, Vec3{src[3 * i], src[3 * i + 1], src[3 * i + 2]}, how);
                         out[3 * i] = c.r;
                         out[3 * i + 1] = c.g;
                         out[3 * i + 2] = c.b;
                     }
                 }
                 return result;
             }, py::arg("colours"), py::arg("interpolation") = "trilinear",
             "The LUT at (..., 3) colours as a client evaluates it (float64): clamped to the domain, "
             "shaped, then 'trilinear' (OCIO for .cube and .spi3d) or 'tetrahedral' (the .clf; ffmpeg) "
             "between the nodes.");

    m.def(
        "bake_lut",
        [](const ClipPipeline& p, int size, const std::string& shaper, double lo, double hi, int stops,
           int threads) {
            LutDomain d{.shaper = parse_shaper(shaper), .min = lo, .max = hi, .stops = stops};
            py::gil_scoped_release release;
            return std::make_shared<Lut3D>(bake_lut(p, size, d, threads));
        },
        py::arg("pipeline"), py::arg("size"), py::arg("shaper"), py::arg("lo"), py::arg("hi"),
        py::arg("stops"), py::arg("threads"));
    m.def(
        "bake_display_lut",
        [](const std::string& view, const std::string& display, const std::string& source, const std::string& target,
           int size, const std::string& format, int threads) {
            const DisplayTransform transform(display_lut_options(view, display, source, target));
            const LutDomain domain = display_lut_domain(transform, lut_format_for("lut." + format));
            py::gil_scoped_release release;
            return std::make_shared<Lut3D>(bake_display_lut(transform, size, domain, threads));
        },
        py::arg("view"), py::arg("display"), py::arg("source"), py::arg("target"), py::arg("size"),
        py::arg("format"), py::arg("threads"));
    m.def(
        "write_ocio_config",
        [](const std::filesystem::path& dir, const std::string& source, const std::string& display,
           const std::vector<std::string>& methods, int size, const std::string& adaptation, int threads,
           const std::optional<std::pair<double, double>>& range,
           const std::optional<std::vector<std::string>>& aces2) {
            OcioConfigOptions o;
            o.source_range = range;
            o.aces2_displays = aces2;
            o.source = color_space(source);
            o.display = color_space(display);
            for (const std::string& name : methods) o.methods.push_back(parse_clip_method(name));
            o.size = size;
            o.adaptation = parse_chromatic_adaptation(adaptation);
            o.threads = threads;
            py::gil_scoped_release release;
            const OcioConfig config = make_ocio_config(o);
            try {
                (void)write_ocio_config(dir, config);
            } catch (const Error& e) {
                throw FileError(e.what());
            }
            return (dir / "config.ocio").string();
        },
        py::arg("dir"), py::arg("source"), py::arg("display"), py::arg("methods"), py::arg("size"),
        py::arg("adaptation"), py::arg("threads"), py::arg("range"), py::arg("aces2"));
    m.def("lut_format_interpolation",
          [](const std::string& format) {
              return std::string(lut_interpolation_name(lut_format_interpolation(lut_format_for("lut." + format))));
          },
          py::arg("format"));
}

}  // namespace irid::python
