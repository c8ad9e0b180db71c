#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/optics/film.h>

#include <cmath>
#include <string>

namespace irid {
namespace {

constexpr std::array<std::string_view, 4> model_names{"exact", "thesis", "thesis-multilayer", "morpho"};

void check_k(double k) {
    if (!(std::isfinite(k) && k > 0.0)) {
        throw Error("K " + format_shortest(k) + " must be a finite number > 0");
    }
}

double real_index(const Material& m, double lambda_nm) { return m.index(lambda_nm).real(); }

/// The colour of a reflectance on the 1 nm grid.
FilmColor color_of(const DenseValues& r, const Colorimeter& colorimeter) noexcept {
    const Xyz xyz = colorimeter.xyz_of(
        [&](double lambda) { return r[static_cast<std::size_t>(std::lround(lambda - lambda_min_nm))]; });
    return {xyz, colorimeter.linear_rgb(xyz)};
}

/// Any model at an angle through a function of (wavelength, thickness) built once per angle.
template <class F>
class FunctionAtAngle final : public FilmAtAngle {
public:
    explicit FunctionAtAngle(F f) : m_f(std::move(f)) {}
    void reflectance(double thickness_nm, DenseValues& out) const override {
        for (int i = 0; i < dense_sample_count; ++i) {
            out[static_cast<std::size_t>(i)] = m_f(DenseSpectrum::wavelength_nm(i), thickness_nm);
        }
    }
    [[nodiscard]] FilmColor color(double thickness_nm, const Colorimeter& colorimeter) const override {
        const Xyz xyz = colorimeter.xyz_of([&](double lambda) { return m_f(lambda, thickness_nm); });
        return {xyz, colorimeter.linear_rgb(xyz)};
    }

private:
    F m_f;
};

template <class F>
std::unique_ptr<FilmAtAngle> function_at_angle(F f) {
    return std::make_unique<FunctionAtAngle<F>>(std::move(f));
}

class AiryAtAngle final : public FilmAtAngle {
public:
    AiryAtAngle(const SingleFilm& film, double angle_rad) : m_prepared(film, angle_rad) {}
    void reflectance(double thickness_nm, DenseValues& out) const override {
        for (int i = 0; i < dense_sample_count; ++i) out[static_cast<std::size_t>(i)] = m_prepared.reflectance(i, thickness_nm);
    }
    [[nodiscard]] FilmColor color(double thickness_nm, const Colorimeter& colorimeter) const override {
        return m_prepared.color(thickness_nm, colorimeter);
    }
    [[nodiscard]] FilmColor exact_color(double thickness_nm, const Colorimeter& colorimeter) const override {
        return m_prepared.refined_color(thickness_nm, colorimeter);
    }
    [[nodiscard]] bool aliases(double thickness_nm) const noexcept override { return m_prepared.aliases(thickness_nm); }

private:
    PreparedFilm m_prepared;
};

/// The transfer matrix at an angle: the stack is built once per thickness.
class StackAtAngle final : public FilmAtAngle {
public:
    StackAtAngle(const ExactFilm& film, double angle_rad)
        : m_ambient(film.ambient()), m_substrate(film.substrate()), m_layers(film.layers()),
          m_angle_rad(angle_rad), m_polarization(film.polarization()) {}
    void reflectance(double thickness_nm, DenseValues& out) const override {
        std::vector<Layer> layers = m_layers;
        layers.front().thickness_nm = thickness_nm;
        const FilmStack stack(m_ambient, std::move(layers), m_substrate);
        for (int i = 0; i < dense_sample_count; ++i) {
            out[static_cast<std::size_t>(i)] =
                stack.evaluate(DenseSpectrum::wavelength_nm(i), m_angle_rad, m_polarization).R;
        }
    }

private:
    Material m_ambient, m_substrate;
    std::vector<Layer> m_layers;
    double m_angle_rad;
    Polarization m_polarization;
};

}  // namespace

std::string_view film_model_name(FilmModelKind kind) noexcept {
    return model_names[static_cast<std::size_t>(kind)];
}

FilmModelKind parse_film_model(std::string_view name) {
    for (std::size_t i = 0; i < model_names.size(); ++i) {
        if (name == model_names[i]) return static_cast<FilmModelKind>(i);
    }
    throw UnknownNameError("film model '" + std::string(name) +
                               "' is unknown; valid: exact, thesis, thesis-multilayer, morpho",
                           {model_names.begin(), model_names.end()});
}

void check_film_thickness(double thickness_nm, std::string_view what) {
    if (!(std::isfinite(thickness_nm) && thickness_nm >= 0.0 && thickness_nm <= 1e6)) {
        throw Error(std::string(what) + " " + format_shortest(thickness_nm) +
                    " nm must be finite and in [0, 1e6] nm (1 mm)");
    }
}

FilmColor FilmAtAngle::color(double thickness_nm, const Colorimeter& colorimeter) const {
    DenseValues r;
    reflectance(thickness_nm, r);
    return color_of(r, colorimeter);
}

FilmColor FilmModel::color(const Colorimeter& colorimeter, double angle_rad,
                           std::optional<double> thickness) const {
    const double t = thickness.value_or(thickness_nm());
    if (thickness) check_film_thickness(t);
    return at_angle(angle_rad)->exact_color(t, colorimeter);
}

void FilmModel::check_work(std::vector<WorkFactor> spectra, bool at_wavelengths,
                           const FilmWorkNames&) const {
    if (at_wavelengths) check_spectrum_work(spectra);
    else check_color_work(spectra);
}

// --- Exact ---------------------------------------------------------------------------------

ExactFilm::ExactFilm(Material ambient, std::vector<Layer> layers, Material substrate,
                     Polarization polarization)
    : m_ambient(std::move(ambient)),
      m_substrate(std::move(substrate)),
      m_layers(std::move(layers)),
      m_polarization(polarization) {
    if (!m_ambient.is_lossless()) {
        throw Error("the ambient '" + m_ambient.name() + "' absorbs (k > 0); it must have k = 0");
    }
    if (m_layers.empty()) throw Error("an exact film needs at least one layer");
    for (std::size_t i = 0; i < m_layers.size(); ++i) {
        check_film_thickness(m_layers[i].thickness_nm, "layer " + std::to_string(i + 1) + " thickness");
    }
}

bool ExactFilm::is_airy() const noexcept {
    return m_layers.size() == 1 && m_polarization == Polarization::unpolarized;
}

FilmStack ExactFilm::stack(std::optional<double> thickness_nm) const {
    std::vector<Layer> layers = m_layers;
    if (thickness_nm) {
        check_film_thickness(*thickness_nm);
        layers.front().thickness_nm = *thickness_nm;
    }
    return FilmStack(m_ambient, std::move(layers), m_substrate);
}

std::function<Optics(double)> ExactFilm::spectrum(double angle_rad, std::optional<double> thickness_nm) const {
    check_incidence_angle(angle_rad);
    return [s = stack(thickness_nm), angle_rad, p = m_polarization](double lambda_nm) {
        return s.evaluate(lambda_nm, angle_rad, p);
    };
}

std::unique_ptr<FilmAtAngle> ExactFilm::at_angle(double angle_rad) const {
    check_incidence_angle(angle_rad);
    if (is_airy()) {
        return std::make_unique<AiryAtAngle>(SingleFilm{m_ambient, m_layers.front().material, m_substrate},
                                             angle_rad);
    }
    return std::make_unique<StackAtAngle>(*this, angle_rad);
}

void ExactFilm::check_work(std::vector<WorkFactor> spectra, bool at_wavelengths,
                            const FilmWorkNames& names) const {
    // Colours of one unpolarised layer take the prepared Airy film; any other exact stack (and
    // every spectrum at given wavelengths) the transfer matrix.
    if (is_airy() && !at_wavelengths) {
        check_color_work(spectra);
        return;
    }
    if (!at_wavelengths) {
        spectra.push_back({"the 1 nm grid 360-830 nm", static_cast<double>(dense_sample_count), "wavelengths"});
    }
    spectra.push_back({names.layers, static_cast<double>(m_layers.size()), "layers"});
    check_stack_work(spectra);
}

// --- Thesis single film -------------------------------------------------------------------

ThesisFilm::ThesisFilm(SingleFilm film, double thickness_nm, std::optional<double> k,
                       std::optional<bool> phase_change)
    : m_film(std::move(film)), m_thickness_nm(thickness_nm), m_phase_change(phase_change) {
    if (!m_film.ambient.is_lossless()) {
        throw Error("the ambient '" + m_film.ambient.name() + "' absorbs (k > 0); it must have k = 0");
    }
    check_thesis_single_film(m_film);
    check_film_thickness(thickness_nm);
    if (k) check_k(*k);
    m_k = k ? *k : thesis_matched_k(m_film);
}

std::function<Optics(double)> ThesisFilm::spectrum(double angle_rad, std::optional<double> thickness_nm) const {
    check_incidence_angle(angle_rad);
    if (thickness_nm) check_film_thickness(*thickness_nm);
    return [film = m_film, t = thickness_nm.value_or(m_thickness_nm), angle_rad, k = m_k,
            phase = m_phase_change](double lambda_nm) {
        return Optics{thesis_single_film_reflectance(film, t, lambda_nm, angle_rad, k, phase), 0.0};
    };
}

std::unique_ptr<FilmAtAngle> ThesisFilm::at_angle(double angle_rad) const {
    check_incidence_angle(angle_rad);
    return function_at_angle([film = m_film, angle_rad, k = m_k, phase = m_phase_change](double lambda_nm, double t) {
        return thesis_single_film_reflectance(film, t, lambda_nm, angle_rad, k, phase);
    });
}

// --- Thesis multilayer --------------------------------------------------------------------

ThesisMultilayerFilm::ThesisMultilayerFilm(Material film, double thickness_nm, int periods,
                                           std::optional<double> k)
    : m_film(std::move(film)), m_thickness_nm(thickness_nm), m_periods(periods) {
    check_thesis_material(m_film, "film");
    check_thesis_air_index(real_index(m_film, 555.0), "'" + m_film.name() + "' at 555 nm");
    check_thesis_periods(periods);
    check_film_thickness(thickness_nm);
    if (k) check_k(*k);
    m_k = k ? *k : thesis_unit_peak_k(periods);
}

std::function<Optics(double)> ThesisMultilayerFilm::spectrum(double angle_rad,
                                                             std::optional<double> thickness_nm) const {
    check_incidence_angle(angle_rad);
    if (thickness_nm) check_film_thickness(*thickness_nm);
    return [film = m_film, t = thickness_nm.value_or(m_thickness_nm), angle_rad, l = m_periods,
            k = m_k](double lambda_nm) {
        const double t_theta = thesis_multilayer_effective_thickness_nm(t, real_index(film, lambda_nm), angle_rad);
        return Optics{thesis_multilayer_reflectance(lambda_nm, t_theta, l, k), 0.0};
    };
}

std::unique_ptr<FilmAtAngle> ThesisMultilayerFilm::at_angle(double angle_rad) const {
    check_incidence_angle(angle_rad);
    // Eq. 26's factor (n² − sin²θ)^½ per wavelength does not depend on the thickness.
    DenseValues factor;
    for (int i = 0; i < dense_sample_count; ++i) {
        const double lambda = DenseSpectrum::wavelength_nm(i);
        factor[static_cast<std::size_t>(i)] =
            thesis_multilayer_effective_thickness_nm(1.0, real_index(m_film, lambda), angle_rad);
    }
    return function_at_angle([factor, l = m_periods, k = m_k](double lambda_nm, double t) {
        const auto i = static_cast<std::size_t>(std::lround(lambda_nm - lambda_min_nm));
        return thesis_multilayer_reflectance(lambda_nm, t * factor[i], l, k);
    });
}

// --- Morpho ---------------------------------------------------------------------------------

MorphoFilm::MorphoFilm(MorphoParameters wing, std::optional<MorphoBlend> blend)
    : m_wing(wing), m_blend(blend) {
    validate_morpho(m_wing);
    if (m_blend) validate_morpho_blend(*m_blend);
}

std::function<Optics(double)> MorphoFilm::spectrum(double angle_rad, std::optional<double>) const {
    check_incidence_angle(angle_rad);
    return [wing = m_wing, blend = m_blend, angle_rad](double lambda_nm) {
        return Optics{blend ? morpho_blend_reflectance(wing, *blend, lambda_nm, angle_rad)
                            : morpho_reflectance(wing, lambda_nm, angle_rad),
                      0.0};
    };
}

std::unique_ptr<FilmAtAngle> MorphoFilm::at_angle(double angle_rad) const {
    check_incidence_angle(angle_rad);
    return function_at_angle([wing = m_wing, blend = m_blend, angle_rad](double lambda_nm, double) {
        return blend ? morpho_blend_reflectance(wing, *blend, lambda_nm, angle_rad)
                     : morpho_reflectance(wing, lambda_nm, angle_rad);
    });
}

std::optional<double> MorphoFilm::effective_thickness_nm(double angle_rad) const {
    return morpho_effective_thickness_nm(m_wing, angle_rad);
}

void MorphoFilm::check_work(std::vector<WorkFactor> spectra, bool at_wavelengths,
                            const FilmWorkNames& names) const {
    std::optional<WorkFactor> per_wavelength;
    if (m_blend) per_wavelength = WorkFactor{names.blend, static_cast<double>(m_blend->samples), "samples"};
    if (at_wavelengths) {
        if (per_wavelength) spectra.push_back(*per_wavelength);
        check_spectrum_work(spectra);
    } else {
        check_color_work(spectra, per_wavelength);
    }
}

}  // namespace irid
