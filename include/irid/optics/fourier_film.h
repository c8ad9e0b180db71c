#pragma once

// The exact colour of a single film in about a microsecond: the Airy reflectance written as a
// Fourier series in the film's phase, R(φ) = A0 + 2 Re Σ_m G q^(m−1) e^(imφ), and summed against
// the Fourier transform of the weighted colour-matching functions, tabulated once per
// colorimeter (FourierColorimeter). Nothing is fitted: for wavelength-independent indices the
// result is the 1 nm sum up to the table's interpolation and the series' truncation.
//
// Dispersive media (water, oil, silica) are followed through seven Chebyshev nodes per band
// (`slopes`). Where the series does not apply (a film past its critical angle, a metal's
// table, a critical wavelength inside the spectrum, aliasing) FourierFilm uses nested
// quadratures or the 1 nm sum. The derivation, the error budgets and the accuracy against the
// 1 nm sum, measured over each film's thickness and angle ranges, are in docs/OPTICS.md ("The
// fast exact film colour"); the speeds in docs/PERFORMANCE.md.

#include <irid/color/types.h>
#include <irid/optics/film.h>
#include <irid/optics/film_color.h>

#include <array>
#include <complex>
#include <memory>
#include <optional>
#include <utility>
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
    /// Where the nodal tables (U_j, for dispersive films) end: past it the terms of a dispersive
    /// film take V times their mean over the band (at 40 µm |V| is below 4e-4 of the white).
    static constexpr double max_node_opd_nm = 40000.0;
    /// With slopes, a film's coefficients are taken at this many Chebyshev nodes per band: the
    /// interpolant through them is of degree node_count − 1.
    static constexpr int node_count = 7;
    /// The nested quadratures for smooth reflectances (quadrature_weights): level L has
    /// 8 · 2^L + 1 Chebyshev–Lobatto nodes, the finest quadrature_node_count.
    static constexpr int quadrature_levels = 5;
    static constexpr int quadrature_node_count = (8 << (quadrature_levels - 1)) + 1;

    /// Throws irid::Error unless 1 <= bands <= max_bands. With `slopes`, each band also holds
    /// the nodal transforms U_j that FourierFilm's dispersive films need, to max_node_opd_nm.
    /// One band: 1.2 MB, with slopes 4.6 MB (docs/PERFORMANCE.md has the build times); the
    /// tabulation runs on oneTBB's threads, its result independent of their number.
    explicit FourierColorimeter(const Colorimeter& colorimeter, int bands = 1, bool slopes = false);

    struct Transform {
        std::complex<double> x, y, z;
    };
    [[nodiscard]] int bands() const noexcept { return static_cast<int>(m_bands.size()); }
    [[nodiscard]] bool slopes() const noexcept { return m_slopes; }
    /// The band's interval in wavenumber [1/nm] as the Chebyshev variable sees it: x = (ν −
    /// mid) / half maps 780–380 nm onto [−1, 1] for one band (with slopes; the weights outside,
    /// 360–380 and 780–830 nm, extrapolate to x = 1.22 and −1.11).
    [[nodiscard]] double band_mid(int b) const noexcept { return m_bands[b].mid; }
    [[nodiscard]] double band_half_width(int b) const noexcept { return m_bands[b].half; }
    /// The Chebyshev variable of node j < node_count, x_j = cos((2j + 1)π / (2 node_count)).
    [[nodiscard]] static double node_x(int j) noexcept;
    /// The wavenumber [1/nm] of node j of band b (with slopes).
    [[nodiscard]] double node_wavenumber(int b, int j) const noexcept {
        return m_bands[b].mid + m_bands[b].half * node_x(j);
    }
    /// The Chebyshev coefficients of the interpolant through values at the nodes:
    /// c_k = Σ_j coefficient_matrix(k, j) v_j.
    [[nodiscard]] static double coefficient_matrix(int k, int j) noexcept;
    /// The quadratures for a reflectance smooth in wavenumber: Σ_j R(ν_j) quadrature_weights(L, j)
    /// is the 1 nm sum of the polynomial through R at level L's nodes, the Chebyshev–Lobatto
    /// points x_j = cos(jπ/128) over 360–830 nm (j = 0 at 360 nm) for j a multiple of
    /// 2^(quadrature_levels − 1 − L); the weights of the other j are 0.
    [[nodiscard]] double quadrature_wavenumber(int j) const noexcept { return m_quadrature_nu[j]; }
    [[nodiscard]] const Xyz& quadrature_weights(int level, int j) const noexcept {
        return m_quadrature_weights[level][j];
    }
    /// max |V_b| over the last cut_run_nm of the band's table: the estimate of the transform past
    /// the table's end that FourierFilm bounds the terms it drops with.
    [[nodiscard]] double band_floor(int b) const noexcept { return m_bands[b].floor; }
    /// The band's centre: the wavenumber [1/nm] at which its amplitudes and phase are taken (the
    /// Y-weighted mean wavenumber of the band).
    [[nodiscard]] double band_wavenumber(int b) const noexcept { return m_bands[b].nu_c; }
    /// Σ_i w_b(ν_i) w_i: the band's part of the white (the whites of all bands sum to the
    /// colorimeter's white).
    [[nodiscard]] const Xyz& band_white(int b) const noexcept { return m_bands[b].white; }
    /// Σ_i w_b(ν_i) w_i ℓ_j(x_i): node j's share of the band's white (U_j(0); with slopes).
    [[nodiscard]] const Xyz& node_white(int b, int j) const noexcept { return m_bands[b].node_white[j]; }
    /// The band's demodulated transform V_b(τ) = Σ_i w_b(ν_i) w_i e^{2πiτ(ν_i − ν_c)},
    /// interpolated; 0 beyond the band's table.
    [[nodiscard]] Transform transform(int b, double tau_nm) const noexcept;
    /// U_0 .. U_6 of band b, interpolated (with slopes; 0 past max_node_opd_nm and without
    /// slopes).
    [[nodiscard]] std::array<Transform, node_count> node_transforms(int b, double tau_nm) const noexcept;
    /// Σ_j values[j] U_j(τ) (with slopes, τ < max_node_opd_nm; 0 outside the nodal table): what
    /// a dispersive film's term needs, without forming the U_j.
    [[nodiscard]] Transform node_sum(int b, double tau_nm,
                                     const std::array<std::complex<double>, node_count>& values) const noexcept;
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
    /// The same for Σ_j |U_j| (0 without slopes).
    [[nodiscard]] double node_envelope(int b, double tau_nm) const noexcept {
        return envelope_at(m_bands[b].node_envelope, 0.0, tau_nm);
    }
    [[nodiscard]] const Colorimeter& colorimeter() const noexcept { return m_colorimeter; }

