#pragma once

// The thin-film models production renderers use, implemented from their published descriptions,
// and their error against irid's exact optics (PreparedFilm, the Airy sum on the 1 nm grid).
//
// - gltf: the reference implementation in the appendix of Khronos' KHR_materials_iridescence
//   (https://github.com/KhronosGroup/glTF/tree/main/extensions/2.0/Khronos/KHR_materials_iridescence,
//   and its GLSL in KhronosGroup/glTF-Sample-Renderer source/Renderer/shaders/iridescence.glsl),
//   which three.js, Filament, Babylon.js and Unreal follow: Schlick's Fresnel for both faces,
//   phase shifts of 0 or π, OPD = 2 n d cos θ₂, the Airy series to m = 2, the Gaussian fits of the
//   CIE 1931 functions in Fourier space, XYZ → Rec.709, max(0).
// - belcour: L. Belcour and P. Barla, "A Practical Extension to Microfacet Theory for the
//   Modeling of Varying Iridescence", ACM Trans. Graph. 36(4), 65 (SIGGRAPH 2017), and its
//   supplemental shader: the Airy series to m = 3 with exact Fresnel amplitudes and phases for
//   s and p (averaged), the same Gaussian fits.
// - cycles: Blender Cycles' thin film (intern/cycles/kernel/closure/bsdf_util.h,
//   fresnel_iridescence, Blender 5.0, 2025): the same series to m = 3, exact Fresnel, with the
//   sensitivity looked up in a table of the FFT of the CIE 1931 functions
//   (intern/cycles/doc/precompute/thin_film_table.py and scene/shader.cpp,
//   compute_thin_film_table), built here the same way from irid's CIE 1931 table.
//
// These models give a colour, linear Rec.709 RGB as the renderer uses it (a reflectance whose
// white (1, 1, 1) is D65), not a spectrum. They take real ambient and film indices and one
// complex base index per RGB channel (a renderer's "IOR" and a conductor's RGB n and k); glTF
// takes the base as its F0 colour instead.
//
// They are not FilmModel kinds (film.h): FilmModel's contract is a spectrum (spectrum(),
// at_angle()'s reflectance on the 1 nm grid) and a colour under any Colorimeter, while these
// models give one colour under fixed sensitivities (CIE 1931, Rec.709, white D65) from inputs a
// FilmModel does not carry (per-channel base indices, glTF's F0). They have their own entry
// points instead: `irid film --model`, `irid film-error --model`, the figure renderer-films and
// Python's renderer_film_color.

#include <irid/optics/film_color.h>
#include <irid/optics/film_error_study.h>

#include <array>
#include <complex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace irid {

enum class RendererFilmModel { gltf, belcour, cycles };

/// "gltf", "belcour", "cycles".
[[nodiscard]] std::string_view renderer_film_model_name(RendererFilmModel model) noexcept;
/// The model of a name above; throws UnknownNameError listing them.
[[nodiscard]] RendererFilmModel parse_renderer_film_model(std::string_view name);
/// The model of a name, or nothing when it is none of them.
[[nodiscard]] std::optional<RendererFilmModel> find_renderer_film_model(std::string_view name) noexcept;
[[nodiscard]] std::vector<std::string> renderer_film_model_names();

/// A base index per Rec.709 channel: R, G, B.
using ChannelIndices = std::array<Complex, 3>;

/// The wavelengths [nm] at which a renderer's per-channel ("RGB") optical constants are read
/// from a measured table: the dominant wavelengths of the Rec.709 primaries with respect to D65
/// (the wavelength where the line from the white through the primary meets the spectral locus;
/// computed from ITU-R BT.709-6's chromaticities and the CIE 1931 locus, tested).
inline constexpr std::array<double, 3> renderer_channel_wavelengths_nm = {611.3, 549.1, 464.3};
/// The wavelength [nm] of a renderer's single "IOR": the d line of helium, 587.56 nm, where
/// glass catalogues and ISO 7944 quote n_d.
inline constexpr double renderer_ior_wavelength_nm = 587.56;

// --- the sensitivities ----------------------------------------------------------------------

/// Belcour & Barla's Gaussian fits of the CIE 1931 x̄, ȳ, z̄ in Fourier space, as published in the
/// supplemental shader and in KHR_materials_iridescence's evalSensitivity: for an optical path
/// difference [nm] and a phase shift [rad], the XYZ of cos(2π OPD ν + shift) against the fits,
/// divided by 1.0685e-7 (≈ ∫ȳ dλ in metres), so that OPD 0, shift 0 gives about (1, 1, 1): the
/// white of illuminant E.
[[nodiscard]] Xyz gaussian_fit_sensitivity(double opd_nm, double shift_rad) noexcept;
/// The same, unnormalised: the fits' integrals in the units of the fits (metres of wavelength).
[[nodiscard]] Xyz gaussian_fit_sensitivity_unnormalized(double opd_nm, double shift_rad) noexcept;
/// XYZ → linear Rec.709 with the matrix every renderer above uses (D65; glTF-Sample-Renderer's
/// XYZ_TO_REC709 and Cycles' init_xyz_transforms: 3.2404542, -1.5371385, ...).
[[nodiscard]] Rgb renderer_xyz_to_rec709(const Xyz& c) noexcept;

