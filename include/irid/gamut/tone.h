#pragma once

// A highlight roll-off for scene-referred luminance: the display step before a gamut method
// when the scene is brighter than the display's white (a renderer's glints, the sun's disc).
//
// The curve (irid's "rolloff" view, docs/RENDER.md) is the identity up to a knee k and,
// above it, Reinhard et al.'s global operator L/(1 + L) (E. Reinhard, M. Stark, P. Shirley,
// J. Ferwerda, "Photographic Tone Reproduction for Digital Images", SIGGRAPH 2002, eq. 3) on
// the part of the luminance above the knee, scaled so that value and slope meet at the knee:
//
//   f(Y) = Y                                    for Y <= k
//   f(Y) = k + (1 − k) u / (1 + u),  u = (Y − k)/(1 − k)   for Y > k
//
// It is strictly increasing, the identity below the knee, C¹ (slope 1 on both sides of the
// knee), and tends to the display white 1 without reaching it: every scene luminance keeps a
// display luminance of its own. 1 − f(Y) = (1 − k)² / (Y + 1 − 2k) above the knee.

namespace irid {

class HighlightRolloff {
public:
    /// Throws irid::Error unless 0 <= knee <= 0.95.
    explicit HighlightRolloff(double knee = 0.4);

    [[nodiscard]] double knee() const noexcept { return m_knee; }
    /// f(Y) for Y >= 0 (negative Y comes back unchanged; NaN stays NaN).
    [[nodiscard]] double operator()(double y) const noexcept {
        if (!(y > m_knee)) return y;
        const double u = (y - m_knee) / m_range;
        return m_knee + m_range * u / (1.0 + u);
    }
    /// f′(Y): 1 up to the knee, 1/(1 + u)² above it.
    [[nodiscard]] double slope(double y) const noexcept {
        if (!(y > m_knee)) return 1.0;
        const double u = (y - m_knee) / m_range;
        return 1.0 / ((1.0 + u) * (1.0 + u));
    }

    static constexpr double max_knee = 0.95;

private:
    double m_knee;
    double m_range;  // 1 − knee
};

}  // namespace irid
