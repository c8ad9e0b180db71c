#include <irid/error.h>
#include <irid/optics/fine_sum.h>
#include <irid/optics/multilayer.h>

#include <optional>

#include <fmt/core.h>

#include <algorithm>
#include <complex>
#include <cmath>
#include <utility>

namespace irid {

AliasReach alias_reach(const SingleFilm& film, double angle_rad) noexcept {
    constexpr double lambda = 555.0;
    const double n0 = film.ambient.index(lambda).real();
    const double q0 = n0 * std::cos(angle_rad);
    const auto q_of = [&](Complex n) {
        Complex q = std::sqrt((n - n0) * (n + n0) + q0 * q0);
        if (q.imag() < 0.0 || (q.imag() == 0.0 && q.real() < 0.0)) q = -q;
        return q;
    };
    const Complex n1 = film.film.index(lambda), n2 = film.substrate.index(lambda);
    const Complex q1 = q_of(n1), q2 = q_of(n2);
    const double a0 = n0 * n0;
    const Complex a1 = n1 * n1, a2 = n2 * n2;
    const double ratio_s = std::abs((q0 - q1) / (q0 + q1) * (q1 - q2) / (q1 + q2));
    const double ratio_p = std::abs((a0 * q1 - a1 * q0) / (a0 * q1 + a1 * q0) * (a1 * q2 - a2 * q1) / (a1 * q2 + a2 * q1));
    const double ratio = std::max(ratio_s, ratio_p);
    // Round trips until the amplitude falls to 1e-3 of the first (at least one; a ratio of 1 is
    // capped at 1e6 round trips).
    const double trips = ratio > 1e-3 ? std::min(1e6, std::max(1.0, std::log(1e-3) / std::log(std::min(ratio, 1.0 - 1e-12)))) : 1.0;
    const double opd_per_nm = 2.0 * std::abs(q1.real());
    return {opd_per_nm, trips * opd_per_nm};
}

double alias_free_step_nm(const AliasReach& reach, double thickness_nm) noexcept {
    constexpr double shortest = 380.0;
    // The 1 nm sum's transform departs from a finer sum's by 1e-4 of the white at 0.7 × 380² nm
    // (100 µm; docs/OPTICS.md): the step keeps the reach within 0.7 λ_min² / step.
    const double r = thickness_nm * reach.reach_per_nm;
    return r > 0.0 ? std::min(1.0, 0.7 * shortest * shortest / r) : 1.0;
}

double alias_free_step_nm(const SingleFilm& film, double thickness_nm, double angle_rad) noexcept {
    return alias_free_step_nm(alias_reach(film, angle_rad), thickness_nm);
}

Xyz finely_summed_film_xyz(const SingleFilm& film, double thickness_nm, double angle_rad,
                           const Colorimeter& colorimeter, double step_nm) {
    if (!(step_nm >= 1e-4 && step_nm <= 1.0)) {
        throw Error(fmt::format("fine film sum: step {} nm; allowed 1e-4 to 1 nm", step_nm));
    }
    const auto last = static_cast<long>(std::floor((lambda_max_nm - lambda_min_nm) / step_nm));
    const DenseSpectrum* weights[3] = {&colorimeter.weight_x(), &colorimeter.weight_y(), &colorimeter.weight_z()};
    double sum[3] = {0.0, 0.0, 0.0}, white[3] = {0.0, 0.0, 0.0};
    const double cos_theta0 = std::cos(angle_rad);
    for (long j = 0; j <= last; ++j) {
        const double lambda = lambda_min_nm + static_cast<double>(j) * step_nm;
        const double u = lambda - lambda_min_nm;
        const int i = std::min(dense_sample_count - 2, static_cast<int>(u));
        const double f = u - i;
        // PreparedFilm's Airy sum, written without cancellation where both faces reflect almost
        // totally; the transfer matrix at the film's own critical angle, where it is 0/0.
        bool degenerate = false;
        const PreparedFilm::Sample sample = PreparedFilm::prepare_at(film, cos_theta0, lambda, degenerate);
        const double r = degenerate
                             ? FilmStack(film.ambient, {Layer{film.film, thickness_nm}}, film.substrate)
                                   .evaluate(lambda, angle_rad, Polarization::unpolarized)
                                   .R
                             : PreparedFilm::airy_reflectance(sample, thickness_nm);
        for (int ch = 0; ch < 3; ++ch) {
            const double w = (*weights[ch])[i] * (1.0 - f) + (*weights[ch])[i + 1] * f;
            sum[ch] += r * w;
            white[ch] += w;
        }
    }
    const Xyz& w = colorimeter.white();
    return {white[0] > 0.0 ? sum[0] * w.X / white[0] : 0.0, white[1] > 0.0 ? sum[1] * w.Y / white[1] : 0.0,
            white[2] > 0.0 ? sum[2] * w.Z / white[2] : 0.0};
}

double optical_path_difference_nm(const SingleFilm& film, double thickness_nm, double angle_rad) noexcept {
    return thickness_nm * alias_reach(film, angle_rad).opd_per_nm;
}

Xyz incoherent_film_xyz(const SingleFilm& film, double angle_rad, const Colorimeter& colorimeter) noexcept {
    // Per polarisation the mean of the Airy reflectance over a period of the phase is the
    // incoherent sum of the faces, R = 1 − (1 − R01)(1 − R12) / (1 − R01 R12) (Stokes), written
    // from PreparedFilm's cancellation-free factors: (1 − r01²)(1 − r12²) / ((1 − x)(1 + x)).
    // Wavelengths where the film absorbs or its top face reflects totally keep the Airy sum (an
    // absorbing film this thick returns nothing from its far face; a totally reflecting one
    // reflects everything).
    const double cos_theta0 = std::cos(angle_rad);
    int i = 0;
    return colorimeter.xyz_of([&](double lambda) {
        bool degenerate = false;
        const PreparedFilm::Sample s = PreparedFilm::prepare(film, cos_theta0, i++, degenerate);
        if (degenerate) {
            return FilmStack(film.ambient, {Layer{film.film, 0.0}}, film.substrate)
                .evaluate(lambda, angle_rad, Polarization::unpolarized)
                .R;
        }
        if (!s.real && s.phase_per_nm.real() == 0.0) {
            // A lossless film whose far face is complex (an absorbing substrate, or one past
            // its critical angle): the same Stokes sum with the faces' |r|², which the phase of
            // r12 does not enter.
            double r = 0.0;
            for (const auto& [r01, r12] : {std::pair{s.r01_s, s.r12_s}, std::pair{s.r01_p, s.r12_p}}) {
                const double a = std::norm(r01), b = std::norm(r12);
                r += 0.5 * (a + (1.0 - a) * (1.0 - a) * b / (1.0 - a * b));
            }
            return std::clamp(r, 0.0, 1.0);
        }
        if (!s.real) return PreparedFilm::airy_reflectance(s, 1e6);
        double r = 0.0;
        for (int k = 0; k < 2; ++k) {
            const double one_plus_x = std::sqrt(s.one_plus_x_sq[k]);
            const double one_minus_x = 1.0 - s.x[k];
            r += 0.5 * (1.0 - s.transmitted[k] / (one_minus_x * one_plus_x));
        }
        return std::clamp(r, 0.0, 1.0);
    });
}

std::optional<Xyz> alias_free_xyz(const SingleFilm& film, double thickness_nm, double angle_rad,
                                  const AliasReach& reach, const Colorimeter& colorimeter) noexcept {
    if (!(std::isfinite(thickness_nm) && thickness_nm >= 0.0)) return std::nullopt;
    if (!(alias_free_step_nm(reach, thickness_nm) < 1.0)) return std::nullopt;
    // Where the 1 nm grid aliases and the single pass is past incoherent_opd_nm, the
    // interference terms weigh the spectrum's transform at that path and beyond, below 8e-5 of
    // the white: the colour is the incoherent one, at the 1 nm sum's cost.
    if (thickness_nm * reach.opd_per_nm >= incoherent_opd_nm) return incoherent_film_xyz(film, angle_rad, colorimeter);
    return std::nullopt;
}

bool aliases_on_the_grid(const AliasReach& reach, double thickness_nm) noexcept {
    return std::isfinite(thickness_nm) && thickness_nm >= 0.0 && alias_free_step_nm(reach, thickness_nm) < 1.0 &&
           thickness_nm * reach.opd_per_nm < incoherent_opd_nm;
}

std::optional<Xyz> refined_film_xyz(const SingleFilm& film, double thickness_nm, double angle_rad,
                                    const AliasReach& reach, const Colorimeter& colorimeter) noexcept {
    if (std::optional<Xyz> incoherent = alias_free_xyz(film, thickness_nm, angle_rad, reach, colorimeter)) {
        return incoherent;
    }
    if (!aliases_on_the_grid(reach, thickness_nm)) return std::nullopt;
    const double step = std::max(alias_free_step_nm(reach, thickness_nm), finest_refinement_nm);
    return finely_summed_film_xyz(film, thickness_nm, angle_rad, colorimeter, step);
}

std::optional<Xyz> alias_free_xyz(const SingleFilm& film, double thickness_nm, double angle_rad,
                                  const Colorimeter& colorimeter) noexcept {
    return alias_free_xyz(film, thickness_nm, angle_rad, alias_reach(film, angle_rad), colorimeter);
}

}  // namespace irid
