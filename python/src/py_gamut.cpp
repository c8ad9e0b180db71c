// Gamut mapping for Python: the clip methods and their parameters, and ClipPipeline (what
// `irid clip` does to colours) on arrays, float32 through the SIMD batch kernels, float64
// through the double methods.

#include "arrays.h"

#include <irid/color.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/display_transform.h>
#include <irid/gamut/pipeline.h>
#include <irid/gamut/report.h>
#include <irid/exchange/icc.h>
#include <irid/exchange/image_source.h>
#include <irid/exchange/image_clip.h>
#include <irid/figures/clip_sets.h>
#include <irid/io/image.h>

#include <cstring>

#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace irid::python {
namespace {


/// What read_image's metadata dict says about a file's space, as the io::Image the library's
/// decisions read (the keys irid.read_image returns; absent ones are as for a float file that
/// says nothing). Python's irid/__init__.py checks the values' types first.
io::Image image_facts(const py::dict& m) {
    io::Image image;
    const auto get = [&m](const char* key) { return m.contains(key) ? py::object(m[key]) : py::object(py::none()); };
    if (const py::object icc = get("icc_profile"); !icc.is_none()) {
        const std::string bytes = icc.cast<py::bytes>();
        image.icc_profile.assign(bytes.begin(), bytes.end());
    }
    if (const py::object c = get("chromaticities"); !c.is_none()) image.chromaticities = c.cast<std::vector<float>>();
    if (const py::object v = get("integer"); !v.is_none()) image.stored_integer = v.cast<bool>();
    if (const py::object v = get("bits"); !v.is_none()) image.stored_bits = v.cast<int>();
    if (const py::object v = get("icc_profile_rejected"); !v.is_none()) image.icc_profile_rejected = v.cast<bool>();
    if (const py::object v = get("icc_profile_damage"); !v.is_none()) image.icc_profile_damage = v.cast<std::string>();
    if (const py::object v = get("cmyk"); !v.is_none()) image.stored_cmyk = v.cast<bool>();
    if (const py::object v = get("model"); !v.is_none()) image.stored_model = v.cast<std::string>();
    if (const py::object v = get("png"); !v.is_none()) {
        const py::dict png = v.cast<py::dict>();
        if (png.contains("srgb")) image.png_srgb = png["srgb"].cast<bool>();
        if (png.contains("gamma")) image.png_gamma = png["gamma"].cast<double>();
        if (png.contains("chromaticities")) image.png_chromaticities = png["chromaticities"].cast<std::vector<float>>();
        if (png.contains("cicp")) {
            for (const int code : png["cicp"].cast<std::vector<int>>()) {
                image.png_cicp.push_back(static_cast<unsigned char>(code));
            }
        }
    }
    return image;
}

/// The pipeline of ClipPipeline's Python constructors (the arguments as irid._pipeline passes them).
ClipPipeline make_pipeline(const std::string& method, const ColorSpace& from, const std::string& target,
                           double max, double wx, double wy, const std::string& adaptation,
                           const std::vector<std::pair<std::string, double>>& params, bool inverse,
                           bool display) {
    const ClipMethod cm = parse_clip_method(method);
    const ColorSpace to = color_space(target);
    if (!to.is_rgb()) {
        throw Error("target '" + target + "' is not an RGB space; the gamut is an RGB space's cube");
    }
    ClipPipelineOptions o;
    o.max = max;
    o.white = {wx, wy};
    o.adaptation = parse_chromatic_adaptation(adaptation);
    o.settings.inverse = inverse;
    for (const auto& [k, v] : params) o.settings.set(k, v);
    if (display) o.settings = display_clip_settings(cm, std::move(o.settings));
    return ClipPipeline(cm, from, to, o);
}

}  // namespace

