// Every film colour finite at the edges of the domain the commands accept, and equal to its
// limits there: grazing incidence to within 1e-9 rad of 90°, thickness 0 and 1e-12 nm, film and
// substrate indices from 1.0001 to 1e6, absorbing substrates, the film's own critical angle.
// Checked for the 1 nm sum (PreparedFilm, exact_film_color), the Fourier colour and the transfer
// matrix.
#include <irid/color/illuminant.h>
#include <irid/optics/film_color.h>
#include <irid/optics/fourier_film.h>
#include <irid/optics/multilayer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace irid {
namespace {

constexpr double pi = std::numbers::pi;

bool finite(const Xyz& c) { return std::isfinite(c.X) && std::isfinite(c.Y) && std::isfinite(c.Z); }

std::string describe(const SingleFilm& f, double t, double angle) {
    std::ostringstream out;
    out << f.ambient.name() << " | " << f.film.name() << " " << t << " nm | " << f.substrate.name() << " at "
        << angle << " rad";
    return out.str();
}

/// The angles: normal, oblique, and up to 1e-9 rad short of grazing.
std::vector<double> edge_angles() {
    return {0.0, pi / 4.0, 89.0 * pi / 180.0, 89.9 * pi / 180.0, pi / 2.0 - 1e-6, pi / 2.0 - 1e-9};
}

TEST(FilmEdges, EveryColourIsFiniteAtEveryEdge) {
    const Colorimeter c;
    const auto table = std::make_shared<const FourierColorimeter>(c, 1, false);
    const std::vector<double> indices = {1.0001, 1.33, 2.4, 10.0, 1e3, 1e6};
    std::vector<Material> substrates;
    for (const double n : {1.0, 1.0001, 1.5, 1e6}) {
        std::ostringstream name;
        name << "n" << n;
        substrates.push_back(Material::constant(name.str(), n));
    }
    substrates.push_back(Material::constant("absorbing", 0.2, 3.5));
    for (const double ambient : {1.0, 1.33}) {
        for (const double n1 : indices) {
            for (const Material& substrate : substrates) {
                const SingleFilm film{Material::constant("ambient", ambient), Material::constant("film", n1), substrate};
                const FourierFilm fourier(film, table);
                for (const double angle : edge_angles()) {
                    const PreparedFilm prepared(film, angle);
                    for (const double t : {0.0, 1e-12, 1.0, 550.0, 5000.0}) {
                        const Xyz sum = prepared.color(t, c).xyz;
                        ASSERT_TRUE(finite(sum)) << describe(film, t, angle);
                        ASSERT_TRUE(finite(exact_film_color(film, t, angle, c).xyz)) << describe(film, t, angle);
                        ASSERT_TRUE(finite(fourier.xyz(t, std::cos(angle)))) << describe(film, t, angle);
                        const DenseSpectrum spectrum = prepared.reflectance_spectrum(t);
                        for (const double r : spectrum.values()) {
                            ASSERT_TRUE(r >= -1e-12 && r <= 1.0 + 1e-12) << r << " " << describe(film, t, angle);
                        }
                    }
                }
            }
        }
    }
}

TEST(FilmEdges, ZeroThicknessIsTheBareInterfaceAtEveryAngle) {
    // d = 0: the film is absent, R is the ambient–substrate interface's. At 1e-12 nm the film is
    // there (of index 1e6 it already reflects 3e-5): the transfer matrix's value.
    for (const double n1 : {1.0001, 1.33, 2.4, 1e6}) {
        for (const double n2 : {1.0, 1.5, 1e6}) {
            const SingleFilm film{Material::constant("air", 1.0), Material::constant("film", n1),
                                  Material::constant("substrate", n2)};
            const FilmStack bare(film.ambient, {}, film.substrate);
            for (const double angle : edge_angles()) {
                const PreparedFilm prepared(film, angle);
                for (const double t : {0.0, 1e-12}) {
                    const FilmStack stack(film.ambient, {Layer{film.film, t}}, film.substrate);
                    const double want = (t == 0.0 ? bare : stack).evaluate(550.0, angle, Polarization::unpolarized).R;
                    const int i = 550 - lambda_min_nm;
                    EXPECT_NEAR(prepared.reflectance(i, t), want, 1e-9)
                        << "n1 " << n1 << " n2 " << n2 << " angle " << angle << " t " << t;
                }
            }
        }
    }
}

TEST(FilmEdges, GrazingIncidenceReflectsEverything) {
    // R -> 1 as θ -> 90° for any film of some thickness on a substrate unlike the ambient, and for
    // a bare interface; within 1e-5 at 1e-9 rad short of grazing (1 − R ~ 4 q0 / q1).
    const Colorimeter c;
    for (const double n1 : {1.0001, 1.33, 2.4, 1e3}) {
        for (const double n2 : {1.0, 1.5}) {
            const SingleFilm film{Material::constant("air", 1.0), Material::constant("film", n1),
                                  Material::constant("substrate", n2)};
            const Xyz white = exact_film_color(film, 0.0, 0.0, c).xyz;  // to scale: any, finite
            ASSERT_TRUE(finite(white));
            const PreparedFilm prepared(film, pi / 2.0 - 1e-9);
            const Xyz xyz = prepared.color(300.0, c).xyz;
            EXPECT_NEAR(xyz.Y, 1.0, 1e-5) << "n1 " << n1 << " n2 " << n2;
        }
    }
}

}  // namespace
}  // namespace irid
