#include "kernels.h"

namespace irid::detail {

std::size_t clip_aces_rgc_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept { return 0; }  // PROVISIONAL

}  // namespace irid::detail
