// The renderers' thin-film models (irid/optics/renderer_films.h) against closed forms, limits and
// irid's exact optics: the series against the Airy sum, the Fresnel terms against the closed
// forms of Born & Wolf, the Gaussian fits and Cycles' table against the CIE table's integrals.

#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/optics/renderer_films.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace irid {
namespace {

constexpr double pi = std::numbers::pi;

/// Born & Wolf §1.5.2, lossless media: unpolarised reflectance of one interface.
double fresnel_closed(double n_i, double n_t, double cos_i) {
    const double sin_t = n_i / n_t * std::sqrt(1.0 - cos_i * cos_i);
    const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
    const double rs = (n_i * cos_i - n_t * cos_t) / (n_i * cos_i + n_t * cos_t);
    const double rp = (n_t * cos_i - n_i * cos_t) / (n_t * cos_i + n_i * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

/// The sums of the 1 nm CIE 1931 table: ∫x̄ dλ, ∫ȳ dλ, ∫z̄ dλ [nm].
Xyz cmf_integrals() {
    const ColorMatchingFunctions& c = color_matching_functions(Observer::cie1931_2deg);
    Xyz s;
    for (int i = 0; i < dense_sample_count; ++i) {
        s.X += c.x[i];
        s.Y += c.y[i];
        s.Z += c.z[i];
    }
    return s;
}

void expect_rgb_near(const Rgb& a, const Rgb& b, double tolerance) {
    EXPECT_NEAR(a.r, b.r, tolerance);
    EXPECT_NEAR(a.g, b.g, tolerance);
    EXPECT_NEAR(a.b, b.b, tolerance);
}

ChannelIndices dielectric(double n) { return {Complex(n), Complex(n), Complex(n)}; }

TEST(RendererFilms, NamesRoundTripAndUnknownNamesAreRefused) {
    for (const std::string& name : renderer_film_model_names()) {
        EXPECT_EQ(renderer_film_model_name(parse_renderer_film_model(name)), name);
    }
    EXPECT_THROW((void)parse_renderer_film_model("thesis"), UnknownNameError);
    EXPECT_FALSE(find_renderer_film_model("exact"));
}

TEST(RendererFilms, SeriesToManyOrdersIsTheAiryFilm) {
    // Belcour & Barla's eq. 10 is the Airy sum expanded in the round trip's phase: with enough
    // orders it is airy_film at one wavelength, normal incidence (r from irid's convention).
    for (const auto [n1, n2, d] : {std::array{1.33, 1.5, 300.0}, std::array{2.0, 1.0, 120.0},
                                   std::array{1.2, 1.5, 777.0}}) {
        const double lambda = 550.0;
        const double exact = airy_film(1.0, n1, n2, d, lambda, 0.0, Polarization::unpolarized).R;
        const double r12 = (1.0 - n1) / (1.0 + n1);
        const double r23 = (n1 - n2) / (n1 + n2);
        const double phase = 2.0 * pi * 2.0 * n1 * d / lambda + std::arg(Complex(-r12)) +
                             std::arg(Complex(r23));
        EXPECT_NEAR(airy_series_reflectance(r12, r23, phase, 60), exact, 1e-12);
        // Truncated at m = 3 the error is at most 2 Σ_{m>3} |C_m| <= 2 |C_1| r123³ / (1 - r123).
        const double r123 = std::abs(r12 * r23);
        const double c1 = std::abs((1.0 - r12 * r12) * (1.0 - r12 * r12) * r23 * r23 /
                                       (1.0 - r12 * r12 * r23 * r23) -
                                   (1.0 - r12 * r12)) *
                          r123;
        EXPECT_LE(std::abs(airy_series_reflectance(r12, r23, phase, 3) - exact),
                  2.0 * c1 * r123 * r123 * r123 / (1.0 - r123) + 1e-15);
    }
}

TEST(RendererFilms, GaussianFitsIntegrateToTheCieFunctions) {
    // At OPD 0 the fits give their areas in metres of wavelength: ∫x̄ dλ, ∫ȳ dλ, ∫z̄ dλ of the
    // CIE 1931 table (106.87, 106.86, 106.89 nm). The fits hold them to 0.2 %.
    const Xyz fit = gaussian_fit_sensitivity_unnormalized(0.0, 0.0);
    const Xyz cie = cmf_integrals();
    EXPECT_NEAR(fit.X / (cie.X * 1e-9), 1.0, 2e-3);
    EXPECT_NEAR(fit.Y / (cie.Y * 1e-9), 1.0, 2e-3);
    EXPECT_NEAR(fit.Z / (cie.Z * 1e-9), 1.0, 2e-3);
    // Normalised, illuminant E's white: X = Y = Z = 1 within the same.
    const Xyz w = gaussian_fit_sensitivity(0.0, 0.0);
    EXPECT_NEAR(w.X, 1.0, 2e-3);
    EXPECT_NEAR(w.Y, 1.0, 2e-3);
    EXPECT_NEAR(w.Z, 1.0, 2e-3);
    // A shift of π negates, and the fits decay: at 20 µm of OPD nothing is left.
    EXPECT_NEAR(gaussian_fit_sensitivity(0.0, pi).Y, -w.Y, 1e-12);
    EXPECT_LT(std::abs(gaussian_fit_sensitivity(20000.0, 0.0).Y), 1e-6);
}

TEST(RendererFilms, FitsWhiteIsIlluminantEInRec709) {
    // E (X = Y = Z) through the D65 Rec.709 matrix: rows' sums 1.2048, 0.9484, 0.9086.
    const Rgb w = renderer_sensitivity_white(RendererFilmModel::gltf);
    EXPECT_NEAR(w.r, 3.2404542 - 1.5371385 - 0.4985314, 4e-3);
    EXPECT_NEAR(w.g, -0.9692660 + 1.8760108 + 0.0415560, 4e-3);
    EXPECT_NEAR(w.b, 0.0556434 - 0.2040259 + 1.0572252, 4e-3);
    expect_rgb_near(renderer_sensitivity_white(RendererFilmModel::cycles), {1.0, 1.0, 1.0}, 1e-12);
}

TEST(RendererFilms, CyclesTableAtZeroIsTheIntegralOfTheCmfs) {
    // The DC entry is Σ_n S(f_n), a Riemann sum of ∫ S df = ∫ cmf dλ / 1000 over df = π/60 µm⁻¹.
    const CyclesSensitivityTable& table = cycles_sensitivity_table();
    const Xyz cie = cmf_integrals();
    const double df = pi / 60.0;
    const auto dc = table.xyz_entry(0);
    EXPECT_NEAR(dc[0].real() * df * 1000.0 / cie.X, 1.0, 5e-3);
    EXPECT_NEAR(dc[1].real() * df * 1000.0 / cie.Y, 1.0, 5e-3);
    EXPECT_NEAR(dc[2].real() * df * 1000.0 / cie.Z, 1.0, 5e-3);
    EXPECT_NEAR(dc[1].imag(), 0.0, 1e-12);
    // The table's OPD range: 512 entries, 0 to 60 µm / 2π, clamped beyond.
    EXPECT_NEAR(CyclesSensitivityTable::max_opd_nm, 60000.0 / (2.0 * pi), 1e-9);
    const auto last = table.at(CyclesSensitivityTable::max_opd_nm);
    const auto beyond = table.at(3.0 * CyclesSensitivityTable::max_opd_nm);
    EXPECT_EQ(last[1], beyond[1]);
    // Between entries the lookup is linear.
    const double step = CyclesSensitivityTable::opd_step_nm;
    const auto a = table.at(10.0 * step), b = table.at(11.0 * step), mid = table.at(10.5 * step);
    EXPECT_NEAR(std::abs(mid[0] - 0.5 * (a[0] + b[0])), 0.0, 1e-6);
}

TEST(RendererFilms, CyclesTableAgreesWithTheGaussianFitsWhereTheyAreGood) {
    // Both are the Fourier transform of the same functions: at short OPD (the first fringes)
    // the fits' Y and the table's (Y from its Rec.709 rows) agree to a few per cent of the DC.
    const CyclesSensitivityTable& table = cycles_sensitivity_table();
    const double dc_y = table.xyz_entry(0)[1].real();
    for (const int k : {5, 10, 20}) {
        const double opd = k * CyclesSensitivityTable::opd_step_nm;
        const double fit_y = gaussian_fit_sensitivity(opd, 0.0).Y;
        EXPECT_NEAR(table.xyz_entry(k)[1].real() / dc_y, fit_y, 0.05) << "OPD " << opd;
    }
}

TEST(RendererFilms, ChannelWavelengthsAreTheRec709DominantWavelengths) {
    // The line from D65's xy (0.3127, 0.3290) through each primary meets the locus there.
    const Xy white{0.3127, 0.3290};
    const Xy primaries[3] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
    for (int c = 0; c < 3; ++c) {
        const double lambda = renderer_channel_wavelengths_nm[static_cast<std::size_t>(c)];
        const Xy p = primaries[c];
        // The locus crosses the line within 0.2 nm: the cross product changes sign.
        const auto side = [&](double l) {
            const Xy s = spectral_locus_xy(l);
            return (p.x - white.x) * (s.y - white.y) - (p.y - white.y) * (s.x - white.x);
        };
        EXPECT_LT(side(lambda - 0.2) * side(lambda + 0.2), 0.0) << "channel " << c;
    }
}

TEST(RendererFilms, WithoutAFilmEveryModelIsItsBaseFresnel) {
    // n1 = n0: no first face, no interference. Belcour: the base's exact Fresnel times the fits'
    // white; Cycles: the same times (1, 1, 1).
    for (const double angle : {0.0, 0.6, 1.2}) {
        const double c = std::cos(angle);
        const double R = fresnel_closed(1.0, 1.5, c);
        const Rgb w = renderer_sensitivity_white(RendererFilmModel::belcour);
        expect_rgb_near(belcour_iridescence(1.0, 1.0, dielectric(1.5), 400.0, c),
                        {R * w.r, R * w.g, R * w.b}, 1e-12);
        expect_rgb_near(cycles_iridescence(1.0, 1.0, dielectric(1.5), 400.0, c), {R, R, R}, 1e-12);
    }
}

TEST(RendererFilms, FilmOfTheBaseIndexIsItsTopFaceFresnel) {
    // n1 = n2: the second face vanishes, leaving the first face's exact Fresnel (air → 1.5).
    for (const double angle : {0.0, 0.9}) {
        const double c = std::cos(angle);
        const double R = fresnel_closed(1.0, 1.5, c);
        expect_rgb_near(cycles_iridescence(1.0, 1.5, dielectric(1.5), 250.0, c), {R, R, R}, 1e-12);
        const Rgb w = renderer_sensitivity_white(RendererFilmModel::belcour);
        expect_rgb_near(belcour_iridescence(1.0, 1.5, dielectric(1.5), 250.0, c),
                        {R * w.r, R * w.g, R * w.b}, 1e-12);
    }
}

TEST(RendererFilms, GltfAtZeroThicknessKeepsSchlicksTopFace) {
    // Thickness 0: the film index becomes the outside index, so R0 of the top face is 0, but
    // Schlick's R12 = (1 - cos θ)^5 does not vanish away from normal incidence. With OPD 0 the
    // sensitivities are ±(the fits' white) (shift mπ, φ = π for a base above the film), so
    // I = R12 + Rs + 2 Σ_{m=1,2} (Rs - T121) r123^m (-1)^m w, r123² = max(R12 R23, 1e-5).
    const double f0 = 0.04;
    const Rgb w = renderer_xyz_to_rec709(gaussian_fit_sensitivity(0.0, 0.0));
    for (const double c : {1.0, 0.5, 0.1}) {
        const double m = 1.0 - c;
        const double R12 = m * m * m * m * m;
        const double R23 = f0 + (1.0 - f0) * R12;
        const double R123 = std::max(R12 * R23, 1e-5), r = std::sqrt(R123);
        const double Rs = (1.0 - R12) * (1.0 - R12) * R23 / (1.0 - R123);
        const double cm = Rs - (1.0 - R12);
        const auto expected = [&](double white) {
            return std::max(0.0, R12 + Rs + 2.0 * cm * (-r + r * r) * white);
        };
        expect_rgb_near(gltf_iridescence(1.0, 1.33, {f0, f0, f0}, 0.0, c),
                        {expected(w.r), expected(w.g), expected(w.b)}, 1e-12);
    }
    // At normal incidence that is the base's F0, up to the clamp's residue 2 sqrt(1e-5) w.
    EXPECT_NEAR(gltf_iridescence(1.0, 1.33, {f0, f0, f0}, 0.0, 1.0).g, f0, 2.0 * std::sqrt(1e-5) * 1.21);
    // Fresnel0ToIor and IorToFresnel0 invert each other.
    EXPECT_NEAR(gltf_fresnel0_to_ior(gltf_ior_to_fresnel0(1.5, 1.0)), 1.5, 1e-12);
}

TEST(RendererFilms, ThickFilmsAverageToTheIncoherentSum) {
    // Far beyond the coherence length the fits vanish and the series keeps C0 = R12 + Rs: the
    // incoherent sum of the two faces' reflections, R12 + T12² R23 / (1 - R12 R23), per polarisation.
    const double c = 1.0;
    const double R12 = fresnel_closed(1.0, 1.33, c), R23 = fresnel_closed(1.33, 1.5, c);
    const double incoherent = R12 + (1.0 - R12) * (1.0 - R12) * R23 / (1.0 - R12 * R23);
    const Rgb w = renderer_sensitivity_white(RendererFilmModel::belcour);
    expect_rgb_near(belcour_iridescence(1.0, 1.33, dielectric(1.5), 1e5, c),
                    {incoherent * w.r, incoherent * w.g, incoherent * w.b}, 1e-9);
    // Cycles' table holds its last entry beyond 9.5 µm of OPD: the remaining fringe is at most
    // 2 Σ |C_m| |S_last|.
    const auto last = cycles_sensitivity_table().at(CyclesSensitivityTable::max_opd_nm);
    const double bound = 2.0 * std::sqrt(R12 * R23) * 3.0 * std::abs(last[1]) + 1e-12;
    EXPECT_NEAR(cycles_iridescence(1.0, 1.33, dielectric(1.5), 1e5, c).g, incoherent, bound);
    // glTF: Schlick's faces at normal incidence are the exact F0.
    EXPECT_NEAR(gltf_iridescence(1.0, 1.33, {0.04, 0.04, 0.04}, 1e5, c).g,
                [] {
                    const double a = gltf_ior_to_fresnel0(1.33, 1.0);
                    const double b = gltf_ior_to_fresnel0(gltf_fresnel0_to_ior(0.04), 1.33);
                    return a + (1.0 - a) * (1.0 - a) * b / (1.0 - a * b);
                }(),
                1e-9);
}

TEST(RendererFilms, AtNormalIncidenceSAndPAreOne) {
    // The polarisations coincide at normal incidence, so the average is the single value: the
    // series with the closed-form amplitudes of one polarisation and the fits.
    const double n1 = 1.33, n2 = 1.5, d = 350.0;
    const double r12 = (1.0 - n1) / (1.0 + n1), r23 = (n1 - n2) / (n1 + n2);
    const double R12 = r12 * r12, R23 = r23 * r23, T = 1.0 - R12;
    const double Rs = T * T * R23 / (1.0 - R12 * R23);
    const double phi = std::arg(Complex(-r12)) + std::arg(Complex(r23));
    Xyz I = gaussian_fit_sensitivity(0.0, 0.0);
    I = {I.X * (R12 + Rs), I.Y * (R12 + Rs), I.Z * (R12 + Rs)};
    double cm = Rs - T;
    for (int m = 1; m <= 3; ++m) {
        cm *= std::sqrt(R12 * R23);
        const Xyz s = gaussian_fit_sensitivity(m * 2.0 * n1 * d, m * phi);
        I = {I.X + 2.0 * cm * s.X, I.Y + 2.0 * cm * s.Y, I.Z + 2.0 * cm * s.Z};
    }
    expect_rgb_near(belcour_iridescence(1.0, n1, dielectric(n2), d, 1.0), renderer_xyz_to_rec709(I), 1e-12);
}

TEST(RendererFilms, ConductorPhasesFollowTheExactFilm) {
    // On gold the reflection phase is neither 0 nor π: with the phase of irid's complex r23 the
    // series (what belcour and cycles sum) is the Airy film at one wavelength.
    const Complex gold = find_material("gold")->index(550.0);
    const double n1 = 1.5, d = 100.0, lambda = 550.0;
    const double exact = airy_film(1.0, n1, gold, d, lambda, 0.0, Polarization::unpolarized).R;
    const FresnelCoefficients top = fresnel(1.0, n1, 0.0), bottom = fresnel(n1, gold, 0.0);
    const double phase = 2.0 * pi * 2.0 * n1 * d / lambda + std::arg(-top.r_s) + std::arg(bottom.r_s);
    EXPECT_NEAR(airy_series_reflectance(std::abs(top.r_s), std::abs(bottom.r_s), phase, 80), exact, 1e-9);
}

TEST(RendererFilms, InputsFromMaterials) {
    const Material air = *find_material("air");
    const RendererFilmInputs gold = renderer_film_inputs({air, Material::constant("f", 1.5), *find_material("gold")});
    // Gold's F0: yellow, R > G > B, and its per-channel indices differ.
    EXPECT_GT(gold.gltf_base_f0.r, gold.gltf_base_f0.g);
    EXPECT_GT(gold.gltf_base_f0.g, gold.gltf_base_f0.b);
    EXPECT_NE(gold.base[0], gold.base[2]);
    const RendererFilmInputs glass = renderer_film_inputs({air, Material::constant("f", 1.33), Material::constant("g", 1.5)});
    EXPECT_NEAR(glass.gltf_base_f0.g, 0.04, 1e-12);
    EXPECT_EQ(glass.base[0], Complex(1.5));
    EXPECT_THROW((void)renderer_film_inputs({air, Material::constant("metal", 0.2, 3.0), air}), Error);
}

TEST(RendererFilms, ErrorMapsCoverTheGridAndRefuseWhatTheyCannotModel) {
    const Material air = *find_material("air");
    const SingleFilm soap{air, Material::constant("soap", 1.33), air};
    ErrorStudyOptions o;
    o.max_thickness_nm = 200.0;
    o.thickness_step_nm = 50.0;
    o.max_angle_deg = 60.0;
    o.angle_step_deg = 30.0;
    const FilmErrorMap map = renderer_film_error_map(RendererFilmModel::cycles, soap, o);
    EXPECT_EQ(map.thickness_count, 5u);
    EXPECT_EQ(map.angle_count, 3u);
    ASSERT_EQ(map.delta_e.size(), 15u);
    for (const double d : map.delta_e) EXPECT_TRUE(std::isfinite(d) && d >= 0.0);
    const FilmErrorRegions r = summarize_film_error("soap", map);
    EXPECT_EQ(r.summary.samples, 15u);
    EXPECT_LE(r.summary.median, r.summary.p95);
    EXPECT_LE(r.summary.p95, r.summary.max);
    EXPECT_LE(r.above_5, r.above_2);
    EXPECT_THROW((void)thesis_film_error_map({air, Material::constant("f", 1.5), *find_material("gold")}, o), Error);
    o.thickness_step_nm = 0.0;
    EXPECT_THROW((void)renderer_film_error_map(RendererFilmModel::gltf, soap, o), Error);
    // One exact spectrum per sample: 100 001 thicknesses × 86 angles = 8 600 086 > 2 123 142.
    ErrorStudyOptions big;
    big.max_thickness_nm = 1e5;
    big.thickness_step_nm = 1.0;
    big.max_angle_deg = 85.0;
    big.angle_step_deg = 1.0;
    try {
        validate_renderer_error_study(big);
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("8 600 086 spectra"), std::string::npos) << e.what();
    }
    big.max_thickness_nm = 2e4;  // 20 001 × 86 = 1 720 086: within the limit
    EXPECT_NO_THROW(validate_renderer_error_study(big));
}

TEST(RendererFilms, AtZeroThicknessTheErrorIsTheBaseAndTheFitsWhite) {
    // Without a film on a constant-index base the exact colour is F times the white, F the
    // base's Fresnel. Cycles gives F (1, 1, 1): no error at any angle. Belcour & Barla give F times
    // the fits' white: at normal incidence their error is the ΔE2000 between the two greys,
    // derived here from Rec.709's matrix.
    const Material air = *find_material("air");
    const SingleFilm film{air, Material::constant("film", 1.33), Material::constant("glass", 1.5)};
    ErrorStudyOptions o;
    o.max_thickness_nm = 0.0;
    o.max_angle_deg = 80.0;
    o.angle_step_deg = 20.0;
    for (const double d : renderer_film_error_map(RendererFilmModel::cycles, film, o).delta_e) {
        EXPECT_LT(d, 1e-6);
    }
    const double n0 = air.index(renderer_ior_wavelength_nm).real();
    const double F = std::pow((1.5 - n0) / (1.5 + n0), 2.0);
    const Rgb w = renderer_sensitivity_white(RendererFilmModel::belcour);
    const Colorimeter colorimeter;
    const Xyz& white = colorimeter.white();
    const Xyz tinted = srgb().to_xyz({F * w.r, F * w.g, F * w.b});
    const Xyz& rec709 = srgb().white_xyz();
    const Xyz model{tinted.X * white.X / rec709.X, tinted.Y * white.Y / rec709.Y, tinted.Z * white.Z / rec709.Z};
    const double expected = delta_e_2000_of(colorimeter, model, {F * white.X, F * white.Y, F * white.Z});
    EXPECT_GT(expected, 1.0);
    EXPECT_NEAR(renderer_film_error_map(RendererFilmModel::belcour, film, o).delta_e[0], expected, 1e-6);
}

TEST(RendererFilms, ModelsGiveFiniteColoursOverTheStudy) {
    for (const StudyFilm& f : renderer_study_films()) {
        const RendererFilmInputs in = renderer_film_inputs(f.film);
        for (const RendererFilmModel m : {RendererFilmModel::gltf, RendererFilmModel::belcour, RendererFilmModel::cycles}) {
            for (const double t : {0.0, 0.5, 37.0, 2000.0}) {
                for (const double a : {0.0, 1.48}) {
                    const FilmColor c = renderer_film_color(m, in, t, a);
                    EXPECT_TRUE(std::isfinite(c.xyz.X) && std::isfinite(c.xyz.Y) && std::isfinite(c.xyz.Z))
                        << f.name << " " << renderer_film_model_name(m);
                    EXPECT_GE(c.rgb_linear.r, 0.0);
                }
            }
        }
    }
}

}  // namespace
}  // namespace irid
