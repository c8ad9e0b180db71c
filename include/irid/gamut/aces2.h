#pragma once

// The ACES 2.0 Output Transform's rendering (the Academy's aces-core, "Output Transform"; as
// OpenColorIO 2.4+ implements its FixedFunction ACES_OUTPUT_TRANSFORM_20), in double: ACES2065-1
// scene values to display-linear RGB of the limiting primaries (1.0 = 100 cd/m²) and back.
//
// Its stages, each available on its own for tests and tools:
// - the JMh model: a simplified Hellwig 2022 colour appearance model with its own cone
//   primaries, in dim surround, with the compressive response mirrored for negative values;
// - the tonescale (Daniele Siragusano's curve) on J, for a peak luminance;
// - chroma compression, scaled with the tonescale and normalised by a hue-dependent M_norm,
//   its toe limited by the reach gamut (AP1) at the peak's J;
// - gamut compression toward a focus point, against the limiting gamut's cusp per hue (a table
//   whose hues sample the cube's corners exactly), its upper and lower hull gammas and the
//   reach gamut's boundary.
// The tables are built once per display (tens of milliseconds); every evaluation after that is
// noexcept and allocates nothing; forward() gives a finite result for any finite input.
// docs/DISPLAY.md describes the transform, its sources and its accuracy against OpenColorIO's
// test vectors.

#include <irid/color/matrix.h>
#include <irid/color/rgb.h>
#include <irid/color/types.h>

#include <array>
#include <vector>

namespace irid {

/// J, M and the hue h in degrees [0, 360) of the ACES 2.0 model.
struct Aces2Jmh {
    double J = 0.0, M = 0.0, h = 0.0;
};

/// The JMh model for one set of primaries (the RGB whose white is the model's white).
class Aces2JmhModel {
public:
    /// Throws irid::Error for primaries rgb_to_xyz_matrix refuses.
    Aces2JmhModel(const RgbPrimaries& primaries, const Xy& white);

    /// RGB (1.0 = 100 cd/m²) to the achromatic response A and the opponent a, b.
    [[nodiscard]] Vec3 rgb_to_aab(const Vec3& rgb) const noexcept;
    [[nodiscard]] Vec3 aab_to_rgb(const Vec3& aab) const noexcept;
    /// (0, 0, 0) for A <= 0.
    [[nodiscard]] Aces2Jmh aab_to_jmh(const Vec3& aab) const noexcept;
    [[nodiscard]] Vec3 jmh_to_aab(const Aces2Jmh& jmh) const noexcept;
    [[nodiscard]] Aces2Jmh rgb_to_jmh(const Vec3& rgb) const noexcept {
        return aab_to_jmh(rgb_to_aab(rgb));
    }
    [[nodiscard]] Vec3 jmh_to_rgb(const Aces2Jmh& jmh) const noexcept {
        return aab_to_rgb(jmh_to_aab(jmh));
    }

    /// The J of an achromatic luminance Y (cd/m² / 100 × 100: the white is 100), mirrored for
    /// negatives, and its inverse for J >= 0.
    [[nodiscard]] double y_to_j(double y) const noexcept;
    [[nodiscard]] double j_to_y(double j) const noexcept;
    /// The achromatic response of J, and J of A.
    [[nodiscard]] double j_to_a(double j) const noexcept;
    [[nodiscard]] double a_to_j(double a) const noexcept;
    /// The exponent c z of J = 100 A^(c z) (the model's "gamma").
    [[nodiscard]] double exponent() const noexcept { return m_cz; }

private:
    friend class Aces2Kernel;  // converts the matrices and constants to float once

    Mat3 m_rgb_to_cone;  // RGB to the adapted cone response, scaled by the reference 100
    Mat3 m_cone_to_rgb;
    Mat3 m_cone_to_aab;  // the opponent matrix, A normalised by the white's
    Mat3 m_aab_to_cone;
    double m_fl_n = 0.0;   // F_L / 100
    double m_cz = 0.0;     // the exponent c z of J
    double m_a_w_j = 0.0;  // the response of the reference luminance
};

/// The most steps of the inverse's focus-gain fixed point (Aces2Rendering::inverse); it
/// converges to 1e-13 in far fewer.
inline constexpr int aces2_inverse_focus_iterations = 64;

/// A display's rendering parameters: peak luminance and limiting primaries and white.
struct Aces2Display {
    double peak_nits = 100.0;
    RgbPrimaries limiting{};
    Xy limiting_white{};
};

/// The rendering for one display: tables built at construction (throws irid::Error unless
/// 100 <= peak_nits <= 10000 and the primaries are valid).
class Aces2Rendering {
public:
    explicit Aces2Rendering(const Aces2Display& display);

    /// ACES2065-1 to display-linear RGB of the limiting primaries, 1.0 = 100 cd/m² (the fixed
    /// function alone: no clamp before or after).
    [[nodiscard]] Vec3 forward(const Vec3& aces) const noexcept;
    /// Its inverse, for display values inside the limiting cube [0, peak/100]³ (the display
    /// chain clamps to the cube first). Exact wherever reaches(display): the source J on which
    /// the focus gain depends is solved by iterating to convergence the fixed point of which the
    /// Academy's inverse takes one step, and forward(inverse(d)) returns d to 1e-12 of the peak
    /// (docs/DISPLAY.md). Elsewhere it returns the source at the compression's asymptote, as the
    /// Academy's does.
    [[nodiscard]] Vec3 inverse(const Vec3& display) const noexcept;
    /// Whether a display value is one the forward produces, so that inverse() is its source:
    /// false above the peak's J, beyond the gamut compression's asymptote (next to the limiting
    /// cube's top corners, where the cube reaches beyond the hull the compression aims at) and
    /// beyond the most M the chroma compression gives (limiting gamuts much wider than the reach
    /// gamut AP1); docs/DISPLAY.md, "The inverse".
    [[nodiscard]] bool reaches(const Vec3& display) const noexcept;

