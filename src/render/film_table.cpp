#include "film_table.h"

#include <irid/error.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace irid::render {

namespace {
template <class Value>
Value lerp(const Value& a, const Value& b, double f) noexcept {
    Value r = a;
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = a[i] + f * (b[i] - a[i]);
    return r;
}
}  // namespace

FilmTable::FilmTable(double max_nm, double step_nm, double cos_min, int cos_count,
                     const std::function<std::vector<Rgb3>(double, const std::vector<double>&)>&
                         row_of)
    : m_max(max_nm), m_cos_min(cos_min) {
    if (!(max_nm > 0) || !(step_nm > 0) || !(cos_min >= 0 && cos_min < 1) || cos_count < 2)
        throw Error("film table: needs max > 0, step > 0, 0 <= cos_min < 1, >= 2 rows");
    m_count = static_cast<int>(std::ceil(max_nm / step_nm)) + 1;
    m_step = max_nm / (m_count - 1);
    m_rows = cos_count;
    m_cos_step = (1.0 - cos_min) / (cos_count - 1);
    std::vector<double> thicknesses(m_count);
    for (int i = 0; i < m_count; ++i) thicknesses[i] = m_step * i;
    m_colors.resize(static_cast<std::size_t>(m_count) * m_rows);
    m_integrals.resize(m_colors.size());
    tbb::parallel_for(0, m_rows, [&](int row) {
        const std::vector<Rgb3> values = row_of(m_cos_min + m_cos_step * row, thicknesses);
        Rgb3 sum{0, 0, 0};
        for (int i = 0; i < m_count; ++i) {
            const std::size_t k = static_cast<std::size_t>(row) * m_count + i;
            m_colors[k] = values[i];
            if (i > 0) {
                for (int c = 0; c < 3; ++c) sum[c] += 0.5 * m_step * (values[i - 1][c] + values[i][c]);
            }
            m_integrals[k] = sum;
        }
    });
}

Rgb3 FilmTable::point(int row, double t) const noexcept {
    const double x = std::clamp(t, 0.0, m_max) / m_step;
    const int i = std::min(static_cast<int>(x), m_count - 2);
    const double f = x - i;
    const std::size_t k = static_cast<std::size_t>(row) * m_count + i;
    return lerp(m_colors[k], m_colors[k + 1], f);
}

Rgb3 FilmTable::integral(int row, double t) const noexcept {
    const std::size_t base = static_cast<std::size_t>(row) * m_count;
    if (t >= m_max) {
        const Rgb3& end = m_integrals[base + m_count - 1];
        const Rgb3& c = m_colors[base + m_count - 1];
        const double d = t - m_max;
        return {end[0] + c[0] * d, end[1] + c[1] * d, end[2] + c[2] * d};
    }
    const double x = std::max(t, 0.0) / m_step;
    const int i = std::min(static_cast<int>(x), m_count - 2);
    const double s = (x - i) * m_step;
    const Rgb3& at = m_integrals[base + i];
    const Rgb3& a = m_colors[base + i];
    const Rgb3& b = m_colors[base + i + 1];
    Rgb3 r;
    for (int c = 0; c < 3; ++c) r[c] = at[c] + a[c] * s + (b[c] - a[c]) * s * s / (2.0 * m_step);
    return r;
}

Rgb3 FilmTable::at(double t_nm, double footprint_nm, double cos_theta) const noexcept {
    const double y = (std::clamp(cos_theta, m_cos_min, 1.0) - m_cos_min) / m_cos_step;
    const int j = std::min(static_cast<int>(y), m_rows - 2);
    const double g = y - j;
    Rgb3 lo, hi;
    // A footprint under half a table step changes nothing the table can show.
    if (footprint_nm > 0.5 * m_step) {
        const double a = std::max(0.0, t_nm - 0.5 * footprint_nm);
        const double b = std::max(t_nm + 0.5 * footprint_nm, a + 0.5 * m_step);
        const Rgb3 la = integral(j, a), lb = integral(j, b);
        const Rgb3 ha = integral(j + 1, a), hb = integral(j + 1, b);
        for (int c = 0; c < 3; ++c) {
            lo[c] = (lb[c] - la[c]) / (b - a);
            hi[c] = (hb[c] - ha[c]) / (b - a);
        }
    } else {
        lo = point(j, t_nm);
        hi = point(j + 1, t_nm);
    }
    return lerp(lo, hi, g);
}

template <class Value>
AngleTable<Value>::AngleTable(double step_deg, const std::function<Value(double)>& value_of) {
    const int n = static_cast<int>(std::ceil(90.0 / step_deg)) + 1;
    m_step = 90.0 / (n - 1);
    m_values.resize(n);
    tbb::parallel_for(0, n, [&](int i) { m_values[i] = value_of(std::min(90.0, m_step * i)); });
}

template <class Value>
Value AngleTable<Value>::at(double theta_deg) const noexcept {
    const double x = std::clamp(theta_deg, 0.0, 90.0) / m_step;
    const int i = std::min(static_cast<int>(x), static_cast<int>(m_values.size()) - 2);
    return lerp(m_values[i], m_values[i + 1], x - i);
}

template class AngleTable<Rgb3>;
template class AngleTable<std::array<double, dense_sample_count>>;

}  // namespace irid::render
