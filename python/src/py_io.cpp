// Images for Python through irid_io (OpenImageIO): read into float32 arrays with their
// metadata, write from arrays. What irid_io refuses about a file (missing, unreadable, corrupt,
// too large, not a regular file to replace) raises OSError; a bad array raises ValueError.

#include "arrays.h"

#include <irid/color/convert.h>
#include <irid/exchange/icc.h>
#include <irid/io/image.h>

#include <pybind11/stl.h>

#include <optional>
#include <span>

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <vector>

namespace irid::python {
namespace {

/// The RGB space a name says: for a NAME-linear name, its primaries and white with a linear curve.
RgbSpace as_named(const ColorSpace& s) {
    if (s.family == SpaceFamily::rgb_linear && s.rgb->transfer().kind() != TransferFunction::Kind::linear) {
        return RgbSpace(s.rgb->name() + "-linear", s.rgb->primaries(), s.rgb->white(),
                        TransferFunction(TransferFunction::Kind::linear));
    }
    return *s.rgb;
}

}  // namespace

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
            meta["icc_profile"] = image.icc_profile.empty()
                                      ? py::object(py::none())
                                      : py::object(py::bytes(reinterpret_cast<const char*>(image.icc_profile.data()),
                                                             image.icc_profile.size()));
            meta["icc_profile_rejected"] = image.icc_profile_rejected;
            meta["cmyk"] = image.stored_cmyk;
            py::dict png;
            if (image.png_srgb) png["srgb"] = true;
            if (image.png_gamma > 0.0) png["gamma"] = image.png_gamma;
            if (!image.png_chromaticities.empty()) png["chromaticities"] = py::tuple(py::cast(image.png_chromaticities));
            if (!image.png_cicp.empty()) png["cicp"] = py::tuple(py::cast(std::vector<int>(image.png_cicp.begin(), image.png_cicp.end())));
            meta["png"] = png.empty() ? py::object(py::none()) : py::object(png);
            const auto window = data_window(image);
            meta["data_window"] = py::make_tuple(window[0], window[1], window[2], window[3]);
            meta["display_window"] = image.display_window
                                         ? py::make_tuple((*image.display_window)[0], (*image.display_window)[1],
                                                          (*image.display_window)[2], (*image.display_window)[3])
                                         : py::make_tuple(window[0], window[1], window[2], window[3]);
            meta["model"] = image.stored_model.empty() ? py::object(py::none()) : py::object(py::str(image.stored_model));
            meta["icc_profile_damage"] = image.icc_profile_damage.empty() ? py::object(py::none())
                                                                          : py::object(py::str(image.icc_profile_damage));
            meta["chromaticities"] = image.chromaticities.empty() ? py::object(py::none())
                                                                  : py::object(py::tuple(py::cast(image.chromaticities)));
            meta["adopted_neutral"] = image.adopted_neutral.empty() ? py::object(py::none())
                                                                    : py::object(py::tuple(py::cast(image.adopted_neutral)));
            return py::make_tuple(pixels, meta);
        },
        py::arg("path"));

    m.def(
        "write_image",
        [](const std::string& path, const py::handle& array, std::vector<std::string> channels,
           const std::string& color_space, const std::string& description, int bits,
           const std::string& compression, bool tag, const std::optional<py::bytes>& icc_profile,
           const std::optional<std::vector<float>>& chromaticities,
           const std::optional<std::array<long long, 4>>& data_window,
           const std::optional<std::array<long long, 4>>& display_window) {
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
            // The file says what space it holds: a built-in space's profile or chromaticities
            // (irid/exchange/icc.h), or what the caller gives.
            io::ImageFormat format{};
            try {
                format = io::image_format_for(path);
            } catch (const Error& e) {
                throw FileError(e.what());
            }
            // With tag, color_space names one of irid's spaces (UnknownNameError: KeyError) and
            // the file also says so to other programs, which only an RGB space can; without, it
            // is a text attribute.
            std::optional<ColorSpace> named;
            if (!color_space.empty()) {
                if (tag) {
                    try {
                        named = irid::color_space(color_space);
                    } catch (const UnknownNameError& e) {
                        throw UnknownNameError(std::string(e.what()) +
                                                   " (give tag=False to store another name as a text attribute)",
                                               e.valid());
                    }
                } else {
                    named = find_color_space(color_space);
                }
            }
            if (tag && named) {
                if (!named->is_rgb()) {
                    throw py::value_error("color_space '" + color_space + "' is not an RGB space: no ICC profile or "
                                          "chromaticities describe it; give tag=False to write its name alone");
                }
                tag_image(image, as_named(*named), format);
            }
            // A name of irid's, in any case, is written as its canonical one.
            image.color_space = tag && named ? color_space_name(*named) : color_space;
            if (icc_profile) {
                if (format == io::ImageFormat::exr) {
                    throw py::value_error("icc_profile: EXR files carry chromaticities, not ICC profiles");
                }
                const std::string bytes = *icc_profile;
                image.icc_profile.assign(bytes.begin(), bytes.end());
                (void)IccProfile::parse(image.icc_profile, "icc_profile");  // refused like a file's
            }
            if (chromaticities) {
                if (format != io::ImageFormat::exr) {
                    throw py::value_error("chromaticities: only EXR files carry them (PNG and TIFF carry an ICC profile)");
                }
                (void)rgb_space_from_chromaticities(*chromaticities, "chromaticities", "chromaticities");
                image.chromaticities = *chromaticities;
                image.adopted_neutral.clear();
            }
            if (named && named->is_rgb() && (icc_profile || chromaticities)) {
                check_tags_agree(image, as_named(*named), color_space);
            }
            if ((data_window || display_window) && format != io::ImageFormat::exr) {
                throw py::value_error("data_window, display_window: only EXR files carry windows");
            }
            io::set_windows(image, data_window, display_window);
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
        py::arg("description"), py::arg("bits"), py::arg("compression"), py::arg("tag"),
        py::arg("icc_profile"), py::arg("chromaticities"), py::arg("data_window"), py::arg("display_window"));

    m.def(
        "icc_profile",
        [](const std::string& space, const std::string& description) {
            const ColorSpace s = color_space(space);
            if (!s.is_rgb()) throw Error("space '" + space + "' is not an RGB space; ICC profiles describe RGB spaces");
            const std::vector<unsigned char> bytes = make_icc_profile(as_named(s), description);
            return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        },
        py::arg("space"), py::arg("description"));

    m.def(
        "read_icc_profile",
        [](const py::bytes& data) {
            const std::string bytes = data;
            const IccProfile p = IccProfile::parse(
                std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()), "profile");
            py::dict d;
            d["description"] = p.description();
            d["version"] = p.version();
            d["exact"] = p.rgb_space().has_value();
            d["reason"] = p.not_exact_reason();
            if (p.rgb_space()) {
                const RgbSpace& s = *p.rgb_space();
                const RgbSpace* builtin = matching_builtin_space(s);
                d["space"] = builtin != nullptr ? py::object(py::str(builtin->name())) : py::object(py::none());
                const RgbPrimaries& q = s.primaries();
                d["primaries"] = py::make_tuple(py::make_tuple(q.red.x, q.red.y), py::make_tuple(q.green.x, q.green.y),
                                                py::make_tuple(q.blue.x, q.blue.y));
                d["white"] = py::make_tuple(s.white().x, s.white().y);
                py::dict t;
                if (const auto params = s.transfer().parameters()) {
                    t["kind"] = "parametric";
                    t["parameters"] = py::tuple(py::cast(std::vector<double>(params->begin(), params->end())));
                } else {
                    t["kind"] = "sampled";
                    const auto samples = s.transfer().samples();
                    t["samples"] = py::tuple(py::cast(std::vector<double>(samples.begin(), samples.end())));
                }
                d["transfer"] = t;
            } else {
                d["space"] = py::none();
                d["primaries"] = py::none();
                d["white"] = py::none();
                d["transfer"] = py::none();
            }
            return d;
        },
        py::arg("data"));
}

}  // namespace irid::python
