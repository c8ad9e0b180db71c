#pragma once

// The exact colour of a single lossless film as a GLSL ES 3.00 chunk for real-time renderers
// (three.js and glTF's KHR_materials_iridescence): `evalIridescence(outsideIOR, eta2, cosTheta1,
// thinFilmThickness, baseF0)` sums the Airy reflectance's Fourier series against one small
// table, the demodulated transform of the weighted colour-matching functions in the working
// space's channels, as FourierFilm does on the CPU (fourier_film.h); where that series would need
// too many terms, or the film is past its critical angle, it sums the Airy reflectance at
// quadrature nodes instead. FilmShader builds the table,
// the GLSL text and the table's JSON description, and evaluates the chunk's algorithm in single
// precision on the CPU (evaluate(): the same table, interpolation and term loop as the GLSL, line
// for line), so its accuracy can be measured without a GPU. The algorithm, the table's layout and
// the measured errors are in docs/OPTICS.md ("In a renderer").

#include <irid/color/colorimeter.h>
#include <irid/color/rgb.h>
#include <irid/color/types.h>

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace irid {

/// The languages FilmShader writes: "glsl" (GLSL ES 3.00, WebGL 2 and three.js's WebGLRenderer)
/// and "wgsl" (WebGPU's shading language).
enum class ShaderLanguage { glsl, wgsl };
/// The language of a name ("glsl", "wgsl"); throws UnknownNameError listing the names.
[[nodiscard]] ShaderLanguage parse_shader_language(std::string_view name);

class FilmShader {
public:
    /// The table: width() × 2 RGBA float32 texels. Texel k of row 0 holds Re V_c(τ_k) in
    /// R, G, B (c = the working space's channels), row 1 Im V_c(τ_k), with τ_k = (k − 1) ×
    /// table_step_nm(): the first texel is τ = −step, so the cubic interpolant's four taps stay
    /// inside the table for 0 <= τ < table_end_nm. A = 0. The default width keeps the
    /// interpolant within 1e-4 of the white (docs/OPTICS.md measures the error against the width).
    static constexpr int default_table_width = 512;
    static constexpr int min_table_width = 16;
    /// WebGL 2's least MAX_TEXTURE_SIZE (OpenGL ES 3.0 §6.2, table 6.28).
    static constexpr int max_table_width = 2048;
    static constexpr int table_height = 2;
    /// Where the table's τ (optical path difference) ends [nm]: terms past it are dropped. |V|
    /// is below 1e-3 of the white from 30 µm on (docs/OPTICS.md measures it), and the first
    /// term of every film of the accuracy goal (2000 nm of n = 2.4 at normal incidence: 9.6 µm)
    /// lies well inside.
    static constexpr double table_end_nm = 30000.0;
    /// The envelope (the largest |V_c| from τ on, over channels) is baked into the chunk at this
    /// many equal steps of [0, table_end_nm()).
    static constexpr int envelope_count = 32;
    /// The term loop stops when the bound on the remaining terms (envelope × geometric tail of
    /// |G| |q|^m) falls below this, in units of the white (1 per channel).
    static constexpr double term_tolerance = 1e-5;
    /// The most terms the series sums. A film whose series needs more (its faces both reflect
    /// almost all and its path is short: a free film near grazing incidence) is taken by the
    /// quadrature instead, as is a film past its own critical angle.
    static constexpr int max_terms = 168;
    /// The quadrature's nodes: Chebyshev points in wavenumber over 360–830 nm, the reflectance
    /// summed against the 1 nm sums of their Lagrange polynomials.
    static constexpr int quadrature_nodes = 24;
    /// Indices above this are taken as this (a float's squares and products stay finite).
    static constexpr double max_index = 1e3;
    /// Thicknesses above this [nm] are taken as this: every term is past the table long before.
    static constexpr double max_thickness_nm = 1e9;
    /// (n1 cos θ1)² is kept this many n1² from 0, where the film's faces are 0/0 (their limit
    /// is continuous there): within it the film is taken as just short of its critical angle.
    static constexpr double min_film_q_sq = 1e-12;
    /// The name of the table's sampler uniform.
    static constexpr std::string_view uniform_name = "iridFilmTable";

    /// Tabulates the colorimeter's weighted matching functions in its RGB space. The names are
    /// what the JSON records (illuminant and space as given on the command line). Throws
    /// irid::Error unless min_table_width <= table_width <= max_table_width.
    FilmShader(const Colorimeter& colorimeter, std::string illuminant_name, std::string space_name,
               int table_width = default_table_width);

    /// The table's texels as described above, row-major: width() × table_height × 4 floats.
    [[nodiscard]] std::span<const float> table() const noexcept { return m_table; }
    [[nodiscard]] int width() const noexcept { return m_width; }
    /// The spacing of the table's τ [nm]: table_end_nm / (width() − 3).
    [[nodiscard]] double table_step_nm() const noexcept {
        return table_end_nm / static_cast<double>(m_width - 3);
    }
    /// Each channel's centre wavenumber [1/nm] (Σ w ν / Σ w over the 1 nm grid), about which
    /// its transform is demodulated: V_c(τ) = Σ_i w_c,i e^{2πiτ(ν_i − ν_c)}.
    [[nodiscard]] const std::array<double, 3>& centre_wavenumber() const noexcept {
        return m_centre;
    }
    /// Σ_i w_c,i per channel: the white, (1, 1, 1) to rounding.
    [[nodiscard]] const std::array<double, 3>& white() const noexcept { return m_white; }
    /// V_c(τ) exactly (the sum over the 1 nm grid, double precision): what the table samples.
    struct Transform {
        std::array<double, 3> re, im;
    };
    [[nodiscard]] Transform exact_transform(double tau_nm) const noexcept;
    /// V_c(τ) as the chunk interpolates it (Catmull-Rom through the table, in float), for
    /// 0 <= τ < table_end_nm.
    [[nodiscard]] Transform interpolated_transform(float tau_nm) const noexcept;
    /// The envelope baked into the chunk: envelope()[j] >= |V_c(τ)| for τ >= j × table_end_nm /
    /// envelope_count, every channel.
    [[nodiscard]] const std::array<double, envelope_count>& envelope() const noexcept {
        return m_envelope;
    }
    /// The quadrature's wavenumbers [1/nm] and weights per channel: Σ_j weight_c,j R(ν_j) is the
    /// 1 nm sum of the polynomial through R at the nodes (exact for degree < quadrature_nodes).
    [[nodiscard]] const std::array<double, quadrature_nodes>& node_wavenumber() const noexcept {
        return m_node_nu;
    }
    [[nodiscard]] const std::array<std::array<double, 3>, quadrature_nodes>& node_weight()
        const noexcept {
        return m_node_weight;
    }

    /// The chunk's branches: the bare interface (no film), the series, the quadrature of a film
    /// whose phase is real, that of a film past its critical angle.
    enum class Path { bare, series, fringes, tunnelling };
    /// What one evaluation did (for measuring the cost).
    struct Evaluation {
        Rgb rgb;
        /// Terms of the series summed (0 for the other paths).
        int terms = 0;
        Path path = Path::series;
    };
    /// The chunk's evalIridescence in single precision, step for step as the GLSL does it.
    [[nodiscard]] Evaluation evaluate(float outside_ior, float eta2, float cos_theta1,
                                      float thickness_nm,
                                      const std::array<float, 3>& base_f0) const noexcept;

    /// The GLSL ES 3.00 chunk (no #version line, one uniform, helpers prefixed irid_).
    [[nodiscard]] std::string glsl() const;
    /// The WGSL chunk: irid_eval(table: texture_2d<f32>, outsideIOR, eta2, cosTheta1,
    /// thinFilmThickness, baseF0) -> vec3f and its helpers (prefixed irid_ / Irid), then, after
    /// wgsl_binding_marker, the table's binding (@group(0) @binding(0)) and evalIridescence of
    /// the GLSL signature, which reads it. The same algorithm as glsl(), line for line.
    [[nodiscard]] std::string wgsl() const;
    /// The line before the WGSL's module-scope binding: a node system that binds the table itself
    /// (three.js's TSL) takes the text before it.
    static constexpr std::string_view wgsl_binding_marker =
        "\n// --- evalIridescence with the table bound at module scope ---\n";
    /// The table as little-endian float32 RGBA texels, row-major.
    [[nodiscard]] std::string table_bytes() const;
    /// {"width", "height", "uniform", "illuminant", "space", "primaries": [rx, ry, gx, gy, bx,
    /// by], "white": [x, y], "filter": "nearest"}: the primaries and white are the working
    /// space's, for a renderer to check against its own (irid-three.js does).
    [[nodiscard]] std::string table_json() const;
    /// The three files, each its name and bytes: irid_iridescence.glsl (or .wgsl),
    /// irid_film_table.f32, irid_film_table.json (the same table for both languages).
    [[nodiscard]] std::vector<std::pair<std::string, std::string>> files(
        ShaderLanguage language = ShaderLanguage::glsl) const;

private:
    std::array<std::vector<double>, 3> m_weight;
    std::vector<double> m_wavenumber;
    std::array<double, 3> m_centre{}, m_white{};
    std::array<double, envelope_count> m_envelope{};
    std::array<double, quadrature_nodes> m_node_nu{};
    std::array<std::array<double, 3>, quadrature_nodes> m_node_weight{};
    int m_width = default_table_width;
    std::vector<float> m_table;
    std::string m_illuminant, m_space;
    RgbPrimaries m_primaries{};
    Xy m_white_xy{};
};

/// What a shader is built for, from the names a user gives (irid shader --illuminant, --space):
/// the colorimeter (the illuminant, CIE 1931, the working space) and the names the files record,
/// written one way whatever the case of the input: the illuminant as canonical_illuminant_name
/// writes it, the space as the linear form three.js names ("srgb-linear", "display-p3-linear",
/// "rec2020-linear", "acescg"). The chunk returns linear light, so a working space is taken by
/// its name or NAME-linear; an encoding (acescct, rec1886, rec2100-pq, ...) is refused, naming the
/// working space of its primaries. Throws UnknownNameError (unknown) or irid::Error (refused).
struct FilmShaderSetup {
    Colorimeter colorimeter;
    std::string illuminant, space;
};
[[nodiscard]] FilmShaderSetup film_shader_setup(std::string_view illuminant, std::string_view space);

}  // namespace irid
