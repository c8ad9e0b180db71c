// The GLSL chunk's algorithm, through its single-precision CPU mirror (FilmShader::evaluate),
// against the exact 1 nm sum (PreparedFilm) over the accuracy goal of issue 28, and against the
// closed forms it must reduce to; the table's interpolation against the exact transform; the
// files' bytes and keys.
#include <irid/error.h>
#include <irid/optics/film_color.h>
#include <irid/optics/film_shader.h>

#include "film_shader_reference.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <string>

namespace irid {
namespace {

constexpr double pi = std::numbers::pi;

using test::clamped;
using test::d65_srgb;
using test::f0_of;
using test::to_xyz;

const FilmShader& shader() {
    return test::default_shader();
}

SingleFilm constant_film(double n0, double n1, double n2) {
    return {Material::constant("ambient", n0), Material::constant("film", n1),
            Material::constant("substrate", n2)};
}

/// Unpolarised Fresnel reflectance of one interface (Born & Wolf §1.5.2), q = N cos θ.
double bare_interface(double n0, double n2, double cos0) {
    const double sin2 = 1.0 - cos0 * cos0;
    const double q2sq = n2 * n2 - n0 * n0 * sin2;
    if (q2sq <= 0.0) return 1.0;
    const double q0 = n0 * cos0, q2 = std::sqrt(q2sq);
    const double rs = (q0 - q2) / (q0 + q2);
    const double rp = (n2 * n2 * q0 - n0 * n0 * q2) / (n2 * n2 * q0 + n0 * n0 * q2);
    return 0.5 * (rs * rs + rp * rp);
}

TEST(FilmShader, MeetsTheAccuracyGoalAgainstTheOneNanometreSum) {
    // Issue 28's goal: films 1.2–2.4, bases 1.0–2.5, 0–2000 nm, 0–85°, in air: mean ΔE2000
    // <= 0.05, max <= 0.5 against the 1 nm sum (its negative channels at 0, as the chunk's).
    const Colorimeter& c = d65_srgb();
    double sum = 0.0, worst = 0.0;
    long count = 0, terms = 0;
    int most_terms = 0;
    std::string where;
    for (const double n1 : {1.2, 1.33, 1.5, 1.8, 2.0, 2.4}) {
        for (const double n2 : {1.0, 1.2, 1.5, 1.8, 2.5}) {
            const float f0 = f0_of(n2);
            for (int a = 0; a <= 17; ++a) {
                const double theta = a * 5.0 * pi / 180.0;
                const PreparedFilm exact(constant_film(1.0, n1, n2), theta);
                for (int t = 0; t <= 2000; t += 20) {
                    const FilmShader::Evaluation e = shader().evaluate(
                        1.0f, static_cast<float>(n1), static_cast<float>(std::cos(theta)),
                        static_cast<float>(t), {f0, f0, f0});
                    const double d =
                        delta_e_2000_of(c, clamped(c, exact.color(t, c).xyz), to_xyz(c, e.rgb));
                    sum += d;
                    ++count;
                    terms += e.terms;
                    most_terms = std::max(most_terms, e.terms);
                    if (d > worst) {
                        worst = d;
                        where = "film " + std::to_string(n1) + " on " + std::to_string(n2) + ", " +
                                std::to_string(t) + " nm, " + std::to_string(a * 5) + " deg";
                    }
                }
            }
        }
    }
    const double mean = sum / static_cast<double>(count);
    std::cout << "ΔE2000 over " << count << " colours: mean " << mean << ", max " << worst << " ("
              << where << "); terms per colour: mean "
              << static_cast<double>(terms) / static_cast<double>(count) << ", max " << most_terms
              << "\n";
    EXPECT_LE(mean, 0.05);
    EXPECT_LE(worst, 0.5) << where;
}

TEST(FilmShader, TotalReflectionAtTheBaseMatchesTheOneNanometreSum) {
    // From glass (1.5) through a film of 2.0 onto a base of 1.2 past 53.1°: the base reflects
    // totally and r12 is complex of modulus 1; the series still holds.
    const Colorimeter& c = d65_srgb();
    const float f0 = f0_of(1.2);
    for (const double deg : {55.0, 60.0, 70.0, 80.0}) {
        const double theta = deg * pi / 180.0;
        const PreparedFilm exact(constant_film(1.5, 2.0, 1.2), theta);
        for (int t = 0; t <= 1000; t += 50) {
            const FilmShader::Evaluation e =
                shader().evaluate(1.5f, 2.0f, static_cast<float>(std::cos(theta)),
                                  static_cast<float>(t), {f0, f0, f0});
            EXPECT_LT(delta_e_2000_of(c, clamped(c, exact.color(t, c).xyz), to_xyz(c, e.rgb)), 0.1)
                << deg << " deg, " << t << " nm";
        }
    }
}

TEST(FilmShader, TableInterpolationStaysWithinTheBudget) {
    // The demodulated transform through Catmull-Rom on the default table: within 1e-4 of the
    // white (issue 28's budget) over the whole table, and a cubic's error falls at least
    // fourfold when the step halves.
    const auto largest_error = [](const FilmShader& s) {
        double worst = 0.0;
        for (double tau = 0.25; tau < FilmShader::table_end_nm; tau += 3.7) {
            const FilmShader::Transform a = s.exact_transform(tau);
            const FilmShader::Transform b = s.interpolated_transform(static_cast<float>(tau));
            for (std::size_t ch = 0; ch < 3; ++ch) {
                worst = std::max(worst, std::hypot(a.re[ch] - b.re[ch], a.im[ch] - b.im[ch]));
            }
        }
        return worst;
    };
    const double fine = largest_error(shader());
    EXPECT_LT(fine, 1e-4);
    const FilmShader coarse(d65_srgb(), "D65", "srgb", (FilmShader::default_table_width + 3) / 2);
    EXPECT_GT(largest_error(coarse), 4.0 * fine);
}

TEST(FilmShader, EnvelopeBoundsTheTransform) {
    const FilmShader& s = shader();
    const double step = FilmShader::table_end_nm / FilmShader::envelope_count;
    for (double tau = 0.0; tau < FilmShader::table_end_nm; tau += 11.3) {
        const FilmShader::Transform v = s.exact_transform(tau);
        const double bound = s.envelope()[static_cast<std::size_t>(tau / step)];
        for (std::size_t ch = 0; ch < 3; ++ch) {
            EXPECT_LE(std::hypot(v.re[ch], v.im[ch]), bound) << tau;
        }
    }
}

TEST(FilmShader, WhiteAndCentresComeFromTheWeights) {
    // Σ w_c = 1 per channel (the white reflector is RGB 1, 1, 1), and V_c(0) is that white.
    const FilmShader& s = shader();
    const FilmShader::Transform v = s.exact_transform(0.0);
    for (std::size_t ch = 0; ch < 3; ++ch) {
        EXPECT_NEAR(s.white()[ch], 1.0, 1e-4);
        EXPECT_NEAR(v.re[ch], s.white()[ch], 1e-12);
        EXPECT_NEAR(v.im[ch], 0.0, 1e-12);
    }
    // Red's centre is the longest wavelength, blue's the shortest, all inside 380–780 nm.
    const auto& nu = s.centre_wavenumber();
    EXPECT_LT(nu[0], nu[1]);
    EXPECT_LT(nu[1], nu[2]);
    EXPECT_GT(nu[0], 1.0 / 780.0);
    EXPECT_LT(nu[2], 1.0 / 380.0);
}

TEST(FilmShader, ZeroThicknessIsTheBareInterface) {
    for (const double n0 : {1.0, 1.33, 1.5}) {
        for (const double n2 : {1.0, 1.2, 1.5, 2.5, 4.0}) {
            for (const double cos0 : {1.0, 0.8, 0.5, 0.2, 0.05, 0.0}) {
                const float f0 = f0_of(n2);
                // The base index glTF's F0 stands for, in float.
                const double s = std::sqrt(static_cast<double>(f0));
                const double n2f = (1.0 + s) / (1.0 - s);
                const Rgb rgb = shader()
                                    .evaluate(static_cast<float>(n0), 1.7f,
                                              static_cast<float>(cos0), 0.0f, {f0, f0, f0})
                                    .rgb;
                const double expected = bare_interface(n0, n2f, cos0);
                EXPECT_NEAR(rgb.r, expected, 1e-6) << n0 << " " << n2 << " " << cos0;
                EXPECT_NEAR(rgb.g, expected, 1e-6);
                EXPECT_NEAR(rgb.b, expected, 1e-6);
            }
        }
    }
}

TEST(FilmShader, ThickFilmIsTheIncoherentSumOfItsFaces) {
    // Past the table every term is dropped: R01 + (1 − R01)² R12 / (1 − R01 R12) per
    // polarisation (the mean of the Airy reflectance over its phase), at normal incidence
    // R = ((n_i − n_j)/(n_i + n_j))² for both.
    const double n1 = 1.6, n2 = 2.2;
    const double r01 = std::pow((1.0 - n1) / (1.0 + n1), 2.0),
                 r12 = std::pow((n1 - n2) / (n1 + n2), 2.0);
    const double expected = r01 + (1.0 - r01) * (1.0 - r01) * r12 / (1.0 - r01 * r12);
    const float f0 = f0_of(n2);
    const FilmShader::Evaluation e = shader().evaluate(1.0f, 1.6f, 1.0f, 20000.0f, {f0, f0, f0});
    EXPECT_EQ(e.terms, 0);
    EXPECT_NEAR(e.rgb.r, expected, 1e-6);
    EXPECT_NEAR(e.rgb.b, expected, 1e-6);
}

TEST(FilmShader, ColouredBaseTakesEachChannelFromItsOwnIndex) {
    const std::array<float, 3> f0{0.9f, 0.5f, 0.04f};
    for (const float cos0 : {1.0f, 0.6f, 0.1f}) {
        for (const float t : {0.0f, 90.0f, 400.0f, 1500.0f}) {
            const Rgb mixed = shader().evaluate(1.0f, 1.4f, cos0, t, f0).rgb;
            const Rgb r = shader().evaluate(1.0f, 1.4f, cos0, t, {f0[0], f0[0], f0[0]}).rgb;
            const Rgb g = shader().evaluate(1.0f, 1.4f, cos0, t, {f0[1], f0[1], f0[1]}).rgb;
            const Rgb b = shader().evaluate(1.0f, 1.4f, cos0, t, {f0[2], f0[2], f0[2]}).rgb;
            // The loop may run longer for one channel than the grey evaluation did (its bound is
            // the largest of the three): the difference is below the term tolerance.
            EXPECT_NEAR(mixed.r, r.r, FilmShader::term_tolerance) << cos0 << " " << t;
            EXPECT_NEAR(mixed.g, g.g, FilmShader::term_tolerance) << cos0 << " " << t;
            EXPECT_NEAR(mixed.b, b.b, FilmShader::term_tolerance) << cos0 << " " << t;
        }
    }
}

TEST(FilmShader, PerfectMirrorAndGrazingIncidenceAreWhite) {
    // F0 = 1 (clamped to 0.9999: a base of index 19 999) under a lossless film reflects all
    // but a fraction of order 4/n of the light; at grazing incidence every face reflects all.
    for (const float n1 : {1.2f, 1.5f, 2.4f}) {
        for (const float t : {0.0f, 120.0f, 700.0f}) {
            const Rgb mirror = shader().evaluate(1.0f, n1, 0.7f, t, {1.0f, 1.0f, 1.0f}).rgb;
            EXPECT_NEAR(mirror.r, 1.0, 1e-3);
            EXPECT_NEAR(mirror.g, 1.0, 1e-3);
            EXPECT_NEAR(mirror.b, 1.0, 1e-3);
            const Rgb grazing = shader().evaluate(1.0f, n1, 0.0f, t, {0.04f, 0.04f, 0.04f}).rgb;
            EXPECT_NEAR(grazing.r, 1.0, 1e-5);
            EXPECT_NEAR(grazing.g, 1.0, 1e-5);
            EXPECT_NEAR(grazing.b, 1.0, 1e-5);
        }
    }
}

TEST(FilmShader, FilmPastItsCriticalAngleTunnelsAsTheExactFilm) {
    // Water (1.33) under glass (1.5) past 62.5°: the film is evanescent, the light tunnels
    // through it, and the chunk's quadrature gives the exact film (PreparedFilm's 1 nm sum),
    // from a few nanometres, where nearly all tunnels, to a film that lets nothing through.
    const Colorimeter& c = d65_srgb();
    const float f0 = f0_of(1.7);
    for (const double deg : {62.6, 65.0, 75.0, 85.0, 89.9}) {
        const double cos0 = std::cos(deg * pi / 180.0);
        const PreparedFilm exact(
            constant_film(test::as_float(1.5), test::as_float(1.33), test::base_index_of(f0)),
            std::acos(test::as_float(cos0)));
        for (const double t : {1.0, 10.0, 100.0, 300.0, 1000.0}) {
            const FilmShader::Evaluation e = shader().evaluate(
                1.5f, 1.33f, static_cast<float>(cos0), static_cast<float>(t), {f0, f0, f0});
            EXPECT_EQ(e.path, FilmShader::Path::tunnelling);
            EXPECT_LT(delta_e_2000_of(c, clamped(c, exact.color(t, c).xyz), to_xyz(c, e.rgb)), 0.01)
                << deg << " deg, " << t << " nm";
        }
    }
    // A thick evanescent film lets nothing through: all is reflected.
    const Rgb thick = shader().evaluate(1.5f, 1.0f, 0.3f, 5000.0f, {f0, f0, f0}).rgb;
    EXPECT_NEAR(thick.g, 1.0, 1e-6);
}

TEST(FilmShader, GrazingFreeFilmsAndThickFilmsUnderAClearcoat) {
    // Where the chunk once broke (issue 38): a free film of 1.33, 0.1 nm, at 89.9° was grey 0.5
    // (the film: 0.029, 0.040, 0.059, its 64-term series cut short); 2.4 at 0.001 nm and 89°
    // gave 0.063 where the film reflects about 1e-6; water in glass, 20 µm, at 62° was a
    // saturated orange where the film is grey (0.586, 0.629, 0.628; its Airy reflectance at one
    // wavenumber per channel taken for the band).
    const Rgb a = shader().evaluate(1.0f, 1.33f, static_cast<float>(std::cos(89.9 * pi / 180.0)),
                                    0.1f, {0.0f, 0.0f, 0.0f})
                      .rgb;
    EXPECT_NEAR(a.r, 0.029, 1e-3);
    EXPECT_NEAR(a.g, 0.040, 1e-3);
    EXPECT_NEAR(a.b, 0.059, 1e-3);
    const Rgb b = shader().evaluate(1.0f, 2.4f, static_cast<float>(std::cos(89.0 * pi / 180.0)),
                                    0.001f, {0.0f, 0.0f, 0.0f})
                      .rgb;
    EXPECT_LT(std::max({b.r, b.g, b.b}), 1e-5);
    const float glass = f0_of(1.5);
    for (const double deg : {61.8, 62.0}) {
        const Rgb c = shader().evaluate(1.5f, 1.33f, static_cast<float>(std::cos(deg * pi / 180.0)),
                                        20000.0f, {glass, glass, glass})
                          .rgb;
        if (deg == 62.0) {
            EXPECT_NEAR(c.r, 0.586, 1e-3);
            EXPECT_NEAR(c.g, 0.629, 1e-3);
            EXPECT_NEAR(c.b, 0.628, 1e-3);
        }
        // Grey on both sides of where the chunk once switched method: no channel far from the mean.
        const double mean = (c.r + c.g + c.b) / 3.0;
        EXPECT_LT(std::max({std::fabs(c.r - mean), std::fabs(c.g - mean), std::fabs(c.b - mean)}), 0.05)
            << deg;
    }
}

TEST(FilmShader, HostileInputsGiveFiniteColours) {
    const float inf = std::numeric_limits<float>::max();
    int checked = 0;
    // Indices up to a float's largest (eta2 >= 1e10 and outsideIOR >= 3.2e6 once gave NaN).
    for (const float n0 : {1.0f, 1.5f, 2.5f, 3.2e6f, inf}) {
        for (const float n1 : {0.0f, 1.0f, 1.2f, 1.5f, 2.4f, 5.0f, 1e10f, inf}) {
            for (const float cos0 :
                 {-0.5f, 0.0f, 1e-7f, 0.001f, 0.3f, 0.577f, 0.999f, 1.0f, 1.5f}) {
                for (const float t :
                     {-5.0f, 0.0f, 1e-30f, 0.5f, 80.0f, 2000.0f, 1e5f, 1e30f, inf}) {
                    for (const float f0 : {-1.0f, 0.0f, 1e-9f, 0.04f, 0.5f, 0.9999f, 1.0f, 2.0f}) {
                        const FilmShader::Evaluation e =
                            shader().evaluate(n0, n1, cos0, t, {f0, 0.04f, 1.0f});
                        for (const double v : {e.rgb.r, e.rgb.g, e.rgb.b}) {
                            ASSERT_TRUE(std::isfinite(v))
                                << n0 << " " << n1 << " " << cos0 << " " << t << " " << f0;
                            // A lossless film reflects at most everything; RGB may pass 1 for
                            // a saturated colour, but not by much, and is clamped at 0.
                            ASSERT_LT(v, 2.0);
                            ASSERT_GE(v, 0.0);
                        }
                        EXPECT_LE(e.terms, FilmShader::max_terms);
                        ++checked;
                    }
                }
            }
        }
    }
    EXPECT_GT(checked, 0);
}

TEST(FilmShader, RandomInputsOverWideRangesGiveFiniteColours) {
    // Ambients 0.5–4, films 0.5–5 (log-uniform), any cos θ, thicknesses up to 10 mm, any F0,
    // with the exact edges mixed in: grazing and normal incidence, a film matching the ambient,
    // a film exactly at its critical angle.
    std::mt19937 rng(28);
    const auto log_uniform = [&](float lo, float hi) {
        return std::exp(std::uniform_real_distribution<float>(std::log(lo), std::log(hi))(rng));
    };
    const auto uniform = [&](float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(rng);
    };
    for (int i = 0; i < 200000; ++i) {
        const float n0 = log_uniform(0.5f, 4.0f);
        float n1 = log_uniform(0.5f, 5.0f);
        float c = uniform(0.0f, 1.0f);
        const float d = i % 5 == 0 ? log_uniform(1e-6f, 1e7f) : uniform(0.0f, 3000.0f);
        if (i % 97 == 0) c = 0.0f;
        if (i % 89 == 0) c = 1.0f;
        if (i % 83 == 0) n1 = n0;
        if (i % 79 == 0) c = std::sqrt(std::max(0.0f, 1.0f - (n1 / n0) * (n1 / n0)));
        const std::array<float, 3> f0{uniform(0.0f, 1.0f), uniform(0.0f, 1.0f),
                                      log_uniform(1e-8f, 1.0f)};
        const Rgb rgb = shader().evaluate(n0, n1, c, d, f0).rgb;
        ASSERT_TRUE(std::isfinite(rgb.r) && std::isfinite(rgb.g) && std::isfinite(rgb.b))
            << n0 << " " << n1 << " " << c << " " << d << " " << f0[0] << " " << f0[1] << " "
            << f0[2];
        ASSERT_LT(std::max({std::fabs(rgb.r), std::fabs(rgb.g), std::fabs(rgb.b)}), 2.0);
    }
}

TEST(FilmShader, TableBytesAreLittleEndianFloatTexels) {
    const FilmShader& s = shader();
    const std::string bytes = s.table_bytes();
    ASSERT_EQ(bytes.size(), static_cast<std::size_t>(s.width() * FilmShader::table_height * 16));
    const std::span<const float> table = s.table();
    ASSERT_EQ(table.size() * 4, bytes.size());
    for (std::size_t i = 0; i < table.size(); ++i) {
        std::uint32_t u = 0;
        for (std::size_t b = 0; b < 4; ++b)
            u |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[4 * i + b]))
                 << (8 * b);
        float f = 0.0f;
        std::memcpy(&f, &u, 4);
        ASSERT_EQ(f, table[i]) << i;
    }
    // Row 0, texel 1 is Re V(0): the white; row 1, texel 1 is Im V(0) = 0; alpha is 0.
    EXPECT_NEAR(table[4], 1.0, 1e-4);
    EXPECT_EQ(table[static_cast<std::size_t>(4 * (s.width() + 1))], 0.0f);
    EXPECT_EQ(table[3], 0.0f);
}

