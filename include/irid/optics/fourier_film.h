#pragma once

// The exact colour of a dielectric film in a few hundred nanoseconds: the Airy reflectance as a
// Fourier series in the film's phase, summed against the Fourier transform of the weighted
// colour-matching functions.
//
// For a lossless film (index n1, no total reflection inside it) between a lossless ambient and
// any substrate, the Airy amplitude r = (r01 + r12 z) / (1 + r01 r12 z), z = e^{iφ}, expands in
// powers of z (Born & Wolf §7.6.1): r = r01 + Σ_{k≥1} b q^{k-1} z^k with b = r12 (1 − r01²) and
// q = −r01 r12. Its square |r|² is then a Fourier series in φ whose coefficients are geometric:
//
//   R(φ) = A0 + 2 Re Σ_{m≥1} G q^{m-1} e^{imφ},
//   A0 = r01² + |b|² / (1 − |q|²),   G = r01 b + |b|² q / (1 − |q|²)
//
// (r01 is real for a lossless film below its critical angle; r12 is complex for an absorbing
// substrate or one past its critical angle). The phase is φ = 2π OPD ν with the optical path
// difference OPD = 2 d n1 cos θ1 and the wavenumber ν = 1/λ, so the colour's 1 nm sum is
//
//   X = A0 Σ_i w_i + 2 Re Σ_m G q^{m-1} W(m OPD),   W(τ) = Σ_i w_i e^{2πi τ / λ_i}
//
// with w_i the colorimeter's summation weights (S(λ) x̄(λ) / Σ S ȳ; likewise for Y and Z). W is
// the discrete Fourier transform of the weighted matching functions as functions of wavenumber;
// it depends only on the illuminant and the observer, so it is tabulated once
// (FourierColorimeter) and every colour after that costs the Fresnel amplitudes and a few table
// lookups per term of the series. Nothing here is fitted: with wavelength-independent indices
// the result is the 1 nm sum up to the table's interpolation and the series' truncation, both
// bounded (below); Belcour & Barla (2017) replace W by Gaussian fits of the matching functions,
// which is where their colour error comes from (docs/OPTICS.md).
//
// Dispersion. The amplitudes and the phase depend on the wavelength through the indices. The
// spectrum is split into bands by a smooth partition of unity in wavenumber (normalised
// Gaussians, so that each band's transform decays as fast as the whole's). In each band the
// phase φ = 4π d f(ν), f(ν) = ν q1(ν) with q1 = n1 cos θ1, is expanded about the band's centre.
// With `slopes` off ("the index held constant per band") it is linear, φ ≈ φ_c + 4π d g (ν − ν_c)
// with g = q1 − λ dq1/dλ the group value of q1, and the series' coefficients are held at the
// centre. With `slopes` on, f, the coefficients A0 and G q^{m-1} are evaluated at ν_c and ν_c ± δ:
// the coefficients vary linearly through the band, and the phase gets its quadratic term
// ψ = 2π d f''(ν_c) (ν − ν_c)², to first order (e^{imψ} ≈ 1 + imψ). These need the moments
// V1(τ) = Σ_i w_i (ν_i − ν_c) e^{2πiτ(ν_i − ν_c)} and V2 (with (ν_i − ν_c)²) beside V. One band is
// exact for wavelength-independent media; for dispersive ones (water, oil, silica, metals) see
// docs/OPTICS.md, "The fast exact film colour", for what each correction buys.

#include <irid/color/types.h>
#include <irid/optics/film.h>
#include <irid/optics/film_color.h>

#include <array>
#include <complex>
#include <memory>
#include <vector>

namespace irid {

/// The Fourier transforms of a colorimeter's weighted matching functions, in bands, tabulated
/// over the optical path difference τ. Immutable once built; share it between films (building
/// one costs tens of milliseconds per band).
class FourierColorimeter {
public:
    /// The most bands a table may have.
    static constexpr int max_bands = 64;
    /// Tabulation step of τ [nm]. The transforms are stored demodulated about each band's
    /// centre, V(τ) = W(τ) e^{−2πiτν_c}, which varies on a scale of 1/(ν range) ≈ 1 270 nm; at
    /// 2 nm linear interpolation errs by at most h²/8 max|V''| ≈ 1.2e-5 of the white's Y.
    static constexpr double step_nm = 2.0;
    /// Where a band's table ends: once |V| has stayed below this fraction of the white's Y for
    /// cut_run_nm of τ (the terms beyond are dropped), and at most at max_opd_cap_nm.
    static constexpr double cut_tolerance = 1e-7;
    static constexpr double cut_run_nm = 4000.0;
    /// The tables end here at the latest. Past 20 µm the transforms of the tabulated data are
    /// below 5e-3 of the white and falling slowly (their floor is the kinks of the 5 nm
    /// illuminant tables, interpolated linearly to 1 nm), so dropping the terms beyond changes a
    /// colour by at most 1e-2 × the magnitude of those terms: a few 1e-4 for the thickest films
    /// of docs/OPTICS.md's study, and the table (480 kB a band) stays in a core's L2 cache.
    static constexpr double max_opd_cap_nm = 20000.0;

