#include <irid/color/numeric_table.h>
#include <irid/color/spectrum.h>
#include <irid/error.h>
#include <irid/optics/material.h>
#include <irid/text_input.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <functional>
#include <optional>
#include <system_error>
#include <utility>

namespace irid {
namespace {

// --- Published data of the named materials -----------------------------------------------------

/// Standard air (dry, 15 °C, 101.325 kPa, 450 ppm CO2) at the sodium D line, 589.3 nm
/// [dimensionless]: P. E. Ciddor, "Refractive index of air: new equations for the visible and
/// near infrared", Appl. Opt. 35, 1566-1573 (1996), eq. 1,
/// (n - 1) 10⁸ = 5792105 / (238.0185 - σ²) + 167917 / (57.362 - σ²), σ = 1/λ [µm⁻¹].
/// Its change over 360-830 nm (+8e-6 to -2e-6 about this value) is neglected: no film colour
/// shows it.
inline constexpr double air_index = 1.0002771;

/// Distilled water at 20.0 °C: M. Daimon and A. Masumura, "Measurement of the refractive index of
/// distilled water from the near-infrared region to the ultraviolet region", Appl. Opt. 46,
/// 3811-3820 (2007), their four-term Sellmeier fit for 20.0 °C (B dimensionless, C [µm²]);
/// valid 182-1129 nm.
inline constexpr std::array<SellmeierTerm, 4> water_20c_sellmeier = {{
    {5.684027565e-1, 5.101829712e-3},
    {1.726177391e-1, 1.821153936e-2},
    {2.086189578e-2, 2.620722293e-2},
    {1.130748688e-1, 1.069792721e1},
}};

/// Fused silica at 20 °C: I. H. Malitson, "Interspecimen comparison of the refractive index of
/// fused silica", J. Opt. Soc. Am. 55, 1205-1208 (1965), three-term Sellmeier fit, resonance
/// wavelengths 0.0684043, 0.1162414 and 9.896161 µm (C = their squares [µm²]); valid 0.21-3.71 µm.
inline constexpr std::array<SellmeierTerm, 3> fused_silica_sellmeier = {{
    {0.6961663, 0.0684043 * 0.0684043},
    {0.4079426, 0.1162414 * 0.1162414},
    {0.8974794, 9.896161 * 9.896161},
}};

/// Butterfly wing-scale chitin: H. L. Leertouwer, B. D. Wilts and D. G. Stavenga, "Refractive
/// index and dispersion of butterfly chitin and bird keratin measured by polarizing interference
/// microscopy", Opt. Express 19, 24061-24066 (2011): Cauchy n = A + B/λ², A = 1.517
/// [dimensionless], B = 8.80e3 nm² = 8.80e-3 µm² (n = 1.572, 1.552, 1.541 at 400, 500, 600 nm).
/// Vukusic et al. 1999 (Proc. R. Soc. B 266, 1403) model Morpho cuticle with n = 1.56, inside
/// this curve's range.
inline constexpr double chitin_cauchy_a = 1.517;
inline constexpr double chitin_cauchy_b_um2 = 8.80e-3;

/// Mineral oil (liquid paraffin, "Nujol") at 20 °C and the sodium D line [dimensionless]:
/// E. S. Larsen Jr, R. Meyrowitz and A. J. C. Wilson, International Tables for Crystallography
/// Vol. C (2006), Table 3.3.2.1, "petroleum oil (Nujol) 1.477", dispersion listed as slight.
inline constexpr double mineral_oil_index = 1.477;

/// Silver: P. B. Johnson and R. W. Christy, "Optical constants of the noble metals", Phys. Rev.
/// B 6, 4370-4379 (1972), n and k measured at 49 photon energies 0.64-6.60 eV; wavelengths
/// λ = hc/E [nm] as the refractiveindex.info database (CC0) lists them (main/Ag/Johnson.yml).
/// The same numbers are in data/materials/silver.csv.
inline constexpr std::array<IndexSample, 49> silver_johnson_christy = {{
    {187.9, 1.07, 1.212},  {191.6, 1.10, 1.232},  {195.3, 1.12, 1.255},  {199.3, 1.14, 1.277},
    {203.3, 1.15, 1.296},  {207.3, 1.18, 1.312},  {211.9, 1.20, 1.325},  {216.4, 1.22, 1.336},
    {221.4, 1.25, 1.342},  {226.2, 1.26, 1.344},  {231.3, 1.28, 1.357},  {237.1, 1.28, 1.367},
    {242.6, 1.30, 1.378},  {249.0, 1.31, 1.389},  {255.1, 1.33, 1.393},  {261.6, 1.35, 1.387},
    {268.9, 1.38, 1.372},  {276.1, 1.41, 1.331},  {284.4, 1.41, 1.264},  {292.4, 1.39, 1.161},
    {300.9, 1.34, 0.964},  {310.7, 1.13, 0.616},  {320.4, 0.81, 0.392},  {331.5, 0.17, 0.829},
    {342.5, 0.14, 1.142},  {354.2, 0.10, 1.419},  {367.9, 0.07, 1.657},  {381.5, 0.05, 1.864},
    {397.4, 0.05, 2.070},  {413.3, 0.05, 2.275},  {430.5, 0.04, 2.462},  {450.9, 0.04, 2.657},
    {471.4, 0.05, 2.869},  {495.9, 0.05, 3.093},  {520.9, 0.05, 3.324},  {548.6, 0.06, 3.586},
    {582.1, 0.05, 3.858},  {616.8, 0.06, 4.152},  {659.5, 0.05, 4.483},  {704.5, 0.04, 4.838},
    {756.0, 0.03, 5.242},  {821.1, 0.04, 5.727},  {892.0, 0.04, 6.312},  {984.0, 0.04, 6.992},
    {1088.0, 0.04, 7.795}, {1216.0, 0.09, 8.828}, {1393.0, 0.13, 10.10}, {1610.0, 0.15, 11.85},
    {1937.0, 0.24, 14.08},
}};

/// Gold: Johnson and Christy 1972 as for silver (refractiveindex.info main/Au/Johnson.yml); the
/// same numbers are in data/materials/gold.csv.
inline constexpr std::array<IndexSample, 49> gold_johnson_christy = {{
    {187.9, 1.28, 1.188},  {191.6, 1.32, 1.203},  {195.3, 1.34, 1.226},  {199.3, 1.33, 1.251},
    {203.3, 1.33, 1.277},  {207.3, 1.30, 1.304},  {211.9, 1.30, 1.350},  {216.4, 1.30, 1.387},
    {221.4, 1.30, 1.427},  {226.2, 1.31, 1.460},  {231.3, 1.30, 1.497},  {237.1, 1.32, 1.536},
    {242.6, 1.32, 1.577},  {249.0, 1.33, 1.631},  {255.1, 1.33, 1.688},  {261.6, 1.35, 1.749},
    {268.9, 1.38, 1.803},  {276.1, 1.43, 1.847},  {284.4, 1.47, 1.869},  {292.4, 1.49, 1.878},
    {300.9, 1.53, 1.889},  {310.7, 1.53, 1.893},  {320.4, 1.54, 1.898},  {331.5, 1.48, 1.883},
    {342.5, 1.48, 1.871},  {354.2, 1.50, 1.866},  {367.9, 1.48, 1.895},  {381.5, 1.46, 1.933},
    {397.4, 1.47, 1.952},  {413.3, 1.46, 1.958},  {430.5, 1.45, 1.948},  {450.9, 1.38, 1.914},
    {471.4, 1.31, 1.849},  {495.9, 1.04, 1.833},  {520.9, 0.62, 2.081},  {548.6, 0.43, 2.455},
    {582.1, 0.29, 2.863},  {616.8, 0.21, 3.272},  {659.5, 0.14, 3.697},  {704.5, 0.13, 4.103},
    {756.0, 0.14, 4.542},  {821.1, 0.16, 5.083},  {892.0, 0.17, 5.663},  {984.0, 0.22, 6.350},
    {1088.0, 0.27, 7.150}, {1216.0, 0.35, 8.145}, {1393.0, 0.43, 9.519}, {1610.0, 0.56, 11.21},
    {1937.0, 0.92, 13.78},
}};

/// Nanometres per micrometre: the dispersion formulas take λ in µm.
inline constexpr double nm_per_um = 1000.0;

// --- Validation ------------------------------------------------------------------------------

std::string material_label(std::string_view name) {
    return "material '" + std::string(name) + "'";
}

/// Throws unless n > 0 and k >= 0, both finite. `where` names the material, sample or line.
/// Bounds that keep every product in the optics finite in double precision (N² and N⁴ of the
/// p admittances): far beyond any material (n of optical materials lies in about 0.05-5, k of
/// metals below about 20 in the visible).
inline constexpr double min_index_n = 1e-6;
inline constexpr double max_index_n = 1e6;
inline constexpr double max_index_k = 1e6;

void check_index(const std::string& where, double n, double k) {
    if (!std::isfinite(n) || !(n >= min_index_n && n <= max_index_n)) {
        throw Error(where + ": refractive index n " + format_shortest(n) +
                    " must be > 0 and in [1e-6, 1e6]");
    }
    if (!std::isfinite(k) || !(k >= 0.0 && k <= max_index_k)) {
        throw Error(where + ": extinction coefficient k " + format_shortest(k) +
                    " must be >= 0 and <= 1e6 (N = n + ik, k > 0 absorbs)");
    }
}

/// Throws unless value_at(λ) > 0 at every whole nanometre of the visible range: the check that a
/// dispersion formula gives a real, positive n (or n²) where irid uses it.
template <class F>
void check_positive_over_visible(const std::string& where, const char* what, F value_at) {
    for (int lambda = lambda_min_nm; lambda <= lambda_max_nm; ++lambda) {
        const double v = value_at(static_cast<double>(lambda));
        if (!std::isfinite(v) || !(v > 0.0)) {
            throw Error(where + ": " + what + " at " + std::to_string(lambda) + " nm is " +
                        format_shortest(v) + "; it must be finite and > 0 over " +
                        std::to_string(lambda_min_nm) + "-" + std::to_string(lambda_max_nm) +
                        " nm");
        }
    }
}

/// Checks tabulated samples; where(i) names sample i (a material and index, or a file and line).
void check_samples(const std::vector<IndexSample>& samples,
                   const std::function<std::string(std::size_t)>& where) {
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const IndexSample& s = samples[i];
        if (!std::isfinite(s.wavelength_nm) || !(s.wavelength_nm > 0.0)) {
            throw Error(where(i) + ": wavelength " + format_shortest(s.wavelength_nm) +
                        " nm must be finite and > 0");
        }
        if (i > 0 && !(s.wavelength_nm > samples[i - 1].wavelength_nm)) {
            throw Error(where(i) + ": wavelength " + format_shortest(s.wavelength_nm) +
                        " nm must be greater than the previous one, " +
                        format_shortest(samples[i - 1].wavelength_nm) + " nm");
        }
        check_index(where(i), s.n, s.k);
    }
}

// --- Dispersion formulas ---------------------------------------------------------------------

/// Cauchy: n = A + B/λ² + C/λ⁴, λ in µm (Cauchy 1836).
double cauchy_n(double a, double b_um2, double c_um4, double lambda_nm) noexcept {
    const double inv_l2 = 1.0 / ((lambda_nm / nm_per_um) * (lambda_nm / nm_per_um));
    return a + inv_l2 * (b_um2 + inv_l2 * c_um4);
}

/// Sellmeier: n² = 1 + Σ B_i λ² / (λ² - C_i), λ in µm, C_i in µm² (Sellmeier 1871).
double sellmeier_n2(const std::vector<SellmeierTerm>& terms, double lambda_nm) noexcept {
    const double l2 = (lambda_nm / nm_per_um) * (lambda_nm / nm_per_um);
    double n2 = 1.0;
    for (const SellmeierTerm& t : terms) n2 += t.b * l2 / (l2 - t.c_um2);
    return n2;
}

/// Linear interpolation of n and k in wavelength, ends held.
Complex interpolate(const std::vector<IndexSample>& samples, double lambda_nm) noexcept {
    const auto upper =
        std::upper_bound(samples.begin(), samples.end(), lambda_nm,
                         [](double l, const IndexSample& s) { return l < s.wavelength_nm; });
    if (upper == samples.begin()) return {samples.front().n, samples.front().k};
    if (upper == samples.end()) return {samples.back().n, samples.back().k};
    const IndexSample& a = *(upper - 1);
    const IndexSample& b = *upper;
    const double f = (lambda_nm - a.wavelength_nm) / (b.wavelength_nm - a.wavelength_nm);
    return {a.n + f * (b.n - a.n), a.k + f * (b.k - a.k)};
}

template <class... Fs>
struct Overloaded : Fs... {
    using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

// --- Parsing "1.33", "1.5+0.02i" ------------------------------------------------------------

std::string_view trim(std::string_view s) noexcept {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\r\n");
    return s.substr(first, last - first + 1);
}

/// Reads a number at the front of s and removes it; nullopt when s does not start with one.
std::optional<double> take_number(std::string_view& s) noexcept {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec != std::errc() || end == s.data()) return std::nullopt;
    s.remove_prefix(static_cast<std::size_t>(end - s.data()));
    return value;
}

/// "n" or "n+ki" / "n-ki" as (n, k); nullopt for any other text.
std::optional<std::pair<double, double>> parse_index_text(std::string_view s) noexcept {
    const std::optional<double> n = take_number(s);
    if (!n) return std::nullopt;
    if (s.empty()) return std::pair{*n, 0.0};
    const double sign = s.front() == '+' ? 1.0 : s.front() == '-' ? -1.0 : 0.0;
    s.remove_prefix(1);
    if (sign == 0.0 || s.empty() || s.front() == '+' || s.front() == '-') return std::nullopt;
    const std::optional<double> k = take_number(s);
    if (!k || s != "i") return std::nullopt;
    return std::pair{*n, sign * *k};
}

char ascii_lower(char c) noexcept {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

/// Names compare case-insensitively, as illuminant names do.
bool same_name(std::string_view a, std::string_view b) noexcept {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](char x, char y) { return ascii_lower(x) == ascii_lower(y); });
}

