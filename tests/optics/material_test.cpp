#include <irid/error.h>
#include <irid/optics/material.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace irid {
namespace {

/// The message of the irid::Error that f throws, or "" when it throws none.
template <class F>
std::string error_message(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return {};
}

const Material& named(const char* name) {
    const Material* m = find_material(name);
    if (m == nullptr) throw std::runtime_error(std::string("no material ") + name);
    return *m;
}

Material from_csv_text(const std::string& text) {
    std::istringstream in(text);
    return Material::read_csv(in, "test.csv", "test");
}

TEST(Material, ConstantIndexIsTheSameAtEveryWavelength) {
    const Material m = Material::constant("glass", 1.5, 0.02);
    for (const double lambda : {300.0, 360.0, 555.0, 830.0, 2000.0}) {
        EXPECT_EQ(m.index(lambda), Complex(1.5, 0.02));
    }
    EXPECT_FALSE(m.is_lossless());
    EXPECT_TRUE(Material::constant("glass", 1.5).is_lossless());
}

TEST(Material, CauchyReproducesItsFormulaWithLambdaInMicrometres) {
    const double a = 1.45, b = 0.0035, c = 0.0002;
    const Material m = Material::cauchy("test", a, b, c);
    for (const double lambda_nm : {360.0, 486.1, 587.6, 656.3, 830.0}) {
        const double l = lambda_nm / 1000.0;
        const double expected = a + b / (l * l) + c / (l * l * l * l);
        EXPECT_NEAR(m.index(lambda_nm).real(), expected, 1e-15) << lambda_nm;
        EXPECT_EQ(m.index(lambda_nm).imag(), 0.0);
    }
}

TEST(Material, SellmeierReproducesItsFormulaWithLambdaInMicrometres) {
    const Material m = Material::sellmeier("test", {{1.0, 0.01}, {0.5, 100.0}});
    for (const double lambda_nm : {360.0, 500.0, 830.0}) {
        const double l2 = (lambda_nm / 1000.0) * (lambda_nm / 1000.0);
        const double n2 = 1.0 + 1.0 * l2 / (l2 - 0.01) + 0.5 * l2 / (l2 - 100.0);
        EXPECT_NEAR(m.index(lambda_nm).real(), std::sqrt(n2), 1e-15) << lambda_nm;
        EXPECT_EQ(m.index(lambda_nm).imag(), 0.0);
    }
}

TEST(Material, SellmeierBeyondAResonanceIsEvanescentNotNan) {
    // n² = 1 + 2 λ²/(λ² - 0.04) is negative just below the resonance at 200 nm:
    // at 190 nm, λ² = 0.0361 µm², n² = 1 + 2 × 0.0361 / (-0.0039) < 0, so N = i sqrt(-n²).
    const Material m = Material::sellmeier("uv-resonance", {{2.0, 0.04}});
    const double l2 = 0.19 * 0.19;
    const double n2 = 1.0 + 2.0 * l2 / (l2 - 0.04);
    ASSERT_LT(n2, 0.0);
    EXPECT_NEAR(m.index(190.0).real(), 0.0, 1e-15);
    EXPECT_NEAR(m.index(190.0).imag(), std::sqrt(-n2), 1e-12);
}

TEST(Material, TabulatedIndexIsLinearBetweenSamplesAndHeldBeyondThem) {
    const Material m = Material::tabulated("test", {{400.0, 1.0, 2.0}, {500.0, 2.0, 4.0}});
    EXPECT_EQ(m.index(400.0), Complex(1.0, 2.0));
    EXPECT_EQ(m.index(500.0), Complex(2.0, 4.0));
    EXPECT_NEAR(m.index(425.0).real(), 1.25, 1e-15);
    EXPECT_NEAR(m.index(425.0).imag(), 2.5, 1e-15);
    EXPECT_EQ(m.index(300.0), Complex(1.0, 2.0));
    EXPECT_EQ(m.index(900.0), Complex(2.0, 4.0));
    EXPECT_FALSE(m.is_lossless());
    EXPECT_TRUE(Material::tabulated("clear", {{400.0, 1.5, 0.0}}).is_lossless());
}

TEST(Material, FactoriesRejectUnphysicalParametersNamingThem) {
    EXPECT_NE(error_message([] { (void)Material::constant("x", 0.0); }).find("n 0 must be"),
              std::string::npos);
    EXPECT_NE(error_message([] { (void)Material::constant("x", 1.5, -0.1); }).find("k -0.1"),
              std::string::npos);
    EXPECT_THROW((void)Material::constant("x", std::nan("")), Error);
    EXPECT_THROW((void)Material::constant("x", 1.5, std::numeric_limits<double>::infinity()),
                 Error);
    // Cauchy n = 1 - 0.2/λ² is negative below 447 nm.
    EXPECT_NE(error_message([] { (void)Material::cauchy("x", 1.0, -0.2); }).find("at 360 nm"),
              std::string::npos);
    EXPECT_THROW((void)Material::cauchy("x", 1.5, std::nan("")), Error);
    // A resonance at 500 nm, inside the visible range.
    EXPECT_NE(error_message([] {
                  (void)Material::sellmeier("x", {{1.0, 0.25}});
              }).find("500 nm"),
              std::string::npos);
    EXPECT_THROW((void)Material::sellmeier("x", {}), Error);
    EXPECT_THROW((void)Material::sellmeier("x", {{1.0, -0.01}}), Error);
    // Poles outside the visible range but n² = 1 - 2 λ²/(λ² - 0.01) < 0 across it.
    EXPECT_THROW((void)Material::sellmeier("x", {{-2.0, 0.01}}), Error);
    EXPECT_THROW((void)Material::tabulated("x", {}), Error);
    EXPECT_THROW((void)Material::tabulated("x", {{500.0, 1.0, 0.0}, {500.0, 1.1, 0.0}}), Error);
    EXPECT_THROW((void)Material::tabulated("x", {{-1.0, 1.0, 0.0}}), Error);
    EXPECT_NE(error_message([] {
                  (void)Material::tabulated("x", {{400.0, 1.0, 0.0}, {500.0, 1.0, -1.0}});
              }).find("sample 2"),
              std::string::npos);
}

TEST(MaterialCsv, LoadsWavelengthNAndKAfterAHeader) {
    const Material m = from_csv_text("wavelength_nm,n,k\n400,0.5,3\n600,0.7,4\n");
    EXPECT_EQ(m.name(), "test");
    EXPECT_NEAR(m.index(500.0).real(), 0.6, 1e-15);
    EXPECT_NEAR(m.index(500.0).imag(), 3.5, 1e-15);
}

TEST(MaterialCsv, ErrorsNameTheFileAndLine) {
    const auto message = [](const std::string& text) {
        return error_message([&] { (void)from_csv_text(text); });
    };
    EXPECT_NE(message("wavelength_nm,n,k\n400,1.5,0\n500,1.5,-0.1\n").find("test.csv:3"),
              std::string::npos);
    EXPECT_NE(message("wavelength_nm,n,k\n400,1.5,0\n500,0,0\n").find("test.csv:3"),
              std::string::npos);
    EXPECT_NE(message("wavelength_nm,n,k\n500,1.5,0\n400,1.5,0\n").find("test.csv:3"),
              std::string::npos);
    EXPECT_NE(message("wavelength_nm,n,k\n400,1.5\n").find("test.csv:2"), std::string::npos);
    EXPECT_NE(message("wavelength_nm,n,k\n400,abc,0\n").find("test.csv:2"), std::string::npos);
    EXPECT_NE(message("wavelength_nm,n,k\n").find("test.csv"), std::string::npos);
    EXPECT_NE(error_message([] {
                  (void)Material::read_csv(std::string("/no/such/file.csv"));
              }).find("/no/such/file.csv"),
              std::string::npos);
}

TEST(MaterialCsv, EmbeddedMetalTablesEqualTheirCsvSources) {
    for (const char* metal : {"silver", "gold"}) {
        const std::string path = std::string(IRID_DATA_DIR) + "/materials/" + metal + ".csv";
        const Material from_file = Material::read_csv(path);
        EXPECT_EQ(from_file.name(), metal);
        std::ifstream in(path);
        std::string line;
        std::getline(in, line);  // header
        int rows = 0;
        while (std::getline(in, line)) {
            const double lambda = std::stod(line.substr(0, line.find(',')));
            EXPECT_EQ(named(metal).index(lambda), from_file.index(lambda)) << metal << " " << line;
            // Midway between samples too: the same samples give the same interpolation.
            EXPECT_EQ(named(metal).index(lambda + 0.5), from_file.index(lambda + 0.5));
            ++rows;
        }
        EXPECT_EQ(rows, 49) << metal;
    }
}

// --- Named materials against their published values ------------------------------------------

TEST(NamedMaterials, FusedSilicaMatchesMalitsonAtTheFraunhoferLines) {
    // Malitson 1965: n_d = 1.4585 at the helium d line, 587.56 nm; the Abbe number
    // V_d = (n_d - 1)/(n_F - n_C) = 67.8 with F = 486.13 nm, C = 656.27 nm.
    const Material& silica = named("fused-silica");
    const double nd = silica.index(587.56).real();
    const double nf = silica.index(486.13).real();
    const double nc = silica.index(656.27).real();
    EXPECT_NEAR(nd, 1.4585, 1e-4);
    EXPECT_NEAR((nd - 1.0) / (nf - nc), 67.8, 0.1);
    EXPECT_TRUE(silica.is_lossless());
}

TEST(NamedMaterials, WaterAt20CMatchesTheTabulatedSodiumDIndex) {
    // n_D(20 °C) = 1.333 (International Tables for Crystallography C, Table 3.3.2.1). Daimon &
    // Masumura's index is relative to vacuum; the tabulated one relative to air, lower by
    // 1.333 × 2.8e-4 = 3.7e-4, hence the tolerance.
    EXPECT_NEAR(named("water").index(589.3).real(), 1.333, 5e-4);
    // Relative to air it is 1.3330 within the 4-digit rounding.
    EXPECT_NEAR(named("water").index(589.3).real() / named("air").index(589.3).real(), 1.3330,
                1e-4);
    // Normal dispersion: higher in the blue.
    EXPECT_GT(named("water").index(400.0).real(), named("water").index(700.0).real());
}

TEST(NamedMaterials, SoapFilmIsWater) {
    for (const double lambda : {380.0, 550.0, 780.0}) {
        EXPECT_EQ(named("soap-film").index(lambda), named("water").index(lambda));
    }
}

TEST(NamedMaterials, ChitinMatchesLeertouwerMeasurements) {
    // Leertouwer, Wilts & Stavenga 2011: measured 1.572, 1.552, 1.541 at 400, 500, 600 nm.
    EXPECT_NEAR(named("chitin").index(400.0).real(), 1.572, 1e-3);
    EXPECT_NEAR(named("chitin").index(500.0).real(), 1.552, 1e-3);
    EXPECT_NEAR(named("chitin").index(600.0).real(), 1.541, 1e-3);
}

TEST(NamedMaterials, AirIsCiddorStandardAirAtTheSodiumDLine) {
    // Ciddor 1996 eq. 1, σ = 1/λ in µm⁻¹.
    const double sigma2 = 1.0 / (0.5893 * 0.5893);
    const double n_minus_1 =
        (5792105.0 / (238.0185 - sigma2) + 167917.0 / (57.362 - sigma2)) * 1e-8;
    EXPECT_NEAR(named("air").index(589.3).real(), 1.0 + n_minus_1, 1e-7);
    EXPECT_TRUE(named("air").is_lossless());
}

TEST(NamedMaterials, MineralOilIsNujolAtTheSodiumDLine) {
    // International Tables for Crystallography C, Table 3.3.2.1: petroleum oil (Nujol) 1.477.
    EXPECT_NEAR(named("mineral-oil").index(589.3).real(), 1.477, 1e-12);
    EXPECT_TRUE(named("mineral-oil").is_lossless());
}

TEST(NamedMaterials, SilverAndGoldAreJohnsonChristyMetals) {
    // Johnson & Christy 1972 at 1.91 eV (λ = hc/E = 659.5 nm): Ag 0.05 + 4.483i, Au 0.14 + 3.697i.
    EXPECT_NEAR(named("silver").index(659.5).real(), 0.05, 1e-12);
    EXPECT_NEAR(named("silver").index(659.5).imag(), 4.483, 1e-12);
    EXPECT_NEAR(named("gold").index(659.5).real(), 0.14, 1e-12);
    EXPECT_NEAR(named("gold").index(659.5).imag(), 3.697, 1e-12);
    EXPECT_FALSE(named("silver").is_lossless());
    // Metals reflect strongly: k > n across the visible range.
    for (int lambda = 360; lambda <= 830; lambda += 10) {
        EXPECT_GT(named("silver").index(lambda).imag(), named("silver").index(lambda).real());
    }
}

TEST(NamedMaterials, NamesAreListedSortedAndUnknownNamesAreNull) {
    const std::vector<std::string> names = material_names();
    EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
    for (const char* required :
         {"air", "water", "soap-film", "mineral-oil", "chitin", "fused-silica", "silver", "gold"}) {
        EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
        EXPECT_NE(find_material(required), nullptr) << required;
        EXPECT_EQ(find_material(required)->name(), required);
    }
    EXPECT_EQ(find_material("unobtainium"), nullptr);
    EXPECT_EQ(find_material("WATER"), find_material("water"));
}

// --- parse_material ------------------------------------------------------------------------

TEST(ParseMaterial, AcceptsRealAndComplexIndicesAndNames) {
    EXPECT_EQ(parse_material("1.33").index(500.0), Complex(1.33, 0.0));
    EXPECT_EQ(parse_material(" 1.5+0.02i ").index(500.0), Complex(1.5, 0.02));
    EXPECT_EQ(parse_material("2e0+1e-1i").index(500.0), Complex(2.0, 0.1));
    EXPECT_EQ(parse_material("1.5+0i").index(500.0), Complex(1.5, 0.0));
    EXPECT_EQ(parse_material("water").index(589.3), named("water").index(589.3));
    EXPECT_EQ(parse_material("silver").name(), "silver");
    EXPECT_EQ(parse_material("Fused-Silica").name(), "fused-silica");
}

TEST(ParseMaterial, RejectsNegativeKAsGain) {
    const std::string message = error_message([] { (void)parse_material("1.5-0.02i"); });
    EXPECT_NE(message.find("k -0.02"), std::string::npos) << message;
    EXPECT_NE(message.find(">= 0"), std::string::npos) << message;
}

TEST(ParseMaterial, RejectsNonPositiveOrNonFiniteIndices) {
    for (const char* text : {"0", "-1.33", "nan", "inf", "1.5+nani"}) {
        EXPECT_THROW((void)parse_material(text), Error) << text;
    }
}

TEST(ParseMaterial, UnknownTextListsTheAcceptedFormsAndNames) {
    for (const char* text :
         {"unobtainium", "", "1.5+0.02", "1.5+i", "1.5+-0.1i", "1.5 + 0.1i", "1.5+0.1j", "+1.5"}) {
        const std::string message = error_message([&] { (void)parse_material(text); });
        EXPECT_NE(message.find("1.5+0.02i"), std::string::npos) << text << ": " << message;
        EXPECT_NE(message.find("fused-silica"), std::string::npos) << text << ": " << message;
        EXPECT_NE(message.find("mineral-oil"), std::string::npos) << text << ": " << message;
    }
}

}  // namespace
}  // namespace irid