private:
    struct Band {
        double nu_c = 0.0;
        Xyz white;
        std::array<Xyz, node_count> node_white{};
        double bound = 0.0, floor = 0.0, mid = 0.0, half = 1.0;
        /// V per node of τ: x, y, z as real and imaginary parts. Single precision (its rounding,
        /// 6e-8 of the white, is far below the interpolation's 1.2e-5) halves what a lookup far
        /// out in τ brings into the cache.
        std::vector<float> table;
        std::size_t nodes = 0;
        /// U_0 .. U_6 per node of τ, likewise (with slopes).
        std::vector<float> node_table;
        std::size_t node_rows = 0;
        /// envelope[j]: max |V| over τ >= j × envelope_step_nm; node_envelope[j] the same of
        /// Σ_j |U_j| (with slopes).
        std::vector<double> envelope, node_envelope;
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
    std::array<double, quadrature_node_count> m_quadrature_nu{};
    std::array<std::array<Xyz, quadrature_node_count>, quadrature_levels> m_quadrature_weights{};
};

/// Whether a film's media disperse (any of ambient, film, substrate not Material::is_constant),
/// so that its coefficients need the slopes.
[[nodiscard]] bool fourier_needs_slopes(const SingleFilm& film) noexcept;
/// A colorimeter's transforms as a film needs them by default: one band, with slopes when the
/// media disperse (docs/OPTICS.md measures more bands: they cost more than they gain). The last
/// four built are kept and handed out again to a colorimeter of the same weights (building one
/// takes 30–200 ms; a Python call per colour would otherwise pay that each time). Thread-safe.
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
    /// incidence in the ambient (in [0, 1]); NaN outside those. In order:
    /// - the series (header);
    /// - past the film's critical angle at every wavelength, the white where nothing tunnels
    ///   through it;
    /// - the nested quadratures (header), where the 1 nm grid does not alias;
    /// - the sum: the 1 nm sum (PreparedFilm's Airy sum per wavelength), or where the 1 nm grid
    ///   aliases, the incoherent colour past 100 µm of path and a finer sum under it (fine_sum.h,
    ///   down to fallback_min_step_nm).
    /// The series does not apply where: the film is past its critical angle somewhere in the
    /// spectrum; |q| > max_ratio at grazing incidence (too slow to converge); dispersive media
    /// bend too fast through the band (max_amplitude_tail, max_phase_tail); a term's residual
    /// phase is past max_residual_phase while the terms from it on could add more than
    /// max_dropped_tail, or its interpolation could err by more than max_interpolation_error
    /// (thick films near their critical angle, or at grazing incidence); terms dropped past the
    /// table's end would matter (max_dropped_tail); the media are ones the nodes do not follow
    /// (max_index_misfit: a metal's table).
    [[nodiscard]] Xyz xyz(double thickness_nm, double cos_theta) const noexcept;
    [[nodiscard]] FilmColor color(double thickness_nm, double cos_theta) const noexcept;
    /// Whether xyz() sums at this thickness and cos θ, taking neither the series nor a
    /// quadrature (false outside the preconditions, where it is NaN): what BM_FourierFilmGrid
    /// counts as falling back.
    [[nodiscard]] bool summed_at(double thickness_nm, double cos_theta) const noexcept;

    /// |q| above which the 1 nm sum is used (about 900 terms for 1e-7 near this ratio).
    static constexpr double max_ratio = 0.98;
    /// With slopes: the largest last Chebyshev coefficient of A0 through the nodes, and of the
    /// first term's phase 4π d f(ν), for which the band's model is used. A film near its
    /// critical angle, or a Sellmeier pole just past the visible, bends them so that their
    /// series no longer converges within seven nodes; then the sum is used.
    static constexpr double max_amplitude_tail = 1e-4;
    static constexpr double max_phase_tail = 0.02;
    /// With slopes: media whose indices (real and imaginary parts) the nodes' interpolant misses
    /// by more than this anywhere on the 1 nm grid from 380 to 780 nm are summed (uses_sum()):
    /// a metal's table, whose kinks between its samples no polynomial follows.
    static constexpr double max_index_misfit = 1e-4;
    /// With slopes: the largest residual phase m max_j |ρ_j| of the m-th term at the nodes
    /// (what is left of m φ after its linear carrier) for which it is interpolated; past it the
    /// five nodes no longer resolve e^{imρ} (docs/OPTICS.md measures the error against it).
    static constexpr double max_residual_phase = 2.0;
    /// With slopes: the most the interpolation may err in Y (white = 1), by its estimate
    /// summed over the terms, before the sum is used instead.
    static constexpr double max_interpolation_error = 3e-4;
    /// With slopes: the budgets above (max_interpolation_error, max_dropped_tail) shrink to this
    /// fraction of the film's incoherent Y where that is smaller (a dark film).
    static constexpr double relative_budget = 5e-3;
    /// A quadrature is taken when it agrees with the one before to this in X, Y and Z, in units
    /// of the white's Y or, for a colour darker than 1 % of it, of 100 times its Y; and when the
    /// one before that agreed to within the square root of this.
    static constexpr double max_quadrature_disagreement = 2e-5;
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
    /// Whether every colour is the sum (media the nodes do not follow: max_index_misfit).
    [[nodiscard]] bool uses_sum() const noexcept { return m_sum_only; }
    [[nodiscard]] const FourierColorimeter& colorimeter() const noexcept { return *m_colorimeter; }

