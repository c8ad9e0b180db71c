#pragma once

#include <complex>
#include <istream>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace irid {

/// A complex number: refractive indices, amplitudes, admittances.
using Complex = std::complex<double>;

// Sign convention: optical constants are written N = n + ik with k >= 0 for an absorbing medium.
// With irid's time dependence exp(-iωt) a plane wave exp(i(2π N z / λ - ωt)) then decays as
// exp(-2π k z / λ), the convention of Born & Wolf, Principles of Optics, 7th ed., ch. 14 (optics
// of metals, n̂ = n(1 + iκ)). k < 0 would be a medium with gain and is rejected everywhere.

/// One Sellmeier term B λ² / (λ² - C): B dimensionless, C [µm²], the square of the term's
/// resonance wavelength in µm (Malitson 1965 lists the wavelengths, Daimon & Masumura 2007 C).
struct SellmeierTerm {
    double b;
    double c_um2;
};

/// Measured optical constants at one wavelength.
struct IndexSample {
    double wavelength_nm;
    double n;
    double k;
};

/// A medium: a name and a dispersion model giving N(λ) = n(λ) + i k(λ).
///
/// Built only by the factory functions, which validate the parameters once (throwing irid::Error
/// naming the parameter and its allowed range): n > 0 and k >= 0, finite, at every wavelength of
/// the visible range 360-830 nm. index() then evaluates without checks. Outside 360-830 nm the
/// formulas are evaluated as written (a Sellmeier n² < 0 beyond a resonance gives a purely
/// imaginary index, n = 0, k > 0) and tables hold their end values.
class Material {
public:
    /// A wavelength-independent index n + ik. Requires n > 0, k >= 0, both finite.
    [[nodiscard]] static Material constant(std::string name, double n, double k = 0.0);

    /// Cauchy's formula n(λ) = A + B/λ² + C/λ⁴ with λ in µm (B in µm², C in µm⁴), k = 0
    /// (A.-L. Cauchy, Mémoire sur la dispersion de la lumière, 1836).
    /// Requires finite coefficients and n > 0 over 360-830 nm.
    [[nodiscard]] static Material cauchy(std::string name, double a, double b_um2,
                                         double c_um4 = 0.0);

    /// Sellmeier's formula n²(λ) = 1 + Σ B_i λ² / (λ² - C_i), λ in µm, C_i in µm², k = 0
    /// (W. Sellmeier 1871, in the form I. H. Malitson fits, J. Opt. Soc. Am. 55, 1205, 1965).
    /// Requires at least one term, finite B_i and finite C_i >= 0 whose poles sqrt(C_i) lie
    /// outside the visible range 360-830 nm, and n² > 0 over that range.
    [[nodiscard]] static Material sellmeier(std::string name, std::vector<SellmeierTerm> terms);

    /// Measured n and k, linear in wavelength between samples and held beyond the first and last
    /// (the rule CIE 015:2018 §7.2.2 gives for measured spectra). Requires at least one sample,
    /// finite strictly increasing positive wavelengths, n > 0 and k >= 0 finite.
    [[nodiscard]] static Material tabulated(std::string name, std::vector<IndexSample> samples);

    /// Reads tabulated optical constants from CSV lines `wavelength_nm,n,k` (a non-numeric first
    /// line is a header and is skipped). Throws irid::Error "<source>:<line>: <what>" for a bad
    /// line, including a value out of range.
    [[nodiscard]] static Material read_csv(std::istream& in, std::string_view source,
                                           std::string name);
    /// As above from a file; the material is named after the file's stem ("silver" for
    /// data/materials/silver.csv) unless a name is given.
    [[nodiscard]] static Material read_csv(const std::string& path, std::string name = {});

    /// The complex index N = n + ik at a vacuum wavelength [nm] (lambda_nm > 0).
    [[nodiscard]] Complex index(double lambda_nm) const noexcept;

    [[nodiscard]] const std::string& name() const noexcept { return m_name; }

    /// True when k = 0 at every wavelength: always for the Cauchy and Sellmeier models (validated
    /// to be real over the visible range), for constant and tabulated data when every k is 0.
    [[nodiscard]] bool is_lossless() const noexcept;
    /// True when N does not depend on the wavelength: a constant index, a Cauchy formula with
    /// B = C = 0, a Sellmeier formula each of whose terms has B = 0 or C = 0, a table whose
    /// samples all hold the same n and k.
    [[nodiscard]] bool is_constant() const noexcept;

private:
    struct Constant {
        Complex index;
    };
    struct Cauchy {
        double a;
        double b_um2;
        double c_um4;
    };
    struct Sellmeier {
        std::vector<SellmeierTerm> terms;
    };
    struct Tabulated {
        std::vector<IndexSample> samples;
    };
    using Model = std::variant<Constant, Cauchy, Sellmeier, Tabulated>;

    Material(std::string name, Model model) : m_name(std::move(name)), m_model(std::move(model)) {}

    std::string m_name;
    Model m_model;
};

/// The named materials, each with its published source (see material.cpp and
/// data/materials/README.md): air, chitin, fused-silica, gold, mineral-oil, silver, soap-film
/// (water), water; case-insensitive. nullptr for any other name.
[[nodiscard]] const Material* find_material(std::string_view name) noexcept;

/// Names accepted by find_material, sorted.
[[nodiscard]] std::vector<std::string> material_names();

/// A material as the command line writes it: a real index ("1.33"), a complex index n+ki
/// ("1.5+0.02i", k >= 0 absorbing), or a name from material_names(). Spaces around the text are
/// ignored. Throws irid::Error naming the text, listing the accepted forms and the names.
[[nodiscard]] Material parse_material(std::string_view text);

}  // namespace irid