std::string joined_names() {
    std::string out;
    for (const std::string& name : material_names()) out += (out.empty() ? "" : ", ") + name;
    return out;
}

// --- The named materials ---------------------------------------------------------------------

std::vector<Material> make_named_materials() {
    const std::vector<SellmeierTerm> water(water_20c_sellmeier.begin(), water_20c_sellmeier.end());
    std::vector<Material> m;
    m.push_back(Material::constant("air", air_index));
    m.push_back(Material::cauchy("chitin", chitin_cauchy_a, chitin_cauchy_b_um2));
    m.push_back(Material::sellmeier(
        "fused-silica", {fused_silica_sellmeier.begin(), fused_silica_sellmeier.end()}));
    m.push_back(
        Material::tabulated("gold", {gold_johnson_christy.begin(), gold_johnson_christy.end()}));
    m.push_back(Material::constant("mineral-oil", mineral_oil_index));
    m.push_back(Material::tabulated(
        "silver", {silver_johnson_christy.begin(), silver_johnson_christy.end()}));
    // A soap film is modelled as water: its surfactant is a small fraction of it.
    m.push_back(Material::sellmeier("soap-film", water));
    m.push_back(Material::sellmeier("water", water));
    return m;
}

const std::vector<Material>& named_materials() {
    static const std::vector<Material> materials = make_named_materials();
    return materials;
}

}  // namespace