private:
    /// The media at one wavenumber.
    struct Media {
        double n0 = 1.0, n1 = 1.0;
        std::complex<double> n2;
    };
    struct BandMedia {
        double lambda_c = 0.0;
        /// The real indices' wavelength derivatives at the centre [1/nm] (without slopes).
        double dn0 = 0.0, dn1 = 0.0;
        /// At ν_c, and at the band's Chebyshev nodes (with slopes).
        Media centre;
        std::array<Media, FourierColorimeter::node_count> nodes;
    };
    /// The band's part of the series with slopes (header), added to `out`; false where the
    /// series does not apply (and `no_series` where that is because some node has none: the
    /// film past its critical angle there, or |q| > max_ratio).
    [[nodiscard]] bool add_interpolated_band(int b, double thickness_nm, double cos_theta, double sin2,
                                             Xyz& out, bool& no_series) const noexcept;
    /// The first of the nested quadratures that agrees with the one before
    /// (max_quadrature_disagreement) and has five intervals for each of the reflectance's
    /// `cycles` over the spectrum, or nothing. cycles = 0: the reflectance is analytic (an
    /// evanescent film), from 17 nodes on; otherwise from 33 on, with the agreement established.
    [[nodiscard]] std::optional<Xyz> quadrature(double thickness_nm, double cos_theta, double cycles) const noexcept;
    /// The series, or where it does not apply and the 1 nm grid does not alias, the quadrature:
    /// what xyz() takes without summing.
    [[nodiscard]] std::optional<Xyz> fast(double thickness_nm, double cos_theta) const noexcept;
    /// The media at the quadratures' nodes.
    std::array<Media, FourierColorimeter::quadrature_node_count> m_quadrature_media;
    /// The media on the 1 nm grid, 360–830 nm: what the sum reads.
    std::vector<Media> m_dense;
    [[nodiscard]] Xyz exact_sum(double thickness_nm, double cos_theta) const noexcept;
    /// The colour of a film past its own critical angle at every wavelength: the white where no
    /// light tunnels through it (e^{−2κd} < 1e-10), else quadrature(); nothing where some
    /// wavelengths are not past it.
    [[nodiscard]] std::optional<Xyz> total_reflection(double thickness_nm, double cos_theta, double sin2) const noexcept;
    /// The wavelengths every 10 nm over 360–830 nm, with n0² and n1² there: what
    /// total_reflection reads.
    std::vector<std::array<double, 3>> m_barrier;
    /// Whether the film or a lossless substrate is past its critical angle at some wavelength
    /// of the spectrum and not at others (sin2 = sin²θ in the ambient).
    [[nodiscard]] bool critical_inside(double sin2) const noexcept;
    /// The range over the wavelengths of m_barrier of n1²/n0² and of n2²/n0² (empty, low > high,
    /// for an absorbing substrate): what critical_inside reads.
    std::array<std::pair<double, double>, 2> m_critical_ratios{};
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
