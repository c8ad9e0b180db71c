// aces-rgc against OpenColorIO 2.1 itself (libopencolorio-dev, OCIO 2.1.2): its FixedFunction
// ACES_GAMUT_COMP_13 (FixedFunctionOpCPU.cpp, in float) and its built-in LMT
// "ACES-LMT - ACES 1.3 Reference Gamut Compression" (BuiltinTransformRegistry: the AP0 → AP1
// matrix, the FixedFunction with the published parameters, AP1 → AP0), on ≥ 100 000 colours
// each: negative, zero, achromatic, beyond the limits and above 1, forward and inverse.
//
// Tolerance: 1e-6 × max(1, |ach| + |value|) (ach the colour's largest channel, value irid's
// result), since OCIO computes in float (6e-8 of every magnitude it handles, and the output
// ach − D |ach| is the difference of terms up to |ach| + |value| in size). The inverse is
// ill-conditioned near its asymptote: one rounding of the distance d is amplified by the curve's
// slope κ = (1 − u)^(−(1+p)/p), u = nd^p, so there the tolerance is multiplied by κ (computed
// from the input in double); colours whose distance lies within 1e-6 (relative) above the
// asymptote, where the inverse jumps from +inf back to the identity and float may round d to the
// other side, are counted and left out. The largest errors measured are printed.

