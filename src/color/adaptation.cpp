#include <irid/color/adaptation.h>
#include <irid/error.h>
#include <irid/text_input.h>

#include <cmath>
#include <string>

namespace irid {
namespace {

/// Bradford cone matrix, Lam 1985; ICC.1:2010 Annex E.
constexpr Mat3 bradford_matrix{{{{0.8951, 0.2664, -0.1614},
                                 {-0.7502, 1.7135, 0.0367},
                                 {0.0389, -0.0685, 1.0296}}}};
/// CAT02, CIE 159:2004 (CIECAM02).
constexpr Mat3 cat02_matrix{{{{0.7328, 0.4296, -0.1624},
                              {-0.7036, 1.6975, 0.0061},
                              {0.0030, 0.0136, 0.9834}}}};
/// Hunt-Pointer-Estévez cone fundamentals normalised to D65 (Fairchild, Color Appearance
/// Models, 3rd ed., ch. 9).
constexpr Mat3 hpe_matrix{{{{0.4002, 0.7076, -0.0808},
                            {-0.2263, 1.1653, 0.0457},
                            {0.0, 0.0, 0.9182}}}};

}  // namespace

Mat3 cone_response_matrix(ChromaticAdaptation method) noexcept {
    switch (method) {
        case ChromaticAdaptation::bradford: return bradford_matrix;
        case ChromaticAdaptation::cat02: return cat02_matrix;
        case ChromaticAdaptation::von_kries: return hpe_matrix;
        case ChromaticAdaptation::none: break;
    }
    return Mat3::identity();
}

Mat3 adaptation_matrix(const Xyz& source_white, const Xyz& destination_white,
                       ChromaticAdaptation method) {
    if (method == ChromaticAdaptation::none) return Mat3::identity();
    const Mat3 m = cone_response_matrix(method);
    const Vec3 s = m * Vec3{source_white.X, source_white.Y, source_white.Z};
    const Vec3 d = m * Vec3{destination_white.X, destination_white.Y, destination_white.Z};
    Vec3 gain{};
    for (int i = 0; i < 3; ++i) {
        if (!(std::abs(s[i]) > 1e-12) || !std::isfinite(d[i])) {
            throw Error("chromatic adaptation: the source white has no response in cone channel " +
                        std::to_string(i + 1) + "; whites must be real, positive colours");
        }
        gain[i] = d[i] / s[i];
    }
    return inverse(m, "cone response matrix") * Mat3::diagonal(gain) * m;
}

ChromaticAdaptation parse_chromatic_adaptation(std::string_view name) {
    if (name == "bradford") return ChromaticAdaptation::bradford;
    if (name == "cat02") return ChromaticAdaptation::cat02;
    if (name == "von-kries") return ChromaticAdaptation::von_kries;
    if (name == "none") return ChromaticAdaptation::none;
    throw UnknownNameError("unknown chromatic adaptation " + quote_untrusted(name) +
                               "; valid names: bradford, cat02, von-kries, none",
                           {"bradford", "cat02", "von-kries", "none"});
}

}  // namespace irid