Material Material::constant(std::string name, double n, double k) {
    check_index(material_label(name), n, k);
    return Material(std::move(name), Constant{Complex(n, k)});
}

Material Material::cauchy(std::string name, double a, double b_um2, double c_um4) {
    const std::string where = material_label(name);
    if (!std::isfinite(a) || !std::isfinite(b_um2) || !std::isfinite(c_um4)) {
        throw Error(where + ": Cauchy coefficients A " + format_shortest(a) + ", B " +
                    format_shortest(b_um2) + " um^2, C " + format_shortest(c_um4) +
                    " um^4 must be finite");
    }
    check_positive_over_visible(
        where, "Cauchy n", [&](double lambda_nm) { return cauchy_n(a, b_um2, c_um4, lambda_nm); });
    return Material(std::move(name), Cauchy{a, b_um2, c_um4});
}

Material Material::sellmeier(std::string name, std::vector<SellmeierTerm> terms) {
    const std::string where = material_label(name);
    if (terms.empty()) throw Error(where + ": a Sellmeier formula needs at least one term");
    for (std::size_t i = 0; i < terms.size(); ++i) {
        const SellmeierTerm& t = terms[i];
        const std::string term = where + ": Sellmeier term " + std::to_string(i + 1);
        if (!std::isfinite(t.b) || !std::isfinite(t.c_um2) || !(t.c_um2 >= 0.0)) {
            throw Error(term + ": B " + format_shortest(t.b) + " must be finite and C " +
                        format_shortest(t.c_um2) + " um^2 finite and >= 0");
        }
        const double pole_nm = std::sqrt(t.c_um2) * nm_per_um;
        if (pole_nm >= lambda_min_nm && pole_nm <= lambda_max_nm) {
            throw Error(term + ": its pole sqrt(C) = " + format_shortest(pole_nm) +
                        " nm must lie outside the visible range " + std::to_string(lambda_min_nm) +
                        "-" + std::to_string(lambda_max_nm) + " nm");
        }
    }
    check_positive_over_visible(where, "Sellmeier n^2",
                                [&](double lambda_nm) { return sellmeier_n2(terms, lambda_nm); });
    return Material(std::move(name), Sellmeier{std::move(terms)});
}

