#pragma once

#include <irid/optics/material.h>

#include <vector>

namespace irid {

// Reflection and transmission of plane waves by planar films, in one convention throughout:
//
// - Time dependence exp(-iωt), N = n + ik with k >= 0 absorbing (see material.h). z points from
//   the ambient into the stack; in medium j a wave travelling towards +z varies as
//   exp(2πi q_j z / λ) with q_j = N_j cos θ_j, so it decays into an absorbing medium.
// - Snell's law n0 sin θ0 = N_j sin θ_j holds across every interface; s = n0 sin θ0 is its
//   invariant, real because the ambient is lossless.
// - Tilted optical admittances in units of the free-space admittance (H. A. Macleod,
//   Thin-Film Optical Filters, 4th ed., 2010, ch. 2): η = N cos θ for s, η = N / cos θ for p.
// - Amplitude coefficients r and t are ratios of the field components tangential to the
//   interfaces (Macleod ch. 2): r = (η_i - η_t) / (η_i + η_t), t = 2 η_i / (η_i + η_t) for both
//   polarisations. Hence r_p = r_s at normal incidence; Born & Wolf's r∥ (Principles of Optics,
//   7th ed., §1.5.2) has the opposite sign, and their full-amplitude t∥ is t_p cos θ_i / cos θ_t.
//   Reflectance and transmittance do not depend on these choices.
// - Angles are in radians, measured in the ambient, in [0, π/2).

enum class Polarization { s, p, unpolarized };

/// Reflectance and transmittance: fractions of the incident power, 0 <= R, T and R + T <= 1.
struct Optics {
    double R;
    double T;
};

/// Fresnel amplitude coefficients of one interface (tangential-field convention, above).
struct FresnelCoefficients {
    Complex r_s;
    Complex r_p;
    Complex t_s;
    Complex t_p;
};

/// A film: a material and its thickness [nm].
struct Layer {
    Material material;
    double thickness_nm;
};

/// Throws irid::Error unless 0 <= angle_rad < π/2: the angles of incidence every function here
/// accepts (grazing incidence, π/2, carries no power into the stack).
void check_incidence_angle(double angle_rad);

/// cos θ in a medium of index n by the complex Snell's law n0 sin θ0 = n sin θ, given the
/// invariant s = n0 sin θ0: cos θ = sqrt(n² - s²) / n, with the branch of the root for which
/// Im(n cos θ) >= 0 (and Re(n cos θ) >= 0 when it is real), so the wave decays into the medium:
/// the right choice for absorbing media and for total internal reflection, where n cos θ is
/// imaginary (Born & Wolf §1.5.4).
[[nodiscard]] Complex cos_theta(Complex n, double snell_invariant) noexcept;

/// Fresnel coefficients for light going from a medium of index n_i into one of index n_t, at the
/// Snell invariant s = n0 sin θ0 of the stack (s = n_i sin θ_i for a lossless incident medium).
/// r = (η_i - η_t)/(η_i + η_t), t = 2 η_i/(η_i + η_t), η of each polarisation as above (Fresnel
/// 1823; Born & Wolf §1.5.2, up to the sign convention of r_p). For lossless media
/// |r|² is the reflectance and Re(η_t)/Re(η_i) |t|² the transmittance.
[[nodiscard]] FresnelCoefficients fresnel(Complex n_i, Complex n_t,
                                          double snell_invariant) noexcept;
/// The same for a stack lit from a lossless ambient n0 at q0 = n0 cos θ0: each N cos θ from q0
/// rather than from the Snell invariant, which keeps its digits at grazing incidence (where
/// sin θ0 rounds to 1 and N² − s² would be 0 for a medium of the ambient's index).
[[nodiscard]] FresnelCoefficients fresnel_from(Complex n_i, Complex n_t, double n0, double q0) noexcept;

/// One film of index n1 and thickness [nm] on a substrate n2, lit from a lossless ambient n0, by
/// the Airy summation of all internal reflections (Born & Wolf §1.6.4 and §7.6.1):
/// r = (r01 + r12 e^{2iβ}) / (1 + r01 r12 e^{2iβ}), t = t01 t12 e^{iβ} / (1 + r01 r12 e^{2iβ}),
/// β = 2π n1 d cos θ1 / λ. R = |r|²; T = Re(η2)/η0 |t|², the power entering the substrate (the
/// power transmitted into it when it is lossless, the power it absorbs otherwise). Unpolarised
/// light gives the mean of s and p. Preconditions: n0 > 0, lambda_nm > 0, thickness_nm >= 0,
/// angle as check_incidence_angle; the film must not be exactly at its own critical angle
/// (cos θ1 = 0), where the summation is 0/0 (FilmStack::evaluate has the limit).
[[nodiscard]] Optics airy_film(double n0, Complex n1, Complex n2, double thickness_nm,
                               double lambda_nm, double angle_rad,
                               Polarization polarization) noexcept;

/// Films on a substrate: ambient | layers (listed from the ambient side) | substrate, each
/// interface planar and each layer homogeneous, evaluated by the characteristic (transfer)
/// matrix method (Born & Wolf §1.6.2; Macleod ch. 2).
class FilmStack {
public:
    /// Throws irid::Error unless every thickness is finite and >= 0 ("layer 2 thickness -5 nm
    /// must be >= 0", layers counted from 1 at the ambient side) and the ambient is lossless
    /// (k = 0), so that the angle of incidence, and the Snell invariant, are real.
    FilmStack(Material ambient, std::vector<Layer> layers, Material substrate);

    /// Reflectance and transmittance at a vacuum wavelength [nm] and an angle of incidence in the
    /// ambient [rad] (as check_incidence_angle; not checked here). Each layer j contributes the
    /// characteristic matrix [[cos δ, -i sin δ / η], [-i η sin δ, cos δ]], δ = 2π N_j d_j cos θ_j
    /// / λ (Born & Wolf §1.6.2, whose time dependence is irid's); with
    /// [B, C] = M_1 ... M_L [1, η_s]: r = (η0 B - C) / (η0 B + C), R = |r|², and
    /// T = 4 η0 Re(η_s) / |η0 B + C|² (Macleod ch. 2), the power entering the substrate (the
    /// power transmitted when it is lossless, the power it absorbs otherwise). Unpolarised light
    /// gives the mean of s and p. Allocates nothing.
    [[nodiscard]] Optics evaluate(double lambda_nm, double angle_rad,
                                  Polarization polarization) const noexcept;

    [[nodiscard]] const Material& ambient() const noexcept { return m_ambient; }
    [[nodiscard]] const std::vector<Layer>& layers() const noexcept { return m_layers; }
    [[nodiscard]] const Material& substrate() const noexcept { return m_substrate; }

private:
    Material m_ambient;
    std::vector<Layer> m_layers;
    Material m_substrate;
};

}  // namespace irid
