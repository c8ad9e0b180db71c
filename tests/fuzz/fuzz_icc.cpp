// Fuzz harness: ICC profiles through irid::IccProfile::parse (include/irid/exchange/icc.h), the
// reader of every profile embedded in an image irid opens (Little CMS 2 underneath).
//
// Input: the profile's bytes. Checked: a profile is either refused with irid::Error or parsed;
// a parsed profile's exact space decodes every code of [0, 1] to a finite value and encodes it
// is written again by make_icc_profile (or refused by it) and then reads back as the same space
// (primaries and white within 1e-4), and the Little CMS transform runs on a few colours.
#include "fuzz_support.h"

#include <irid/error.h>
#include <irid/exchange/icc.h>

#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::optional<irid::IccProfile> p;
    try {
        p.emplace(irid::IccProfile::parse(std::span<const unsigned char>(data, size), "fuzz.icc"));
    } catch (const irid::Error&) {
        return 0;
    }
    // The transform to XYZ runs (values need not be finite for a hostile table: the clip
    // pipeline takes non-finite values by its own rule).
    std::vector<float> rgb{0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 0.25f, 0.5f, 0.75f};
    std::vector<float> xyz(rgb.size());
    p->to_xyz(rgb, xyz, {0.3127, 0.3290}, 1);
    if (!p->rgb_space()) return 0;
    const irid::RgbSpace& s = *p->rgb_space();
    for (int i = 0; i <= 64; ++i) {
        const double e = i / 64.0;
        const double v = s.transfer().decode(e);
        IRID_FUZZ_REQUIRE(std::isfinite(v), "decode(" + std::to_string(e) + ") is not finite");
    }
    std::vector<unsigned char> again;
    try {
        again = irid::make_icc_profile(s);
    } catch (const irid::Error&) {
        return 0;  // a space no profile can hold (make_icc_profile reads its own result back)
    }
    const irid::IccProfile q = irid::IccProfile::parse(again, "fuzz.icc (written again)");
    IRID_FUZZ_REQUIRE(q.rgb_space().has_value(), "irid's own profile of the space is not exact");
    const auto near = [](const irid::Xy& a, const irid::Xy& b) {
        return std::abs(a.x - b.x) <= 1e-4 && std::abs(a.y - b.y) <= 1e-4;
    };
    const irid::RgbSpace& r = *q.rgb_space();
    IRID_FUZZ_REQUIRE(near(r.primaries().red, s.primaries().red) &&
                          near(r.primaries().green, s.primaries().green) &&
                          near(r.primaries().blue, s.primaries().blue) && near(r.white(), s.white()),
                      "the space written again reads back with other primaries or white");
    return 0;
}
