#include "kernels.h"

namespace irid::detail {

std::size_t clip_css_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept { return 0; }  // PROVISIONAL
std::size_t clip_css_raytrace_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept { return 0; }  // PROVISIONAL

}  // namespace irid::detail