Material Material::tabulated(std::string name, std::vector<IndexSample> samples) {
    const std::string where = material_label(name);
    if (samples.empty()) throw Error(where + ": a table needs at least one sample");
    check_samples(samples,
                  [&](std::size_t i) { return where + " sample " + std::to_string(i + 1); });
    return Material(std::move(name), Tabulated{std::move(samples)});
}

Material Material::read_csv(std::istream& in, std::string_view source, std::string name) {
    const NumericTable table = read_numeric_table(in, source, 3);
    if (table.empty()) {
        throw Error(std::string(source) + ": no data; expected lines wavelength_nm,n,k");
    }
    std::vector<IndexSample> samples;
    samples.reserve(table.rows());
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const std::span<const double> row = table.row(r);
        samples.push_back({row[0], row[1], row[2]});
    }
    check_samples(samples, [&](std::size_t i) {
        return std::string(source) + ":" + std::to_string(table.line_numbers[i]);
    });
    return Material(std::move(name), Tabulated{std::move(samples)});
}

Material Material::read_csv(const std::string& path, std::string name) {
    std::istringstream in(read_text_file(path, "material table (wavelength_nm,n,k)",
                                         StreamInput::accept));
    if (name.empty()) name = std::filesystem::path(path).stem().string();
    return read_csv(in, path, std::move(name));
}

