#include "kernels.h"

namespace irid::detail {

std::size_t clip_smits_xyz_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept { return 0; }  // PROVISIONAL
std::size_t clip_luv_lightness_hue_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept { return 0; }  // PROVISIONAL
std::size_t clip_smits_corrected_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept { return 0; }  // PROVISIONAL
std::size_t clip_smits_soft_simd(const GamutClipper&, const float*, float*, std::size_t) noexcept { return 0; }  // PROVISIONAL

}  // namespace irid::detail
