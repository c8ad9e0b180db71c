// The renderer for Python: a scene (built-in name, JSON file or JSON text from a dict) with
// overrides, rendered with the GIL released; the images come back as float32 arrays.

#include "arrays.h"

#include <irid/gallery/gallery.h>
#include <irid/render/render.h>
#include <irid/render/scene.h>

#include <pybind11/stl.h>

#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace irid::python {
namespace {

py::array_t<float> image_array(const io::Image& image) {
    py::array_t<float> a({py::ssize_t{image.height}, py::ssize_t{image.width}, py::ssize_t{image.channels}});
    std::memcpy(a.mutable_data(), image.pixels.data(), image.pixels.size() * sizeof(float));
    return a;
}

}  // namespace

void add_render(py::module_& m) {
    m.def("scene_names", &render::builtin_scene_names);
    m.def(
        "render",
        [](const std::string& scene, bool is_json, const std::string& source, const std::string& directory,
           std::vector<std::string> overrides, std::optional<int> width, std::optional<int> height, int threads) {
            const auto load = [&](const std::vector<std::string>& with) {
                return is_json ? render::parse_scene(scene, source, directory, with)
                               : render::load_scene(scene, with);
            };
            // width or height alone keeps the scene's aspect ratio (after the overrides), as the
            // command line does.
            for (const std::string& o : render::image_size_overrides(load(overrides), width, height)) {
                overrides.push_back(o);
            }
            const render::Scene s = load(overrides);
            if (threads < 0) throw Error("threads " + std::to_string(threads) + " must be >= 0 (0: every core)");
            render::RenderOptions options;
            options.threads = threads;
            render::RenderResult r;
            {
                py::gil_scoped_release release;
                r = render::render(s, options);
            }
            py::dict stats;
            stats["camera_rays"] = r.stats.camera_rays;
            stats["rays"] = r.stats.rays;
            stats["out_of_gamut_pixels"] = r.stats.out_of_gamut_pixels;
            stats["seconds"] = r.stats.seconds;
            stats["table_seconds"] = r.stats.table_seconds;
            stats["space"] = s.render.space;
            stats["clip"] = std::string(clip_method_name(s.render.clip));
            stats["view"] = s.render.view == render::ViewTransform::thesis ? "thesis" : "rolloff";
            stats["width"] = s.image.width;
            stats["height"] = s.image.height;
            stats["spp"] = s.image.spp;
            stats["source"] = s.source;
            return py::make_tuple(image_array(r.linear), image_array(r.display), image_array(r.xyz), stats);
        },
        py::arg("scene"), py::arg("is_json"), py::arg("source"), py::arg("directory"), py::arg("overrides"),
        py::arg("width"), py::arg("height"), py::arg("threads"));
    m.def(
        "gallery",
        [](const std::string& dir, int width, int height, int spp, int figure_width, int threads,
           const std::vector<std::pair<std::string, std::string>>& pages) {
            gallery::GalleryOptions o;
            o.dir = dir;
            o.width = width, o.height = height, o.spp = spp, o.figure_width = figure_width, o.threads = threads;
            for (const auto& [file, title] : pages) o.pages.push_back({file, title});
            gallery::GalleryResult r;
            {
                py::gil_scoped_release release;
                try {
                    r = gallery::make_gallery(o);
                } catch (const Error& e) {
                    // Options out of range stay ValueError; a folder or file that cannot be
                    // written is an OSError.
                    const std::string what = e.what();
                    if (what.rfind("gallery: ", 0) == 0) throw;
                    throw FileError(what);
                }
            }
            return py::make_tuple(r.index.string(), r.seconds);
        },
        py::arg("dir"), py::arg("width"), py::arg("height"), py::arg("spp"), py::arg("figure_width"),
        py::arg("threads"), py::arg("pages"));
}

}  // namespace irid::python