Complex Material::index(double lambda_nm) const noexcept {
    return std::visit(
        Overloaded{
            [](const Constant& c) { return c.index; },
            [&](const Cauchy& c) { return Complex(cauchy_n(c.a, c.b_um2, c.c_um4, lambda_nm)); },
            // The complex root keeps n² < 0 (beyond a resonance, outside the validated range)
            // physical: N = i sqrt(-n²), k > 0, an evanescent wave.
            [&](const Sellmeier& s) {
                return std::sqrt(Complex(sellmeier_n2(s.terms, lambda_nm), 0.0));
            },
            [&](const Tabulated& t) { return interpolate(t.samples, lambda_nm); },
        },
        m_model);
}

bool Material::is_constant() const noexcept {
    return std::visit(Overloaded{
                          [](const Constant&) { return true; },
                          [](const Cauchy& c) { return c.b_um2 == 0.0 && c.c_um4 == 0.0; },
                          [](const Sellmeier& m) {
                              return std::all_of(m.terms.begin(), m.terms.end(), [](const SellmeierTerm& t) {
                                  return t.b == 0.0 || t.c_um2 == 0.0;
                              });
                          },
                          [](const Tabulated& t) {
                              return std::all_of(t.samples.begin(), t.samples.end(), [&](const IndexSample& s) {
                                  return s.n == t.samples.front().n && s.k == t.samples.front().k;
                              });
                          },
                      },
                      m_model);
}

bool Material::is_lossless() const noexcept {
    return std::visit(Overloaded{
                          [](const Constant& c) { return c.index.imag() == 0.0; },
                          [](const Cauchy&) { return true; },
                          [](const Sellmeier&) { return true; },
                          [](const Tabulated& t) {
                              return std::all_of(t.samples.begin(), t.samples.end(),
                                                 [](const IndexSample& s) { return s.k == 0.0; });
                          },
                      },
                      m_model);
}

const Material* find_material(std::string_view name) noexcept {
    for (const Material& m : named_materials()) {
        if (same_name(m.name(), name)) return &m;
    }
    return nullptr;
}

std::vector<std::string> material_names() {
    std::vector<std::string> names;
    for (const Material& m : named_materials()) names.push_back(m.name());
    std::sort(names.begin(), names.end());
    return names;
}

Material parse_material(std::string_view text) {
    const std::string_view t = trim(text);
    if (const Material* named = find_material(t)) return *named;
    const std::optional<std::pair<double, double>> nk = parse_index_text(t);
    if (!nk) {
        throw Error(material_label(t) +
                    " is neither an index nor a known material; write a real index (1.33), a "
                    "complex index n+ki with k >= 0 (1.5+0.02i), or one of: " +
                    joined_names());
    }
    return Material::constant(std::string(t), nk->first, nk->second);
}

}  // namespace irid
