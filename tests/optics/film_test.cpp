// The film abstraction (irid/optics/film.h): each model gives what the functions it wraps give
// (the transfer matrix, the Airy film, eq. 21/22, eq. 25 with 26 and 29), at_angle() agrees with
// spectrum(), and the constructors and work checks refuse what they document.

#include <irid/error.h>
#include <irid/optics/film.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace irid {
namespace {

const Material& named(const char* name) { return *find_material(name); }

/// spectrum() on the 1 nm grid against at_angle()->reflectance(): the two routes of one model.
void expect_routes_agree(const FilmModel& f, double angle, double thickness, double tolerance) {
    const auto at = f.spectrum(angle, f.has_thickness() ? std::optional<double>(thickness) : std::nullopt);
    DenseValues r;
    f.at_angle(angle)->reflectance(thickness, r);
    for (int i = 0; i < dense_sample_count; i += 7) {
        ASSERT_NEAR(r[static_cast<std::size_t>(i)], at(DenseSpectrum::wavelength_nm(i)).R, tolerance)
            << f.name() << " at " << DenseSpectrum::wavelength_nm(i) << " nm";
    }
}

TEST(Film, ExactIsTheTransferMatrix) {
    const ExactFilm f(named("air"), {{named("water"), 350.0}, {named("mineral-oil"), 120.0}}, named("water"),
                      Polarization::p);
    const FilmStack stack(named("air"), {{named("water"), 200.0}, {named("mineral-oil"), 120.0}}, named("water"));
    const double angle = 0.6;
    const auto at = f.spectrum(angle, 200.0);  // the first layer's thickness replaced
    for (double lambda : {380.0, 455.5, 600.0, 780.0}) {
        const Optics a = at(lambda), b = stack.evaluate(lambda, angle, Polarization::p);
        EXPECT_EQ(a.R, b.R);
        EXPECT_EQ(a.T, b.T);
    }
    EXPECT_TRUE(f.has_transmittance());
    EXPECT_FALSE(f.is_airy());
    expect_routes_agree(f, angle, 200.0, 0.0);
}

TEST(Film, ExactSingleLayerIsTheAiryFilm) {
    const SingleFilm soap{named("air"), named("water"), named("air")};
    const ExactFilm f(soap.ambient, {{soap.film, 0.0}}, soap.substrate);
    ASSERT_TRUE(f.is_airy());
    const Colorimeter c;
    const FilmColor a = f.color(c, 0.3, 420.0);
    const FilmColor b = PreparedFilm(soap, 0.3).color(420.0, c);
    EXPECT_EQ(a.xyz.X, b.xyz.X);
    EXPECT_EQ(a.rgb_linear.b, b.rgb_linear.b);
    // The Airy sum and the transfer matrix agree (tested to 1e-12 in film_color_test).
    expect_routes_agree(f, 0.3, 420.0, 1e-12);
}

TEST(Film, ThesisIsEq21WithTheMatchedK) {
    const SingleFilm soap{named("air"), named("water"), named("air")};
    const ThesisFilm f(soap, 300.0);
    EXPECT_EQ(f.k(), thesis_matched_k(soap));
    EXPECT_DOUBLE_EQ(ThesisFilm(soap, 300.0, 1.0).k(), 1.0);
    const auto at = f.spectrum(0.4);
    EXPECT_EQ(at(500.0).R, thesis_single_film_reflectance(soap, 300.0, 500.0, 0.4, f.k(), std::nullopt));
    EXPECT_EQ(at(500.0).T, 0.0);
    expect_routes_agree(f, 0.4, 300.0, 0.0);
}

TEST(Film, MultilayerIsEq25WithEq26) {
    const ThesisMultilayerFilm f(named("chitin"), 100.0, 12);
    EXPECT_DOUBLE_EQ(f.k(), 2.0 / 169.0);
    const double angle = 0.5, lambda = 480.0;
    const double n = named("chitin").index(lambda).real();
    const double t = 100.0 * std::sqrt(n * n - std::sin(angle) * std::sin(angle));
    EXPECT_DOUBLE_EQ(f.spectrum(angle)(lambda).R, thesis_multilayer_reflectance(lambda, t, 12, 2.0 / 169.0));
    // at_angle precomputes eq. 26's factor: the same to rounding.
    expect_routes_agree(f, angle, 100.0, 1e-12);
}

TEST(Film, MorphoIsEq25WithEq29) {
    const MorphoParameters wing{150.0, 50.0, 1.56, 12, thesis_unit_peak_k(12)};
    const MorphoFilm plain(wing), blended(wing, MorphoBlend{});
    EXPECT_FALSE(plain.has_thickness());
    EXPECT_EQ(plain.spectrum(0.3)(450.0).R, morpho_reflectance(wing, 450.0, 0.3));
    EXPECT_EQ(blended.spectrum(0.3)(450.0).R, morpho_blend_reflectance(wing, MorphoBlend{}, 450.0, 0.3));
    EXPECT_DOUBLE_EQ(*plain.effective_thickness_nm(0.0), 150.0 + 50.0 * 1.56);
    EXPECT_FALSE(ExactFilm(named("air"), {{named("water"), 1.0}}, named("air")).effective_thickness_nm(0.0));
    expect_routes_agree(blended, 0.3, 0.0, 0.0);
}

TEST(Film, ModelNames) {
    for (FilmModelKind k : {FilmModelKind::exact, FilmModelKind::thesis, FilmModelKind::thesis_multilayer,
                            FilmModelKind::morpho}) {
        EXPECT_EQ(parse_film_model(film_model_name(k)), k);
    }
    try {
        (void)parse_film_model("airy");
        FAIL();
    } catch (const UnknownNameError& e) {
        EXPECT_EQ(e.valid().size(), 4u);
        EXPECT_NE(std::string(e.what()).find("thesis-multilayer"), std::string::npos);
    }
}

TEST(Film, ConstructorsRefuse) {
    const Material& air = named("air");
    const Material& water = named("water");
    EXPECT_THROW(ExactFilm(air, {}, air), Error);
    EXPECT_THROW(ExactFilm(air, {{water, -1.0}}, air), Error);
    EXPECT_THROW(ExactFilm(air, {{water, std::nan("")}}, air), Error);
    EXPECT_THROW(ExactFilm(air, {{water, 2e6}}, air), Error);
    EXPECT_THROW(ExactFilm(Material::constant("lossy", 1.5, 0.1), {{water, 1.0}}, air), Error);
    EXPECT_THROW(ThesisFilm({air, named("silver"), air}, 100.0), Error);  // absorbs
    EXPECT_THROW(ThesisFilm({air, water, air}, 100.0, 0.0), Error);
    EXPECT_THROW(ThesisMultilayerFilm(Material::constant("low", 0.9), 100.0, 12), Error);
    EXPECT_THROW(ThesisMultilayerFilm(water, 100.0, -1), Error);
    EXPECT_THROW(MorphoFilm(MorphoParameters{150.0, 50.0, 0.5, 12, 1.0}), Error);
    const ExactFilm f(air, {{water, 100.0}}, air);
    EXPECT_THROW((void)f.spectrum(std::numbers::pi / 2), Error);
    EXPECT_THROW((void)f.at_angle(-0.1), Error);
    EXPECT_THROW((void)f.spectrum(0.0, -5.0), Error);
    EXPECT_THROW((void)f.color(Colorimeter(), 0.0, std::nan("")), Error);
}

TEST(Film, WorkChecksNameTheCallersFactors) {
    const Material& air = named("air");
    const ExactFilm stack(air, std::vector<Layer>(1000, Layer{named("water"), 10.0}), air);
    try {
        stack.check_work({{"--wavelengths 200:2000:0.009", 200001.0}}, true, {"--layer", "--blend"});
        FAIL();
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("--layer (1 000 layers)"), std::string::npos) << m;
        EXPECT_NE(m.find("200 001 000 layer evaluations"), std::string::npos) << m;
    }
    const MorphoFilm wing(MorphoParameters{}, MorphoBlend{});
    try {
        wing.check_work({{"angles", 1e6}}, false);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("the blend (101 samples"), std::string::npos) << e.what();
    }
    // The prepared Airy film counts colours alone: 2 million are within the limit.
    EXPECT_NO_THROW(ExactFilm(air, {{named("water"), 1.0}}, air).check_work({{"t", 2e6}}, false));
}

}  // namespace
}  // namespace irid
