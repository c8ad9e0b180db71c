#include <irid/error.h>
#include <irid/io/image.h>

#include "image_backend.h"
#include "image_header.h"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

namespace irid::io {
namespace fs = std::filesystem;

namespace {

std::string default_channel_name(int c, int channels) {
    static const char* const rgba[] = {"R", "G", "B", "A"};
    if (channels <= 4 || c < 4) return rgba[c];
    return "channel" + std::to_string(c);
}

std::string lowercase(std::string s) {
    for (char& ch : s) {
        if (ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
    }
    return s;
}

/// Where the module may be, in order: $IRID_OIIO_MODULE; beside the running program (the build
/// tree's build/irid and an installed bin/irid's ../lib/irid); the build tree; the install tree.
std::vector<fs::path> module_candidates() {
    std::vector<fs::path> out;
    if (const char* env = std::getenv("IRID_OIIO_MODULE"); env != nullptr && *env != '\0') {
        out.emplace_back(env);
    }
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        out.push_back(exe.parent_path() / IRID_OIIO_MODULE_NAME);
        out.push_back(exe.parent_path().parent_path() / "lib" / "irid" / IRID_OIIO_MODULE_NAME);
    }
    // Beside the shared object this code is linked into (the Python extension, whose package
    // carries a copy of the module; for a program, the program itself, as above).
    Dl_info self{};
    if (dladdr(reinterpret_cast<void*>(&module_candidates), &self) != 0 && self.dli_fname != nullptr) {
        out.push_back(fs::path(self.dli_fname).parent_path() / IRID_OIIO_MODULE_NAME);
    }
    out.emplace_back(IRID_OIIO_MODULE_BUILD_PATH);
    out.emplace_back(IRID_OIIO_MODULE_INSTALL_PATH);
    return out;
}

const ImageBackend& backend() {
    static const ImageBackend* loaded = nullptr;
    static std::string failure;
    static std::once_flag once;
    std::call_once(once, [] {
        std::string tried;
        for (const fs::path& candidate : module_candidates()) {
            std::error_code ec;
            if (!fs::exists(candidate, ec)) {
                tried += "\n  " + candidate.string() + " (absent)";
                continue;
            }
            void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (handle == nullptr) {
                tried += "\n  " + candidate.string() + " (" + dlerror() + ")";
                continue;
            }
            using Entry = const ImageBackend* (*)();
            const auto entry = reinterpret_cast<Entry>(dlsym(handle, "irid_image_backend"));
            const ImageBackend* table = entry != nullptr ? entry() : nullptr;
            if (table == nullptr || table->abi_version != image_backend_abi_version) {
                tried += "\n  " + candidate.string() + " (not a matching irid image module)";
                continue;
            }
            loaded = table;
            return;
        }
        failure = "the OpenImageIO module " + std::string(IRID_OIIO_MODULE_NAME) +
                  " of irid was not found; looked for:" + tried +
                  "\n(set IRID_OIIO_MODULE to its path)";
    });
    if (loaded == nullptr) throw Error(failure);
    return *loaded;
}

}  // namespace

Image Image::blank(int width, int height, int channels) {
    if (width < 1 || height < 1 || channels < 1) {
        throw Error("an image needs width, height and channels of at least 1 (got " +
                    std::to_string(width) + ", " + std::to_string(height) + ", " +
                    std::to_string(channels) + ")");
    }
    Image image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    for (int c = 0; c < channels; ++c) image.channel_names.push_back(default_channel_name(c, channels));
    image.pixels.assign(image.pixel_count() * static_cast<std::size_t>(channels), 0.0f);
    return image;
}

int Image::channel_index(std::string_view name) const noexcept {
    for (std::size_t c = 0; c < channel_names.size(); ++c) {
        if (channel_names[c] == name) return static_cast<int>(c);
    }
    return -1;
}

ImageFormat image_format_for(const fs::path& path) {
    const std::string extension = lowercase(path.extension().string());
    if (extension == ".exr") return ImageFormat::exr;
    if (extension == ".png") return ImageFormat::png;
    if (extension == ".tif" || extension == ".tiff") return ImageFormat::tiff;
    if (extension == ".jpg" || extension == ".jpeg") return ImageFormat::jpeg;
    throw Error(path.string() + ": unsupported extension '" + path.extension().string() +
                "'; images are written as .exr (linear float), .png, .tif or .tiff (8 or 16 bit), "
                ".jpg or .jpeg (8 bit)");
}

std::array<long long, 4> data_window(const Image& image) noexcept {
    return {image.origin_x, image.origin_y, static_cast<long long>(image.origin_x) + image.width - 1,
            static_cast<long long>(image.origin_y) + image.height - 1};
}

void set_windows(Image& image, const std::optional<std::array<long long, 4>>& data_window,
                 const std::optional<std::array<long long, 4>>& display_window) {
    const auto text = [](const std::array<long long, 4>& b) {
        return std::to_string(b[0]) + " " + std::to_string(b[1]) + " " + std::to_string(b[2]) + " " +
               std::to_string(b[3]);
    };
    const auto check = [&](const std::array<long long, 4>& b, const char* name) {
        for (const long long v : b) {
            if (v < -max_window_coordinate || v > max_window_coordinate) {
                throw Error(std::string(name) + " " + text(b) + ": corners lie within ±" +
                            std::to_string(max_window_coordinate) + " (OpenEXR's limit)");
            }
        }
        if (b[0] > b[2] || b[1] > b[3]) {
            throw Error(std::string(name) + " " + text(b) + ": x min <= x max and y min <= y max");
        }
    };
    if (data_window) {
        const auto& d = *data_window;
        check(d, "data_window");
        if (d[2] - d[0] + 1 != image.width || d[3] - d[1] + 1 != image.height) {
            throw Error("data_window " + text(d) + " is " + std::to_string(d[2] - d[0] + 1) + " x " +
                        std::to_string(d[3] - d[1] + 1) + " pixels; the image is " + std::to_string(image.width) +
                        " x " + std::to_string(image.height));
        }
        image.origin_x = static_cast<int>(d[0]);
        image.origin_y = static_cast<int>(d[1]);
    }
    if (display_window) {
        check(*display_window, "display_window");
        const auto& d = *display_window;
        image.display_window = std::array<int, 4>{static_cast<int>(d[0]), static_cast<int>(d[1]),
                                                  static_cast<int>(d[2]), static_cast<int>(d[3])};
    }
}

std::string windows_dropped(const Image& image, ImageFormat format) {
    if (format == ImageFormat::exr) return "";
    const std::array<long long, 4> data = data_window(image);
    const bool display = image.display_window &&
                         !std::equal(data.begin(), data.end(), image.display_window->begin());
    if (image.origin_x == 0 && image.origin_y == 0 && !display) return "";
    const auto box = [](const auto& b) {
        return std::to_string(b[0]) + " " + std::to_string(b[1]) + " " + std::to_string(b[2]) + " " +
               std::to_string(b[3]);
    };
    static constexpr const char* names[] = {"EXR", "PNG", "TIFF", "JPEG"};
    return "the data window " + box(data) +
           (image.display_window ? " and display window " + box(*image.display_window) + " are" : " is") +
           " not kept in " + names[static_cast<int>(format)] + "; write an EXR to keep where the pixels sit";
}

Image read_image(const fs::path& path, const ImageLimits& limits) {
    const HeaderFacts facts = check_image_header(path, limits);
    Image image;
    std::string error;
    if (!backend().read(path.c_str(), &limits, &image, &error)) throw Error(error);
    if (!facts.icc_damage.empty()) {
        // OpenImageIO 2.4 drops a profile whose container is damaged, or passes on a part of it.
        image.icc_profile.clear();
        image.icc_profile_rejected = true;
        image.icc_profile_damage = facts.icc_damage;
    } else if (!facts.container_icc_profile.empty()) {
        // OpenImageIO joins JPEG segments in file order, and libtiff drops a TIFF profile tag
        // typed other than UNDEFINED or BYTE.
        image.icc_profile = facts.container_icc_profile;
    } else if (facts.png_icc_chunk && image.icc_profile.empty()) {
        image.icc_profile_rejected = true;
        image.icc_profile_damage = "libpng rejected it (it drops, with only a warning, a profile that is damaged "
                                   "or does not suit the image: CMYK, Lab or named colours in an RGB PNG)";
    }
    image.png_srgb = facts.png_srgb;
    image.png_gamma = facts.png_gamma;
    image.png_chromaticities = facts.png_chromaticities;
    image.png_cicp = facts.png_cicp;
    return image;
}

void write_image(OutputFile& file, const Image& image, const ImageEncoding& encoding) {
    std::string error;
    if (!backend().write(&file, &image, &encoding, &error)) throw Error(error);
}

void write_image(const fs::path& path, const Image& image, const ImageEncoding& encoding) {
    // The extension first: an unsupported one creates nothing.
    (void)image_format_for(path);
    OutputFile file(path);
    write_image(file, image, encoding);
    file.commit();
}

}  // namespace irid::io