/// Cycles' table of the Fourier transform of the CIE 1931 functions, in Rec.709 and normalised
/// so that each channel's DC term is 1, as compute_thin_film_table builds it. The CMFs are
/// resampled as functions of frequency f [µm⁻¹] (S(f) = cmf(1000/f) / f²) at f = n π / 60,
/// n = 0..1021, and transformed by a 1022-point real DFT, giving 512 complex values at optical
/// path differences OPD_k = k × 60000 / (2π × 511) nm ≈ 18.69 k nm: the table covers 0 to
/// 9549 nm (the kernel's "60 µm" is 2π times that) and holds its last value beyond.
class CyclesSensitivityTable {
public:
    static constexpr int size = 512;
    static constexpr int samples = 1022;
    /// OPD step between entries [nm] and the last entry's OPD.
    static constexpr double opd_step_nm = 60000.0 / (2.0 * 3.14159265358979323846 * (size - 1));
    static constexpr double max_opd_nm = opd_step_nm * (size - 1);

    /// Built from an observer's colour-matching functions (linear between irid's 1 nm entries,
    /// 0 outside 360-830 nm; Cycles interpolates its 359-831 nm table with a cubic spline).
    explicit CyclesSensitivityTable(Observer observer = Observer::cie1931_2deg);

    /// Linear Rec.709 sensitivity at an OPD [nm], complex per channel, linear between entries and
    /// clamped at both ends (Cycles' lookup_table_read).
    [[nodiscard]] std::array<Complex, 3> at(double opd_nm) const noexcept;
    /// The k-th entry, before normalisation, in XYZ (the FFT of the resampled CMFs).
    [[nodiscard]] std::array<Complex, 3> xyz_entry(int k) const noexcept { return m_xyz[static_cast<std::size_t>(k)]; }

private:
    std::array<std::array<Complex, 3>, size> m_xyz{};
    std::array<std::array<Complex, 3>, size> m_rgb{};
};

/// The table built once from the CIE 1931 2° observer.
[[nodiscard]] const CyclesSensitivityTable& cycles_sensitivity_table();

// --- the models -----------------------------------------------------------------------------

/// glTF's Fresnel0ToIor: the index of a medium in air of normal-incidence reflectance F0.
[[nodiscard]] double gltf_fresnel0_to_ior(double f0) noexcept;
/// glTF's IorToFresnel0: ((n_t - n_i) / (n_t + n_i))².
[[nodiscard]] double gltf_ior_to_fresnel0(double transmitted_ior, double incident_ior) noexcept;

/// KHR_materials_iridescence's evalIridescence: ambient ("outside") index, film index, the base's
/// F0 colour (linear Rec.709, as the material's specular colour or metal's base colour), film
/// thickness [nm] and cos θ in the ambient (in [0, 1]). As in the reference, the m-th term's
/// sensitivity takes the phase shift of each RGB channel in the XYZ component of the same
/// position (evalSensitivity's vec3 shift), and the film index blends to the outside index over
/// 0-0.03 nm of thickness (smoothstep(0.0, 0.03, thinFilmThickness) with nm).
[[nodiscard]] Rgb gltf_iridescence(double outside_ior, double film_ior, const Rgb& base_f0,
                                   double thickness_nm, double cos_theta) noexcept;
/// Belcour & Barla 2017; each channel of the result uses that channel's base index (the
/// three are equal for a dielectric).
[[nodiscard]] Rgb belcour_iridescence(double ambient_ior, double film_ior, const ChannelIndices& base,
                                      double thickness_nm, double cos_theta) noexcept;
/// Blender Cycles' fresnel_iridescence (Blender 5.0).
[[nodiscard]] Rgb cycles_iridescence(double ambient_ior, double film_ior, const ChannelIndices& base,
                                     double thickness_nm, double cos_theta) noexcept;

/// The monochromatic Airy sum as Belcour & Barla's series (their eq. 10) truncated at `orders`
/// terms: R12 + Rs + 2 Σ_{m=1}^{orders} C_m cos(m φ), Rs = T121² R23 / (1 - R12 R23),
/// C_m = (Rs - T121) (R12 R23)^{m/2}, where φ is the round trip's phase: 2π OPD / λ plus the
/// phases of r21 and r23. Exact as orders → ∞ for a lossless first face.
[[nodiscard]] double airy_series_reflectance(double r12, double r23, double phase_rad, int orders) noexcept;

