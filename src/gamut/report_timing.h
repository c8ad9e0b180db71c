#pragma once

// How the clip report times a method (private to irid_gamut).

#include <cstddef>
#include <functional>

namespace irid {

struct ClipTiming {
    std::size_t colors = 0;          // colours clipped in all rounds
    double seconds = 0.0;            // their time
    double colors_per_second = 0.0;  // the median of the rounds' rates (nearest rank)
};

/// Runs `pass` (one clip of `colors` colours) in clip_report_timing_rounds rounds of at least
/// min_seconds / rounds each (one pass when min_seconds is 0), on std::chrono::steady_clock.
[[nodiscard]] ClipTiming time_passes(const std::function<void()>& pass, std::size_t colors, double min_seconds);

}  // namespace irid
