#pragma once

// What a ray carries on each of the renderer's two colour paths (irid/render/scene.h ColorPath).
//
// - RgbCarrier: the thesis' path. Linear RGB with Rec. 709 primaries relative to the D65 white;
//   reflectances and lights multiply channel by channel, as the thesis' RGB tables do.
// - SpectralCarrier: a value per nanometre on the 1 nm grid (360–830 nm) relative to the D65
//   illuminant: radiance(λ) = S_D65(λ) × value(λ). Products are taken wavelength by wavelength
//   and XYZ comes at the end from the colorimeter's weights (CIE 015:2018 1 nm summation).
//
// Both are plain value types with +, × and scaling; the integrator is written once for both.

#include <irid/color/spectrum.h>
#include <irid/color/types.h>
#include <irid/optics/film_color.h>

#include <algorithm>
#include <array>

namespace irid::render {

using Rgb3 = std::array<double, 3>;

struct RgbCarrier {
    std::array<double, 3> v{};

    static RgbCarrier constant(double x) noexcept { return {{x, x, x}}; }
    RgbCarrier& operator+=(const RgbCarrier& o) noexcept {
        for (int i = 0; i < 3; ++i) v[i] += o.v[i];
        return *this;
    }
    friend RgbCarrier operator*(const RgbCarrier& a, const RgbCarrier& b) noexcept {
        return {{a.v[0] * b.v[0], a.v[1] * b.v[1], a.v[2] * b.v[2]}};
    }
    friend RgbCarrier operator*(const RgbCarrier& a, double s) noexcept {
        return {{a.v[0] * s, a.v[1] * s, a.v[2] * s}};
    }
    friend RgbCarrier operator+(RgbCarrier a, const RgbCarrier& b) noexcept { return a += b; }
    /// 1 − this: the transmittance of a lossless film from its reflectance.
    [[nodiscard]] RgbCarrier complement() const noexcept {
        return {{1.0 - v[0], 1.0 - v[1], 1.0 - v[2]}};
    }
    /// The largest component, for pruning paths that can no longer matter.
    [[nodiscard]] double max_value() const noexcept { return std::max({v[0], v[1], v[2]}); }
};

struct SpectralCarrier {
    std::array<double, dense_sample_count> v{};

    static SpectralCarrier constant(double x) noexcept {
        SpectralCarrier s;
        s.v.fill(x);
        return s;
    }
    SpectralCarrier& operator+=(const SpectralCarrier& o) noexcept {
        for (int i = 0; i < dense_sample_count; ++i) v[i] += o.v[i];
        return *this;
    }
    friend SpectralCarrier operator*(const SpectralCarrier& a, const SpectralCarrier& b) noexcept {
        SpectralCarrier r;
        for (int i = 0; i < dense_sample_count; ++i) r.v[i] = a.v[i] * b.v[i];
        return r;
    }
    friend SpectralCarrier operator*(const SpectralCarrier& a, double s) noexcept {
        SpectralCarrier r;
        for (int i = 0; i < dense_sample_count; ++i) r.v[i] = a.v[i] * s;
        return r;
    }
    friend SpectralCarrier operator+(SpectralCarrier a, const SpectralCarrier& b) noexcept {
        return a += b;
    }
    [[nodiscard]] SpectralCarrier complement() const noexcept {
        SpectralCarrier r;
        for (int i = 0; i < dense_sample_count; ++i) r.v[i] = 1.0 - v[i];
        return r;
    }
    [[nodiscard]] double max_value() const noexcept {
        return *std::max_element(v.begin(), v.end());
    }
};

/// Turns the scene's RGB values (albedos, light colours, environment pixels) into spectra for
/// the spectral path, and spectra into XYZ.
///
/// The upsampling is grey plus a chromatic residual: s(λ) = w + Σ_c (rgb_c − w) B_c(λ), w the
/// smallest channel (≥ 0). B_c are combinations of the CIE 1931 colour-matching functions chosen
/// so that the RGB of B_c under D65 is the unit vector e_c, which makes the round trip exact:
/// RGB(s) = rgb for every rgb. Greys become flat spectra, so a grey surface under any light
/// multiplies the same way on both paths; saturated colours become smooth but not necessarily
/// non-negative spectra (they are not offered as physical reflectances).
class SpectralBasis {
public:
    SpectralBasis();

    [[nodiscard]] SpectralCarrier from_rgb(const Rgb3& rgb) const noexcept;
    [[nodiscard]] Xyz xyz(const SpectralCarrier& s) const noexcept;
    /// XYZ of linear Rec. 709 RGB relative to D65 (the RGB carrier's end).
    [[nodiscard]] Xyz xyz(const RgbCarrier& c) const noexcept;
    [[nodiscard]] const Colorimeter& colorimeter() const noexcept { return m_colorimeter; }

private:
    Colorimeter m_colorimeter;  // D65, CIE 1931 2°, sRGB primaries
    std::array<std::array<double, dense_sample_count>, 3> m_basis{};
    Mat3 m_rgb_to_xyz;
};

}  // namespace irid::render