namespace {

template <class T>
py::array run_pipeline(const ClipPipeline& p, const py::handle& a, int threads, const py::object& out) {
    if (threads < 0) throw py::value_error("threads: " + std::to_string(threads) + " must be >= 0 (0: all)");
    Rows<T> in = rows_of<T>(a, 3, "colours");
    py::array_t<T> result = result_array<T>(out, in.shape);
    std::span<T> dst = mutable_values(result);
    {
        py::gil_scoped_release release;
        if constexpr (std::is_same_v<T, float>) {
            p.clip(in.values(), dst, BatchOptions{.threads = threads, .simd = true});
        } else {
            p.clip(in.values(), dst, threads);
        }
    }
    return result;
}

template <class T>
py::array run_display(const DisplayTransform& t, const py::handle& a, int threads, const py::object& out) {
    if (threads < 0) throw py::value_error("threads: " + std::to_string(threads) + " must be >= 0 (0: all)");
    Rows<T> in = rows_of<T>(a, 3, "colours");
    py::array_t<T> result = result_array<T>(out, in.shape);
    std::span<T> dst = mutable_values(result);
    {
        py::gil_scoped_release release;
        t.apply(in.values(), dst, threads);
    }
    return result;
}

py::dict statistics(const ClipStatistics& s) {
    py::dict d;
    d["mean"] = s.mean;
    d["p95"] = s.p95;
    d["max"] = s.max;
    d["count"] = s.count;
    return d;
}

py::dict method_report(const MethodClipReport& m) {
    py::dict d;
    d["delta_e2000"] = statistics(m.delta_e2000);
    d["hue_lab"] = statistics(m.hue_lab);
    d["hue_oklab"] = statistics(m.hue_oklab);
    d["hue_luv"] = statistics(m.hue_luv);
    d["hue_undefined"] = m.hue_undefined;
    d["delta_y"] = statistics(m.delta_y);
    d["chroma_kept"] = m.chroma_kept;
    d["chroma_kept_count"] = m.chroma_kept_count;
    d["colors_per_second"] = m.colors_per_second;
    d["in_gamut_moved"] = statistics(m.in_gamut_moved);
    d["banding"] = statistics(m.banding);
    d["collapse"] = statistics(m.collapse);
    d["collapse_relative"] = statistics(m.collapse_relative);
    return d;
}

py::dict report_dict(const ClipReport& r) {
    py::dict d;
    d["set"] = r.set_name;
    d["description"] = r.set_description;
    d["destination"] = r.destination;
    d["max"] = r.max;
    d["size"] = r.size;
    d["out_of_gamut"] = r.out_of_gamut;
    d["ramps"] = r.ramps;
    d["input_banding"] = statistics(r.input_banding);
    py::dict methods;
    for (const MethodClipReport& m : r.methods) {
        methods[py::str(std::string(clip_method_name(m.method)))] = method_report(m);
    }
    d["methods"] = methods;
    return d;
}

}  // namespace

