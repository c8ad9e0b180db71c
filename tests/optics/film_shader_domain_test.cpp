// The GLSL chunk's algorithm (its single-precision mirror, FilmShader::evaluate) over the whole
// domain its signature reaches, against the alias-free exact film (FourierFilm: the series, its
// quadratures, or the 1 nm or finer sum where those do not apply): ambients 1–2, films 1–3 above
// and below the ambient, bases 1–3, 0–89.99°, 0–30 µm, with grazing views, clearcoats and the
// band about a film's critical angle sampled densely (issue 38's goal: mean ΔE2000 <= 0.01, max
// <= 0.5).
#include <irid/optics/film_shader.h>
#include <irid/optics/fourier_film.h>

#include "film_shader_reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace irid {
namespace {

constexpr double pi = std::numbers::pi;

using test::as_float;
using test::clamped;
using test::d65_srgb;
using test::to_xyz;

const FilmShader& shader() {
    return test::default_shader();
}

/// The exact film the chunk stands for, from its float inputs: an ambient, a film and a base of
/// glTF F0 f0.
FourierFilm exact_film(double n0, double n1, float f0) {
    const SingleFilm film{Material::constant("ambient", as_float(n0)),
                          Material::constant("film", as_float(n1)),
                          Material::constant("substrate", test::base_index_of(f0))};
    return FourierFilm(film, fourier_colorimeter_for(film, d65_srgb()));
}

struct Film {
    double n0, n1, n2;
};

/// The angles [deg]: every 10° to 80°, then dense towards grazing incidence, and where the film
/// is less dense than the ambient, a band about its critical angle.
std::vector<double> angles(const Film& f) {
    std::vector<double> a{0, 10, 20, 30, 40, 50, 60, 70, 80, 84, 86, 87, 88, 89, 89.5, 89.8, 89.9,
                          89.95, 89.99};
    if (f.n1 < f.n0) {
        const double critical = std::asin(f.n1 / f.n0) * 180.0 / pi;
        for (const double delta : {-3.0, -1.0, -0.3, -0.1, -0.03, -0.01, 0.0, 0.01, 0.03, 0.1, 0.3,
                                   1.0, 3.0}) {
            const double t = critical + delta;
            if (t > 0.0 && t < 89.99) a.push_back(t);
        }
    }
    std::sort(a.begin(), a.end());
    return a;
}

const std::vector<double>& thicknesses() {
#ifdef IRID_SANITIZED
    // The sanitizers' build: every other thickness (the reference runs ten times slower there).
    static const std::vector<double> t{0.0, 1.0, 20.0, 100.0, 250.0, 600.0, 1300.0, 3000.0, 8000.0,
                                       20000.0, 30000.0};
#else
    static const std::vector<double> t{0.0,    0.1,    1.0,    5.0,    20.0,   50.0,   100.0,
                                       170.0,  250.0,  400.0,  600.0,  900.0,  1300.0, 2000.0,
                                       3000.0, 5000.0, 8000.0, 12000.0, 20000.0, 30000.0};
#endif
    return t;
}

TEST(FilmShaderDomain, MeetsTheGoalAgainstTheExactFilm) {
    const Colorimeter& c = d65_srgb();
    std::vector<Film> films;
    for (const double n0 : {1.0, 1.33, 1.5, 2.0}) {
        for (const double n1 : {1.0, 1.2, 1.33, 1.5, 2.0, 2.4, 3.0}) {
            for (const double n2 : {1.0, 1.2, 1.5, 2.0, 3.0}) films.push_back({n0, n1, n2});
        }
    }
    double sum = 0.0, worst = 0.0;
    long count = 0;
    std::string where;
    std::vector<std::pair<double, std::string>> all;
    std::map<int, std::pair<double, long>> by_path;
    std::map<int, double> worst_by_path;
    for (const Film& f : films) {
        const float f0 = test::f0_of(f.n2);
        const FourierFilm exact = exact_film(f.n0, f.n1, f0);
        for (const double deg : angles(f)) {
            const double cos0 = std::cos(deg * pi / 180.0);
            for (const double t : thicknesses()) {
                const FilmShader::Evaluation e =
                    shader().evaluate(static_cast<float>(f.n0), static_cast<float>(f.n1),
                                      static_cast<float>(cos0), static_cast<float>(t), {f0, f0, f0});
                // The reference at the angle the float cosine stands for.
                const double cf = static_cast<double>(static_cast<float>(cos0));
                const Xyz ref = clamped(c, exact.xyz(t, cf));
                const double d = delta_e_2000_of(c, ref, to_xyz(c, e.rgb));
                sum += d;
                ++count;
                auto& p = by_path[static_cast<int>(e.path)];
                p.first += d;
                ++p.second;
                worst_by_path[static_cast<int>(e.path)] =
                    std::max(worst_by_path[static_cast<int>(e.path)], d);
                if (d > 0.05) {
                    all.emplace_back(d, std::to_string(f.n0) + " " + std::to_string(f.n1) + " " +
                                            std::to_string(f.n2) + " t=" + std::to_string(t) +
                                            " deg=" + std::to_string(deg) + " path " +
                                            std::to_string(static_cast<int>(e.path)) + " terms " +
                                            std::to_string(e.terms));
                }
                if (d > worst) {
                    worst = d;
                    where = "n0 " + std::to_string(f.n0) + ", film " + std::to_string(f.n1) +
                            ", base " + std::to_string(f.n2) + ", " + std::to_string(t) + " nm, " +
                            std::to_string(deg) + " deg, path " +
                            std::to_string(static_cast<int>(e.path));
                }
            }
        }
    }
    const double mean = sum / static_cast<double>(count);
    std::cout << "ΔE2000 over " << count << " colours: mean " << mean << ", max " << worst << " ("
              << where << ")\n";
    std::sort(all.rbegin(), all.rend());
    std::cout << all.size() << " above 0.05\n";
    for (std::size_t i = 0; i < std::min<std::size_t>(all.size(), 40); ++i)
        std::cout << "  " << all[i].first << "  " << all[i].second << "\n";
    for (const auto& [path, p] : by_path) {
        std::cout << "  path " << path << ": " << p.second << " colours, mean "
                  << p.first / static_cast<double>(p.second) << ", max " << worst_by_path[path]
                  << "\n";
    }
    EXPECT_LE(mean, 0.01);
    EXPECT_LE(worst, 0.5) << where;
}

TEST(FilmShaderDomain, RandomFilmsConcentratedAtTheEdges) {
    // Random films over the domain, half of them within 5° of grazing incidence and a fifth
    // within 1° of the film's critical angle, log-uniform thicknesses 0.01 nm – 30 µm, a tenth
    // with a coloured base (channel c of the reference from the base index of channel c).
    const Colorimeter& c = d65_srgb();
    std::mt19937 rng(38);
    const auto uniform = [&](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    double sum = 0.0, worst = 0.0;
    std::string where;
#ifdef IRID_SANITIZED
    const int count = 4000;
#else
    const int count = 40000;
#endif
    for (int i = 0; i < count; ++i) {
        const double n0 = i % 3 == 0 ? 1.0 : uniform(1.0, 2.0);
        const double n1 = uniform(1.0, 3.0);
        double deg = uniform(0.0, 89.999);
        if (i % 2 == 0) deg = 90.0 - std::pow(10.0, uniform(-3.0, std::log10(5.0)));
        if (i % 5 == 1 && n1 < n0) deg = std::asin(n1 / n0) * 180.0 / pi + uniform(-1.0, 1.0);
        deg = std::clamp(deg, 0.0, 89.999);
        const double t = i % 10 == 3 ? 0.0 : std::pow(10.0, uniform(-2.0, std::log10(30000.0)));
        std::array<float, 3> f0{};
        const bool coloured = i % 10 == 7;
        const double grey = uniform(1.0, 3.0);
        for (float& f : f0) {
            const double n = coloured ? uniform(1.0, 3.0) : grey;
            f = test::f0_of(n);
        }
        const auto cos0 = static_cast<float>(std::cos(deg * pi / 180.0));
        const FilmShader::Evaluation e = shader().evaluate(
            static_cast<float>(n0), static_cast<float>(n1), cos0, static_cast<float>(t), f0);
        std::array<double, 3> ref{};
        for (std::size_t ch = 0; ch < 3; ++ch) {
            if (ch > 0 && !coloured) {
                ref[ch] = ref[0];
                continue;
            }
            const FourierFilm exact = exact_film(n0, n1, f0[ch]);
            const Rgb rgb = c.linear_rgb(exact.xyz(t, static_cast<double>(cos0)));
            ref[ch] = std::max(ch == 0 ? rgb.r : ch == 1 ? rgb.g : rgb.b, 0.0);
            if (!coloured) {
                ref = {std::max(rgb.r, 0.0), std::max(rgb.g, 0.0), std::max(rgb.b, 0.0)};
                break;
            }
        }
        const double d =
            delta_e_2000_of(c, to_xyz(c, Rgb{ref[0], ref[1], ref[2]}), to_xyz(c, e.rgb));
        sum += d;
        if (d > worst) {
            worst = d;
            where = "n0 " + std::to_string(n0) + ", film " + std::to_string(n1) + ", F0 " +
                    std::to_string(f0[0]) + "/" + std::to_string(f0[1]) + "/" +
                    std::to_string(f0[2]) + ", " + std::to_string(t) + " nm, " +
                    std::to_string(deg) + " deg, path " + std::to_string(static_cast<int>(e.path));
        }
    }
    std::cout << "ΔE2000 over " << count << " random films: mean " << sum / count << ", max "
              << worst << " (" << where << ")\n";
    EXPECT_LE(sum / count, 0.01);
    EXPECT_LE(worst, 0.5) << where;
}

TEST(FilmShaderDomain, ClearcoatOverABaseThatReflectsTotally) {
    // Under a clearcoat (ambient 1.5–2) over a base of lower index, past the base's critical
    // angle r12 has modulus 1 and any phase, so near grazing incidence the film's sharp lines
    // fall anywhere in the spectrum, at any thickness: the hardest case for the quadrature.
    const Colorimeter& c = d65_srgb();
    double sum = 0.0, worst = 0.0;
    long count = 0;
    std::string where;
    for (const double n0 : {1.5, 2.0}) {
        for (const double n2 : {1.0, 1.2, 1.4}) {
#ifdef IRID_SANITIZED
            constexpr double film_step = 1.0;
#else
            constexpr double film_step = 0.2;
#endif
            for (double n1 = 1.0; n1 <= 3.0; n1 += film_step) {
                const float f0 = test::f0_of(n2);
                const FourierFilm exact = exact_film(n0, n1, f0);
                for (const double deg : {60.0, 75.0, 85.0, 88.0, 89.0, 89.5, 89.8, 89.9, 89.95, 89.99,
                                         89.999}) {
                    const auto cos0 = static_cast<float>(std::cos(deg * pi / 180.0));
                    for (double t = 0.5; t < 2000.0; t *= 1.2) {
                        const FilmShader::Evaluation e =
                            shader().evaluate(static_cast<float>(n0), static_cast<float>(n1), cos0,
                                              static_cast<float>(t), {f0, f0, f0});
                        const double d =
                            delta_e_2000_of(c, clamped(c, exact.xyz(t, static_cast<double>(cos0))),
                                            to_xyz(c, e.rgb));
                        sum += d;
                        ++count;
                        if (d > worst) {
                            worst = d;
                            where = "n0 " + std::to_string(n0) + ", film " + std::to_string(n1) +
                                    ", base " + std::to_string(n2) + ", " + std::to_string(t) +
                                    " nm, " + std::to_string(deg) + " deg, path " +
                                    std::to_string(static_cast<int>(e.path)) + ", terms " +
                                    std::to_string(e.terms);
                        }
                    }
                }
            }
        }
    }
    std::cout << "ΔE2000 over " << count << " colours: mean " << sum / static_cast<double>(count)
              << ", max " << worst << " (" << where << ")\n";
    EXPECT_LE(sum / static_cast<double>(count), 0.01);
    EXPECT_LE(worst, 0.5) << where;
}

/// Walks one parameter and returns the largest step of the chunk's colour (ΔE2000 between
/// neighbours) beyond the reference's step there: a seam where the chunk changes branch shows as
/// a step the film does not take.
struct Walk {
    double largest = 0.0;
    std::string where;
};

/// Steps per walk (fewer under the sanitizers, whose build runs the reference ten times slower).
#ifdef IRID_SANITIZED
constexpr int walk_steps = 200;
#else
constexpr int walk_steps = 1200;
#endif

TEST(FilmShaderDomain, NoSeamWhereTheChunkChangesBranch) {
    const Colorimeter& c = d65_srgb();
    const std::vector<Film> films{{1.0, 1.33, 1.0}, {1.0, 2.4, 1.0},  {1.5, 1.33, 1.5},
                                  {1.5, 1.0, 1.2},  {2.0, 1.2, 1.0},  {1.33, 1.5, 1.33},
                                  {1.5, 2.0, 1.0},  {1.0, 1.33, 1.5}};
    Walk walk;
    const auto run = [&](const Film& f, const std::vector<std::pair<double, double>>& points,
                         const std::string& what) {
        const float f0 = test::f0_of(f.n2);
        const FourierFilm exact = exact_film(f.n0, f.n1, f0);
        Xyz last_chunk{}, last_ref{};
        FilmShader::Path last_path{};
        for (std::size_t i = 0; i < points.size(); ++i) {
            const auto [deg, t] = points[i];
            const auto cos0 = static_cast<float>(std::cos(deg * pi / 180.0));
            const FilmShader::Evaluation e =
                shader().evaluate(static_cast<float>(f.n0), static_cast<float>(f.n1), cos0,
                                  static_cast<float>(t), {f0, f0, f0});
            const Xyz chunk = to_xyz(c, e.rgb);
            const Xyz ref = clamped(c, exact.xyz(t, static_cast<double>(cos0)));
            if (i > 0) {
                const double excess =
                    delta_e_2000_of(c, last_chunk, chunk) - delta_e_2000_of(c, last_ref, ref);
                if (excess > walk.largest) {
                    walk.largest = excess;
                    walk.where = what + ": n0 " + std::to_string(f.n0) + ", film " +
                                 std::to_string(f.n1) + ", base " + std::to_string(f.n2) + ", " +
                                 std::to_string(t) + " nm, " + std::to_string(deg) + " deg, path " +
                                 std::to_string(static_cast<int>(last_path)) + " -> " +
                                 std::to_string(static_cast<int>(e.path));
                }
            }
            last_chunk = chunk;
            last_ref = ref;
            last_path = e.path;
        }
    };
    for (const Film& f : films) {
        for (const double t : {1.0, 30.0, 100.0, 300.0, 1000.0, 5000.0, 20000.0}) {
            std::vector<std::pair<double, double>> by_angle;
            // 0–89.999°, the step shrinking towards grazing incidence.
            for (int i = 0; i <= walk_steps; ++i) {
                by_angle.emplace_back(90.0 - 90.0 * std::pow(1e-3 / 90.0, i / static_cast<double>(walk_steps)),
                                      t);
            }
            if (f.n1 < f.n0) {
                const double critical = std::asin(f.n1 / f.n0) * 180.0 / pi;
                for (int i = -walk_steps / 4; i <= walk_steps / 4; ++i)
                    by_angle.emplace_back(critical + 4e-3 * i / (walk_steps / 1000.0), t);
            }
            run(f, by_angle, "angle");
        }
        std::vector<double> angles_of{30.0, 85.0, 88.0, 89.5, 89.9, 89.99};
        if (f.n1 < f.n0) {
            const double critical = std::asin(f.n1 / f.n0) * 180.0 / pi;
            for (const double delta : {-0.01, -1e-4, 1e-4, 0.01}) angles_of.push_back(critical + delta);
        }
        for (const double deg : angles_of) {
            std::vector<std::pair<double, double>> by_thickness;
            for (int i = 0; i <= walk_steps; ++i)
                by_thickness.emplace_back(deg, 0.01 * std::pow(3e6, i / static_cast<double>(walk_steps)));
            run(f, by_thickness, "thickness");
        }
    }
    std::cout << "largest step beyond the film's: " << walk.largest << " (" << walk.where
              << ")\n";
    EXPECT_LE(walk.largest, 0.1) << walk.where;
}

}  // namespace
}  // namespace irid
