#include "png_space.h"

#include <irid/color/rgb.h>
#include <irid/error.h>

#include <fmt/core.h>

#include <cmath>

namespace irid::detail {

ImageSpace png_cicp_space(const io::Image& image, const std::string& what) {
    const auto& c = image.png_cicp;
    if (c.size() != 4) throw Error(what + ": cICP: " + std::to_string(c.size()) + " codes; it holds 4");
    const int primaries = c[0], transfer = c[1], matrix = c[2], full = c[3];
    const std::string codes = fmt::format("colour primaries {}, transfer {}, matrix {}, full range {}",
                                          primaries, transfer, matrix, full);
    const RgbSpace* space = nullptr;
    bool linear = false;
    if (matrix == 0 && full == 1) {
        // ITU-T H.273 Tables 2 and 3: primaries 1 BT.709, 9 BT.2020, 12 SMPTE EG 432-1 (P3,
        // D65); transfer 13 IEC 61966-2-1 (sRGB), 8 linear.
        if (primaries == 1 && transfer == 13) space = &srgb();
        if (primaries == 12 && transfer == 13) space = &display_p3();
        if (transfer == 8) {
            linear = true;
            space = primaries == 1 ? &srgb() : primaries == 9 ? &rec2020() : primaries == 12 ? &display_p3() : nullptr;
        }
    }
    if (space == nullptr) {
        throw Error(what + ": its cICP chunk names " + codes +
                    ", which irid does not read (it reads RGB, full range, with BT.709 or P3 primaries and the "
                    "sRGB transfer, or BT.709, BT.2020 or P3 primaries and the linear one)");
    }
    ImageSpace s;
    s.builtin = space;
    s.rgb = *space;
    s.encoded = !linear;
    s.linear_stated = linear;
    s.origin = "its cICP chunk (" + codes + ")";
    return s;
}

ImageSpace png_chunks_space(const io::Image& image, const std::string& what) {
    ImageSpace s;
    if (image.png_srgb) {
        s.builtin = &srgb();
        s.rgb = srgb();
        s.encoded = true;
        s.origin = "its sRGB chunk";
        return s;
    }
    const bool chromaticities = !image.png_chromaticities.empty();
    const bool gamma = image.png_gamma > 0.0;
    const RgbSpace primaries = chromaticities ? rgb_space_from_chromaticities(image.png_chromaticities, "png-chrm",
                                                                              what + ": cHRM")
                                              : srgb();
    TransferFunction curve = srgb().transfer();
    if (gamma) {
        // gAMA's gamma g: samples = light^g (ISO/IEC 15948 §11.3.3.2), the power law v^(1/γ) with γ = 1/g.
        const double g = image.png_gamma;
        if (g < 0.1) {
            throw Error(fmt::format("{}: its gAMA chunk gives a gamma of {:g} (samples = light^{:g}); irid decodes "
                                    "gammas of 0.1 or more",
                                    what, g, g));
        }
        curve = TransferFunction(TransferFunction::Kind::gamma, 1.0 / g);
    }
    // gAMA 1 (100000): the samples are linear light, in the linear form of a space.
    const bool linear = gamma && image.png_gamma == 1.0;
    const RgbSpace space("png-gama-chrm", primaries.primaries(), primaries.white(),
                         linear ? TransferFunction(TransferFunction::Kind::linear) : curve);
    s.builtin = matching_builtin_space(space, 2e-4, linear);
    s.rgb = s.builtin != nullptr ? *s.builtin : space;
    s.encoded = !linear;
    s.linear_stated = linear;
    const std::string said_primaries =
        chromaticities ? fmt::format("cHRM red {:.5f}, {:.5f}, green {:.5f}, {:.5f}, blue {:.5f}, {:.5f}, white "
                                     "{:.5f}, {:.5f}",
                                     image.png_chromaticities[0], image.png_chromaticities[1],
                                     image.png_chromaticities[2], image.png_chromaticities[3],
                                     image.png_chromaticities[4], image.png_chromaticities[5],
                                     image.png_chromaticities[6], image.png_chromaticities[7])
                       : std::string("no cHRM, so sRGB's primaries and white");
    const std::string said_gamma =
        gamma ? fmt::format("gAMA {:g}", image.png_gamma) : std::string("no gAMA, so sRGB's curve");
    s.origin = "its " + said_gamma + " and " + said_primaries;
    return s;
}

}  // namespace irid::detail
