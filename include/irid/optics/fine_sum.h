#pragma once

// The colour of a single film summed finer than the 1 nm grid: the reference where the 1 nm sum
// aliases.
//
// The 1 nm sum samples the phase 2π OPD/λ once per nanometre. Once the optical path difference
// of the reflections that matter (OPD times the number of round trips whose amplitude has not yet
// died away) nears λ²/(1 nm), 144 µm at 380 nm, successive samples step by a whole period and the
// sum aliases: the 1 nm grid "sees" interference that the continuous spectrum has averaged away
// (docs/OPTICS.md, "The fast exact film colour"). A finer step moves that limit out in proportion.

#include <irid/optics/film_color.h>

#include <optional>

namespace irid {

/// The AliasReach (film_color.h) of a film at an angle.
[[nodiscard]] AliasReach alias_reach(const SingleFilm& film, double angle_rad) noexcept;
/// alias_free_step_nm below, from a reach already found for the film and angle.
[[nodiscard]] double alias_free_step_nm(const AliasReach& reach, double thickness_nm) noexcept;

/// A step [nm] at which the colour of `film` at this thickness and angle does not alias: the
/// reflections whose amplitude is above 1e-3 of the first (|q|^m, q = r01 r12 at 555 nm, the larger
/// of s and p) reach m × OPD; the step keeps that below 0.7 λ_min² / step at 380 nm (where the
/// 1 nm sum departs from a finer one by 1e-4 of the white). At most 1 nm.
/// Preconditions: thickness finite and >= 0, angle in [0, π/2), a lossless ambient.
[[nodiscard]] double alias_free_step_nm(const SingleFilm& film, double thickness_nm, double angle_rad) noexcept;

/// XYZ (white Y = 1) of a single film summed every `step_nm` over 360–830 nm: the Airy reflectance
/// at each wavelength times the colorimeter's 1 nm weights interpolated linearly between their
/// nanometres, normalised so that a perfect reflector gives the colorimeter's white. Equal to the
/// 1 nm sum to interpolation error where neither aliases. Throws irid::Error unless
/// 1e-4 <= step_nm <= 1 (a step of 1e-4 nm is 4.7 million reflectances).
[[nodiscard]] Xyz finely_summed_film_xyz(const SingleFilm& film, double thickness_nm, double angle_rad,
                                         const Colorimeter& colorimeter, double step_nm);

/// 2 d n1 cos θ1 at 555 nm [nm]: the optical path difference of one round trip in the film.
[[nodiscard]] double optical_path_difference_nm(const SingleFilm& film, double thickness_nm,
                                                double angle_rad) noexcept;

/// XYZ of the film's incoherent reflectance, summed at 1 nm: per wavelength and polarisation the
/// mean of the Airy reflectance over a period of the phase, R01 + (1 − R01)² R12 / (1 − R01 R12).
/// What a film reflects once its fringes are far finer than the spectrum's features.
[[nodiscard]] Xyz incoherent_film_xyz(const SingleFilm& film, double angle_rad, const Colorimeter& colorimeter) noexcept;

/// The single-pass optical path past which alias_free_xyz takes the incoherent colour: 100 µm,
/// where the transform of the weighted matching functions is below 8e-5 of the white (and the
/// 1 nm grid's own transform begins to alias; docs/OPTICS.md).
inline constexpr double incoherent_opd_nm = 100000.0;

/// Where the 1 nm grid aliases for this film, thickness and angle (alias_free_step_nm < 1) and
/// one round trip is past incoherent_opd_nm, the incoherent colour; nothing otherwise. The 1 nm
/// colours (PreparedFilm::color, exact_film_color) defer to it. Below that path the 1 nm colours
/// stay 1 nm sums (aliases_on_the_grid says where they alias): summing a colour table there as
/// finely as it needs would cost up to about 65 times the work the request limits count
/// (docs/OPTICS.md); refined_film_xyz does it for one colour.
[[nodiscard]] std::optional<Xyz> alias_free_xyz(const SingleFilm& film, double thickness_nm, double angle_rad,
                                                const Colorimeter& colorimeter) noexcept;
/// The same from a reach already found for the film and angle (PreparedFilm finds it once).
[[nodiscard]] std::optional<Xyz> alias_free_xyz(const SingleFilm& film, double thickness_nm, double angle_rad,
                                                const AliasReach& reach, const Colorimeter& colorimeter) noexcept;

/// The 1 nm sum of this film aliases at this thickness below incoherent_opd_nm (where
/// alias_free_xyz does not take over): high finesse, a metal base, grazing light.
[[nodiscard]] bool aliases_on_the_grid(const AliasReach& reach, double thickness_nm) noexcept;

/// The finest step refined_film_xyz sums at [nm]: 47 000 reflectances per colour.
inline constexpr double finest_refinement_nm = 0.01;

/// One colour without aliasing at any thickness: alias_free_xyz's incoherent colour, else where
/// aliases_on_the_grid the film summed at alias_free_step_nm (no finer than
/// finest_refinement_nm), else nothing (the 1 nm sum holds).
[[nodiscard]] std::optional<Xyz> refined_film_xyz(const SingleFilm& film, double thickness_nm, double angle_rad,
                                                  const AliasReach& reach, const Colorimeter& colorimeter) noexcept;

}  // namespace irid
