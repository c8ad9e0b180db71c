#include <irid/exchange/image_source.h>

#include <fmt/format.h>

namespace irid {
namespace {

/// What the file itself says about its space, in words, for a note that a given space
/// overrides it; empty when it says nothing.
std::string what_the_file_says(const io::Image& image, const std::string& what) {
    if (!image_says_its_space(image)) return "";
    try {
        return image_space(image, what).origin;
    } catch (const Error& e) {
        return std::string("a space irid cannot use (") + e.what() + ")";
    }
}

/// "--from srgb" for an option, "source='srgb'" for a keyword ("source=").
std::string naming(const std::string& option, const std::string& name) {
    if (!option.empty() && option.back() == '=') return option + "'" + name + "'";
    return option + " " + name;
}

}  // namespace

bool image_says_its_space(const io::Image& image) noexcept {
    return !image.icc_profile.empty() || image.icc_profile_rejected || !image.chromaticities.empty() ||
           image.stored_cmyk || !image.stored_model.empty() || image.png_srgb || image.png_gamma > 0.0 ||
           !image.png_chromaticities.empty() || !image.png_cicp.empty();
}

ImageSource decide_image_source(const io::Image& image, bool xyz_channels, const std::optional<ColorSpace>& given,
                                const std::string& what, const std::string& option) {
    ImageSource s;
    if (xyz_channels) {
        if (given && given->family != SpaceFamily::xyz) {
            throw ImageSourceConflict(what + " holds X, Y and Z channels (CIE XYZ) but " + option + " is " +
                                      color_space_name(*given) + "; give " + naming(option, "xyz") +
                                      ", or leave it out");
        }
        s.space = ColorSpace{SpaceFamily::xyz, nullptr};
        s.described = "xyz";
    } else if (given) {
        s.space = *given;
        s.described = color_space_name(*given);
        if (const std::string said = what_the_file_says(image, what); !said.empty()) {
            s.notes.push_back(fmt::format("{} overrides what {} says: {}", naming(option, s.described), what, said));
        }
    } else {
        auto file = std::make_shared<ImageSpace>(image_space(image, what));
        if (file->assumed && image.stored_integer) {
            s.notes.push_back(fmt::format("{} has no ICC profile; its values are taken as sRGB (give {} to say otherwise)",
                                          what, !option.empty() && option.back() == '=' ? option + "NAME" : option));
        }
        s.space = file->colour_space();
        s.described = file->profile   ? file->origin
                      : file->assumed ? color_space_name(s.space)
                                      : fmt::format("{} ({})", color_space_name(s.space), file->origin);
        s.file = std::move(file);
    }
    // Not when the file itself says its integers are linear light (a PNG's gAMA 1, a cICP's linear transfer).
    if (image.stored_integer && s.space.family == SpaceFamily::rgb_linear && !(s.file && s.file->linear_stated)) {
        s.notes.push_back(fmt::format("{} holds {}-bit encoded values; {} takes them as linear light (give {} to "
                                      "decode them)",
                                      what, image.stored_bits, naming(option, color_space_name(s.space)),
                                      naming(option, s.space.rgb->name())));
    }
    return s;
}

}  // namespace irid
