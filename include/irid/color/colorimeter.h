#pragma once

// Reflectance spectra to colour: the illuminant × colour-matching-function weights of the 1 nm
// summation (CIE 015:2018 §7), XYZ relative to the illuminant's white (Y = 1), CIELAB relative to
// that white, and linear RGB of a chosen space, unclipped, after a chromatic adaptation from the
// illuminant's white to the space's white when they differ (Bradford by default), so that a white
// reflector is RGB (1, 1, 1).

#include <irid/color/adaptation.h>
#include <irid/color/illuminant.h>
#include <irid/color/matrix.h>
#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/color/spectrum.h>
#include <irid/color/types.h>

namespace irid {

/// Turns reflectance spectra into colour. Built once (the illuminant × colour-matching-function
/// weights and the XYZ → RGB matrix are precomputed); evaluation is noexcept and allocates
/// nothing.
class Colorimeter {
public:
    explicit Colorimeter(const DenseSpectrum& illuminant = illuminant_d65(),
                         Observer observer = Observer::cie1931_2deg, const RgbSpace& rgb = srgb(),
                         ChromaticAdaptation adaptation = ChromaticAdaptation::bradford);

    /// XYZ of a reflectance spectrum (CIE 015:2018 1 nm summation, white Y = 1).
    [[nodiscard]] Xyz xyz(const DenseSpectrum& reflectance) const noexcept;
    /// XYZ of a reflectance given as a function of wavelength [nm], sampled at 360, ..., 830 nm.
    template <class F>
    [[nodiscard]] Xyz xyz_of(F&& reflectance_at) const {
        Xyz c;
        for (int i = 0; i < dense_sample_count; ++i) {
            const double r = reflectance_at(DenseSpectrum::wavelength_nm(i));
            c.X += r * m_weight_x[i];
            c.Y += r * m_weight_y[i];
            c.Z += r * m_weight_z[i];
        }
        return c;
    }
    /// Linear RGB in the colorimeter's space, unclipped.
    [[nodiscard]] Rgb linear_rgb(const Xyz& c) const noexcept;
    /// CIELAB relative to the illuminant's white.
    [[nodiscard]] Lab lab(const Xyz& c) const noexcept;
    /// The illuminant's white, Y = 1.
    [[nodiscard]] const Xyz& white() const noexcept { return m_white; }
    [[nodiscard]] const RgbSpace& rgb_space() const noexcept { return m_rgb; }
    [[nodiscard]] Observer observer() const noexcept { return m_observer; }
    /// The summation weights S(λ) x̄(λ) / Σ S ȳ, and those of ȳ and z̄, on the 1 nm grid: xyz()
    /// is the dot product of a reflectance with each.
    [[nodiscard]] const DenseSpectrum& weight_x() const noexcept { return m_weight_x; }
    [[nodiscard]] const DenseSpectrum& weight_y() const noexcept { return m_weight_y; }
    [[nodiscard]] const DenseSpectrum& weight_z() const noexcept { return m_weight_z; }

private:
    DenseSpectrum m_weight_x, m_weight_y, m_weight_z;  // S(λ) x̄(λ) / Σ S ȳ, ...
    Xyz m_white;
    Observer m_observer;
    RgbSpace m_rgb;
    Mat3 m_xyz_to_rgb;  // adaptation to the space's white, then the space's matrix
};

/// CIEDE2000 between two XYZ colours, each in CIELAB relative to the colorimeter's white.
[[nodiscard]] double delta_e_2000_of(const Colorimeter& colorimeter, const Xyz& a, const Xyz& b) noexcept;

}  // namespace irid
