#include <irid/color/numeric_table.h>
#include <irid/color/spectrum.h>
#include <irid/error.h>
#include <irid/optics/work_limits.h>

#include <cmath>
#include <string>

namespace irid {
namespace {

/// A count for messages, its digits grouped in threes by spaces ("2 123 142"); beyond 10¹⁸ in
/// the shortest exponent form.
std::string format_count(double count) {
    if (!(count >= 0.0 && count < 1e18)) return format_shortest(count);
    const std::string digits = std::to_string(static_cast<unsigned long long>(std::floor(count)));
    std::string grouped;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) grouped += ' ';
        grouped += digits[i];
    }
    return grouped;
}

}  // namespace

void check_work_limit(std::span<const WorkFactor> factors, double cost_each, double limit,
                      std::string_view unit, std::string_view advice, std::string_view limit_note) {
    double total = 1.0;
    for (const WorkFactor& f : factors) {
        if (!(std::isfinite(f.count) && f.count >= 0.0)) {
            throw Error(f.name + ": the count " + format_shortest(f.count) +
                        " must be finite and >= 0");
        }
        total *= f.count;
    }
    if (!(cost_each > 0.0 && std::isfinite(cost_each))) {
        throw Error("work limit: the cost of each " + std::string(unit) + " " +
                    format_shortest(cost_each) + " must be finite and > 0");
    }
    if (total * cost_each <= limit) return;
    std::string asked;
    for (const WorkFactor& f : factors) {
        if (!asked.empty()) asked += " × ";
        asked += f.name + " (" + format_count(f.count) + " " + f.noun + ")";
    }
    throw Error(asked + " asks for " + format_count(total) + " " + std::string(unit) +
                "; the limit is " + format_count(std::floor(limit / cost_each)) +
                std::string(limit_note) + " (" + std::string(advice) + ")");
}

void check_color_work(std::span<const WorkFactor> spectra,
                      const std::optional<WorkFactor>& per_wavelength) {
    if (!per_wavelength) {
        check_work_limit(spectra, dense_sample_count, max_film_evaluations, "spectra",
                         "use coarser steps");
        return;
    }
    if (!(std::isfinite(per_wavelength->count) && per_wavelength->count >= 1.0)) {
        throw Error(per_wavelength->name + ": the count " + format_shortest(per_wavelength->count) +
                    " must be finite and >= 1");
    }
    check_work_limit(spectra, dense_sample_count * per_wavelength->count, max_film_evaluations,
                     "spectra", "use coarser steps",
                     " with " + per_wavelength->name + " (" + format_count(per_wavelength->count) +
                         " " + per_wavelength->noun + " per wavelength)");
}

void check_spectrum_work(std::span<const WorkFactor> factors) {
    check_work_limit(factors, 1.0, max_film_evaluations, "film evaluations",
                     "use a coarser wavelength step");
}

void check_stack_work(std::span<const WorkFactor> factors) {
    check_work_limit(factors, 1.0, max_stack_layer_evaluations, "layer evaluations",
                     "use a coarser wavelength step or fewer layers");
}

void check_output_rows(std::span<const WorkFactor> factors) {
    check_work_limit(factors, 1.0, max_output_rows, "lines of output", "use coarser steps");
}

}  // namespace irid