void add_gamut(py::module_& m) {
    m.def("clip_methods", [] {
        std::vector<std::string> names;
        for (const ClipMethod c : clip_methods()) names.emplace_back(clip_method_name(c));
        return names;
    });
    m.def("clip_parameters", [](const std::string& method) {
        py::list out;
        for (const ClipParameterInfo& p : clip_parameters(parse_clip_method(method))) {
            py::dict d;
            d["name"] = std::string(p.name);
            d["default"] = p.boolean ? py::object(py::bool_(p.default_value != 0.0))
                                     : py::object(py::float_(p.default_value));
            d["min"] = p.min;
            d["max"] = p.max;
            d["boolean"] = p.boolean;
            d["description"] = std::string(p.description);
            out.append(d);
        }
        return out;
    });
    m.def("has_inverse", [](const std::string& method) { return has_inverse(parse_clip_method(method)); });
    m.def("simd_target", [] { return std::string(simd_target_name()); });
    m.def("image_colour_channels", [](std::vector<std::string> names) {
        io::Image image;
        image.channels = static_cast<int>(names.size());
        image.channel_names = std::move(names);
        const ImageColourChannels c = image_colour_channels(image, "image");
        return py::make_tuple(c.index[0], c.index[1], c.index[2], c.xyz);
    });

    // What an image file says about its space (irid/exchange/icc.h), from read_image's metadata.
    py::class_<ImageSpace, std::shared_ptr<ImageSpace>>(m, "FileSpace")
        .def(py::init([](const py::dict& facts) { return std::make_shared<ImageSpace>(image_space(image_facts(facts), "image")); }),
             py::arg("facts"))
        .def_property_readonly("space", [](const ImageSpace& f) {
            if (f.xyz) return py::object(py::str("xyz"));
            if (f.builtin == nullptr) return py::object(py::none());
            return py::object(py::str(color_space_name(ColorSpace{f.colour_space().family, f.builtin})));
        })
        .def_property_readonly("origin", [](const ImageSpace& f) { return f.origin; })
        .def_property_readonly("assumed", [](const ImageSpace& f) { return f.assumed; })
        .def_property_readonly("encoded", [](const ImageSpace& f) { return f.encoded; })
        .def_property_readonly("exact", [](const ImageSpace& f) { return !f.profile; });

    // Where an image's colours come from (irid/exchange/image_source.h), kept at a fixed address
    // so that the pipelines built on it can point at its RgbSpace.
    py::class_<ImageSource, std::shared_ptr<ImageSource>>(m, "ImageSource")
        .def(py::init([](const py::dict& facts, bool xyz_channels, const std::optional<std::string>& given) {
                 std::optional<ColorSpace> space;
                 if (given) space = color_space(*given);
                 return std::make_shared<ImageSource>(
                     decide_image_source(image_facts(facts), xyz_channels, space, "image", "source="));
             }),
             py::arg("facts"), py::arg("xyz_channels"), py::arg("given"))
        .def_property_readonly("notes", [](const ImageSource& s) { return s.notes; })
        .def_property_readonly("described", [](const ImageSource& s) { return s.described; });

    py::class_<DisplayTransform>(m, "DisplayTransform")
        .def(py::init([](const std::string& view, const std::string& display, const std::string& source,
                         const std::string& target, bool inverse) {
                 return DisplayTransform(DisplayTransformOptions{view, display, source, target, inverse});
             }),
             py::arg("view"), py::arg("display"), py::arg("source"), py::arg("target"), py::arg("inverse"))
        .def(
            "run",
            [](const DisplayTransform& t, const py::handle& a, int threads, const py::object& out) {
                const py::array numbers = numeric_array(a, "colours");
                if (is_float32(numbers)) return run_display<float>(t, numbers, threads, out);
                return run_display<double>(t, numbers, threads, out);
            },
            py::arg("colours"), py::arg("threads"), py::arg("out"))
        .def(
            "scene_values_exist",
            [](const DisplayTransform& t, const py::handle& a, int threads, double tolerance) {
                if (!(tolerance >= 0.0))
                    throw py::value_error("tolerance: " + std::to_string(tolerance) + " must be >= 0");
                if (threads < 0)
                    throw py::value_error("threads: " + std::to_string(threads) + " must be >= 0 (0: all)");
                Rows<double> in = rows_of<double>(numeric_array(a, "colours"), 3, "colours");
                std::vector<unsigned char> flags;
                {
                    py::gil_scoped_release release;
                    flags = t.scene_values_exist(in.values(), threads, tolerance);
                }
                std::vector<py::ssize_t> shape(in.shape.begin(), in.shape.end() - 1);
                py::array_t<bool> result(shape);
                std::copy(flags.begin(), flags.end(), result.mutable_data());
                return result;
            },
            py::arg("colours"), py::arg("threads"), py::arg("tolerance"));
    m.def("display_names", [] {
        std::vector<std::string> names;
        for (const Aces2DisplaySpec& d : aces2_displays()) names.push_back(d.name);
        return names;
    });

    py::class_<ClipPipeline>(m, "ClipPipeline")
        .def(py::init([](const std::string& method, const std::string& source,
                         const std::string& target, double max, double wx, double wy,
                         const std::string& adaptation, const std::vector<std::pair<std::string, double>>& params,
                         bool inverse, bool display) {
                 return make_pipeline(method, color_space(source), target, max, wx, wy, adaptation,
                                      params, inverse, display);
             }),
             py::arg("method"), py::arg("source"), py::arg("target"), py::arg("max"), py::arg("wx"),
             py::arg("wy"), py::arg("adaptation"), py::arg("params"), py::arg("inverse"),
             py::arg("display") = false)
        .def(py::init([](const std::string& method, const ImageSource& source, const std::string& target,
                         double max, double wx, double wy, const std::string& adaptation,
                         const std::vector<std::pair<std::string, double>>& params, bool inverse,
                         bool display) {
                 return make_pipeline(method, source.space, target, max, wx, wy, adaptation, params,
                                      inverse, display);
             }),
             py::keep_alive<1, 3>(),  // the pipeline points at the source's RgbSpace
             py::arg("method"), py::arg("source"), py::arg("target"), py::arg("max"), py::arg("wx"),
             py::arg("wy"), py::arg("adaptation"), py::arg("params"), py::arg("inverse"),
             py::arg("display") = false)
        .def(
            "run",
            [](const ClipPipeline& p, const py::handle& a, int threads, const py::object& out) {
                const py::array numbers = numeric_array(a, "colours");
                if (is_float32(numbers)) return run_pipeline<float>(p, numbers, threads, out);
                return run_pipeline<double>(p, numbers, threads, out);
            },
            py::arg("a"), py::arg("threads"), py::arg("out"))
        .def(
            "branches",
            [](const ClipPipeline& p, const py::handle& a, int threads) {
                if (threads < 0) throw py::value_error("threads: " + std::to_string(threads) + " must be >= 0 (0: all)");
                Rows<double> in = rows_of<double>(a, 3, "colours");
                std::vector<py::ssize_t> shape(in.shape.begin(), in.shape.end() - 1);
                py::array_t<std::uint64_t> result(shape);
                std::span<std::uint64_t> dst(result.mutable_data(), static_cast<std::size_t>(result.size()));
                {
                    py::gil_scoped_release release;
                    p.branch_signatures(in.values(), dst, threads);
                }
                return result;
            },
            py::arg("a"), py::arg("threads"))
        .def_property_readonly("method",
                               [](const ClipPipeline& p) { return std::string(clip_method_name(p.clipper().method())); })
        .def_property_readonly("parameters",
                               [](const ClipPipeline& p) {
                                   py::dict d;
                                   for (const auto& [k, v] : p.clipper().parameters()) d[py::str(k)] = v;
                                   return d;
                               })
        .def_property_readonly("inverse", [](const ClipPipeline& p) { return p.clipper().inverse(); })
        .def_property_readonly("confines_to_cube",
                               [](const ClipPipeline& p) { return p.clipper().confines_to_cube(); });

    m.def(
        "clip_report",
        [](const std::string& set, const std::string& target, double min_seconds) {
            const std::vector<figures::ClipReportSet> kinds = figures::parse_clip_report_sets(set);
            const ColorSpace to = color_space(target);
            if (!to.is_rgb()) {
                throw Error("target '" + target + "' is not an RGB space; the gamut is an RGB space's cube");
            }
            std::vector<ClipReport> reports;
            {
                py::gil_scoped_release release;
                const Gamut gamut(*to.rgb);
                std::vector<ColorSet> sets;
                for (const figures::ClipReportSet k : kinds) {
                    sets.push_back(figures::clip_report_color_set(k, *to.rgb));
                }
                if (sets.size() > 1) sets.push_back(union_color_set(sets, set));
                ClipReportOptions options;
                options.min_seconds = min_seconds;
                for (const ColorSet& s : sets) reports.push_back(measure_clip_report(s, gamut, options));
            }
            py::list out;
            for (const ClipReport& r : reports) out.append(report_dict(r));
            return out;
        },
        py::arg("set"), py::arg("target"), py::arg("min_seconds"));

    m.def(
        "clip_image",
        [](py::array_t<float> pixels, std::vector<std::string> channels, const ClipPipeline& p,
           bool premultiplied_in, bool premultiplied_out, bool encode, int threads, const ImageSource* source) {
            if (pixels.ndim() != 3 || !(pixels.flags() & py::array::c_style) || !pixels.writeable()) {
                throw py::value_error("pixels: a writeable C-contiguous float32 (height, width, channels) array is needed");
            }
            if (static_cast<py::ssize_t>(channels.size()) != pixels.shape(2)) {
                throw py::value_error("channels: " + std::to_string(channels.size()) + " names for " +
                                      std::to_string(pixels.shape(2)) + " channels");
            }
            io::Image image;
            image.height = static_cast<int>(pixels.shape(0));
            image.width = static_cast<int>(pixels.shape(1));
            image.channels = static_cast<int>(pixels.shape(2));
            image.channel_names = std::move(channels);
            float* data = pixels.mutable_data();
            image.pixels.assign(data, data + pixels.size());
            {
                py::gil_scoped_release release;
                const ImageColourChannels colour = image_colour_channels(image, "image");
                clip_image(image, colour, p,
                           ImageClipOptions{.premultiplied_in = premultiplied_in,
                                            .premultiplied_out = premultiplied_out,
                                            .encode = encode,
                                            .threads = threads,
                                            .profile = source != nullptr && source->file ? source->file->profile.get()
                                                                                         : nullptr},
                           "image");
                std::memcpy(data, image.pixels.data(), image.pixels.size() * sizeof(float));
            }
            return image.channel_names;
        },
        py::arg("pixels"), py::arg("channels"), py::arg("pipeline"), py::arg("premultiplied_in"),
        py::arg("premultiplied_out"), py::arg("encode"), py::arg("threads"), py::arg("file") = nullptr);
}

}  // namespace irid::python
