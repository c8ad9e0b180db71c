#pragma once

// The one parallel loop of the batch paths (oneTBB underneath), for the libraries that split a
// buffer of colours or pixels into pieces: irid_gamut's pipelines and irid_exchange's image clip.

#include <cstddef>
#include <functional>

namespace irid {

/// The most threads a caller may ask for: 2^20. Every `--threads` of the command line and every
/// `threads=` of Python takes a whole number in [0, max_threads] (0: all), and irid uses no more
/// than the machine has.
inline constexpr int max_threads = 1 << 20;

/// Runs body(begin, end) over [0, n) in pieces of at least `grain` on up to `threads` threads
/// (0: all; never more than the hardware has, which oneTBB would refuse), in a task arena of
/// that size; one piece, on the calling thread, when one thread is asked for or n <= grain.
/// Exceptions propagate (oneTBB rethrows the first). Implemented in irid_gamut.
void parallel_ranges(std::size_t n, int threads, const std::function<void(std::size_t, std::size_t)>& body,
                     std::size_t grain = 1);

}  // namespace irid
