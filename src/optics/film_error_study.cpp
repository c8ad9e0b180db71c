#include <irid/color/difference.h>
#include <irid/color/measure.h>
#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/optics/film_error_study.h>
#include <irid/optics/thesis_models.h>
#include <irid/optics/work_limits.h>


#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace irid {
namespace {

constexpr double degrees_to_radians = std::numbers::pi / 180.0;

}  // namespace

double error_study_thickness_count(const ErrorStudyOptions& o) noexcept {
    return std::floor(o.max_thickness_nm / o.thickness_step_nm + 1e-9) + 1.0;
}

double error_study_angle_count(const ErrorStudyOptions& o) noexcept {
    return std::floor(o.max_angle_deg / o.angle_step_deg + 1e-9) + 1.0;
}

void validate_error_study(const ErrorStudyOptions& o, double films, std::string_view thickness_name,
                          std::string_view angles_name, std::string_view films_name) {
    const auto finite = [](double v) { return std::isfinite(v); };
    if (!(finite(o.thickness_step_nm) && o.thickness_step_nm > 0.0 && finite(o.max_thickness_nm) &&
          o.max_thickness_nm >= 0.0 && finite(o.angle_step_deg) && o.angle_step_deg > 0.0 &&
          o.max_angle_deg >= 0.0 && o.max_angle_deg < 90.0)) {
        throw Error(
            "error study: steps must be finite and > 0, thickness finite and >= 0 and "
            "angles in [0, 90)");
    }
    if (o.k && !(std::isfinite(*o.k) && *o.k >= 0.0)) {
        throw Error("error study: K " + format_shortest(*o.k) + " must be finite and >= 0");
    }
    std::vector<WorkFactor> spectra{{std::string(thickness_name), error_study_thickness_count(o)},
                                    {std::string(angles_name), error_study_angle_count(o)}};
    if (films != 1.0) spectra.push_back({std::string(films_name), films, "films"});
    spectra.push_back({"the thesis' and the exact model", 2.0, "spectra per sample"});
    check_color_work(spectra);
}

ErrorStudyResult thesis_error_study(const std::string& name, const SingleFilm& film,
                                    const Colorimeter& colorimeter, const ErrorStudyOptions& o) {
    validate_error_study(o);
    ErrorStudyResult r;
    r.name = name;
    r.k = o.k.value_or(thesis_matched_k(film));
    std::vector<double> all;
    const auto thickness_count = static_cast<std::size_t>(std::floor(o.max_thickness_nm / o.thickness_step_nm + 1e-9)) + 1;
    const auto band_count = static_cast<std::size_t>(std::ceil(o.max_thickness_nm / 100.0 - 1e-9));
    std::vector<double> band_sum(std::max<std::size_t>(band_count, 1), 0.0);
    std::vector<std::size_t> band_n(band_sum.size(), 0);
    for (double angle = 0.0; angle <= o.max_angle_deg + 1e-9; angle += o.angle_step_deg) {
        const double theta = angle * degrees_to_radians;
        const PreparedFilm prepared(film, theta);
        double sum = 0.0, worst = 0.0;
        for (std::size_t i = 0; i < thickness_count; ++i) {
            const double t = o.thickness_step_nm * static_cast<double>(i);
            const Xyz exact = prepared.color(t, colorimeter).xyz;
            const Xyz thesis = colorimeter.xyz_of([&](double lambda) {
                return thesis_single_film_reflectance(film, t, lambda, theta, r.k, std::nullopt);
            });
            const double d = delta_e_2000_of(colorimeter, thesis, exact);
            all.push_back(d);
            sum += d;
            worst = std::max(worst, d);
            const std::size_t band = std::min(static_cast<std::size_t>(t / 100.0), band_sum.size() - 1);
            band_sum[band] += d;
            ++band_n[band];
            if (d > r.max) {
                r.max = d;
                r.worst_thickness_nm = t;
                r.worst_angle_deg = angle;
            }
        }
        r.angles_deg.push_back(angle);
        r.mean_by_angle.push_back(sum / static_cast<double>(thickness_count));
        r.max_by_angle.push_back(worst);
    }
    for (std::size_t b = 0; b < band_sum.size(); ++b) {
        r.mean_by_thickness_band.push_back(band_n[b] ? band_sum[b] / static_cast<double>(band_n[b]) : 0.0);
    }
    r.samples = all.size();
    double total = 0.0;
    for (const double d : all) total += d;
    r.mean = total / static_cast<double>(all.size());
    r.median = percentile(all, 0.5);
    r.p95 = percentile(all, 0.95);
    return r;
}

}  // namespace irid
