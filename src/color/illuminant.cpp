#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/color/numeric_table.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/text_input.h>

#include "cie_tables.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

namespace irid {
namespace {

namespace data = detail::cie_data;

/// A 5 nm table starting at 300 nm, linear between its values (CIE 015:2018 §6.1), evaluated
/// on the 1 nm grid. `table` must reach 830 nm.
template <std::size_t Size>
DenseSpectrum from_5nm_table(const std::array<double, Size>& table) {
    static_assert(data::table5_first_nm + data::table5_step_nm * (static_cast<int>(Size) - 1) >=
                  lambda_max_nm);
    return DenseSpectrum::from_function([&](double lambda) {
        const int offset = static_cast<int>(lambda) - data::table5_first_nm;
        const int i = offset / data::table5_step_nm;
        const int r = offset % data::table5_step_nm;
        if (r == 0) return table[i];
        const double f = static_cast<double>(r) / data::table5_step_nm;
        return table[i] + f * (table[i + 1] - table[i]);
    });
}

/// The factor that turns a nominal CCT of the old temperature scale (c2 = 1.4380e-2 m·K) into
/// the CCT on the current one (c2 = 1.4388e-2 m·K): CIE 015:2018, illuminant D65 "approximately
/// 6504 K".
constexpr double c2_ratio = 1.4388 / 1.4380;

bool parse_double(std::string_view s, double& v) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && end == s.data() + s.size() && std::isfinite(v);
}

}  // namespace

DenseSpectrum illuminant_d65() { return from_5nm_table(data::d65); }

DenseSpectrum illuminant_d50() { return daylight_illuminant(5000.0 * c2_ratio); }

DenseSpectrum illuminant_a() {
    /// Constants of the CIE S 014-2 formula: c2 = 1.435e7 nm·K, T = 2848 K, λ₀ = 560 nm.
    constexpr double c2_nm_k = 1.435e7;
    constexpr double t_k = 2848.0;
    constexpr double lambda0_nm = 560.0;
    const double e0 = std::expm1(c2_nm_k / (t_k * lambda0_nm));
    return DenseSpectrum::from_function([&](double lambda) {
        return 100.0 * std::pow(lambda0_nm / lambda, 5.0) * e0 / std::expm1(c2_nm_k / (t_k * lambda));
    });
}

DenseSpectrum illuminant_e() { return DenseSpectrum(100.0); }

Xy daylight_chromaticity(double cct_k) {
    if (!(cct_k >= 4000.0 && cct_k <= 25000.0)) {
        throw Error("daylight illuminant: CCT " + format_shortest(cct_k) +
                    " K is outside the CIE daylight range 4000-25000 K");
    }
    const double t = cct_k;
    const double t2 = t * t;
    const double t3 = t2 * t;
    // CIE 015:2018 daylight locus: x_D for 4000-7000 K and for 7000-25000 K.
    const double x = t <= 7000.0
                         ? -4.6070e9 / t3 + 2.9678e6 / t2 + 0.09911e3 / t + 0.244063
                         : -2.0064e9 / t3 + 1.9018e6 / t2 + 0.24748e3 / t + 0.237040;
    const double y = -3.000 * x * x + 2.870 * x - 0.275;
    return {x, y};
}

namespace {

/// CIE 015:2018 §4: M = 0.0241 + 0.2562 x − 0.7341 y, M1 = (−1.3515 − 1.7703 x + 5.9114 y)/M,
/// M2 = (0.0300 − 31.4424 x + 30.0717 y)/M.
DaylightWeights weights_of(Xy c) noexcept {
    const double m = 0.0241 + 0.2562 * c.x - 0.7341 * c.y;
    return {(-1.3515 - 1.7703 * c.x + 5.9114 * c.y) / m, (0.0300 - 31.4424 * c.x + 30.0717 * c.y) / m};
}

DenseSpectrum daylight_of(DaylightWeights w) {
    std::array<double, data::daylight_s0.size()> table{};
    for (std::size_t i = 0; i < table.size(); ++i) {
        table[i] = data::daylight_s0[i] + w.m1 * data::daylight_s1[i] + w.m2 * data::daylight_s2[i];
    }
    return from_5nm_table(table);
}

}  // namespace

DenseSpectrum daylight_illuminant(double cct_k) {
    // CIE 015:2018: M1, M2 from the chromaticity, rounded to three decimals before use.
    const DaylightWeights w = weights_of(daylight_chromaticity(cct_k));
    return daylight_of({std::round(w.m1 * 1000.0) / 1000.0, std::round(w.m2 * 1000.0) / 1000.0});
}

std::array<DenseSpectrum, 3> daylight_basis() {
    return {from_5nm_table(data::daylight_s0), from_5nm_table(data::daylight_s1),
            from_5nm_table(data::daylight_s2)};
}

DaylightWeights daylight_weights(Xy c) {
    // The denominator is about −0.14 on the daylight locus; far from it the weights blow up.
    const double m = 0.0241 + 0.2562 * c.x - 0.7341 * c.y;
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !(m < -0.01)) {
        std::string message = "daylight weights: the chromaticity (";
        message += format_shortest(c.x);
        message += ", ";
        message += format_shortest(c.y);
        message += ") is too far from the daylight locus (0.0241 + 0.2562 x - 0.7341 y must be below -0.01)";
        throw Error(message);
    }
    return weights_of(c);
}