    /// Throws irid::Error unless 1 <= bands <= max_bands. With `slopes`, each band also holds
    /// the moment transforms V1 and V2 that FourierFilm's dispersion correction needs (three
    /// times the table).
    explicit FourierColorimeter(const Colorimeter& colorimeter, int bands = 1, bool slopes = false);

    struct Transform {
        std::complex<double> x, y, z;
    };
    [[nodiscard]] int bands() const noexcept { return static_cast<int>(m_bands.size()); }
    [[nodiscard]] bool slopes() const noexcept { return m_slopes; }
    /// The half-width δ [1/nm] of the wavenumber interval over which band b's slopes are taken:
    /// half the spacing of the band centres (half the range 380–780 nm for one band), shrunk so
    /// that ν_c ± δ stay within 360–830 nm, where materials are validated (0 without slopes).
    [[nodiscard]] double slope_step(int b) const noexcept { return m_bands[b].delta; }
    /// max |V_b| over the last cut_run_nm of the band's table: the estimate of the transform past
    /// the table's end that FourierFilm bounds the terms it drops with.
    [[nodiscard]] double band_floor(int b) const noexcept { return m_bands[b].floor; }
    /// The band's centre: the wavenumber [1/nm] at which its amplitudes and phase are taken (the
    /// Y-weighted mean wavenumber of the band).
    [[nodiscard]] double band_wavenumber(int b) const noexcept { return m_bands[b].nu_c; }
    /// Σ_i w_b(ν_i) w_i: the band's part of the white (the whites of all bands sum to the
    /// colorimeter's white).
    [[nodiscard]] const Xyz& band_white(int b) const noexcept { return m_bands[b].white; }
    /// Σ_i w_b(ν_i) w_i (ν_i − ν_c): the band's first moment (with slopes).
    [[nodiscard]] const Xyz& band_moment(int b) const noexcept { return m_bands[b].moment; }
    /// The band's demodulated transform V_b(τ) = Σ_i w_b(ν_i) w_i e^{2πiτ(ν_i − ν_c)},
    /// interpolated; 0 beyond the band's table.
    [[nodiscard]] Transform transform(int b, double tau_nm) const noexcept;
    /// V_b, V1_b and V2_b at once (the moments are 0 without slopes).
    [[nodiscard]] std::array<Transform, 3> transforms(int b, double tau_nm) const noexcept;
    /// Where the band's table ends [nm].
    [[nodiscard]] double max_opd_nm(int b) const noexcept {
        return step_nm * static_cast<double>(m_bands[b].nodes - 1);
    }
    /// max over τ and channels of |V_b(τ)|: the bound the series' truncation uses.
    [[nodiscard]] double band_bound(int b) const noexcept { return m_bands[b].bound; }
    /// max over τ and channels of |V1_b(τ)| and of |V2_b(τ)| (0 without slopes).
    [[nodiscard]] double band_moment_bound(int b) const noexcept { return m_bands[b].moment_bound; }
    [[nodiscard]] double band_second_moment_bound(int b) const noexcept {
        return m_bands[b].second_moment_bound;
    }
    [[nodiscard]] const Colorimeter& colorimeter() const noexcept { return m_colorimeter; }

private:
    struct Band {
        double nu_c = 0.0;
        Xyz white, moment;
        double bound = 0.0, moment_bound = 0.0, second_moment_bound = 0.0;
        double delta = 0.0, floor = 0.0;
        /// Per node of τ: V (x, y, z as real and imaginary parts), then with slopes V1 and V2,
        /// side by side so that one lookup reads adjacent memory; the moments are 0 past their
        /// own quiet ends.
        std::vector<double> table;
        std::size_t nodes = 0;
    };
    [[nodiscard]] std::size_t stride() const noexcept { return m_slopes ? 18 : 6; }
    Colorimeter m_colorimeter;
    bool m_slopes = false;
    std::vector<Band> m_bands;
};

/// Whether a film's media disperse (any of ambient, film, substrate not Material::is_constant),
/// so that its coefficients need the slopes.
[[nodiscard]] bool fourier_needs_slopes(const SingleFilm& film) noexcept;
/// A colorimeter's transforms as a film needs them by default: one band, with slopes when the
/// media disperse (docs/OPTICS.md measures more bands: they cost more than they gain).
[[nodiscard]] std::shared_ptr<const FourierColorimeter> fourier_colorimeter_for(
    const SingleFilm& film, const Colorimeter& colorimeter);

/// A single lossless film between a lossless ambient and any substrate, its colour by the
/// Fourier series above at any thickness and angle.
class FourierFilm {
public:
    /// Throws irid::Error for an absorbing ambient or film (the series needs a real r01 and a
    /// real phase; use PreparedFilm, the 1 nm sum, for absorbing films).
    FourierFilm(const SingleFilm& film, std::shared_ptr<const FourierColorimeter> colorimeter);

