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
// centre. With `slopes` on, f and the coefficients A0 and G q^{m-1} are evaluated at ν_c and at
// two nodes inside the band (its outer Chebyshev nodes): each coefficient is the parabola
// through them, c0 + c1 Δ + c2 Δ² with Δ = ν − ν_c, and the phase gets its quadratic term
// ψ = β Δ², β = 2π d f''(ν_c), to second order (e^{imψ} ≈ 1 + imψ − (mψ)²/2). Their products
// need the moments V_k(τ) = Σ_i w_i Δ_i^k e^{2πiτΔ_i}, k = 1..4, beside V. One band is exact for
// wavelength-independent media; for dispersive ones (water, oil, silica, metals) see
// docs/OPTICS.md, "The fast exact film colour", for what each correction buys.

#include <irid/color/types.h>
#include <irid/optics/film.h>
#include <irid/optics/film_color.h>

#include <array>
#include <complex>
#include <memory>
#include <optional>
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
    /// The tables end here at the latest: 100 µm, where the 1 nm sum begins to alias (its
    /// transform departs from that of a 0.1 nm sum by 1.3e-4 of the white, 6e-3 at 150 µm; the
    /// first alias of the 380 nm sample is at 380² nm). Past it the transform of the spectrum
    /// itself is below 8e-5 of the white and falling, so the terms beyond are dropped and a film
    /// whose first term is past it is the incoherent sum of its faces (docs/OPTICS.md).
    static constexpr double max_opd_cap_nm = 100000.0;
    /// Where the moment tables (V1 .. V4, for dispersive films) end: past it the terms of a
    /// dispersive film use V alone (at 40 µm |V| is below 4e-4 of the white).
    static constexpr double max_moment_opd_nm = 40000.0;
    /// The moments tabulated with slopes: V0 = V, and V1 .. V4.
    static constexpr int moment_count = 5;

    /// Throws irid::Error unless 1 <= bands <= max_bands. With `slopes`, each band also holds
    /// the moment transforms V1 .. V4 that FourierFilm's dispersion correction needs, to
    /// max_moment_opd_nm. One band: 1.2 MB and 52 ms to build, with slopes 3.1 MB and 160 ms
    /// (docs/PERFORMANCE.md); the tabulation runs on oneTBB's threads, its result independent
    /// of their number.
    explicit FourierColorimeter(const Colorimeter& colorimeter, int bands = 1, bool slopes = false);

    struct Transform {
        std::complex<double> x, y, z;
    };
    [[nodiscard]] int bands() const noexcept { return static_cast<int>(m_bands.size()); }
    [[nodiscard]] bool slopes() const noexcept { return m_slopes; }
    /// The band's reach δ [1/nm]: how far from its centre its weights extend (to 380 nm for one
    /// band; 0 without slopes).
    [[nodiscard]] double slope_step(int b) const noexcept { return m_bands[b].delta; }
    /// Where, relative to the centre [1/nm], a film's coefficients are sampled for their
    /// parabola through the band (with slopes): below (x0 < 0) and above (x2 > 0) the centre.
    [[nodiscard]] double node_below(int b) const noexcept { return m_bands[b].node_below; }
    [[nodiscard]] double node_above(int b) const noexcept { return m_bands[b].node_above; }
    /// max |V_b| over the last cut_run_nm of the band's table: the estimate of the transform past
    /// the table's end that FourierFilm bounds the terms it drops with.
    [[nodiscard]] double band_floor(int b) const noexcept { return m_bands[b].floor; }
    /// The band's centre: the wavenumber [1/nm] at which its amplitudes and phase are taken (the
    /// Y-weighted mean wavenumber of the band).
    [[nodiscard]] double band_wavenumber(int b) const noexcept { return m_bands[b].nu_c; }
    /// Σ_i w_b(ν_i) w_i: the band's part of the white (the whites of all bands sum to the
    /// colorimeter's white).
    [[nodiscard]] const Xyz& band_white(int b) const noexcept { return m_bands[b].moments[0]; }
    /// Σ_i w_b(ν_i) w_i (ν_i − ν_c)^k, k < moment_count: the band's moments (k = 0 is its white).
    [[nodiscard]] const Xyz& band_moment(int b, int k) const noexcept { return m_bands[b].moments[k]; }
    /// The band's demodulated transform V_b(τ) = Σ_i w_b(ν_i) w_i e^{2πiτ(ν_i − ν_c)},
    /// interpolated; 0 beyond the band's table.
    [[nodiscard]] Transform transform(int b, double tau_nm) const noexcept;
    /// V1_b .. V4_b, with (ν_i − ν_c)^k in the sum (with slopes; 0 past max_moment_opd_nm and
    /// without slopes).
    [[nodiscard]] std::array<Transform, moment_count - 1> moment_transforms(int b, double tau_nm) const noexcept;
    /// Where the band's table ends [nm].
    [[nodiscard]] double max_opd_nm(int b) const noexcept {
        return step_nm * static_cast<double>(m_bands[b].nodes - 1);
    }
    /// max over τ and channels of |V_b(τ)|: the bound the series' truncation uses.
    [[nodiscard]] double band_bound(int b) const noexcept { return m_bands[b].bound; }
    /// The largest |V_b| (over channels) from τ on: decreasing in τ, the band's floor past the
    /// table's end. What FourierFilm bounds the terms it has not yet summed with.
    [[nodiscard]] double envelope(int b, double tau_nm) const noexcept {
        return envelope_at(m_bands[b].envelope, m_bands[b].floor, tau_nm);
    }
    /// The same for max_k |V_k| / δ^k, k = 1 .. 4 (0 without slopes).
    [[nodiscard]] double moment_envelope(int b, double tau_nm) const noexcept {
        return envelope_at(m_bands[b].moment_envelope, 0.0, tau_nm);
    }
    [[nodiscard]] const Colorimeter& colorimeter() const noexcept { return m_colorimeter; }

