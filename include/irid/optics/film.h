#pragma once

// One film abstraction over every film model of irid: the exact optics of a stack (Airy for one
// layer, the transfer matrix for more), the thesis' single film (eq. 21–24), the thesis'
// multilayer (eq. 25–26) and the Morpho wing (eq. 25 with eq. 29, optionally blended). Each
// model implements FilmModel; the command line (`irid film`, `irid film-table`), the renderer,
// the figures and the Python module all go through it, so a model added here reaches all four.
//
// Every constructor checks its parameters and throws irid::Error naming the parameter and the
// allowed range. Angles are in radians in the ambient, in [0, π/2); thicknesses in nm.
//
// "The varied thickness" is the one a table or a thickness sweep replaces: the first layer's
// (exact), the film's (thesis), a period's (thesis multilayer). The Morpho wing has none: its
// thicknesses are d₁ and d₂, and the tables report eq. 29's effective thickness instead.

#include <irid/optics/film_color.h>
#include <irid/optics/material.h>
#include <irid/optics/multilayer.h>
#include <irid/optics/thesis_models.h>
#include <irid/optics/work_limits.h>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

enum class FilmModelKind { exact, thesis, thesis_multilayer, morpho };

/// "exact", "thesis", "thesis-multilayer", "morpho".
[[nodiscard]] std::string_view film_model_name(FilmModelKind kind) noexcept;
/// The model of a name above; throws UnknownNameError listing them.
[[nodiscard]] FilmModelKind parse_film_model(std::string_view name);

/// A reflectance spectrum on the 1 nm grid, 360–830 nm.
using DenseValues = std::array<double, dense_sample_count>;

/// A film at one angle of incidence, prepared for evaluation at any varied thickness: what does
/// not depend on the thickness (Fresnel amplitudes, phases per nm, effective-thickness factors)
/// is computed once. What a colour-table row and a renderer's ray hit need.
class FilmAtAngle {
public:
    virtual ~FilmAtAngle() = default;
    /// The reflectance on the 1 nm grid at a varied thickness (finite, >= 0).
    virtual void reflectance(double thickness_nm, DenseValues& out) const = 0;
    /// The colour at a varied thickness (finite, >= 0); the default sums reflectance().
    [[nodiscard]] virtual FilmColor color(double thickness_nm, const Colorimeter& colorimeter) const;
    /// The same for one colour: where color() is a 1 nm sum that aliases (aliases()), summed as
    /// finely as the film needs (refined_film_xyz, up to about 65 times color()'s work).
    [[nodiscard]] virtual FilmColor exact_color(double thickness_nm, const Colorimeter& colorimeter) const {
        return color(thickness_nm, colorimeter);
    }
    /// color() at this thickness is a 1 nm sum that aliases (fine_sum.h, aliases_on_the_grid).
    [[nodiscard]] virtual bool aliases(double /*thickness_nm*/) const noexcept { return false; }
};

/// How check_work names the factors a model adds, in its messages: the caller's names (a
/// command line's options, a Python function's parameters).
struct FilmWorkNames {
    std::string layers = "layers";
    std::string blend = "the blend";
};

/// The interface every film model implements.
class FilmModel {
public:
    virtual ~FilmModel() = default;
    [[nodiscard]] virtual FilmModelKind kind() const noexcept = 0;
    [[nodiscard]] std::string_view name() const noexcept { return film_model_name(kind()); }
    /// Whether spectrum() computes a transmittance (the exact optics: the power entering the
    /// substrate); the thesis' closed forms give the reflectance alone and T = 0.
    [[nodiscard]] virtual bool has_transmittance() const noexcept { return false; }
    /// Whether the model has a varied thickness (every model but the Morpho wing).
    [[nodiscard]] virtual bool has_thickness() const noexcept { return true; }
    /// The varied thickness as built [nm] (0 for the Morpho wing).
    [[nodiscard]] virtual double thickness_nm() const noexcept = 0;