    /// XYZ (white Y = 1) at a thickness [nm, finite, >= 0] and the cosine of the angle of
    /// incidence in the ambient (in [0, 1]); NaN outside those. Where the series does not apply
    /// the 1 nm sum (PreparedFilm's Airy sum per wavelength) is evaluated instead: the film at
    /// or past its own critical angle; |q| > max_ratio at grazing incidence, where it converges
    /// too slowly; dispersive media changing too fast through the band (near the film's
    /// critical angle under a dispersive ambient, max_q1_variation, max_bend); terms dropped past
    /// the table's end that would matter (max_dropped_tail: thick films near grazing incidence);
    /// a dispersive absorbing substrate (a metal's table: its reflectance turns too sharply for
    /// one band, ΔE2000 up to 18 for gold, docs/OPTICS.md).
    [[nodiscard]] Xyz xyz(double thickness_nm, double cos_theta) const noexcept;
    [[nodiscard]] FilmColor color(double thickness_nm, double cos_theta) const noexcept;

    /// |q| above which the 1 nm sum is used (about 900 terms for 1e-7 near this ratio).
    static constexpr double max_ratio = 0.98;
    /// With slopes: the largest change of q1 = n1 cos θ1 across a band, relative to its value
    /// at the centre, and the largest second difference of A0 across it, for which the band's
    /// linear and quadratic model is used (beyond: the 1 nm sum).
    static constexpr double max_q1_variation = 0.05;
    static constexpr double max_bend = 1e-3;
    /// With slopes: the largest quadratic phase ψ at the band's edges ν_c ± δ [rad] for which
    /// its first-order expansion e^{imψ} ≈ 1 + imψ is used.
    static constexpr double max_quadratic_phase = 0.15;
    /// The most that the terms dropped past the table's end may add to Y, for a film with terms
    /// in the table (beyond: the 1 nm sum; a film whose first term is past the table is the
    /// incoherent sum of its faces).
    static constexpr double max_dropped_tail = 2e-4;
    /// The truncation bound on the remaining terms, in Y (white = 1).
    static constexpr double series_tolerance = 1e-7;

    [[nodiscard]] const SingleFilm& film() const noexcept { return m_film; }
    /// Whether every colour is the 1 nm sum (a dispersive absorbing substrate).
    [[nodiscard]] bool uses_sum() const noexcept { return m_sum_only; }
    [[nodiscard]] const FourierColorimeter& colorimeter() const noexcept { return *m_colorimeter; }

private:
    /// The media at a band's centre: indices and their wavelength derivatives [1/nm].
    struct Media {
        double n0 = 1.0, n1 = 1.0;
        std::complex<double> n2;
    };
    struct BandMedia {
        double lambda_c = 0.0;
        double dn0 = 0.0, dn1 = 0.0;
        /// At ν_c, and at ν_c − δ and ν_c + δ for the slopes.
        Media centre, below, above;
    };
    [[nodiscard]] Xyz exact_sum(double thickness_nm, double cos_theta) const noexcept;

    SingleFilm m_film;
    std::shared_ptr<const FourierColorimeter> m_colorimeter;
    std::vector<BandMedia> m_media;
    bool m_sum_only = false;
};

/// How a colour is integrated over the spectrum: the 1 nm sum (CIE 015:2018) or the Fourier
/// series above.
enum class FilmIntegration { sum, fourier };
/// "sum", "fourier".
[[nodiscard]] std::string_view film_integration_name(FilmIntegration integration) noexcept;
/// The integration of a name above; throws UnknownNameError listing them.
[[nodiscard]] FilmIntegration parse_film_integration(std::string_view name);

/// The single film of an exact model, for FourierFilm: one layer, unpolarised light, a lossless
/// film and ambient. Throws irid::Error naming what is not so ("the Fourier integration needs
/// one layer; the stack has 3").
[[nodiscard]] SingleFilm fourier_single_film(const FilmModel& model);

}  // namespace irid
