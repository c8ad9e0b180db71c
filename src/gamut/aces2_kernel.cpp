// Aces2Kernel: the display chain's constants folded and converted once (aces2_kernel.h); the
// Highway kernel that reads them is aces2_simd_forward.cpp and aces2_simd_inverse.cpp.

#include <irid/gamut/aces2_kernel.h>

#include <irid/error.h>

#include "aces2_constants.h"
#include "aces2_kernel_data.h"

#include <algorithm>
#include <cmath>

namespace irid {
namespace {

template <class T>
std::array<T, 9> to_array(const Mat3& m) noexcept {
    std::array<T, 9> a{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            a[static_cast<std::size_t>(3 * i + j)] = static_cast<T>(m[i][j]);
    return a;
}

/// Peaks above which the float forward computes its tonescale, gamut compression and output
/// stage in double: in float they reached 1.05e-5 of an output channel at 500 cd/m² and
/// 1.3e-5 at 1000, and on bright colours of custom displays 1.0e-5 to 1.4e-5 at 150 to
/// 225 cd/m² (AP1 and Rec.2020 limiting), against 7.9e-6 at most at 100 (docs/KERNELS.md).
constexpr double precise_above_nits = 100.0;

/// Whether every limiting primary lies inside AP1's triangle (to rounding): where one does not,
/// the chain is so ill-conditioned in places (a compression whose hull does not close, colours
/// that reach the peak with an infinite slope) that float's rounding shows by up to 6 % (AP0's
/// own primaries, docs/KERNELS.md), and the kernel hands every colour to the double chain.
bool limiting_inside_ap1(const Aces2DisplaySpec& spec) {
    const Mat3 xyz_to_ap1 = inverse(rgb_to_xyz_matrix(aces2::ap1, aces2::aces_white), "AP1");
    for (const Xy& c : {spec.limiting.red, spec.limiting.green, spec.limiting.blue}) {
        const Vec3 rgb = xyz_to_ap1 * Vec3{c.x / c.y, 1.0, (1.0 - c.x - c.y) / c.y};
        const double sum = rgb[0] + rgb[1] + rgb[2];
        for (const double v : rgb)
            if (v / sum < -1e-9) return false;
    }
    return true;
}

/// Aces2Kernel::error_of_largest: 2.6 and 3.3 times the largest measured, 3.9e-5 (float) and
/// 9.2e-7 (double back end; docs/KERNELS.md).
constexpr double float_error_of_largest = 1e-4;
constexpr double precise_error_of_largest = 3e-6;
/// The double chain's result rounded to float: half a float step, with room.
constexpr double double_error_of_largest = 1e-7;

}  // namespace

struct Aces2Kernel::Builder {
    /// The constants of one direction, in T (see Aces2Params).
    template <class T>
    static detail::Aces2Params<T> params(const Aces2Output& o, bool inverse, const Mat3& in,
                                         const Mat3& out) {
        const Aces2Rendering& r = o.m_rendering;
        const Aces2JmhModel& input = r.m_input;
        const Aces2JmhModel& limiting = r.m_limiting;
        const Aces2JmhModel& from = inverse ? limiting : input;
        const Aces2JmhModel& to = inverse ? input : limiting;
        const double peak = o.m_spec.peak_nits / 100.0;
        const double limit = r.forward_limit();
        detail::Aces2Params<T> p;
        if (!inverse) {
            p.in = to_array<T>(o.m_ap0_to_ap1 * in);
            p.in_max = static_cast<T>(limit);
            p.to_cone = to_array<T>(from.m_rgb_to_cone * o.m_ap1_to_ap0);
            p.from_cone = to_array<T>(to.m_cone_to_rgb);
            p.out_max = static_cast<T>(peak);
            p.out = to_array<T>(out * Mat3::diagonal({o.m_scale, o.m_scale, o.m_scale}) *
                                o.m_limiting_to_xyz);
        } else {
            const double s = 1.0 / o.m_scale;
            p.in = to_array<T>(Mat3::diagonal({s, s, s}) * o.m_xyz_to_limiting * in);
            p.in_max = static_cast<T>(peak);
            p.to_cone = to_array<T>(from.m_rgb_to_cone);
            p.from_cone = to_array<T>(o.m_ap0_to_ap1 * to.m_cone_to_rgb);
            p.out_max = static_cast<T>(limit);
            p.out = to_array<T>(out * o.m_ap1_to_ap0);
        }
        p.to_aab = to_array<T>(from.m_cone_to_aab);
        p.from_aab = to_array<T>(to.m_aab_to_cone);
        p.fl_n = static_cast<T>(input.m_fl_n);
        p.a_w_j = static_cast<T>(input.m_a_w_j);
        p.cz = static_cast<T>(input.m_cz);
        p.cz_inv = static_cast<T>(1.0 / input.m_cz);
        p.limit_j = static_cast<T>(r.m_limit_j_max);
        p.limit_a = static_cast<T>(input.j_to_a(r.m_limit_j_max));
        const Aces2Rendering::Tonescale& t = r.m_tone;
        p.m_2 = static_cast<T>(t.m_2);
        p.s_2 = static_cast<T>(t.s_2);
        p.g = static_cast<T>(t.g);
        p.g_inv = static_cast<T>(1.0 / t.g);
        p.t_1 = static_cast<T>(t.t_1);
        p.inverse_limit = static_cast<T>(t.inverse_limit);
        p.sat = static_cast<T>(r.m_sat);
        p.sat_thr = static_cast<T>(r.m_sat_thr);
        p.compr = static_cast<T>(r.m_compr);
        p.chroma_scale = static_cast<T>(r.m_chroma_scale);
        p.mid_j = static_cast<T>(r.m_mid_j);
        p.focus_dist = static_cast<T>(r.m_focus_dist);
        p.lower_gamma_inv = static_cast<T>(r.m_lower_hull_gamma_inv);
        for (std::size_t i = 0; i < detail::aces2_hue_entries; ++i) {
            p.hue[i] = static_cast<T>(r.m_hues[i]);
            p.cusp_j[i] = static_cast<T>(r.m_cusps[i][0]);
            p.cusp_m[i] = static_cast<T>(r.m_cusps[i][1]);
            p.gamma_top_inv[i] = static_cast<T>(r.m_cusps[i][2]);
        }
        for (std::size_t i = 0; i < 360; ++i) p.reach[i] = static_cast<T>(r.m_reach[i]);
        p.reach[360] = p.reach[0];
        // Per bucket [b/k, (b+1)/k) of hue, the last entry whose hue (in T, as the kernel compares)
        // is below the bucket's start; the kernel steps on from there while the next is below h.
        for (std::size_t b = 0; b < detail::aces2_buckets; ++b) {
            const T start =
                static_cast<T>(static_cast<double>(b) / detail::aces2_buckets_per_degree);
            const T end =
                static_cast<T>(static_cast<double>(b + 1) / detail::aces2_buckets_per_degree);
            std::size_t lo = 0;
            while (lo + 1 < detail::aces2_hue_entries - 1 && p.hue[lo + 1] < start) ++lo;
            p.bucket_lo[b] = static_cast<typename detail::Aces2Params<T>::Index>(lo);
            int inside = 0;
            for (std::size_t i = lo + 1; i < detail::aces2_hue_entries && p.hue[i] < end; ++i)
                ++inside;
            p.bucket_steps = std::max(p.bucket_steps, inside);
        }
        p.hue_search = r.m_hue_search;
        p.precise = o.m_spec.peak_nits > precise_above_nits;
        p.follows = limiting_inside_ap1(o.m_spec);
        return p;
    }
};

Aces2Kernel::Aces2Kernel(const Aces2Output& output, bool inverse, const Mat3& in, const Mat3& out)
    : m_output(output), m_inverse(inverse), m_in(in), m_out(out) {
    auto data = std::make_unique<detail::Aces2KernelData>();
    data->f = Builder::params<float>(output, inverse, in, out);
    data->d = Builder::params<double>(output, inverse, in, out);
    m_data = std::move(data);
}

Aces2Kernel::~Aces2Kernel() = default;

std::size_t Aces2Kernel::run(std::span<const float> in, std::span<float> out) const noexcept {
    const std::size_t colours = std::min(in.size(), out.size()) / 3;
    if (!m_data->f.follows) {
        // In place is allowed: each triple is read before it is written.
        for (std::size_t i = 0; i < colours; ++i) {
            const Vec3 o = reference({in[3 * i], in[3 * i + 1], in[3 * i + 2]});
            for (std::size_t c = 0; c < 3; ++c) out[3 * i + c] = static_cast<float>(o[c]);
        }
        return colours;
    }
    return m_inverse ? detail::aces2_inverse_run(*this, *m_data, in.data(), out.data(), colours)
                     : detail::aces2_forward_run(*this, *m_data, in.data(), out.data(), colours);
}

void Aces2Kernel::run_stage(Stage stage, std::span<const float> in, std::span<float> out,
                            bool in_float) const {
    if (m_inverse) throw Error("Aces2Kernel::run_stage: the stages are the forward's");
    detail::aces2_stage_run(*m_data, stage, in_float, in.data(), out.data(),
                            std::min(in.size(), out.size()) / 3);
}

double Aces2Kernel::error_of_largest() const noexcept {
    if (!m_data->f.follows) return double_error_of_largest;
    return m_data->f.precise ? precise_error_of_largest : float_error_of_largest;
}

Vec3 Aces2Kernel::reference(const Vec3& in) const noexcept {
    Vec3 x = in;
    for (double& v : x) v = aces2_finite_input(v);
    x = m_in * x;
    if (!m_inverse) {
        const Xyz xyz = m_output.forward(x);
        x = {xyz.X, xyz.Y, xyz.Z};
    } else {
        x = m_output.inverse({x[0], x[1], x[2]});
    }
    return m_out * x;
}

}  // namespace irid
