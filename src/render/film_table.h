#pragma once

// Colour tables of the renderer's table path (the thesis' §3.3 approach): a film's colour over
// thickness × cos θ, and a multilayer's colour over angle. The film table also answers the mean
// colour over a thickness interval — the range of thicknesses a pixel covers — in constant time
// from running integrals of the piecewise-linear colour, which is the renderer's cure for thin
// film aliasing (irid/render/scene.h FilmAntialias::footprint).

#include "carriers.h"

#include <functional>
#include <vector>

namespace irid::render {

class FilmTable {
public:
    /// Fills the table with colour_of(t, cos θ) for t = 0, step, ..., max_nm and cos θ =
    /// cos_min, ..., 1 in cos_count equal steps; rows are computed in parallel (each entry
    /// independently, so the table does not depend on the thread count).
    FilmTable(double max_nm, double step_nm, double cos_min, int cos_count,
              const std::function<std::vector<Rgb3>(double cos_theta,
                                                    const std::vector<double>& thicknesses)>&
                  row_of);

    /// The colour at thickness t [nm] (clamped to [0, max]) and cos θ (clamped to [cos_min, 1]),
    /// bilinear; with footprint_nm > 0 the mean over [t − f/2, t + f/2] ∩ [0, ∞) instead.
    [[nodiscard]] Rgb3 at(double t_nm, double footprint_nm, double cos_theta) const noexcept;

    [[nodiscard]] double max_nm() const noexcept { return m_max; }
    [[nodiscard]] double step_nm() const noexcept { return m_step; }

private:
    [[nodiscard]] Rgb3 point(int row, double t) const noexcept;
    /// ∫₀ᵗ colour dt' along a row, the colour held at its last value beyond max.
    [[nodiscard]] Rgb3 integral(int row, double t) const noexcept;

    double m_max, m_step, m_cos_min, m_cos_step;
    int m_count, m_rows;
    std::vector<Rgb3> m_colors;     // row-major: [row][i]
    std::vector<Rgb3> m_integrals;  // ∫ from 0 to node i
};

/// A quantity sampled over the angle θ ∈ [0°, 90°] at equal steps, linear in between: the
/// Morpho wing's colour (RGB) or spectrum.
template <class Value>
class AngleTable {
public:
    AngleTable() = default;
    AngleTable(double step_deg, const std::function<Value(double theta_deg)>& value_of);
    [[nodiscard]] Value at(double theta_deg) const noexcept;

private:
    double m_step = 1;
    std::vector<Value> m_values;
};

}  // namespace irid::render