TEST(FilmShader, JsonDescribesTheTable) {
    const FilmShader s(d65_srgb(), "D65", "srgb", 300);
    const nlohmann::json j = nlohmann::json::parse(s.table_json());
    std::set<std::string> keys;
    for (const auto& item : j.items()) keys.insert(item.key());
    EXPECT_EQ(keys, (std::set<std::string>{"width", "height", "uniform", "illuminant", "space",
                                           "primaries", "white", "filter"}));
    EXPECT_EQ(j["width"], 300);
    EXPECT_EQ(j["height"], 2);
    EXPECT_EQ(j["uniform"], "iridFilmTable");
    EXPECT_EQ(j["illuminant"], "D65");
    EXPECT_EQ(j["space"], "srgb");
    // The chunk reads with texelFetch: no filtering needed.
    EXPECT_EQ(j["filter"], "nearest");
    EXPECT_NE(s.glsl().find("texelFetch"), std::string::npos);
    EXPECT_EQ(s.glsl().find("texture("), std::string::npos);
}

TEST(FilmShader, ChunkHasOneUniformNoVersionAndPrefixedHelpers) {
    const std::string g = shader().glsl();
    EXPECT_EQ(g.find("#version"), std::string::npos);
    // Printable ASCII only, comments included (early WebGL implementations refused other
    // characters even there), and none of ` $ \ that would end or interpolate the JavaScript
    // template string a page often pastes the chunk into.
    for (const char ch : g) {
        const auto u = static_cast<unsigned char>(ch);
        EXPECT_TRUE((u >= 0x20 && u < 0x7f && ch != '`' && ch != '$' && ch != '@' && ch != '\\') ||
                    ch == '\n')
            << "character " << static_cast<int>(u);
    }
    std::size_t uniforms = 0;
    for (std::size_t at = g.find("uniform "); at != std::string::npos;
         at = g.find("uniform ", at + 1))
        ++uniforms;
    EXPECT_EQ(uniforms, 1u);
    EXPECT_NE(g.find("uniform highp sampler2D iridFilmTable;"), std::string::npos);
    EXPECT_NE(g.find("vec3 evalIridescence(float outsideIOR, float eta2, float cosTheta1, float "
                     "thinFilmThickness, "
                     "vec3 baseF0) {"),
              std::string::npos);
    // Every function defined at file scope but evalIridescence is irid_-prefixed: a definition
    // is a line starting with a type and a name followed by '('.
    std::size_t start = 0;
    int functions = 0;
    while (start < g.size()) {
        const std::size_t end = std::min(g.find('\n', start), g.size());
        const std::string line = g.substr(start, end - start);
        start = end + 1;
        for (const char* type : {"vec2 ", "vec3 ", "vec4 ", "float ", "void ", "int ", "bool "}) {
            if (line.rfind(type, 0) != 0 || line.find('(') == std::string::npos ||
                line.find('=') != std::string::npos) {
                continue;
            }
            const std::string name =
                line.substr(std::strlen(type), line.find('(') - std::strlen(type));
            EXPECT_TRUE(name.rfind("irid_", 0) == 0 || name == "evalIridescence") << name;
            ++functions;
        }
    }
    EXPECT_GE(functions, 8);
}

