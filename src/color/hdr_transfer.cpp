#include <irid/color/hdr_transfer.h>

#include <algorithm>
#include <cmath>

namespace irid {
namespace {

// SMPTE ST 2084:2014 / ITU-R BT.2100-2 Table 4, exactly as the standard writes them.
constexpr double pq_m1 = 2610.0 / 16384.0;
constexpr double pq_m2 = 2523.0 / 4096.0 * 128.0;
constexpr double pq_c1 = 3424.0 / 4096.0;
constexpr double pq_c2 = 2413.0 / 4096.0 * 32.0;
constexpr double pq_c3 = 2392.0 / 4096.0 * 32.0;

// ITU-R BT.2100-2 Table 5: a, b = 1 − 4a, c = 0.5 − a ln(4a) (given there to 8 decimals; the
// exact relations keep the two branches continuous at E = 1/12).
constexpr double hlg_a = 0.17883277;
constexpr double hlg_b = 1.0 - 4.0 * hlg_a;
const double hlg_c = 0.5 - hlg_a * std::log(4.0 * hlg_a);

// BT.2100-2 Table 5, the luminance Y_S of the OOTF (Rec.2020 primaries).
constexpr std::array<double, 3> bt2100_luminance{0.2627, 0.6780, 0.0593};

/// x clamped to [lo, hi], NaN taken as 0 (then clamped).
double clamped(double x, double lo, double hi) noexcept {
    if (std::isnan(x)) x = 0.0;
    return std::clamp(x, lo, hi);
}

}  // namespace

double pq_encode(double nits) noexcept {
    const double y = std::pow(clamped(nits, 0.0, pq_peak_nits) / pq_peak_nits, pq_m1);
    return std::pow((pq_c1 + pq_c2 * y) / (1.0 + pq_c3 * y), pq_m2);
}

double pq_decode(double signal) noexcept {
    const double e = std::pow(clamped(signal, 0.0, 1.0), 1.0 / pq_m2);
    const double y = std::max(e - pq_c1, 0.0) / (pq_c2 - pq_c3 * e);
    return pq_peak_nits * std::pow(y, 1.0 / pq_m1);
}

double hlg_oetf(double scene) noexcept {
    const double e = clamped(scene, 0.0, 1.0);
    return e <= 1.0 / 12.0 ? std::sqrt(3.0 * e) : hlg_a * std::log(12.0 * e - hlg_b) + hlg_c;
}

double hlg_inverse_oetf(double signal) noexcept {
    const double e = clamped(signal, 0.0, 1.0);
    return e <= 0.5 ? e * e / 3.0 : (std::exp((e - hlg_c) / hlg_a) + hlg_b) / 12.0;
}

double hlg_system_gamma(double peak_nits) noexcept {
    return 1.2 + 0.42 * std::log10(clamped(peak_nits, 100.0, 10000.0) / 1000.0);
}

std::array<double, 3> hlg_ootf(const std::array<double, 3>& scene, double peak_nits) noexcept {
    const double peak = clamped(peak_nits, 100.0, 10000.0);
    const double gamma = hlg_system_gamma(peak);
    std::array<double, 3> e{};
    double ys = 0.0;
    for (int i = 0; i < 3; ++i) {
        e[i] = clamped(scene[i], 0.0, 1.0);
        ys += bt2100_luminance[i] * e[i];
    }
    // Y_S^(γ − 1) with γ >= 0.78 (at 100 cd/m²): 0^(γ − 1) is only reached with E = 0.
    const double gain = ys > 0.0 ? peak * std::pow(ys, gamma - 1.0) : 0.0;
    return {gain * e[0], gain * e[1], gain * e[2]};
}

std::array<double, 3> hlg_inverse_ootf(const std::array<double, 3>& display, double peak_nits) noexcept {
    const double peak = clamped(peak_nits, 100.0, 10000.0);
    // Below L_W the OOTF can give up to 0.0593^(γ − 1) L_W ≈ 1.86 L_W (pure blue at γ = 0.78);
    // 2 L_W bounds every value it gives.
    std::array<double, 3> f{};
    for (int i = 0; i < 3; ++i) f[i] = clamped(display[i], 0.0, 2.0 * peak);
    const std::array<double, 3> e = hlg_scene_light_unclamped(f, peak);
    return {std::min(1.0, e[0]), std::min(1.0, e[1]), std::min(1.0, e[2])};
}

std::array<double, 3> hlg_scene_light_unclamped(const std::array<double, 3>& display, double peak_nits) noexcept {
    const double peak = clamped(peak_nits, 100.0, 10000.0);
    const double gamma = hlg_system_gamma(peak);
    std::array<double, 3> f{};
    double yd = 0.0;
    for (int i = 0; i < 3; ++i) {
        f[i] = std::isnan(display[i]) ? 0.0 : display[i];
        yd += bt2100_luminance[i] * f[i];
    }
    if (!(yd > 0.0)) return {0.0, 0.0, 0.0};
    const double scale = std::pow(yd / peak, (1.0 - gamma) / gamma) / peak;
    return {f[0] * scale, f[1] * scale, f[2] * scale};
}

std::array<double, 3> hlg_decode(const std::array<double, 3>& signal, double peak_nits) noexcept {
    return hlg_ootf({hlg_inverse_oetf(signal[0]), hlg_inverse_oetf(signal[1]), hlg_inverse_oetf(signal[2])},
                    peak_nits);
}

std::array<double, 3> hlg_encode(const std::array<double, 3>& display, double peak_nits) noexcept {
    const std::array<double, 3> e = hlg_inverse_ootf(display, peak_nits);
    return {hlg_oetf(e[0]), hlg_oetf(e[1]), hlg_oetf(e[2])};
}

}  // namespace irid
