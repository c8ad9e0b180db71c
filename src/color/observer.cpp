#include <irid/color/numeric_table.h>
#include <irid/color/observer.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/text_input.h>

#include "cie_tables.h"

#include <cmath>
#include <string>
#include <vector>

namespace irid {
namespace {

namespace data = detail::cie_data;
static_assert(data::cmf_first_nm == lambda_min_nm && data::cmf_count == dense_sample_count,
              "the CIE colour-matching functions must cover the dense grid exactly");

ColorMatchingFunctions make_cmfs(const std::array<double, dense_sample_count>& x,
                                 const std::array<double, dense_sample_count>& y,
                                 const std::array<double, dense_sample_count>& z) {
    return {DenseSpectrum(x), DenseSpectrum(y), DenseSpectrum(z)};
}

}  // namespace

const ColorMatchingFunctions& color_matching_functions(Observer observer) noexcept {
    static const ColorMatchingFunctions cie1931 =
        make_cmfs(data::cie1931_x, data::cie1931_y, data::cie1931_z);
    static const ColorMatchingFunctions cie1964 =
        make_cmfs(data::cie1964_x, data::cie1964_y, data::cie1964_z);
    return observer == Observer::cie1964_10deg ? cie1964 : cie1931;
}

Observer parse_observer(std::string_view name) {
    if (name == "cie1931" || name == "2") return Observer::cie1931_2deg;
    if (name == "cie1964" || name == "10") return Observer::cie1964_10deg;
    throw UnknownNameError("unknown observer " + quote_untrusted(name) +
                               "; valid names: cie1931, cie1964",
                           {"cie1931", "cie1964"});
}

std::string_view observer_name(Observer observer) noexcept {
    return observer == Observer::cie1964_10deg ? "cie1964" : "cie1931";
}

Xyz monochromatic_xyz(double lambda_nm, Observer observer) noexcept {
    const ColorMatchingFunctions& cmf = color_matching_functions(observer);
    return {cmf.x(lambda_nm), cmf.y(lambda_nm), cmf.z(lambda_nm)};
}

Xy spectral_locus_xy(double lambda_nm, Observer observer) {
    if (!(lambda_nm >= lambda_min_nm && lambda_nm <= lambda_max_nm)) {
        throw Error("spectral locus: wavelength " + format_shortest(lambda_nm) +
                    " nm is outside 360-830 nm");
    }
    return xyz_to_xy(monochromatic_xyz(lambda_nm, observer));
}

bool is_real_chromaticity(const Xy& p) noexcept {
    // The locus as a closed polygon, made once (crossing-number test: W. R. Franklin's rule).
    static const std::vector<Xy> locus = [] {
        std::vector<Xy> v;
        for (int nm = 380; nm <= 700; ++nm) v.push_back(xyz_to_xy(monochromatic_xyz(nm, Observer::cie1931_2deg)));
        return v;
    }();
    if (!(std::isfinite(p.x) && std::isfinite(p.y))) return false;
    // Inside the triangle of the sRGB primaries (ITU-R BT.709), which the locus contains: every
    // common white, decided by three signs instead of the polygon's 321 edges.
    const auto side = [&](double ax, double ay, double bx, double by) {
        return (bx - ax) * (p.y - ay) - (by - ay) * (p.x - ax);
    };
    if (side(0.64, 0.33, 0.30, 0.60) > 0 && side(0.30, 0.60, 0.15, 0.06) > 0 && side(0.15, 0.06, 0.64, 0.33) > 0) {
        return true;
    }
    bool inside = false;
    for (std::size_t i = 0, j = locus.size() - 1; i < locus.size(); j = i++) {
        const Xy& a = locus[i];
        const Xy& b = locus[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
    return inside;
}

void check_white_chromaticity(const Xy& xy, std::string_view what) {
    if (!is_real_chromaticity(xy)) {
        throw Error(std::string(what) + " (" + format_shortest(xy.x) + ", " + format_shortest(xy.y) +
                    ") lies outside the chromaticity diagram (the CIE 1931 spectral locus and the "
                    "purple line): no light has that colour");
    }
}

void check_sample_wavelengths(std::span<const double> w) {
    if (w.size() < 2) {
        throw Error("a spectrum needs at least two wavelengths, found " + std::to_string(w.size()));
    }
    for (std::size_t i = 0; i < w.size(); ++i) {
        if (!(std::isfinite(w[i]) && w[i] > 0.0)) {
            throw Error("wavelength " + std::to_string(i) + " (" + format_shortest(w[i]) +
                        " nm) must be finite and positive");
        }
        if (i > 0 && !(w[i] > w[i - 1])) {
            throw Error("wavelength " + std::to_string(i) + " (" + format_shortest(w[i]) +
                        " nm) must be greater than the one before (" + format_shortest(w[i - 1]) +
                        " nm)");
        }
    }
    if (w.back() < lambda_min_nm || w.front() > lambda_max_nm) {
        throw Error("the wavelengths " + format_shortest(w.front()) + "-" + format_shortest(w.back()) +
                    " nm do not overlap the visible range 360-830 nm");
    }
}

Xyz sampled_reflectance_to_xyz(std::span<const double> wavelengths_nm,
                               std::span<const double> values, const DenseSpectrum& illuminant,
                               Observer observer) {
    if (values.size() != wavelengths_nm.size()) {
        throw Error("a spectrum has " + std::to_string(values.size()) + " values for " +
                    std::to_string(wavelengths_nm.size()) + " wavelengths");
    }
    check_sample_wavelengths(wavelengths_nm);
    const PiecewiseLinearSpectrum measured(
        std::vector<double>(wavelengths_nm.begin(), wavelengths_nm.end()),
        std::vector<double>(values.begin(), values.end()), Extrapolation::hold_ends);
    const Xyz xyz = reflectance_to_xyz(DenseSpectrum::resample(measured), illuminant, observer);
    if (!std::isfinite(xyz.X) || !std::isfinite(xyz.Y) || !std::isfinite(xyz.Z)) {
        throw Error("the spectrum overflows: its values are too large for XYZ (or not finite)");
    }
    return xyz;
}

Xyz reflectance_to_xyz(const DenseSpectrum& reflectance, const DenseSpectrum& illuminant,
                       Observer observer) noexcept {
    const ColorMatchingFunctions& cmf = color_matching_functions(observer);
    double x = 0.0, y = 0.0, z = 0.0, white_y = 0.0;
    for (int i = 0; i < dense_sample_count; ++i) {
        const double s = illuminant[i];
        const double sr = s * reflectance[i];
        x += sr * cmf.x[i];
        y += sr * cmf.y[i];
        z += sr * cmf.z[i];
        white_y += s * cmf.y[i];
    }
    const double k = white_y != 0.0 ? 1.0 / white_y : 0.0;
    return {x * k, y * k, z * k};
}

Xyz illuminant_white(const DenseSpectrum& illuminant, Observer observer) {
    const ColorMatchingFunctions& cmf = color_matching_functions(observer);
    if (!(illuminant.dot(cmf.y) > 0.0)) {
        throw Error("illuminant: its luminance (Σ S ȳ) must be positive");
    }
    return reflectance_to_xyz(DenseSpectrum(1.0), illuminant, observer);
}

Xyz emission_to_xyz_absolute(const DenseSpectrum& spectral_power, Observer observer) noexcept {
    const ColorMatchingFunctions& cmf = color_matching_functions(observer);
    constexpr double delta_lambda_nm = 1.0;
    const double k = max_luminous_efficacy_lm_per_w * delta_lambda_nm;
    return {k * spectral_power.dot(cmf.x), k * spectral_power.dot(cmf.y),
            k * spectral_power.dot(cmf.z)};
}

Xyz emission_to_xyz_relative(const DenseSpectrum& spectral_power, Observer observer) {
    const Xyz a = emission_to_xyz_absolute(spectral_power, observer);
    if (!(a.Y > 0.0) || !std::isfinite(a.Y)) {
        throw Error("emission spectrum: its luminance Y must be positive and finite to normalise");
    }
    return {a.X / a.Y, 1.0, a.Z / a.Y};
}

}  // namespace irid
