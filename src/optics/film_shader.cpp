// FilmShader: the table, the quadrature and the files. The chunk's text is in
// film_shader_glsl.cpp, its single-precision mirror in film_shader_mirror.cpp; docs/OPTICS.md
// ("In a renderer") derives the algorithm.

#include <irid/color/illuminant.h>
#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/color/spectrum.h>
#include <irid/error.h>
#include <irid/optics/film_shader.h>
#include <irid/text_input.h>

#include <fmt/core.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace irid {

ShaderLanguage parse_shader_language(std::string_view name) {
    if (name == "glsl") return ShaderLanguage::glsl;
    if (name == "wgsl") return ShaderLanguage::wgsl;
    throw UnknownNameError(
        "shader language " + quote_untrusted(name) + " is unknown; valid: glsl, wgsl",
        {"glsl", "wgsl"});
}

namespace {

/// The working space whose primaries and white an encoding has, or nullptr.
const RgbSpace* working_space_of(const RgbSpace& encoding) {
    const auto near = [](const Xy& a, const Xy& b) {
        return std::fabs(a.x - b.x) < 1e-4 && std::fabs(a.y - b.y) < 1e-4;
    };
    for (const RgbSpace* w : builtin_rgb_spaces()) {
        const RgbPrimaries& p = w->primaries();
        const RgbPrimaries& q = encoding.primaries();
        if (near(p.red, q.red) && near(p.green, q.green) && near(p.blue, q.blue) &&
            near(w->white(), encoding.white()))
            return w;
    }
    return nullptr;
}

std::string linear_name(const RgbSpace& space) {
    return space.transfer().kind() == TransferFunction::Kind::linear ? space.name()
                                                                      : space.name() + "-linear";
}

}  // namespace

FilmShaderSetup film_shader_setup(std::string_view illuminant, std::string_view space) {
    const std::string illuminant_name = canonical_illuminant_name(illuminant);
    std::vector<std::string> names;
    for (const RgbSpace* w : builtin_rgb_spaces()) {
        names.push_back(w->name());
        if (w->transfer().kind() != TransferFunction::Kind::linear) names.push_back(linear_name(*w));
    }
    const RgbSpace* rgb = nullptr;
    for (const RgbSpace* w : builtin_rgb_spaces()) {
        if (same_name(space, w->name()) || same_name(space, linear_name(*w))) rgb = w;
    }
    if (rgb == nullptr) {
        if (const RgbSpace* encoding = find_rgb_space(space)) {
            const RgbSpace* working = working_space_of(*encoding);
            throw Error(fmt::format(
                "space {} is an encoding, not linear light, and the chunk returns linear light in "
                "a working space's primaries{}; valid: {}",
                quote_untrusted(space),
                working != nullptr ? fmt::format(" (for its primaries: {})", linear_name(*working))
                                   : std::string(),
                fmt::join(names, ", ")));
        }
        throw UnknownNameError(fmt::format("space {} is unknown; valid: {}", quote_untrusted(space),
                                           fmt::join(names, ", ")),
                               names);
    }
    return {Colorimeter(illuminant_by_name(illuminant), Observer::cie1931_2deg, *rgb),
            illuminant_name, linear_name(*rgb)};
}

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

}  // namespace