    /// R (and T) as a function of the wavelength [nm, > 0] at an angle, with the varied
    /// thickness replaced when given; what does not depend on the wavelength is built once,
    /// here. Throws irid::Error for an angle outside [0, π/2) or a thickness that is not finite
    /// and >= 0.
    [[nodiscard]] virtual std::function<Optics(double)> spectrum(
        double angle_rad, std::optional<double> thickness_nm = std::nullopt) const = 0;
    /// The film at an angle, for the 1 nm grid at any thickness. Throws as spectrum().
    [[nodiscard]] virtual std::unique_ptr<FilmAtAngle> at_angle(double angle_rad) const = 0;
    /// The colour (1 nm summation over 360–830 nm) at an angle and varied thickness.
    [[nodiscard]] FilmColor color(const Colorimeter& colorimeter, double angle_rad,
                                  std::optional<double> thickness_nm = std::nullopt) const;
    /// Eq. 29's effective thickness t_θ at an angle for the Morpho wing; nothing for the others.
    [[nodiscard]] virtual std::optional<double> effective_thickness_nm(double /*angle_rad*/) const {
        return std::nullopt;
    }

    /// Checks the work of a request against the library's limits (film_color.h) before anything
    /// is computed: colours (one spectrum on the 1 nm grid each) for the product of `spectra`,
    /// or, with `at_wavelengths`, spectrum() at the product of `spectra` (the wavelengths). The
    /// model adds what each wavelength costs (layers, a blend's samples). Throws irid::Error
    /// naming the factors, the total and the limit.
    virtual void check_work(std::vector<WorkFactor> spectra, bool at_wavelengths,
                            const FilmWorkNames& names = {}) const;
};

/// Exact optics of ambient | layers | substrate (multilayer.h): Fresnel amplitudes, every
/// internal reflection, dispersion and absorption. One unpolarised layer evaluates by the Airy
/// sum prepared per angle (PreparedFilm), anything else by the transfer matrix.
class ExactFilm final : public FilmModel {
public:
    /// Throws irid::Error for an absorbing ambient, no layers, or a thickness that is not finite
    /// and in [0, 1e6] nm.
    ExactFilm(Material ambient, std::vector<Layer> layers, Material substrate,
              Polarization polarization = Polarization::unpolarized);
    [[nodiscard]] FilmModelKind kind() const noexcept override { return FilmModelKind::exact; }
    [[nodiscard]] bool has_transmittance() const noexcept override { return true; }
    [[nodiscard]] double thickness_nm() const noexcept override { return m_layers.front().thickness_nm; }
    [[nodiscard]] std::function<Optics(double)> spectrum(
        double angle_rad, std::optional<double> thickness_nm = std::nullopt) const override;
    [[nodiscard]] std::unique_ptr<FilmAtAngle> at_angle(double angle_rad) const override;
    void check_work(std::vector<WorkFactor> spectra, bool at_wavelengths,
                    const FilmWorkNames& names = {}) const override;

    [[nodiscard]] const Material& ambient() const noexcept { return m_ambient; }
    [[nodiscard]] const Material& substrate() const noexcept { return m_substrate; }
    [[nodiscard]] const std::vector<Layer>& layers() const noexcept { return m_layers; }
    [[nodiscard]] Polarization polarization() const noexcept { return m_polarization; }
    /// One unpolarised layer: the prepared Airy path.
    [[nodiscard]] bool is_airy() const noexcept;

private:
    [[nodiscard]] FilmStack stack(std::optional<double> thickness_nm) const;
    Material m_ambient, m_substrate;
    std::vector<Layer> m_layers;
    Polarization m_polarization;
};

/// The thesis' single film (Smits 1990, eq. 21/22 with eq. 23/24; thesis_single_film_reflectance).
class ThesisFilm final : public FilmModel {
public:
    /// K defaults to thesis_matched_k (the exact film's maxima; K = 1 is the thesis as written);
    /// the phase case to eq. 19's rule per wavelength. Throws irid::Error for an absorbing
    /// ambient, film or substrate (check_thesis_material), a bad thickness or K <= 0.
    ThesisFilm(SingleFilm film, double thickness_nm, std::optional<double> k = std::nullopt,
               std::optional<bool> phase_change = std::nullopt);
    [[nodiscard]] FilmModelKind kind() const noexcept override { return FilmModelKind::thesis; }
    [[nodiscard]] double thickness_nm() const noexcept override { return m_thickness_nm; }
    [[nodiscard]] std::function<Optics(double)> spectrum(
        double angle_rad, std::optional<double> thickness_nm = std::nullopt) const override;
    [[nodiscard]] std::unique_ptr<FilmAtAngle> at_angle(double angle_rad) const override;