private:
    struct Band {
        double nu_c = 0.0;
        std::array<Xyz, moment_count> moments{};
        double bound = 0.0, delta = 0.0, floor = 0.0, node_below = 0.0, node_above = 0.0;
        /// V per node of τ: x, y, z as real and imaginary parts. Single precision (its rounding,
        /// 6e-8 of the white, is far below the interpolation's 1.2e-5) halves what a lookup far
        /// out in τ brings into the cache.
        std::vector<float> table;
        std::size_t nodes = 0;
        /// V1 .. V4 per node, likewise (with slopes).
        std::vector<float> moment_table;
        std::size_t moment_nodes = 0;
        /// envelope[j]: max |V| over τ >= j × envelope_step_nm; moment_envelope[j] the same of
        /// max_k |V_k| / δ^k (with slopes).
        std::vector<double> envelope, moment_envelope;
    };
    static constexpr double envelope_step_nm = 500.0;
    static double envelope_at(const std::vector<double>& e, double beyond, double tau_nm) noexcept {
        const double j = tau_nm / envelope_step_nm;
        if (!(j >= 0.0)) return e.empty() ? beyond : e.front();
        return j < static_cast<double>(e.size()) ? e[static_cast<std::size_t>(j)] : beyond;
    }
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
    /// incidence in the ambient (in [0, 1]); NaN outside those. A film past its own critical
    /// angle through which nothing tunnels is the white. Where the series does not apply the
    /// colour is summed instead: the 1 nm sum (PreparedFilm's Airy sum per wavelength), or where
    /// the 1 nm grid aliases the incoherent colour past 100 µm of path, a finer sum under it
    /// (fine_sum.h, down to fallback_min_step_nm). That is:
    /// the film at or past its own critical angle and still tunnelling; |q| > max_ratio at
    /// grazing incidence, where the series converges too slowly; dispersive media changing too
    /// fast through the band (max_q1_variation, max_bend, max_phase_departure); a term whose
    /// chirp is past max_quadratic_phase while the terms from it on could add more than
    /// max_dropped_tail (thick dispersive films past about 55°); terms dropped past the table's
    /// end that would matter (max_dropped_tail); a dispersive absorbing substrate (a metal's
    /// table: its reflectance turns too sharply for one band, ΔE2000 up to 18 for gold,
    /// docs/OPTICS.md).
    [[nodiscard]] Xyz xyz(double thickness_nm, double cos_theta) const noexcept;
    [[nodiscard]] FilmColor color(double thickness_nm, double cos_theta) const noexcept;
    /// Whether xyz() sums at this thickness and cos θ rather than take the series (false outside
    /// the preconditions, where it is NaN): what BM_FourierFilmGrid counts as falling back.
    [[nodiscard]] bool summed_at(double thickness_nm, double cos_theta) const noexcept;

    /// |q| above which the 1 nm sum is used (about 900 terms for 1e-7 near this ratio).
    static constexpr double max_ratio = 0.98;
    /// With slopes: the largest change of q1 = n1 cos θ1 between the band's nodes, relative to
    /// its value at the centre, for which the band's model is used.
    static constexpr double max_q1_variation = 0.05;
    /// With slopes: the most that A0 and the phase of the first term, 4π d f(ν), may depart from
    /// their parabolas at the band's edges (a Sellmeier pole just past the visible, or a film
    /// near its critical angle, bends them) before the 1 nm sum is used instead.
    static constexpr double max_bend = 1e-3;
    static constexpr double max_phase_departure = 0.2;
    /// With slopes: the largest chirp m|β|δ² of the m-th term at the band's reach δ [rad] for
    /// which its second-order expansion is used (its error there, (m|β|δ²)³/6, falls on the
    /// spectrum's ends, where the weights are small).
    static constexpr double max_quadratic_phase = 1.0;
    /// The most that the terms dropped past the table's end may add to Y, for a film with terms
    /// in the table (beyond: the 1 nm sum; a film whose first term is past the table is the
    /// incoherent sum of its faces).
    static constexpr double max_dropped_tail = 2e-4;
    /// The finest step [nm] of the sum the series falls back to where the 1 nm grid aliases
    /// under 100 µm of path (fine_sum.h): 47 000 reflectances, about 2 ms a colour.
    static constexpr double fallback_min_step_nm = 0.01;
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
        /// At ν_c, at the band's nodes ν_c + x0 and ν_c + x2 (slopes), and at its edges ν_c ± δ
        /// (clamped to 360–830 nm), where the parabolas are checked.
        Media centre, below, above, edge_below, edge_above;
        double edge_x0 = 0.0, edge_x2 = 0.0;
    };
    [[nodiscard]] Xyz exact_sum(double thickness_nm, double cos_theta) const noexcept;
    /// The colour of a film past its own critical angle at every wavelength and thick enough that
    /// no light tunnels through it (e^{−2κd} < 1e-10): the white; nothing otherwise.
    [[nodiscard]] std::optional<Xyz> total_reflection(double thickness_nm, double sin2) const noexcept;
    /// n0² and n1² every 10 nm over 360–830 nm, and the wavelengths: what total_reflection reads.
    std::vector<std::array<double, 3>> m_barrier;
    /// The series' colour, or nothing where the 1 nm sum is to be used.
    [[nodiscard]] std::optional<Xyz> series(double thickness_nm, double cos_theta) const noexcept;

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
