// What a request for film colours or spectra may ask for: the work limits on the product of its
// parameters, the thesis' physical K defaults and the refusal of absorbing media by the thesis'
// closed forms.
#include <irid/error.h>
#include <irid/optics/film_color.h>
#include <irid/optics/film_error_study.h>
#include <irid/optics/multilayer.h>
#include <irid/optics/work_limits.h>
#include <irid/optics/thesis_models.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace irid {
namespace {

constexpr double pi = std::numbers::pi;

/// The message of the irid::Error that f throws ("" and a failure when it throws none).
std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no irid::Error";
    return "";
}

void expect_has(const std::string& message, const std::string& part) {
    EXPECT_NE(message.find(part), std::string::npos)
        << "'" << message << "' lacks '" << part << "'";
}

// --- the work limits ---------------------------------------------------------------------------

TEST(WorkLimit, AcceptsAProductUpToTheLimitAndRefusesOneMore) {
    const std::vector<WorkFactor> at{{"a", 1000.0}, {"b", 500.0}};
    EXPECT_NO_THROW(check_work_limit(at, 2.0, 1e6, "things", "ask less"));
    const std::vector<WorkFactor> beyond{{"a", 1001.0}, {"b", 500.0}};
    const std::string m =
        error_of([&] { check_work_limit(beyond, 2.0, 1e6, "things", "ask less"); });
    // The factors as named, their counts, the total in the unit and the limit in the same unit:
    // 10⁶ / 2 = 500 000 things.
    expect_has(m, "a (1 001 values) × b (500 values)");
    expect_has(m, "asks for 500 500 things");
    expect_has(m, "the limit is 500 000 (ask less)");
}

TEST(WorkLimit, EachFactorInRangeDoesNotMakeTheProductInRange) {
    // 10⁵ thicknesses and 10⁴ angles are each accepted by their own options; 10⁹ spectra are not.
    const std::vector<WorkFactor> one{{"--thickness", 1e5}};
    EXPECT_NO_THROW(check_color_work(one));
    const std::vector<WorkFactor> both{{"--thickness", 1e5}, {"--angles", 1e4}};
    EXPECT_THROW(check_color_work(both), Error);
}

TEST(WorkLimit, ProductsBeyondDoublePrecisionAndBadCountsAreRefused) {
    const std::vector<WorkFactor> huge{{"x", 1e200}, {"y", 1e200}};  // the product overflows to ∞
    EXPECT_THROW(check_spectrum_work(huge), Error);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const double bad : {-1.0, nan, std::numeric_limits<double>::infinity()}) {
        const std::vector<WorkFactor> f{{"--wavelengths", bad}};
        expect_has(error_of([&] { check_spectrum_work(f); }), "--wavelengths");
    }
    const std::vector<WorkFactor> none;
    EXPECT_THROW(check_work_limit(none, 0.0, 1.0, "things", ""), Error);
}

TEST(WorkLimit, ColourWorkIsTheEvaluationBudgetOverThe1nmGrid) {
    // Each colour is one spectrum of 471 wavelengths (360-830 nm at 1 nm), each a closed form.
    ASSERT_EQ(dense_sample_count, 471);
    const double spectra = std::floor(max_film_evaluations / 471.0);
    const std::vector<WorkFactor> at{{"--thickness", spectra}};
    EXPECT_NO_THROW(check_color_work(at));
    const std::vector<WorkFactor> beyond{{"--thickness", spectra + 1.0}};
    const std::string m = error_of([&] { check_color_work(beyond); });
    expect_has(m, "spectra");
    expect_has(m, "use coarser steps");
    // A Morpho blend of 101 samples costs 101 closed forms a wavelength: 101 times fewer spectra.
    const WorkFactor blend{"--blend", 101.0, "samples"};
    const double blended = std::floor(max_film_evaluations / (471.0 * 101.0));
    const std::vector<WorkFactor> blend_at{{"--angles", blended}};
    EXPECT_NO_THROW(check_color_work(blend_at, blend));
    const std::vector<WorkFactor> blend_beyond{{"--angles", blended + 1.0}};
    const std::string mb = error_of([&] { check_color_work(blend_beyond, blend); });
    expect_has(mb, "with --blend (101 samples per wavelength)");
}