#include <irid/color/rgb.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace irid {
namespace {

namespace OCIO = OCIO_NAMESPACE;

/// The seven parameters in OCIO's order (FixedFunctionOpData: lim_cyan, lim_magenta,
/// lim_yellow, thr_cyan, thr_magenta, thr_yellow, power), which is also irid's table order.
using Params = std::array<double, 7>;
constexpr Params published{1.147, 1.264, 1.312, 0.815, 0.803, 0.880, 1.2};
const char* const names[7] = {"limit-cyan",        "limit-magenta",    "limit-yellow",
                              "threshold-cyan",    "threshold-magenta", "threshold-yellow",
                              "power"};

ClipSettings settings(const Params& p, bool inverse) {
    ClipSettings s;
    for (std::size_t k = 0; k < 7; ++k) s.set(names[k], p[k]);
    s.inverse = inverse;
    return s;
}

/// Runs `transform` through OCIO's default CPU processor on packed float RGB, in place.
void ocio_apply(const OCIO::ConstTransformRcPtr& transform, std::vector<float>& rgb) {
    const OCIO::ConstConfigRcPtr config = OCIO::Config::CreateRaw();
    const OCIO::ConstCPUProcessorRcPtr cpu = config->getProcessor(transform)->getDefaultCPUProcessor();
    OCIO::PackedImageDesc image(rgb.data(), static_cast<long>(rgb.size() / 3), 1, 3);
    cpu->apply(image);
}

OCIO::ConstTransformRcPtr fixed_function(const Params& p, bool inverse) {
    OCIO::FixedFunctionTransformRcPtr t =
        OCIO::FixedFunctionTransform::Create(OCIO::FIXED_FUNCTION_ACES_GAMUT_COMP_13, p.data(), 7);
    t->setDirection(inverse ? OCIO::TRANSFORM_DIR_INVERSE : OCIO::TRANSFORM_DIR_FORWARD);
    return t;
}

/// ≥ 100 000 colours (as floats, the precision OCIO works in): wide random colours over six
/// decades, colours at and beyond each channel's limit and threshold, achromatic ones, zeros and
/// a zero maximum, all-negative ones.
std::vector<float> colours(const Params& p, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<float> v;
    const auto push = [&](double r, double g, double b) {
        v.push_back(static_cast<float>(r));
        v.push_back(static_cast<float>(g));
        v.push_back(static_cast<float>(b));
    };
    for (int i = 0; i < 60000; ++i) {
        const double scale = std::pow(10.0, 6.0 * u(rng) - 3.0);
        push(scale * (5 * u(rng) - 2), scale * (5 * u(rng) - 2), scale * (5 * u(rng) - 2));
    }
    for (int i = 0; i < 36000; ++i) {
        // One channel at a distance around its threshold and limit, up to 3 (beyond the limit).
        const int k = i % 3;
        const double ach = std::pow(10.0, 4.0 * u(rng) - 2.0) * (i % 7 == 0 ? -1.0 : 1.0);
        const double d = i % 4 == 0 ? p[3 + static_cast<std::size_t>(k)] + 1e-3 * (u(rng) - 0.5)
                         : i % 4 == 1 ? p[static_cast<std::size_t>(k)] * (1.0 + 1e-3 * (u(rng) - 0.5))
                                      : 3.0 * u(rng);
        double c[3] = {ach, ach, ach};
        c[k] = ach - d * std::abs(ach);
        c[(k + 1) % 3] = ach - 0.5 * u(rng) * std::abs(ach);
        push(c[0], c[1], c[2]);
    }
    for (int i = 0; i < 4000; ++i) {
        const double a = 10 * u(rng) - 5;
        push(a, a, a);                                 // achromatic
        push(0.0, -u(rng), -3 * u(rng));               // zero maximum
        push(-u(rng) - 0.1, -2 * u(rng) - 0.1, -0.05);  // all negative
    }
    push(0, 0, 0);
    return v;
}

/// The inverse's slope κ at channel value c of a colour with axis ach (1 below the threshold),
/// or +inf within 1e-6 above the asymptote (where float may fall on either side).
double inverse_slope(const GamutClipper& g, double ach, double c, std::size_t k) {
    if (ach == 0.0) return 1.0;
    const double d = (ach - c) / std::abs(ach);
    const double thr = g.aces_rgc_prepared().threshold[k], s = g.aces_rgc_prepared().scale[k], p = g.aces_rgc_prepared().power;
    if (d < thr) return 1.0;
    if (d >= thr + s) return d < (thr + s) * (1.0 + 1e-6) ? HUGE_VAL : 1.0;
    const double u = std::pow((d - thr) / s, p);
    return std::max(1.0, std::pow(1.0 - u, -(1.0 + p) / p));
}

struct Errors {
    double worst = 0.0;        // max |irid − OCIO| / (1e-6-scale), conditioning included
    double worst_plain = 0.0;  // the same without κ, over the colours with κ <= 2
    int skipped = 0;           // at the inverse's asymptote
};

/// Compares irid's `out` (3 floats or doubles per colour) with OCIO's; fails above tolerance.
template <class Out>
Errors compare(const GamutClipper& g, const std::vector<float>& in, const std::vector<float>& ocio,
               const Out& out, const std::string& what) {
    Errors e;
    int failures = 0;
    for (std::size_t i = 0; i < in.size() / 3; ++i) {
        const double ach = std::max({in[3 * i], in[3 * i + 1], in[3 * i + 2]});
        for (std::size_t k = 0; k < 3; ++k) {
            const double kappa = g.inverse() ? inverse_slope(g, ach, in[3 * i + k], k) : 1.0;
            if (!std::isfinite(kappa)) {
                ++e.skipped;
                continue;
            }
            const double value = static_cast<double>(out[3 * i + k]);
            const double scale = std::max(1.0, std::abs(ach) + std::abs(value));
            const double err = std::abs(value - static_cast<double>(ocio[3 * i + k])) / scale;
            e.worst = std::max(e.worst, err / kappa);
            if (kappa <= 2.0) e.worst_plain = std::max(e.worst_plain, err);
            if (err > 1e-6 * kappa && ++failures <= 5) {
                ADD_FAILURE() << what << ": colour (" << in[3 * i] << ", " << in[3 * i + 1] << ", "
                              << in[3 * i + 2] << ") channel " << k << ": irid " << value
                              << ", OCIO " << ocio[3 * i + k] << " (kappa " << kappa << ")";
            }
        }
    }
    EXPECT_EQ(failures, 0) << what;
    std::cout << what << ": max error " << e.worst << " x max(1, |ach| + |value|) x kappa; "
              << e.worst_plain << " without kappa where kappa <= 2; " << e.skipped
              << " channels at the asymptote left out\n";
    return e;
}

TEST(AcesRgcOcio, FixedFunctionForwardAndInverseWithDefaultAndOtherParameters) {
    EXPECT_EQ(std::string(OCIO::GetVersion()).substr(0, 3), "2.1");
    const Params others[] = {published,
                             {1.3, 1.2, 1.5, 0.7, 0.75, 0.9, 2.0},
                             {1.05, 1.9, 1.147, 0.5, 0.95, 0.0, 1.0}};
    std::uint32_t seed = 1;
    for (const Params& p : others) {
        for (const bool inverse : {false, true}) {
            const GamutClipper g(ClipMethod::aces_rgc, Gamut(acescg()), settings(p, inverse));
            const std::vector<float> in = colours(p, seed++);
            ASSERT_GE(in.size() / 3, 100000u);
            std::vector<float> ocio = in;
            ocio_apply(fixed_function(p, inverse), ocio);
            std::vector<double> scalar(in.size());
            for (std::size_t i = 0; i < in.size() / 3; ++i) {
                const Rgb o = g.clip({in[3 * i], in[3 * i + 1], in[3 * i + 2]});
                scalar[3 * i] = o.r;
                scalar[3 * i + 1] = o.g;
                scalar[3 * i + 2] = o.b;
            }
            std::vector<float> batch(in.size());
            clip_batch(g, in, batch);
            const std::string what = std::string(inverse ? "inverse" : "forward") + " power " +
                                     std::to_string(p[6]);
            const Errors a = compare(g, in, ocio, scalar, "GamutClipper::clip " + what);
            const Errors b = compare(g, in, ocio, batch, "clip_batch " + what);
            EXPECT_EQ(a.skipped, b.skipped);
            if (!inverse) {
                EXPECT_EQ(a.skipped, 0);
            }
        }
    }
}

TEST(AcesRgcOcio, BuiltinLmtEqualsAp0ToAp1ThenAcesRgcThenBack) {
    // Registered name, checked in OCIO 2.1's BuiltinTransformRegistry.
    const char* const style = "ACES-LMT - ACES 1.3 Reference Gamut Compression";
    const OCIO::ConstBuiltinTransformRegistryRcPtr registry = OCIO::BuiltinTransformRegistry::Get();
    bool listed = false;
    for (std::size_t i = 0; i < registry->getNumBuiltins(); ++i) {
        listed = listed || std::string(registry->getBuiltinStyle(i)) == style;
    }
    ASSERT_TRUE(listed);
    OCIO::BuiltinTransformRcPtr lmt = OCIO::BuiltinTransform::Create();
    lmt->setStyle(style);

    // irid: ACES2065-1 → ACEScg by the RGB spaces' matrices (same white: no adaptation), the
    // compression with its published defaults in ACEScg, and back.
    const Mat3 to_ap1 = acescg().from_xyz_matrix() * aces2065_1().to_xyz_matrix();
    const Mat3 to_ap0 = aces2065_1().from_xyz_matrix() * acescg().to_xyz_matrix();
    const GamutClipper g(ClipMethod::aces_rgc, Gamut(acescg()));

    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<float> in;
    for (int i = 0; i < 120000; ++i) {
        const double scale = std::pow(10.0, 4.0 * u(rng) - 2.0);
        for (int k = 0; k < 3; ++k) {
            // AP0 values, mostly positive (camera data), some negative.
            in.push_back(static_cast<float>(scale * (i % 5 == 0 ? 3 * u(rng) - 1 : 2 * u(rng))));
        }
    }
    in.insert(in.end(), {0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 0.0f});
    std::vector<float> ocio = in;
    ocio_apply(lmt, ocio);
    double worst = 0.0;
    int failures = 0;
    for (std::size_t i = 0; i < in.size() / 3; ++i) {
        const Vec3 ap1 = to_ap1 * Vec3{in[3 * i], in[3 * i + 1], in[3 * i + 2]};
        const Rgb c = g.clip({ap1[0], ap1[1], ap1[2]});
        const Vec3 out = to_ap0 * Vec3{c.r, c.g, c.b};
        const double scale = std::max({1.0, std::abs(static_cast<double>(in[3 * i])),
                                       std::abs(static_cast<double>(in[3 * i + 1])),
                                       std::abs(static_cast<double>(in[3 * i + 2]))});
        for (std::size_t k = 0; k < 3; ++k) {
            const double err = std::abs(out[k] - ocio[3 * i + k]) / scale;
            worst = std::max(worst, err);
            if (err > 1e-6 && ++failures <= 5) {
                ADD_FAILURE() << "AP0 (" << in[3 * i] << ", " << in[3 * i + 1] << ", "
                              << in[3 * i + 2] << ") channel " << k << ": irid "
                              << out[k] << ", OCIO " << ocio[3 * i + k];
            }
        }
    }
    EXPECT_EQ(failures, 0);
    std::cout << "builtin LMT: max error " << worst << " x max(1, max |AP0 input|)\n";
}

}  // namespace
}  // namespace irid
