#pragma once

// The parameters and tables of Aces2Kernel (include/irid/gamut/aces2_kernel.h), converted once
// from an Aces2Output (aces2_kernel.cpp) and read by the Highway kernel (aces2_simd_forward.cpp,
// aces2_simd_inverse.cpp, aces2_simd-inl.h).

#include <irid/gamut/aces2_kernel.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace irid::detail {

/// Hue table entries: 360 and one wrapped at either end (Aces2Rendering::hue_table).
inline constexpr std::size_t aces2_hue_entries = 362;
/// Buckets per degree of the hue table's index (aces2_kernel.cpp: bucket_lo).
inline constexpr int aces2_buckets_per_degree = 2;
inline constexpr std::size_t aces2_buckets = 360 * aces2_buckets_per_degree;

/// One direction's constants in the precision T of the vectors that read them. Matrices are
/// row-major. The direction's stages: `in`, clamp to [0, in_max], `to_cone`, the response,
/// `to_aab`; JMh; the rendering; `from_aab`, the inverse response, `from_cone`, clamp to
/// [0, out_max], `out`.
template <class T>
struct Aces2Params {
    using Index = std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>;
    std::array<T, 9> in{}, to_cone{}, to_aab{}, from_aab{}, from_cone{}, out{};
    T in_max = 0, out_max = 0;
    // The JMh model (Aces2JmhModel: the same for both models but for the matrices).
    T fl_n = 0, a_w_j = 0, cz = 0, cz_inv = 0;
    // The peak's J and its A.
    T limit_j = 0, limit_a = 0;
    // Tonescale.
    T m_2 = 0, s_2 = 0, g = 0, g_inv = 0, t_1 = 0, inverse_limit = 0;
    // Chroma compression.
    T sat = 0, sat_thr = 0, compr = 0, chroma_scale = 0;
    // Gamut compression.
    T mid_j = 0, focus_dist = 0, lower_gamma_inv = 0;
    // Tables: per hue entry the hue, the cusp's J and M, the upper hull's 1/γ; the reach's M per
    // degree (361: the first repeated); per half degree the last hue entry below it.
    std::array<T, aces2_hue_entries> hue{}, cusp_j{}, cusp_m{}, gamma_top_inv{};
    std::array<T, 361> reach{};
    std::array<Index, aces2_buckets> bucket_lo{};
    int bucket_steps = 0;  // the most hue entries in one bucket
    /// The window of OpenColorIO's hue search around h's whole degree (Aces2Rendering).
    std::array<int, 2> hue_search{0, 1};
    /// The float forward's tonescale, gamut compression and output stage in double (peaks
    /// above 100 cd/m²: docs/KERNELS.md).
    bool precise = false;
    /// False where the limiting gamut reaches beyond the reach gamut AP1: every colour then
    /// goes to the double chain (docs/KERNELS.md).
    bool follows = true;
};

struct Aces2KernelData {
    Aces2Params<float> f;
    Aces2Params<double> d;
};

/// The Highway kernel's forward (aces2_simd_forward.cpp) and inverse (aces2_simd_inverse.cpp):
/// `colours` triples of `in` to `out`; each returns how many it handed to kernel.reference().
std::size_t aces2_forward_run(const Aces2Kernel& kernel, const Aces2KernelData& data,
                              const float* in, float* out, std::size_t colours) noexcept;
std::size_t aces2_inverse_run(const Aces2Kernel& kernel, const Aces2KernelData& data,
                              const float* in, float* out, std::size_t colours) noexcept;
/// The forward's stage alone (Aces2Kernel::run_stage).
void aces2_stage_run(const Aces2KernelData& data, Aces2Kernel::Stage stage, bool in_float,
                     const float* in, float* out, std::size_t colours) noexcept;

}  // namespace irid::detail