TEST(WorkLimit, StacksAndOutputLinesHaveTheirOwnLimits) {
    const std::vector<WorkFactor> stack_at{{"--wavelengths", 2e5}, {"--layer", 1000.0, "layers"}};
    EXPECT_NO_THROW(check_stack_work(stack_at));
    const std::vector<WorkFactor> stack_beyond{{"--wavelengths", 200001.0},
                                               {"--layer", 1000.0, "layers"}};
    const std::string m = error_of([&] { check_stack_work(stack_beyond); });
    expect_has(m, "--layer (1 000 layers)");
    expect_has(m, "asks for 200 001 000 layer evaluations");
    // The same product of closed forms is far within its budget: the transfer matrix is dearer.
    EXPECT_NO_THROW(check_spectrum_work(stack_beyond));
    const std::vector<WorkFactor> lines_at{{"--thickness", 1e5}, {"--angles", 10.0}};
    EXPECT_NO_THROW(check_output_rows(lines_at));
    const std::vector<WorkFactor> lines_beyond{{"--thickness", 1e6 + 1.0}, {"--angles", 9.0}};
    expect_has(error_of([&] { check_output_rows(lines_beyond); }), "asks for 9 000 009 lines");
}

TEST(WorkLimit, LimitsAllowTheDocumentedRuns) {
    // `irid film-table --layer mineral-oil --substrate water --thickness 0:1500:2 --angles 0:80:2`
    // (docs/OPTICS.md): 751 × 41 lines and spectra.
    const std::vector<WorkFactor> table{{"--thickness", 751.0}, {"--angles", 41.0}};
    EXPECT_NO_THROW(check_output_rows(table));
    EXPECT_NO_THROW(check_color_work(table));
    // `irid film-error` (both films, 0:1500:5 × 0:80:5).
    EXPECT_NO_THROW(validate_error_study(ErrorStudyOptions{}, 2.0));
}

// --- the error study's request -----------------------------------------------------------------

TEST(ErrorStudyRequest, CountsTheGridAsTheStudySamplesIt) {
    const ErrorStudyOptions o;  // 0:1500:5 × 0:80:5
    EXPECT_EQ(error_study_thickness_count(o), 301.0);
    EXPECT_EQ(error_study_angle_count(o), 17.0);
    const Colorimeter c;
    const SingleFilm soap{*find_material("air"), *find_material("water"), *find_material("air")};
    // 601 angles by repeated steps of 0.1°, which accumulate rounding.
    const ErrorStudyOptions small{100.0, 10.0, 60.0, 0.1, std::nullopt};
    const ErrorStudyResult r = thesis_error_study("soap", soap, c, small);
    EXPECT_EQ(static_cast<double>(r.samples),
              error_study_thickness_count(small) * error_study_angle_count(small));
}

TEST(ErrorStudyRequest, RefusesAGridOfInRangeValuesWhoseProductIsTooLargeNamingBoth) {
    // Each grid is in its range (≤ 10⁵ thicknesses, ≤ 10⁴ angles); 890 100 000 samples are not.
    const ErrorStudyOptions o{99999.0, 1.0, 89.0, 0.01, std::nullopt};
    const std::string m = error_of(
        [&] { validate_error_study(o, 1.0, "--thickness 0:99999:1", "--angles 0:89:0.01"); });
    expect_has(m, "--thickness 0:99999:1 (100 000 values)");
    expect_has(m, "--angles 0:89:0.01 (8 901 values)");
    expect_has(m, "asks for 1 780 200 000 spectra");  // two spectra a sample
    // The study itself refuses it before computing anything (this test would otherwise run for
    // about half an hour).
    const Colorimeter c;
    const SingleFilm soap{*find_material("air"), *find_material("water"), *find_material("air")};
    EXPECT_THROW((void)thesis_error_study("soap", soap, c, o), Error);
    // Two films double the work.
    // 1501 × 401 samples: 1 203 802 spectra for one film, 2 407 604 for two.
    const ErrorStudyOptions half{1500.0, 1.0, 80.0, 0.2, std::nullopt};
    EXPECT_NO_THROW(validate_error_study(half, 1.0));
    EXPECT_THROW(validate_error_study(half, 2.0), Error);
}

TEST(ErrorStudyRequest, RefusesInvalidOptions) {
    const double inf = std::numeric_limits<double>::infinity();
    for (const ErrorStudyOptions& o : {ErrorStudyOptions{1500.0, 0.0, 80.0, 5.0, std::nullopt},
                                       ErrorStudyOptions{inf, 5.0, 80.0, 5.0, std::nullopt},
                                       ErrorStudyOptions{1500.0, 5.0, 90.0, 5.0, std::nullopt},
                                       ErrorStudyOptions{1500.0, 5.0, 80.0, 5.0, -1.0}}) {
        EXPECT_THROW(validate_error_study(o), Error);
    }
}

// --- the thesis' K -------------------------------------------------------------------------------

