// Images for Python through irid_io (OpenImageIO): read into float32 arrays with their
// metadata, write from arrays. What irid_io refuses about a file (missing, unreadable, corrupt,
// too large, not a regular file to replace) raises OSError; a bad array raises ValueError.

#include "arrays.h"

#include <irid/io/image.h>

#include <pybind11/stl.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace irid::python {
void add_io(py::module_& m) {
    m.def(
        "read_image",
        [](const std::string& path) {
            io::Image image;
            {
                py::gil_scoped_release release;
                try {
                    image = io::read_image(path);
                } catch (const Error& e) {
                    throw FileError(e.what());
                }
            }
            py::array_t<float> pixels({py::ssize_t{image.height}, py::ssize_t{image.width},
                                       py::ssize_t{image.channels}});
            std::memcpy(pixels.mutable_data(), image.pixels.data(), image.pixels.size() * sizeof(float));
            py::dict meta;
            meta["channels"] = image.channel_names;
            meta["color_space"] = image.color_space;
            meta["description"] = image.description;
            meta["bits"] = image.stored_bits;
            meta["integer"] = image.stored_integer;
            return py::make_tuple(pixels, meta);
        },
        py::arg("path"));

    m.def(
        "write_image",
        [](const std::string& path, const py::handle& array, std::vector<std::string> channels,
           const std::string& color_space, const std::string& description, int bits,
           const std::string& compression) {
            const auto a = contiguous_of<float>(array, "image");
            if (a.ndim() != 2 && a.ndim() != 3) {
                throw py::value_error("image: shape " + shape_text(a) +
                                      "; expected (height, width) or (height, width, channels)");
            }
            io::Image image;
            image.height = static_cast<int>(std::min<py::ssize_t>(a.shape(0), 1 << 30));
            image.width = static_cast<int>(std::min<py::ssize_t>(a.shape(1), 1 << 30));
            image.channels = a.ndim() == 3 ? static_cast<int>(std::min<py::ssize_t>(a.shape(2), 1 << 30)) : 1;
            if (a.shape(0) < 1 || a.shape(1) < 1 || (a.ndim() == 3 && a.shape(2) < 1) ||
                a.shape(0) > 65536 || a.shape(1) > 65536 || image.channels > 64) {
                throw py::value_error("image: shape " + shape_text(a) +
                                      "; each side 1 to 65536 pixels, 1 to 64 channels");
            }
            if (channels.empty()) {
                static const char* const defaults[4][4] = {
                    {"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
                if (image.channels <= 4) {
                    for (int c = 0; c < image.channels; ++c) channels.emplace_back(defaults[image.channels - 1][c]);
                } else {
                    for (int c = 0; c < image.channels; ++c) channels.push_back("channel" + std::to_string(c));
                }
            }
            if (static_cast<int>(channels.size()) != image.channels) {
                throw py::value_error("channels: " + std::to_string(channels.size()) + " names for " +
                                      std::to_string(image.channels) + " channels");
            }
            for (std::size_t i = 0; i < channels.size(); ++i) {
                if (channels[i].empty()) throw py::value_error("channels: name " + std::to_string(i) + " is empty");
                for (std::size_t j = 0; j < i; ++j) {
                    if (channels[j] == channels[i]) {
                        throw py::value_error("channels: '" + channels[i] + "' is given twice");
                    }
                }
            }
            image.channel_names = std::move(channels);
            image.color_space = color_space;
            image.description = description;
            image.pixels.assign(a.data(), a.data() + a.size());
            py::gil_scoped_release release;
            try {
                io::write_image(path, image, io::ImageEncoding{.bits = bits, .compression = compression});
            } catch (const Error& e) {
                throw FileError(e.what());
            }
        },
        py::arg("path"), py::arg("array"), py::arg("channels"), py::arg("color_space"),
        py::arg("description"), py::arg("bits"), py::arg("compression"));
}

}  // namespace irid::python