TEST(FilmShader, ColorimeterAndLanguageByName) {
    EXPECT_EQ(parse_shader_language("glsl"), ShaderLanguage::glsl);
    EXPECT_THROW((void)parse_shader_language("hlsl"), UnknownNameError);
    EXPECT_THROW((void)film_shader_setup("D65", "no-such-space"), UnknownNameError);
    EXPECT_THROW((void)film_shader_setup("D12", "srgb"), Error);
    EXPECT_THROW(FilmShader(d65_srgb(), "D65", "srgb", 8), Error);
    // Names in any case, written one way; the space as its linear form.
    const FilmShaderSetup p3 = film_shader_setup("d50", "DISPLAY-P3");
    EXPECT_EQ(p3.illuminant, "D50");
    EXPECT_EQ(p3.space, "display-p3-linear");
    EXPECT_EQ(film_shader_setup("D65", "srgb-linear").space, "srgb-linear");
    EXPECT_EQ(film_shader_setup("D65", "ACEScg").space, "acescg");
    EXPECT_EQ(film_shader_setup("d9300 ", "srgb").illuminant, "D9300");
    // An encoding is refused, naming the working space of its primaries.
    try {
        (void)film_shader_setup("D65", "rec2100-pq");
        ADD_FAILURE() << "rec2100-pq accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("rec2020-linear"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)film_shader_setup("D65", "acescct"), Error);
    const FilmShader s(p3.colorimeter, p3.illuminant, p3.space);
    EXPECT_NE(s.glsl().find("illuminant D50, space display-p3-linear"), std::string::npos);
    const nlohmann::json j = nlohmann::json::parse(s.table_json());
    EXPECT_EQ(j["primaries"], nlohmann::json::array({0.68, 0.32, 0.265, 0.69, 0.15, 0.06}));
    EXPECT_EQ(j["white"], nlohmann::json::array({0.3127, 0.329}));
}

}  // namespace
}  // namespace irid
