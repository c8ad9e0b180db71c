#pragma once

// The error study: CIEDE2000 between the thesis' single-film model (eq. 21/22 with eq. 24) and
// the exact Airy model over a thickness × angle grid, as `irid film-error` prints it.

#include <irid/optics/film_color.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

/// The error study: CIEDE2000 between the thesis' single-film model (eq. 21/22 with eq. 24, K
/// from thesis_matched_k unless given) and the exact Airy model, over a thickness × angle grid.
struct ErrorStudyOptions {
    double max_thickness_nm = 1500.0;
    double thickness_step_nm = 5.0;
    double max_angle_deg = 80.0;
    double angle_step_deg = 5.0;
    std::optional<double> k;  // default: thesis_matched_k
};
struct ErrorStudyResult {
    std::string name;
    double k = 1.0;
    std::size_t samples = 0;
    double mean = 0.0, median = 0.0, p95 = 0.0, max = 0.0;
    double worst_thickness_nm = 0.0, worst_angle_deg = 0.0;
    /// Mean and maximum ΔE2000 at each angle of the grid, in order.
    std::vector<double> angles_deg, mean_by_angle, max_by_angle;
    /// Mean ΔE2000 per thickness band of 100 nm (0-100, 100-200, ...; the last includes the
    /// maximum thickness).
    std::vector<double> mean_by_thickness_band;
};
/// Throws irid::Error (see validate_error_study) for invalid options or too much work.
[[nodiscard]] ErrorStudyResult thesis_error_study(const std::string& name, const SingleFilm& film,
                                                  const Colorimeter& colorimeter,
                                                  const ErrorStudyOptions& options = {});

/// The thickness values and the angles of the error study's grid, as thesis_error_study samples
/// them: 0, step, ..., max (within rounding).
[[nodiscard]] double error_study_thickness_count(const ErrorStudyOptions& options) noexcept;
[[nodiscard]] double error_study_angle_count(const ErrorStudyOptions& options) noexcept;
/// Throws irid::Error unless the options are valid (steps > 0, maximum thickness >= 0, maximum
/// angle in [0, 90), all finite) and the study of `films` films is within the work limit: each
/// grid point costs two spectra, the thesis' and the exact, of 471 wavelengths each
/// (check_color_work). `thickness_name` and `angles_name` name the two grids in the message
/// (the caller's names: a command-line option and its value), `films_name` the films when
/// there is more than one. thesis_error_study calls it with films = 1.
void validate_error_study(const ErrorStudyOptions& options, double films = 1.0,
                          std::string_view thickness_name = "thickness grid",
                          std::string_view angles_name = "angle grid",
                          std::string_view films_name = "films");

}  // namespace irid