/// What the models take, from irid's materials: the ambient's and the film's real index at
/// renderer_ior_wavelength_nm; the base's index per channel (at renderer_channel_wavelengths_nm
/// when it absorbs, at renderer_ior_wavelength_nm in all three when it does not, as a renderer's
/// single IOR); glTF's F0: a dielectric's ((n - 1) / (n + 1))² (Fresnel0ToIor assumes air), a
/// conductor's own normal-incidence reflectance in air as linear Rec.709 under D65 (what an
/// artist enters as a metal's base colour), from irid's exact optics.
struct RendererFilmInputs {
    double ambient_ior = 1.0;
    double film_ior = 1.0;
    ChannelIndices base{};
    Rgb gltf_base_f0{};
};
/// Throws irid::Error for an absorbing ambient or film (the renderers' films are real).
[[nodiscard]] RendererFilmInputs renderer_film_inputs(const SingleFilm& film);

/// The model's RGB for the inputs at a thickness [nm] and an angle of incidence [rad, in [0, π/2)].
[[nodiscard]] Rgb renderer_film_rgb(RendererFilmModel model, const RendererFilmInputs& inputs,
                                    double thickness_nm, double angle_rad) noexcept;
/// The colour of the model's RGB read as a Rec.709 reflectance: XYZ relative to D65 (Y = 1 for
/// white), and the RGB itself.
[[nodiscard]] FilmColor renderer_film_color(RendererFilmModel model, const RendererFilmInputs& inputs,
                                            double thickness_nm, double angle_rad) noexcept;

/// The colour each model gives a unit, flat reflectance through its sensitivity at OPD 0 (what a
/// film reflecting everything averages to): the Gaussian fits' white is illuminant E in Rec.709
/// (about 1.205, 0.948, 0.909), Cycles' normalised table gives (1, 1, 1). A film reflecting
/// nothing is (0, 0, 0) in every model (the series is linear).
[[nodiscard]] Rgb renderer_sensitivity_white(RendererFilmModel model) noexcept;

// --- the error study ------------------------------------------------------------------------

/// ΔE2000 over thickness × angle, ErrorStudyOptions' grid (0, step, ..., max; angles likewise),
/// between a model and the exact film, under the default Colorimeter (D65, CIE 1931 2°, sRGB =
/// Rec.709 primaries). Row-major by angle: delta_e[a * thickness_count + t].
struct FilmErrorMap {
    std::size_t thickness_count = 0, angle_count = 0;
    double thickness_step_nm = 0.0, angle_step_deg = 0.0;
    std::vector<double> delta_e;
};
/// Throws irid::Error unless the options are valid (as validate_error_study) and a study of `films`
/// films of a renderer's model is within the work limit: each grid point costs one spectrum, the
/// exact film's (the model's closed form costs under a twentieth of it, docs/PERFORMANCE.md).
/// The names are the caller's, as validate_error_study's.
void validate_renderer_error_study(const ErrorStudyOptions& options, double films = 1.0,
                                   std::string_view thickness_name = "thickness grid",
                                   std::string_view angles_name = "angle grid",
                                   std::string_view films_name = "films");
/// A renderer's model against the exact film. Throws irid::Error as validate_renderer_error_study,
/// and for an absorbing ambient or film.
[[nodiscard]] FilmErrorMap renderer_film_error_map(RendererFilmModel model, const SingleFilm& film,
                                                   const ErrorStudyOptions& options);
/// The thesis' single film (eq. 21/22 with eq. 24, K as options.k or thesis_matched_k) against the
/// exact film. Throws irid::Error as validate_error_study and check_thesis_single_film.
[[nodiscard]] FilmErrorMap thesis_film_error_map(const SingleFilm& film, const ErrorStudyOptions& options);
/// irid's Fourier film colour (irid/optics/fourier_film.h, its default transforms for the film)
/// against the exact film. Throws irid::Error as validate_renderer_error_study, and for an
/// absorbing ambient or film.
[[nodiscard]] FilmErrorMap fourier_film_error_map(const SingleFilm& film, const ErrorStudyOptions& options);

/// A map's statistics (mean, median, p95, max, where the max is, by angle and by 100 nm band)
/// and where the model fails: the fraction of samples above ΔE2000 2 and 5, overall, per angle
/// and per thickness band.
struct FilmErrorRegions {
    ErrorStudyResult summary;
    double above_2 = 0.0, above_5 = 0.0;
    std::vector<double> above_2_by_angle, above_5_by_angle;
    std::vector<double> above_2_by_band, above_5_by_band;
};
[[nodiscard]] FilmErrorRegions summarize_film_error(const std::string& name, const FilmErrorMap& map);

/// The study's films: film indices 1.2, 1.33, 1.5, 2.0 (constant) on air, water, glass (fused
/// silica) and gold (Johnson & Christy), in air.
struct StudyFilm {
    std::string name;
    SingleFilm film;
    bool metal = false;
};
[[nodiscard]] std::vector<StudyFilm> renderer_study_films();

}  // namespace irid