DenseSpectrum daylight_from_chromaticity(Xy c) { return daylight_of(daylight_weights(c)); }

double planck_radiance(double lambda_nm, double temperature_k) noexcept {
    const double lambda_m = lambda_nm * 1e-9;
    const double per_m = planck_c1l_w_m2_per_sr /
                         (std::pow(lambda_m, 5.0) * std::expm1(planck_c2_m_k / (lambda_m * temperature_k)));
    return per_m * 1e-9;  // per metre of wavelength → per nanometre
}

DenseSpectrum blackbody(double temperature_k) {
    if (!(temperature_k >= 100.0 && temperature_k <= 1e6)) {
        throw Error("blackbody: temperature " + format_shortest(temperature_k) +
                    " K is outside 100-1e6 K");
    }
    const double at_560 = planck_radiance(560.0, temperature_k);
    return DenseSpectrum::from_function(
        [&](double lambda) { return 100.0 * planck_radiance(lambda, temperature_k) / at_560; });
}

DenseSpectrum illuminant_by_name(std::string_view name) {
    const std::string n = ascii_lower(name);
    if (n == "d65") return illuminant_d65();
    if (n == "d50") return illuminant_d50();
    if (n == "d55") return daylight_illuminant(5500.0 * c2_ratio);
    if (n == "d75") return daylight_illuminant(7500.0 * c2_ratio);
    if (n == "a") return illuminant_a();
    if (n == "e") return illuminant_e();
    double value = 0.0;
    if (n.size() > 1 && n[0] == 'd' && parse_double(std::string_view(n).substr(1), value) &&
        value >= 1000.0) {
        return daylight_illuminant(value);
    }
    constexpr std::string_view bb = "blackbody:";
    if (n.rfind(bb, 0) == 0 && parse_double(std::string_view(n).substr(bb.size()), value)) {
        return blackbody(value);
    }
    if (n == "c") {
        // C is a white point of the command line (--white C) but has no spectrum here: CIE
        // illuminant C is defined by a filtered source, tabulated in CIE 015, which irid does
        // not ship.
        throw Error("illuminant C has no spectral table in irid; it is available as a white "
                    "point (--white C: x, y = 0.31006, 0.31616) where a chromaticity is enough. "
                    "Spectral illuminants: D50, D55, D65, D75, A, E, D<CCT in K, 4000-25000> (e.g. "
                    "D6774, close to C), blackbody:<T in K>");
    }
    throw UnknownNameError("unknown illuminant " + quote_untrusted(name) +
                               "; valid: D50, D55, D65, D75, A, E, D<CCT in K, 4000-25000> (e.g. "
                               "D9300), blackbody:<T in K>",
                           {"D50", "D55", "D65", "D75", "A", "E", "D<CCT>", "blackbody:<T>"});
}

std::string canonical_illuminant_name(std::string_view name) {
    (void)illuminant_by_name(name);  // throws for a name it does not know
    const std::string n = ascii_lower(name);
    double value = 0.0;
    // The shortest digits that read back to the value (std::to_chars without a precision).
    const auto shortest = [](std::string prefix, double v) {
        char text[32];
        const auto result = std::to_chars(text, text + sizeof text, v);
        prefix.append(text, result.ptr);
        return prefix;
    };
    if (n.size() > 1 && n[0] == 'd' && parse_double(std::string_view(n).substr(1), value))
        return shortest("D", value);
    constexpr std::string_view bb = "blackbody:";
    if (n.rfind(bb, 0) == 0 && parse_double(std::string_view(n).substr(bb.size()), value))
        return shortest("blackbody:", value);
    return n == "a" ? "A" : "E";
}

std::vector<std::string> white_point_names() { return {"D65", "D50", "D55", "D75", "A", "C", "E"}; }

Xy white_point_xy(std::string_view name) {
    const std::string n = ascii_lower(name);
    if (n == "d65") return d65_xy;
    if (n == "d50") return {0.34567, 0.35850};
    if (n == "d55") return {0.33242, 0.34743};
    if (n == "d75") return {0.29902, 0.31485};
    if (n == "a") return {0.44757, 0.40745};
    if (n == "c") return {0.31006, 0.31616};
    if (n == "e") return {1.0 / 3.0, 1.0 / 3.0};
    const auto comma = n.find(',');
    Xy xy;
    if (comma != std::string::npos && parse_double(std::string_view(n).substr(0, comma), xy.x) &&
        parse_double(std::string_view(n).substr(comma + 1), xy.y)) {
        check_white_chromaticity(xy, "white point '" + std::string(name) + "'");
        return xy;
    }
    throw UnknownNameError("unknown white point " + quote_untrusted(name) +
                               "; valid: D65, D50, D55, D75, A, C, E, or x,y (for example "
                               "0.3127,0.329)",
                           white_point_names());
}

}  // namespace irid