    // The stages, in the order forward() applies them.
    [[nodiscard]] const Aces2JmhModel& input_model() const noexcept { return m_input; }
    [[nodiscard]] const Aces2JmhModel& limiting_model() const noexcept { return m_limiting; }
    /// Tonescale (on J) and chroma compression.
    [[nodiscard]] Aces2Jmh tonescale_and_chroma_forward(const Aces2Jmh& jmh) const noexcept;
    [[nodiscard]] Aces2Jmh tonescale_and_chroma_inverse(const Aces2Jmh& jmh) const noexcept;
    [[nodiscard]] Aces2Jmh gamut_compress_forward(const Aces2Jmh& jmh) const noexcept;
    [[nodiscard]] Aces2Jmh gamut_compress_inverse(const Aces2Jmh& jmh) const noexcept;
    /// The tonescale on J alone, and its inverse.
    [[nodiscard]] double tonescale_forward(double j) const noexcept;
    [[nodiscard]] double tonescale_inverse(double j) const noexcept;

    /// The J of the peak (the top of the gamut), and the scene value the built-in chain clamps
    /// AP1 to: 8 r_hit, r_hit = 128 + 768 log(peak/100)/log(100).
    [[nodiscard]] double limit_j_max() const noexcept { return m_limit_j_max; }
    [[nodiscard]] double forward_limit() const noexcept { return m_tone.forward_limit; }
    /// The tables: the hues (361 + wrap entries) and, per hue, the cusp's J, M (scaled by the
    /// smoothing 1 + 0.27 × 0.12) and the upper hull's 1/γ; the reach's M at limit_j_max per
    /// whole degree.
    [[nodiscard]] const std::vector<double>& hue_table() const noexcept { return m_hues; }
    [[nodiscard]] const std::vector<Vec3>& cusp_table() const noexcept { return m_cusps; }
    [[nodiscard]] const std::vector<double>& reach_table() const noexcept { return m_reach; }

    struct Tonescale {
        double n = 0.0, n_r = 0.0, g = 0.0, t_1 = 0.0, c_t = 0.0, s_2 = 0.0, u_2 = 0.0, m_2 = 0.0;
        double forward_limit = 0.0, inverse_limit = 0.0, log_peak = 0.0;
    };
    struct Cusp {
        double J = 0.0, M = 0.0, gamma_top_inv = 0.0, focus_j = 0.0, analytical_threshold = 0.0;
    };

private:
    friend class Aces2Kernel;  // converts the parameters and tables to float once

    [[nodiscard]] double reach_m(double h) const noexcept;
    /// The upper index of the hue table's interval taken for h, as OpenColorIO searches it.
    [[nodiscard]] std::size_t hue_interval(double h) const noexcept;
    [[nodiscard]] Cusp cusp_at(double h) const noexcept;
    [[nodiscard]] double m_norm(double h) const noexcept;
    /// `beyond` (when given) is set where the inverse's M lies at or beyond the compression's
    /// asymptote.
    [[nodiscard]] Aces2Jmh compress(const Aces2Jmh& jmh, double jx, const Cusp& cusp, double reach,
                                    bool inverse, bool* beyond = nullptr) const noexcept;
    /// The gamut compression's inverse; `exact` (when given) says whether the forward takes the
    /// result back (the focus gain's fixed point converged and M is inside the asymptote).
    [[nodiscard]] Aces2Jmh solve_gamut_inverse(const Aces2Jmh& jmh, bool* exact) const noexcept;
    /// The tonescale and chroma compression's inverse; `exact` (when given) says whether M lies
    /// inside what the chroma compression gives.
    [[nodiscard]] Aces2Jmh solve_tonescale_and_chroma_inverse(const Aces2Jmh& jmh,
                                                              bool* exact) const noexcept;
    void build_tables(const Aces2Display& display);

    Aces2JmhModel m_input;        // AP0
    Aces2JmhModel m_reach_model;  // AP1
    Aces2JmhModel m_limiting;
    Tonescale m_tone;
    double m_limit_j_max = 0.0, m_model_gamma_inv = 0.0;
    // Chroma compression.
    double m_sat = 0.0, m_sat_thr = 0.0, m_compr = 0.0, m_chroma_scale = 0.0;
    // Gamut compression.
    double m_mid_j = 0.0, m_focus_dist = 0.0, m_lower_hull_gamma_inv = 0.0;
    std::vector<double> m_hues;   // index 0 and the last wrap around
    std::vector<Vec3> m_cusps;    // J, M, 1/γ_top per entry of m_hues
    std::vector<double> m_reach;  // 360 entries, one per degree
    /// The window of the hue search around h's whole degree (hue_interval).
    std::array<int, 2> m_hue_search{0, 1};
};

}  // namespace irid