    [[nodiscard]] const SingleFilm& film() const noexcept { return m_film; }
    [[nodiscard]] double k() const noexcept { return m_k; }
    [[nodiscard]] std::optional<bool> phase_change() const noexcept { return m_phase_change; }

private:
    SingleFilm m_film;
    double m_thickness_nm, m_k;
    std::optional<bool> m_phase_change;
};

/// The thesis' multilayer (Smits 1990, eq. 25 with eq. 26): `periods` equal films in air.
class ThesisMultilayerFilm final : public FilmModel {
public:
    /// K defaults to thesis_unit_peak_k(periods) (peak 1; K = 1 is the thesis as written).
    /// Throws irid::Error for an absorbing film, an index below 1 at 555 nm (eq. 26 assumes air
    /// around), periods outside thesis_min_periods..thesis_max_periods (check_thesis_periods), a
    /// bad thickness or K <= 0.
    ThesisMultilayerFilm(Material film, double thickness_nm, int periods,
                         std::optional<double> k = std::nullopt);
    [[nodiscard]] FilmModelKind kind() const noexcept override { return FilmModelKind::thesis_multilayer; }
    [[nodiscard]] double thickness_nm() const noexcept override { return m_thickness_nm; }
    [[nodiscard]] std::function<Optics(double)> spectrum(
        double angle_rad, std::optional<double> thickness_nm = std::nullopt) const override;
    [[nodiscard]] std::unique_ptr<FilmAtAngle> at_angle(double angle_rad) const override;

    [[nodiscard]] const Material& film() const noexcept { return m_film; }
    [[nodiscard]] int periods() const noexcept { return m_periods; }
    [[nodiscard]] double k() const noexcept { return m_k; }

private:
    Material m_film;
    double m_thickness_nm;
    int m_periods;
    double m_k;
};

/// The thesis' Morpho wing (Smits 1990, eq. 25 with eq. 29), optionally blended over mullion
/// thicknesses (§3.7). The wing's K is used as given (thesis_unit_peak_k for a peak of 1).
class MorphoFilm final : public FilmModel {
public:
    /// Throws irid::Error unless validate_morpho and validate_morpho_blend accept the parameters.
    explicit MorphoFilm(MorphoParameters wing, std::optional<MorphoBlend> blend = std::nullopt);
    [[nodiscard]] FilmModelKind kind() const noexcept override { return FilmModelKind::morpho; }
    [[nodiscard]] bool has_thickness() const noexcept override { return false; }
    [[nodiscard]] double thickness_nm() const noexcept override { return 0.0; }
    /// The thickness argument is ignored (the wing has no varied thickness).
    [[nodiscard]] std::function<Optics(double)> spectrum(
        double angle_rad, std::optional<double> thickness_nm = std::nullopt) const override;
    [[nodiscard]] std::unique_ptr<FilmAtAngle> at_angle(double angle_rad) const override;
    [[nodiscard]] std::optional<double> effective_thickness_nm(double angle_rad) const override;
    void check_work(std::vector<WorkFactor> spectra, bool at_wavelengths,
                    const FilmWorkNames& names = {}) const override;

    [[nodiscard]] const MorphoParameters& wing() const noexcept { return m_wing; }
    [[nodiscard]] const std::optional<MorphoBlend>& blend() const noexcept { return m_blend; }

private:
    MorphoParameters m_wing;
    std::optional<MorphoBlend> m_blend;
};

/// Throws irid::Error unless a varied thickness is finite and in [0, 1e6] nm (1 mm); `what`
/// names it in the message.
void check_film_thickness(double thickness_nm, std::string_view what = "thickness");

}  // namespace irid