namespace film_shader_text {

std::string float_literal(double v) {
    std::string s = fmt::format("{:.9g}", static_cast<float>(v));
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string vec3_literal(const std::array<double, 3>& v, std::string_view type) {
    return std::string(type) + "(" + float_literal(v[0]) + ", " + float_literal(v[1]) + ", " + float_literal(v[2]) +
           ")";
}

}  // namespace film_shader_text

FilmShader::FilmShader(const Colorimeter& colorimeter, std::string illuminant_name,
                       std::string space_name, int table_width)
    : m_width(table_width),
      m_illuminant(std::move(illuminant_name)),
      m_space(std::move(space_name)),
      m_primaries(colorimeter.rgb_space().primaries()),
      m_white_xy(colorimeter.rgb_space().white()) {
    if (table_width < min_table_width || table_width > max_table_width) {
        throw Error(fmt::format("table width {} is out of range; valid: {} to {}", table_width,
                                min_table_width, max_table_width));
    }
    // The channels' weights on the 1 nm grid: the XYZ → RGB matrix (with the colorimeter's
    // adaptation) applied to the XYZ weights; its columns are the images of the unit vectors.
    const Rgb cx = colorimeter.linear_rgb(Xyz{1.0, 0.0, 0.0});
    const Rgb cy = colorimeter.linear_rgb(Xyz{0.0, 1.0, 0.0});
    const Rgb cz = colorimeter.linear_rgb(Xyz{0.0, 0.0, 1.0});
    const double rows[3][3] = {{cx.r, cy.r, cz.r}, {cx.g, cy.g, cz.g}, {cx.b, cy.b, cz.b}};
    m_wavenumber.resize(dense_sample_count);
    for (int c = 0; c < 3; ++c) m_weight[static_cast<std::size_t>(c)].resize(dense_sample_count);
    for (int i = 0; i < dense_sample_count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        m_wavenumber[k] = 1.0 / DenseSpectrum::wavelength_nm(i);
        const double x = colorimeter.weight_x()[i], y = colorimeter.weight_y()[i],
                     z = colorimeter.weight_z()[i];
        for (std::size_t c = 0; c < 3; ++c)
            m_weight[c][k] = rows[c][0] * x + rows[c][1] * y + rows[c][2] * z;
    }
    for (std::size_t c = 0; c < 3; ++c) {
        double sum = 0.0, moment = 0.0;
        for (int i = 0; i < dense_sample_count; ++i) {
            const auto k = static_cast<std::size_t>(i);
            sum += m_weight[c][k];
            moment += m_weight[c][k] * m_wavenumber[k];
        }
        m_white[c] = sum;
        m_centre[c] = moment / sum;
    }
    // The table: texel k at τ = (k − 1) step, Re in row 0, Im in row 1.
    m_table.assign(static_cast<std::size_t>(m_width * table_height * 4), 0.0f);
    for (int k = 0; k < m_width; ++k) {
        const Transform v = exact_transform(static_cast<double>(k - 1) * table_step_nm());
        for (std::size_t c = 0; c < 3; ++c) {
            m_table[static_cast<std::size_t>(4 * k) + c] = static_cast<float>(v.re[c]);
            m_table[static_cast<std::size_t>(4 * (m_width + k)) + c] = static_cast<float>(v.im[c]);
        }
    }
    // The envelope: max |V_c| over τ from each step on, sampled every eighth of the table's
    // step (where |V| varies by under 1 %: its fastest oscillation, the 380 nm edge against the
    // blue centre, has a period of about 2 000 nm), with 1 % to spare.
    const int fine = 8 * (default_table_width - 3);
    std::vector<double> largest(static_cast<std::size_t>(fine) + 1, 0.0);
    for (int i = fine; i >= 0; --i) {
        const Transform v = exact_transform(table_end_nm * i / fine);
        double m = 0.0;
        for (std::size_t c = 0; c < 3; ++c) m = std::max(m, std::hypot(v.re[c], v.im[c]));
        const auto k = static_cast<std::size_t>(i);
        largest[k] = i == fine ? m : std::max(m, largest[k + 1]);
    }
    for (int j = 0; j < envelope_count; ++j) {
        m_envelope[static_cast<std::size_t>(j)] =
            1.01 * largest[static_cast<std::size_t>(j * fine / envelope_count)];
    }
    // The quadrature: Chebyshev points of the first kind in wavenumber over the weights' span
    // (360–830 nm), x_j = cos((2j + 1)π / 2K), and per channel the 1 nm sum of each node's
    // Lagrange polynomial (barycentric form, weights (−1)^j sin((2j + 1)π / 2K); Berrut &
    // Trefethen 2004, SIAM Review 46, eq. 5.1).
    const double nu_lo = 1.0 / DenseSpectrum::wavelength_nm(dense_sample_count - 1);
    const double nu_hi = 1.0 / DenseSpectrum::wavelength_nm(0);
    const double mid = 0.5 * (nu_hi + nu_lo), half = 0.5 * (nu_hi - nu_lo);
    std::array<double, quadrature_nodes> x{}, lambda{};
    for (int j = 0; j < quadrature_nodes; ++j) {
        const double angle = (2 * j + 1) * std::numbers::pi / (2.0 * quadrature_nodes);
        const auto k = static_cast<std::size_t>(j);
        x[k] = std::cos(angle);
        lambda[k] = (j % 2 == 0 ? 1.0 : -1.0) * std::sin(angle);
        m_node_nu[k] = mid + half * x[k];
    }
    for (std::size_t i = 0; i < m_wavenumber.size(); ++i) {
        const double xi = (m_wavenumber[i] - mid) / half;
        std::array<double, quadrature_nodes> ell{};
        const auto exact = std::find(x.begin(), x.end(), xi);
        if (exact != x.end()) {
            ell[static_cast<std::size_t>(exact - x.begin())] = 1.0;
        } else {
            double denominator = 0.0;
            for (std::size_t j = 0; j < x.size(); ++j) {
                ell[j] = lambda[j] / (xi - x[j]);
                denominator += ell[j];
            }
            for (double& l : ell) l /= denominator;
        }
        for (std::size_t j = 0; j < x.size(); ++j)
            for (std::size_t c = 0; c < 3; ++c) m_node_weight[j][c] += m_weight[c][i] * ell[j];
    }
}

FilmShader::Transform FilmShader::exact_transform(double tau_nm) const noexcept {
    Transform v{};
    for (std::size_t c = 0; c < 3; ++c) {
        double re = 0.0, im = 0.0;
        for (std::size_t i = 0; i < m_wavenumber.size(); ++i) {
            const double phase = two_pi * tau_nm * (m_wavenumber[i] - m_centre[c]);
            re += m_weight[c][i] * std::cos(phase);
            im += m_weight[c][i] * std::sin(phase);
        }
        v.re[c] = re;
        v.im[c] = im;
    }
    return v;
}

std::string FilmShader::table_bytes() const {
    std::string out(m_table.size() * 4, '\0');
    for (std::size_t i = 0; i < m_table.size(); ++i) {
        const auto u = std::bit_cast<std::uint32_t>(m_table[i]);
        for (std::size_t b = 0; b < 4; ++b)
            out[4 * i + b] = static_cast<char>((u >> (8 * b)) & 0xffu);
    }
    return out;
}

std::string FilmShader::table_json() const {
    nlohmann::ordered_json j;
    j["width"] = m_width;
    j["height"] = table_height;
    j["uniform"] = uniform_name;
    j["illuminant"] = m_illuminant;
    j["space"] = m_space;
    const RgbPrimaries& p = m_primaries;
    j["primaries"] = {p.red.x, p.red.y, p.green.x, p.green.y, p.blue.x, p.blue.y};
    j["white"] = {m_white_xy.x, m_white_xy.y};
    j["filter"] = "nearest";
    return j.dump(2) + "\n";
}

std::vector<std::pair<std::string, std::string>> FilmShader::files(ShaderLanguage language) const {
    std::pair<std::string, std::string> chunk;
    switch (language) {
        case ShaderLanguage::glsl: chunk = {"irid_iridescence.glsl", glsl()}; break;
        case ShaderLanguage::wgsl: chunk = {"irid_iridescence.wgsl", wgsl()}; break;
    }
    return {chunk, {"irid_film_table.f32", table_bytes()}, {"irid_film_table.json", table_json()}};
}

}  // namespace irid
