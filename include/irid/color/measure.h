#pragma once

// How irid measures: summary statistics with one percentile convention, the appearance of a
// colour in CIELAB, CIELUV and Oklab, and the difference of two hue angles. Every report (the
// clip report and analysis, the optics' error studies, the renderer's image difference) uses
// these, so one figure means the same thing wherever it is printed.

#include <irid/color/matrix.h>
#include <irid/color/types.h>

#include <cstddef>
#include <span>
#include <vector>

namespace irid {

/// The p-th quantile by nearest rank: the ⌈p·n⌉-th smallest of n values (1-based), the smallest
/// for p = 0 and the largest for p = 1. Every reported median, p95 and p99 is this. `sorted`
/// must be in ascending order; 0 when it is empty. Throws irid::Error for p outside [0, 1].
[[nodiscard]] double percentile_of_sorted(std::span<const double> sorted, double p);

/// The same for values in any order (sorts a copy).
[[nodiscard]] double percentile(std::vector<double> values, double p);

/// Count, mean, 95th percentile, maximum, median and 99th percentile (nearest rank); all 0 when
/// there are no values. (The first four keep the order of the clip report's former
/// ClipStatistics, so aggregate initialisers written for it still mean the same.)
struct Statistics {
    double mean = 0.0, p95 = 0.0, max = 0.0;
    std::size_t count = 0;
    double median = 0.0, p99 = 0.0;
};

/// The statistics of `values`. A NaN among them is counted and makes every figure NaN, so
/// that a broken input shows; callers leave out what has no value (a colour without a hue).
[[nodiscard]] Statistics summarize(std::vector<double> values);

/// Collects values one at a time, then summarises them.
class StatisticsCollector {
public:
    void add(double v) { m_values.push_back(v); }
    [[nodiscard]] std::size_t size() const noexcept { return m_values.size(); }
    [[nodiscard]] Statistics statistics() const { return summarize(m_values); }

private:
    std::vector<double> m_values;
};

/// The signed difference to - from of two hue angles in degrees, in (−180, 180]; |·| is the
/// hue shift the reports give.
[[nodiscard]] double hue_difference(double from_deg, double to_deg) noexcept;

/// A colour's appearance in the three spaces the reports measure: CIELAB and CIELUV relative to
/// a white, and Oklab (whose white is D65, reached by Bradford adaptation from another white).
struct Appearance {
    Lab lab;
    double c_ab = 0.0, h_ab = 0.0;
    double l_uv = 0.0, c_uv = 0.0, h_uv = 0.0;
    double c_ok = 0.0, h_ok = 0.0;
    /// CIE 1976 saturation s_uv relative to the white.
    double saturation_uv = 0.0;
    /// Y relative to the white (after the scale).
    double y = 0.0;
};

/// Measures colours relative to one white: XYZ is multiplied by `scale` (1/max for a gamut of
/// peak max), then measured relative to `white` at Y = 1.
class AppearanceMeter {
public:
    explicit AppearanceMeter(const Xy& white, double scale = 1.0);

    [[nodiscard]] Appearance operator()(const Xyz& c) const noexcept;

private:
    double m_scale;
    Xyz m_white;
    Mat3 m_to_d65;
};

}  // namespace irid
