#pragma once

// The analytic daylight sky of A. J. Preetham, P. Shirley and B. Smits, "A Practical Analytic
// Model for Daylight", SIGGRAPH 1999 (cited below as "Preetham 1999"): the sky's luminance Y and
// chromaticity x, y along a direction, from the sun's zenith angle θs and the turbidity T, as
// Perez et al.'s all-weather distribution normalised at the zenith (the paper's skylight
// section), with the turbidity-linear coefficients and the zenith formulas of its Appendix A.2;
// and the sun's spectral radiance through the atmosphere (its Appendix A.1, whose data the paper
// takes from M. Iqbal, "An Introduction to Solar Radiation", Academic Press 1983).
// Equation numbers are not quoted: the formulas are given in full where they are used.
//
// Directions are unit vectors with +y up (the renderer's convention). Angles in radians.

#include <irid/color/spectrum.h>
#include <irid/color/types.h>

#include <array>

namespace irid::render {

/// The five coefficients of the Perez distribution F(θ, γ) = (1 + A e^{B / cos θ})
/// (1 + C e^{D γ} + E cos² γ) (Perez, Seals & Michalsky 1993, as Preetham 1999 uses it).
struct PerezCoefficients {
    double a = 0, b = 0, c = 0, d = 0, e = 0;
};

/// F(θ, γ) for cos θ of the view's zenith angle (clamped to [0, 1]: at the horizon, cos θ = 0,
/// the first factor is 1 since B < 0) and γ, the angle between the view and the sun.
[[nodiscard]] double perez(const PerezCoefficients& p, double cos_theta, double gamma) noexcept;

/// The coefficients for Y, x and y at a turbidity: Preetham 1999 Appendix A.2, the three
/// matrices that give A…E as linear functions of T.
struct PreethamCoefficients {
    PerezCoefficients Y, x, y;
};
[[nodiscard]] PreethamCoefficients preetham_coefficients(double turbidity) noexcept;

/// The zenith's luminance [kcd/m²]: Y_z = (4.0453 T − 4.9710) tan χ − 0.2155 T + 2.4192,
/// χ = (4/9 − T/120)(π − 2θs) (Preetham 1999 Appendix A.2).
[[nodiscard]] double preetham_zenith_luminance(double turbidity, double sun_zenith) noexcept;
/// The zenith's chromaticity: x_z = (T², T, 1) M_x (θs³, θs², θs, 1)ᵀ and the same for y_z
/// (Preetham 1999 Appendix A.2).
[[nodiscard]] Xy preetham_zenith_chromaticity(double turbidity, double sun_zenith) noexcept;

/// The sun's spectral radiance at the ground [W m⁻² sr⁻¹ nm⁻¹] on irid's 1 nm grid: the
/// extraterrestrial solar radiance of Preetham 1999's table of sunlight's spectral quantities
/// (380–750 nm at 10 nm; held at its end values beyond) times the transmittances of Appendix A.1 (Rayleigh scattering, aerosols
/// with α = 1.3 and β = 0.04608 T − 0.04586, ozone l = 0.35 cm, mixed gases, water vapour
/// w = 2 cm) over the relative optical mass m = 1/(cos θs + 0.15 (93.885° − θs)^−1.253)
/// (Kasten 1966). Throws irid::Error unless 0 <= θs <= π/2 and the turbidity is in range.
[[nodiscard]] DenseSpectrum preetham_sun_radiance(double turbidity, double sun_zenith);

class PreethamSky {
public:
    /// The turbidities irid accepts: the range of the paper's figures and fits (T = 2 a very
    /// clear sky, T = 10 a hazy one); beyond it the zenith luminance formula is not meant to hold.
    static constexpr double min_turbidity = 2.0;
    static constexpr double max_turbidity = 10.0;

    /// `sun`: the direction towards the sun (any non-zero length; normalised here); it must be
    /// above the horizon (y > 0). Throws irid::Error for a turbidity out of range or a sun at or
    /// below the horizon.
    PreethamSky(double turbidity, std::array<double, 3> sun);

    [[nodiscard]] double turbidity() const noexcept { return m_turbidity; }
    [[nodiscard]] double sun_zenith() const noexcept { return m_sun_zenith; }
    [[nodiscard]] const PreethamCoefficients& coefficients() const noexcept { return m_coeff; }

    /// The sky's x, y and Y [kcd/m²] along the unit direction d. Directions below the horizon
    /// are taken at the horizon (cos θ = 0): the renderer puts the ground there.
    [[nodiscard]] Xyy xyy(std::array<double, 3> d) const noexcept;
    [[nodiscard]] Xyz xyz(std::array<double, 3> d) const noexcept;

private:
    double m_turbidity;
    std::array<double, 3> m_sun;
    double m_sun_zenith;
    PreethamCoefficients m_coeff;
    /// Y_z / F(0, θs) and the same for x and y (the zenith normalisation).
    double m_scale_Y, m_scale_x, m_scale_y;
};

}  // namespace irid::render
