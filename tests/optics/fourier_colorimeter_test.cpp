// FourierColorimeter: its bands, transforms, nodal tables and quadratures against the direct sums
// they stand for, and its cache.
#include <irid/color/illuminant.h>
#include <irid/error.h>
#include <irid/optics/fourier_film.h>
#include <irid/optics/multilayer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <vector>

namespace irid {
namespace {

constexpr double pi = std::numbers::pi;

SingleFilm constant_film(double n0, double n1, Complex n2) {
    return {Material::constant("ambient", n0), Material::constant("film", n1),
            Material::constant("substrate", n2.real(), n2.imag())};
}

TEST(FourierColorimeter, BandsPartitionTheWhite) {
    const Colorimeter c;
    for (const int bands : {1, 3, 8}) {
        const FourierColorimeter f(c, bands, true);
        Xyz sum;
        for (int b = 0; b < f.bands(); ++b) {
            sum.X += f.band_white(b).X;
            sum.Y += f.band_white(b).Y;
            sum.Z += f.band_white(b).Z;
            // At τ = 0 the transform is the band's white (every phasor is 1).
            const auto v = f.transform(b, 0.0);
            // (The table is single precision.)
            EXPECT_NEAR(v.y.real(), f.band_white(b).Y, 1e-7);
            EXPECT_NEAR(v.y.imag(), 0.0, 1e-7);
            EXPECT_GT(f.max_opd_nm(b), 10000.0);
        }
        EXPECT_NEAR(sum.X, c.white().X, 1e-12) << bands;
        EXPECT_NEAR(sum.Y, 1.0, 1e-12) << bands;
        EXPECT_NEAR(sum.Z, c.white().Z, 1e-12) << bands;
    }
}

TEST(FourierColorimeter, TransformIsTheDirectSumBetweenNodes) {
    // V(τ) = Σ_i w_i e^{2πiτ(ν_i − ν_c)}, summed directly at a τ between table nodes.
    const Colorimeter c;
    const FourierColorimeter f(c);
    for (const double tau : {1.0, 333.3, 2501.7, 9999.0}) {
        std::complex<double> direct;
        for (int i = 0; i < dense_sample_count; ++i) {
            const double nu = 1.0 / DenseSpectrum::wavelength_nm(i);
            direct += c.weight_y()[i] * std::polar(1.0, 2.0 * pi * tau * (nu - f.band_wavenumber(0)));
        }
        const auto v = f.transform(0, tau);
        // Linear interpolation at a 2 nm step: within h²/8 max|V''| (header).
        EXPECT_NEAR(v.y.real(), direct.real(), 2e-5) << tau;
        EXPECT_NEAR(v.y.imag(), direct.imag(), 2e-5) << tau;
    }
    EXPECT_EQ(f.transform(0, -1.0).y, std::complex<double>(0.0));
    EXPECT_EQ(f.transform(0, 1e9).y, std::complex<double>(0.0));
}

TEST(FourierColorimeter, NodalTransformsAreTheDirectSumsOfTheLagrangePolynomials) {
    // U_j(τ) = Σ_i w_i ℓ_j(x_i) e^{2πiτ(ν_i − ν_c)}: the Lagrange polynomials of the seven
    // Chebyshev nodes, written out as products (not by the barycentric formula the table uses),
    // summed directly; and Σ_j U_j = V (the polynomials partition unity).
    const Colorimeter c;
    const FourierColorimeter f(c, 1, true);
    constexpr int n = FourierColorimeter::node_count;
    const auto lagrange = [&](int j, double x) {
        double l = 1.0;
        for (int k = 0; k < n; ++k) {
            if (k != j) l *= (x - FourierColorimeter::node_x(k)) / (FourierColorimeter::node_x(j) - FourierColorimeter::node_x(k));
        }
        return l;
    };
    Xyz white;
    for (int j = 0; j < n; ++j) {
        white.X += f.node_white(0, j).X;
        white.Y += f.node_white(0, j).Y;
        white.Z += f.node_white(0, j).Z;
        // The node's wavenumber is its Chebyshev point mapped onto the band.
        EXPECT_NEAR((f.node_wavenumber(0, j) - f.band_mid(0)) / f.band_half_width(0), FourierColorimeter::node_x(j), 1e-12);
    }
    EXPECT_NEAR(white.Y, 1.0, 1e-12);
    EXPECT_NEAR(white.X, c.white().X, 1e-12);
    for (const double tau : {0.0, 777.7, 5001.3, 39000.0}) {
        std::array<std::complex<double>, n> values{};
        std::complex<double> direct_sum, table_sum;
        for (int j = 0; j < n; ++j) {
            std::complex<double> direct;
            for (int i = 0; i < dense_sample_count; ++i) {
                const double nu = 1.0 / DenseSpectrum::wavelength_nm(i);
                const double x = (nu - f.band_mid(0)) / f.band_half_width(0);
                direct += c.weight_z()[i] * lagrange(j, x) * std::polar(1.0, 2.0 * pi * tau * (nu - f.band_wavenumber(0)));
            }
            const auto u = f.node_transforms(0, tau)[j].z;
            // Linear interpolation of single-precision rows at a 2 nm step (header).
            EXPECT_NEAR(u.real(), direct.real(), 3e-5) << j << " " << tau;
            EXPECT_NEAR(u.imag(), direct.imag(), 3e-5) << j << " " << tau;
            values[j] = std::polar(0.5 + 0.1 * j, 0.3 * j);
            direct_sum += values[j] * direct;
            table_sum += u;
        }
        const auto v = f.transform(0, tau).z;
        EXPECT_NEAR(table_sum.real(), v.real(), 1e-5) << tau;
        EXPECT_NEAR(table_sum.imag(), v.imag(), 1e-5) << tau;
        const auto contracted = f.node_sum(0, tau, values).z;
        EXPECT_NEAR(contracted.real(), direct_sum.real(), 1e-4) << tau;
        EXPECT_NEAR(contracted.imag(), direct_sum.imag(), 1e-4) << tau;
    }
    // Past the nodal tables: nothing.
    EXPECT_EQ(f.node_transforms(0, FourierColorimeter::max_node_opd_nm + 10.0)[3].y, std::complex<double>(0.0));
}

TEST(FourierColorimeter, TheQuadraturesAreExactForPolynomials) {
    // Σ_j R(ν_j) W_L(j) equals the 1 nm sum of R when R is a polynomial in wavenumber of degree up
    // to level L's 8 · 2^L, and not past it.
    const Colorimeter c;
    const FourierColorimeter f(c);
    const double mid = 0.5 * (1.0 / lambda_min_nm + 1.0 / lambda_max_nm);
    const double half = 0.5 * (1.0 / lambda_min_nm - 1.0 / lambda_max_nm);
    const auto error = [&](int level, int degree) {
        // T_degree: bounded by 1 on the interval, so the sums stay of order 1.
        const auto r = [&](double nu) { return 0.5 + 0.3 * std::cos(degree * std::acos(std::clamp((nu - mid) / half, -1.0, 1.0))); };
        double direct = 0.0, rule = 0.0;
        for (int i = 0; i < dense_sample_count; ++i) direct += r(1.0 / DenseSpectrum::wavelength_nm(i)) * c.weight_y()[i];
        for (int j = 0; j < FourierColorimeter::quadrature_node_count; ++j) {
            rule += r(f.quadrature_wavenumber(j)) * f.quadrature_weights(level, j).Y;
        }
        return std::abs(rule - direct);
    };
    for (int level = 0; level < FourierColorimeter::quadrature_levels; ++level) {
        const int n = 8 << level;
        EXPECT_LT(error(level, 3), 1e-12) << level;
        EXPECT_LT(error(level, n), 1e-12) << level;
        EXPECT_GT(error(level, n + 2), 1e-5) << level;
    }
    EXPECT_NEAR(f.quadrature_wavenumber(0), 1.0 / lambda_min_nm, 1e-15);
    EXPECT_NEAR(f.quadrature_wavenumber(FourierColorimeter::quadrature_node_count - 1), 1.0 / lambda_max_nm, 1e-15);
}

TEST(FourierColorimeter, AColorimeterOfTheSameWeightsGetsTheSameTransforms) {
    // fourier_colorimeter_for keeps what it built: asked again for the same weights (another
    // Colorimeter object, equal), it hands out the same tables; other weights, or the other
    // kind of film, get their own.
    const SingleFilm constant = constant_film(1.0, 1.33, Complex(1.5));
    const SingleFilm soap{*find_material("air"), *find_material("water"), *find_material("air")};
    const auto a = fourier_colorimeter_for(soap, Colorimeter());
    const auto b = fourier_colorimeter_for(soap, Colorimeter());
    EXPECT_EQ(a.get(), b.get());
    EXPECT_TRUE(a->slopes());
    const auto other = fourier_colorimeter_for(soap, Colorimeter(illuminant_by_name("A")));
    EXPECT_NE(other.get(), a.get());
    EXPECT_NEAR(other->colorimeter().white().X, Colorimeter(illuminant_by_name("A")).white().X, 1e-15);
    const auto plain = fourier_colorimeter_for(constant, Colorimeter());
    EXPECT_NE(plain.get(), a.get());
    EXPECT_FALSE(plain->slopes());
    // Still the same after others were asked for (four are kept).
    EXPECT_EQ(fourier_colorimeter_for(soap, Colorimeter()).get(), a.get());
    // The same weights with another RGB space are another colorimeter: its colours' linear RGB
    // are its own (FourierFilm::color converts with the kept one).
    const Colorimeter wide(illuminant_d65(), Observer::cie1931_2deg, rec2020());
    const auto b2020 = fourier_colorimeter_for(soap, wide);
    EXPECT_NE(b2020.get(), a.get());
    const FourierFilm film(soap, b2020);
    const FilmColor colour = film.color(300.0, 0.5);
    const Rgb expected = wide.linear_rgb(colour.xyz);
    EXPECT_NEAR(colour.rgb_linear.r, expected.r, 1e-15);
    EXPECT_NEAR(colour.rgb_linear.b, expected.b, 1e-15);
}

TEST(FourierColorimeter, RejectsBandCounts) {
    const Colorimeter c;
    EXPECT_THROW(FourierColorimeter(c, 0), Error);
    EXPECT_THROW(FourierColorimeter(c, FourierColorimeter::max_bands + 1), Error);
}

}  // namespace
}  // namespace irid
