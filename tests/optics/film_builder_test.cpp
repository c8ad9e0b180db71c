// The film builder: which parameters each of the thesis' and the exact models takes (Smits 1990,
// ch. 3: eq. 21/22 for one film between any media; eq. 25/26 for equal films in air; eq. 25/29 for
// the Morpho wing, whose geometry is d1, d2 and n, not layers), the defaults of the ones left out,
// and messages in the caller's names.
#include <irid/error.h>
#include <irid/optics/film_builder.h>

#include <gtest/gtest.h>

#include <string>

namespace irid {
namespace {

FilmSpec one_layer(FilmModelKind model, double thickness = 300.0) {
    FilmSpec s;
    s.model = model;
    s.layers.push_back({Material::constant("film", 1.33), thickness});
    return s;
}

std::string message_of(const FilmSpec& spec, const FilmSpecNames& names = {}) {
    try {
        (void)build_film(spec, names);
    } catch (const Error& e) {
        return e.what();
    }
    return "(built)";
}

TEST(FilmBuilder, EachModelRefusesWhatItDoesNotTake) {
    // The exact model has no K, periods, phase-change switch or wing.
    FilmSpec s = one_layer(FilmModelKind::exact);
    s.k = 2.0;
    EXPECT_EQ(message_of(s, command_line_film_names()), "--K does not apply to --model exact");
    EXPECT_EQ(message_of(s), "k does not apply to model exact");
    s = one_layer(FilmModelKind::exact);
    s.periods = 3;
    EXPECT_NE(message_of(s).find("periods does not apply"), std::string::npos);
    // The thesis' single film has no polarisation (eq. 21/22 are unpolarised intensities).
    s = one_layer(FilmModelKind::thesis);
    s.polarization = Polarization::s;
    EXPECT_EQ(message_of(s), "polarization does not apply to model thesis");
    // Eq. 26 assumes air around the films: no ambient or substrate.
    s = one_layer(FilmModelKind::thesis_multilayer);
    s.periods = 3;
    s.substrate = Material::constant("glass", 1.5);
    EXPECT_EQ(message_of(s), "substrate does not apply to model thesis-multilayer");
    // The wing's geometry is d1, d2 and n: no layers.
    s = one_layer(FilmModelKind::morpho);
    EXPECT_EQ(message_of(s, command_line_film_names()), "--layer does not apply to --model morpho");
    s = one_layer(FilmModelKind::exact);
    s.blend_varies = MorphoBlendThickness::d2;
    EXPECT_EQ(message_of(s, command_line_film_names()), "--blend-vary does not apply to --model exact");
    FilmSpec wing;
    wing.model = FilmModelKind::morpho;
    wing.blend_varies = MorphoBlendThickness::d2;
    EXPECT_EQ(message_of(wing, command_line_film_names()), "--blend-vary needs --blend");
    wing.blend_varies.reset();
    wing.blend_samples = 5;
    EXPECT_NE(message_of(wing).find("need blend"), std::string::npos);
}

TEST(FilmBuilder, LayerCountsAndRequiredParameters) {
    FilmSpec s;
    EXPECT_NE(message_of(s).find("layers is required"), std::string::npos);
    s = one_layer(FilmModelKind::thesis);
    s.layers.push_back({Material::constant("b", 1.5), 10.0});
    EXPECT_EQ(message_of(s), "model thesis takes exactly 1 layers, found 2");
    s = one_layer(FilmModelKind::thesis_multilayer);
    EXPECT_EQ(message_of(s), "periods is required with model thesis-multilayer");
    // Where a table varies the thickness, the exact model takes exactly one layer and no
    // thickness is needed; otherwise every layer needs its own.
    s = one_layer(FilmModelKind::exact);
    s.layers.front().thickness_nm.reset();
    EXPECT_EQ(message_of(s), "layers[0]: the thickness is required");
    s.thickness_required = false;
    EXPECT_EQ(message_of(s), "(built)");
    s.layers.push_back({Material::constant("b", 1.5), std::nullopt});
    EXPECT_NE(message_of(s).find("takes exactly 1"), std::string::npos);
}

TEST(FilmBuilder, ValuesOutOfRangeInTheCallersNames) {
    FilmSpec s = one_layer(FilmModelKind::thesis_multilayer);
    s.periods = 0;
    EXPECT_EQ(message_of(s, command_line_film_names()).rfind("--periods 0 must be in 1..1000000", 0), 0u);
    FilmSpec wing;
    wing.model = FilmModelKind::morpho;
    wing.periods = -1;
    EXPECT_EQ(message_of(wing).rfind("periods -1 must be in 1..1000000", 0), 0u);
    wing.periods.reset();
    wing.d1_nm = -5.0;
    EXPECT_EQ(message_of(wing, command_line_film_names()), "--d1 -5 must be a thickness in [0, 1e6] nm");
    wing.d1_nm.reset();
    wing.n = 0.5;
    EXPECT_NE(message_of(wing).find("n 0.5 must be >= 1"), std::string::npos);
    s = one_layer(FilmModelKind::thesis);
    s.k = 0.0;
    EXPECT_EQ(message_of(s), "k 0 must be a finite number > 0");
    s = one_layer(FilmModelKind::exact);
    s.ambient = Material::constant("ink", 1.5, 0.1);
    EXPECT_EQ(message_of(s), "ambient 'ink' absorbs (k > 0); the ambient must have k = 0");
    // The thesis' closed forms take real indices only.
    s = one_layer(FilmModelKind::thesis);
    s.substrate = Material::constant("metal", 0.2, 3.0);
    EXPECT_NE(message_of(s).find("use model exact"), std::string::npos);
}

TEST(FilmBuilder, DefaultsOfWhatIsLeftOut) {
    // The wing of Figure 9: d1 150 nm, d2 50 nm, n 1.56, 12 periods, K for a peak of 1.
    FilmSpec wing;
    wing.model = FilmModelKind::morpho;
    const auto built = std::dynamic_pointer_cast<MorphoFilm>(build_film(wing));
    ASSERT_TRUE(built);
    EXPECT_EQ(built->wing().d1_nm, 150.0);
    EXPECT_EQ(built->wing().d2_nm, 50.0);
    EXPECT_EQ(built->wing().n, 1.56);
    EXPECT_EQ(built->wing().periods, 12);
    EXPECT_DOUBLE_EQ(built->wing().K, 2.0 / (13.0 * 13.0));
    EXPECT_FALSE(built->blend().has_value());
    wing.blend = true;
    const auto blended = std::dynamic_pointer_cast<MorphoFilm>(build_film(wing));
    ASSERT_TRUE(blended && blended->blend());
    EXPECT_EQ(blended->blend()->varies, MorphoBlendThickness::d1);
    // The exact film: air on both sides, unpolarised.
    const auto exact = std::dynamic_pointer_cast<ExactFilm>(build_film(one_layer(FilmModelKind::exact)));
    ASSERT_TRUE(exact);
    EXPECT_EQ(exact->polarization(), Polarization::unpolarized);
    EXPECT_EQ(exact->ambient().index(550.0), find_material("air")->index(550.0));
    EXPECT_EQ(exact->substrate().index(550.0), find_material("air")->index(550.0));
    // The thesis' film: K matched to the exact film's maxima unless given.
    const auto thesis = std::dynamic_pointer_cast<ThesisFilm>(build_film(one_layer(FilmModelKind::thesis)));
    ASSERT_TRUE(thesis);
    EXPECT_DOUBLE_EQ(thesis->k(), thesis_matched_k(thesis->film()));
    FilmSpec given = one_layer(FilmModelKind::thesis);
    given.k = 1.0;
    EXPECT_EQ(std::dynamic_pointer_cast<ThesisFilm>(build_film(given))->k(), 1.0);
}

}  // namespace
}  // namespace irid
