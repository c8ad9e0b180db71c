#include "kernels.h"

namespace irid::detail {

std::size_t clip_oklab_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept { return 0; }  // PROVISIONAL
std::size_t clip_oklab_adaptive_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept { return 0; }  // PROVISIONAL
std::size_t clip_oklab_cusp_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept { return 0; }  // PROVISIONAL

}  // namespace irid::detail