TEST(ThesisK, UnitPeakKMakesEquation25PeakAtOne) {
    for (const int l : {0, 1, 5, 12, 100}) {
        const double k = thesis_unit_peak_k(l);
        EXPECT_NEAR(k, 2.0 / ((l + 1.0) * (l + 1.0)), 1e-17) << l;
        // At the pole 2t = λ all l + 1 beams are in phase: ½K(l+1)² = 1.
        EXPECT_NEAR(thesis_multilayer_reflectance(500.0, 250.0, l, k), 1.0, 1e-12) << l;
        // Everywhere else below: a sweep over a period and a half of t.
        double peak = 0.0;
        for (int i = 0; i <= 30000; ++i) {
            peak = std::max(peak, thesis_multilayer_reflectance(500.0, 375.0 * i / 30000.0, l, k));
        }
        EXPECT_LE(peak, 1.0 + 1e-12) << l;
        EXPECT_GT(peak, 1.0 - 1e-6) << l;
    }
    // The Morpho wing of the thesis (twelve mullions): the README's 0.0118.
    EXPECT_NEAR(thesis_unit_peak_k(12), 0.0118, 5e-5);
    const MorphoParameters wing{150.0, 50.0, 1.56, 12, thesis_unit_peak_k(12)};
    const double t = morpho_effective_thickness_nm(wing, 0.0);
    EXPECT_NEAR(morpho_reflectance(wing, 2.0 * t, 0.0), 1.0, 1e-12);
}

TEST(ThesisK, MatchedKGivesTheExactFilmsPeakAtNormalIncidence) {
    // Airy: R = (r01² + r12² + 2 r01 r12 cos φ) / (1 + r01² r12² + 2 r01 r12 cos φ) grows with
    // r01 r12 cos φ, so the exact film's brightest is ((|r01| + |r12|) / (1 + |r01 r12|))², where
    // cos φ = sign(r01 r12): a quarter wave (soap, oil on water) or a half wave (a coating between
    // air and glass). The thesis' two-beam peak K² with K matched is that peak without the
    // multiple reflections, the factor (1 + |r01 r12|)², at the same thickness.
    struct Case {
        double n0, n1, n2;
    };
    const double lambda = 555.0;
    for (const Case& c : {Case{1.0, 1.33, 1.0}, Case{1.0, 1.477, 1.333}, Case{1.0, 1.38, 1.52}}) {
        const SingleFilm film{Material::constant("ambient", c.n0), Material::constant("film", c.n1),
                              Material::constant("substrate", c.n2)};
        const double r01 = (c.n0 - c.n1) / (c.n0 + c.n1);
        const double r12 = (c.n1 - c.n2) / (c.n1 + c.n2);
        const double quarter = lambda / (4.0 * c.n1);
        const double t_peak = r01 * r12 < 0.0 ? quarter : 2.0 * quarter;
        const FilmStack stack(film.ambient, {Layer{film.film, t_peak}}, film.substrate);
        const double exact_peak = stack.evaluate(lambda, 0.0, Polarization::unpolarized).R;
        const double k = thesis_matched_k(film, lambda);
        const double cross = std::abs(r01 * r12);
        EXPECT_NEAR(k * k / ((1.0 + cross) * (1.0 + cross)), exact_peak, 1e-12) << c.n1;
        // It is the exact peak: no thickness reflects more.
        for (int i = 0; i <= 2000; ++i) {
            const FilmStack s(film.ambient, {Layer{film.film, 4.0 * quarter * i / 2000.0}},
                              film.substrate);
            EXPECT_LE(s.evaluate(lambda, 0.0, Polarization::unpolarized).R, exact_peak + 1e-12);
        }
        // The thesis' film with that K peaks at the same thickness, at K².
        const double thesis =
            thesis_single_film_reflectance(film, t_peak, lambda, 0.0, k, std::nullopt);
        EXPECT_NEAR(thesis, k * k, 1e-12) << c.n1;
    }
}

// --- absorbing media ------------------------------------------------------------------------

TEST(ThesisMaterials, AbsorbingFilmsAndSubstratesAreRefusedNamingTheRole) {
    const Material air = *find_material("air");
    const Material water = *find_material("water");
    EXPECT_NO_THROW(check_thesis_single_film({air, water, air}));
    EXPECT_NO_THROW(check_thesis_single_film({air, *find_material("mineral-oil"), water}));
    const std::string silver = error_of([&] {
        check_thesis_single_film({air, *find_material("silver"), air});
    });
    expect_has(silver, "film 'silver'");
    expect_has(silver, "absorbing");
    const std::string lossy = error_of([&] {
        check_thesis_single_film({air, Material::constant("lossy", 1.5, 0.5), air});
    });
    expect_has(lossy, "film 'lossy'");
    const std::string gold = error_of([&] {
        check_thesis_single_film({air, water, *find_material("gold")});
    });
    expect_has(gold, "substrate 'gold'");
    expect_has(error_of([&] { check_thesis_material(*find_material("silver"), "mullion"); }),
               "mullion");
}

}  // namespace
}  // namespace irid
