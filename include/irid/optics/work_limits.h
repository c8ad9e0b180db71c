#pragma once

// Limits on the work of one request.
//
// Each parameter of a request (a thickness range, angles, wavelengths, layers) has its own range;
// these limits bound their product, the work of the whole request, so that values each in range
// cannot together ask for hours of computing or gigabytes of output. The command line calls the
// checks before it computes anything (and the Python module is to do the same). The limits come
// from the costs measured on one core of the development machine (g++ 12 -O2, docs/OPTICS.md,
// "Limits on the work of one request"); each allows about a minute of work at the measured cost.

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace irid {

/// One factor of a request's size: how many values it has (`count`, of `noun`) and how the
/// caller names it in messages: a command-line option with its value ("--thickness 0:1500:5")
/// or a parameter's name. Printed as "<name> (<count> <noun>)".
struct WorkFactor {
    std::string name;
    double count = 1.0;
    std::string noun = "values";
};

/// The most film reflectances one request may evaluate at one wavelength each by a closed form
/// (eq. 21/22, eq. 25 with 26 or 29) or the Airy sum, its colour summed: measured 18–55 ns each
/// (18 ns the exact single film's table, 37 ns the error study, 40 ns eq. 21 with water's
/// dispersion, 45–55 ns eq. 25), so 10⁹ take at most about 55 s.
inline constexpr double max_film_evaluations = 1e9;
/// The most layer evaluations (one layer's characteristic matrix at one wavelength, s and p) of
/// transfer-matrix stacks one request may ask for: measured 190 ns (water), 250 ns (a constant
/// complex index), 280 ns (silver, tabulated), so 2 × 10⁸ take at most about 56 s.
inline constexpr double max_stack_layer_evaluations = 2e8;
/// The most lines one request may write: 10⁶ lines of a colour table are about 130 MB of CSV
/// (measured 131 bytes a line) and 10⁶ lines of a spectrum about 50 MB (49 bytes a line).
inline constexpr double max_output_rows = 1e6;

/// Throws irid::Error unless the product of the factors' counts, times `cost_each`, is at most
/// `limit`. The message names the factors and gives the total in `unit` and the limit in the
/// same unit, floor(limit / cost_each), followed by `limit_note` when there is one:
/// "--thickness 0:99999:1 (100 000 values) × --angles 0:89:0.01 (8 901 values) asks for
/// 890 100 000 spectra; the limit is 2 123 142 (use coarser steps)". Counts must be finite and
/// >= 0, cost_each finite and > 0.
void check_work_limit(std::span<const WorkFactor> factors, double cost_each, double limit,
                      std::string_view unit, std::string_view advice,
                      std::string_view limit_note = {});

/// Colours of films on the 1 nm grid (one spectrum of dense_sample_count = 471 wavelengths per
/// colour), as many as the product of `spectra` (thickness values × angles × ...): at most
/// max_film_evaluations in all, so at most 2 123 142 spectra. When each wavelength costs more
/// than one closed form (the samples of a Morpho blend), `per_wavelength` names and counts them
/// and the limit shrinks by its count. The message counts spectra.
void check_color_work(std::span<const WorkFactor> spectra,
                      const std::optional<WorkFactor>& per_wavelength = std::nullopt);
/// Reflectances by the closed forms or the Airy sum at the product of `factors` (wavelengths ×
/// blend samples × ...): at most max_film_evaluations. The message counts film evaluations.
void check_spectrum_work(std::span<const WorkFactor> factors);
/// Transfer-matrix stacks: the product of `factors` (wavelengths × layers × ...) at most
/// max_stack_layer_evaluations. The message counts layer evaluations.
void check_stack_work(std::span<const WorkFactor> factors);
/// Lines of output: the product of `factors` at most max_output_rows. The message counts lines.
void check_output_rows(std::span<const WorkFactor> factors);

}  // namespace irid
