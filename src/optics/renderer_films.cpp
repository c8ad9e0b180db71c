#include <irid/color/measure.h>
#include <irid/color/numeric_table.h>
#include <irid/color/observer.h>
#include <irid/color/rgb.h>
#include <irid/error.h>
#include <irid/optics/fourier_film.h>
#include <irid/optics/renderer_films.h>
#include <irid/optics/work_limits.h>


#include <algorithm>
#include <cmath>
#include <numbers>

namespace irid {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double degrees_to_radians = pi / 180.0;

constexpr std::array<std::string_view, 3> model_names = {"gltf", "belcour", "cycles"};

/// XYZ → linear Rec.709 (D65), rows: glTF-Sample-Renderer iridescence.glsl XYZ_TO_REC709 (given
/// there column-major) and Blender's intern/cycles/scene/shader.cpp init_xyz_transforms.
constexpr double xyz_to_rec709[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                        {-0.9692660, 1.8760108, 0.0415560},
                                        {0.0556434, -0.2040259, 1.0572252}};

double smoothstep(double edge0, double edge1, double x) noexcept {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);  // GLSL smoothstep (OpenGL Shading Language 4.60, §8.3)
}

double mix(double a, double b, double t) noexcept { return a + (b - a) * t; }

/// Schlick's approximation with F90 = 1 (C. Schlick, Computer Graphics Forum 13(3), 1994), as
/// glTF's F_Schlick.
double schlick(double f0, double cos_theta) noexcept {
    const double m = std::clamp(1.0 - cos_theta, 0.0, 1.0);
    return f0 + (1.0 - f0) * (m * m) * (m * m) * m;
}

double channel(const Rgb& c, int i) noexcept { return i == 0 ? c.r : (i == 1 ? c.g : c.b); }
double& channel(Rgb& c, int i) noexcept { return i == 0 ? c.r : (i == 1 ? c.g : c.b); }

Rgb clamp01(const Rgb& c) noexcept {
    return {std::clamp(c.r, 0.0, 1.0), std::clamp(c.g, 0.0, 1.0), std::clamp(c.b, 0.0, 1.0)};
}

/// The series' coefficients for one polarisation: C0 and C1 (C_m = C1 r123^{m-1}), r123.
struct Series {
    double c0, c1, ratio;
};
Series series(double R12, double R23) noexcept {
    // Belcour & Barla 2017, eq. 10 and the supplemental shader: T121 = 1 - R12,
    // Rs = T121² R23 / (1 - R12 R23), C0 = R12 + Rs, C_m = (Rs - T121) (R12 R23)^{m/2}.
    // 1 − R12 R23 is written (1 − R12) + R12 (1 − R23), which loses no digit where both faces
    // reflect almost totally (grazing incidence); where both do exactly, Rs → 0 (T121² vanishes
    // faster than the denominator).
    const double T121 = 1.0 - R12;
    const double R123 = R12 * R23;
    const double r123 = std::sqrt(R123);
    const double den = T121 + R12 * (1.0 - R23);
    const double Rs = den > 0.0 ? T121 * T121 * R23 / den : 0.0;
    return {R12 + Rs, (Rs - T121) * r123, r123};
}

/// The phasor of a complex amplitude (1 for a zero amplitude, whose terms vanish anyway).
Complex unit(Complex r) noexcept {
    const double a = std::abs(r);
    return a > 0.0 ? r / a : Complex(1.0, 0.0);
}

/// One polarisation of the exact two faces of a film: R12 (real first face), R23, and the
/// round trip's phasor exp(i (φ21 + φ23)), from irid's fresnel() (multilayer.h), whose r21 = -r12.
struct Faces {
    double R12, R23;
    Complex phasor;
};
std::array<Faces, 2> exact_faces(double n0, double n1, Complex n2, double cos_theta) noexcept {
    // From q0 = n0 cos θ0, not from the Snell invariant: at grazing incidence sin θ0 rounds to 1,
    // and a film blended to the ambient's index would get N cos θ = 0 on both sides (0/0).
    const double q0 = n0 * cos_theta;
    const FresnelCoefficients top = fresnel_from(n0, n1, n0, q0);
    const FresnelCoefficients bottom = fresnel_from(n1, n2, n0, q0);
    const auto faces = [](Complex r12, Complex r23) {
        return Faces{std::norm(r12), std::norm(r23), unit(-r12) * unit(r23)};
    };
    return {faces(top.r_s, bottom.r_s), faces(top.r_p, bottom.r_p)};
}

bool same(const ChannelIndices& base) noexcept { return base[0] == base[1] && base[1] == base[2]; }

template <class ModelXyz>
FilmErrorMap error_map(const SingleFilm& film, const ErrorStudyOptions& o, ModelXyz&& model_xyz) {
    const Colorimeter colorimeter;
    FilmErrorMap map;
    map.thickness_count = static_cast<std::size_t>(error_study_thickness_count(o));
    map.angle_count = static_cast<std::size_t>(error_study_angle_count(o));
    map.thickness_step_nm = o.thickness_step_nm;
    map.angle_step_deg = o.angle_step_deg;
    map.delta_e.reserve(map.thickness_count * map.angle_count);
    for (std::size_t a = 0; a < map.angle_count; ++a) {
        const double theta = o.angle_step_deg * static_cast<double>(a) * degrees_to_radians;
        const PreparedFilm prepared(film, theta);
        for (std::size_t i = 0; i < map.thickness_count; ++i) {
            const double t = o.thickness_step_nm * static_cast<double>(i);
            const Xyz exact = prepared.color(t, colorimeter).xyz;
            map.delta_e.push_back(delta_e_2000_of(colorimeter, model_xyz(t, theta, colorimeter), exact));
        }
    }
    return map;
}

}  // namespace

// --- names ----------------------------------------------------------------------------------

std::string_view renderer_film_model_name(RendererFilmModel model) noexcept {
    return model_names[static_cast<std::size_t>(model)];
}

std::optional<RendererFilmModel> find_renderer_film_model(std::string_view name) noexcept {
    for (std::size_t i = 0; i < model_names.size(); ++i) {
        if (name == model_names[i]) return static_cast<RendererFilmModel>(i);
    }
    return std::nullopt;
}

RendererFilmModel parse_renderer_film_model(std::string_view name) {
    if (const auto m = find_renderer_film_model(name)) return *m;
    throw UnknownNameError(std::string("renderer film model '") + std::string(name) +
                               "' is unknown; valid: gltf, belcour, cycles",
                           renderer_film_model_names());
}

std::vector<std::string> renderer_film_model_names() {
    return {model_names.begin(), model_names.end()};
}

// --- sensitivities --------------------------------------------------------------------------

namespace {

/// The fits with a shift per component, as the glTF reference's evalSensitivity(OPD, vec3 shift)
/// takes them (X with the first, Y the second, Z the third; the extra x̄ lobe with the first).
Xyz fits(double opd_nm, const std::array<double, 3>& shift) noexcept {
    // Belcour & Barla 2017, supplemental shader evalSensitivity; the same constants are in
    // KHR_materials_iridescence's reference (glTF-Sample-Renderer iridescence.glsl): a Gaussian
    // per function of frequency [1/m] with amplitude val, centre pos and width var, plus a second
    // lobe for x̄. phase = 2π OPD with OPD in metres.
    constexpr double val[3] = {5.4856e-13, 4.4201e-13, 5.2481e-13};
    constexpr double pos[3] = {1.6810e+06, 1.7953e+06, 2.2084e+06};
    constexpr double var[3] = {4.3278e+09, 9.3046e+09, 6.6121e+09};
    constexpr double x2_val = 9.7470e-14, x2_pos = 2.2399e+06, x2_var = 4.5282e+09;
    const double phase = 2.0 * pi * opd_nm * 1e-9;
    double v[3];
    for (int i = 0; i < 3; ++i) {
        v[i] = val[i] * std::sqrt(2.0 * pi * var[i]) * std::cos(pos[i] * phase + shift[static_cast<std::size_t>(i)]) *
               std::exp(-phase * phase * var[i]);
    }
    v[0] += x2_val * std::sqrt(2.0 * pi * x2_var) * std::cos(x2_pos * phase + shift[0]) *
            std::exp(-x2_var * phase * phase);
    return {v[0], v[1], v[2]};
}

/// The normalisation of the same shaders: xyz /= 1.0685e-7.
constexpr double fits_normalization = 1.0685e-7;

Xyz normalized_fits(double opd_nm, const std::array<double, 3>& shift) noexcept {
    const Xyz u = fits(opd_nm, shift);
    return {u.X / fits_normalization, u.Y / fits_normalization, u.Z / fits_normalization};
}

}  // namespace

Xyz gaussian_fit_sensitivity_unnormalized(double opd_nm, double shift_rad) noexcept {
    return fits(opd_nm, {shift_rad, shift_rad, shift_rad});
}

Xyz gaussian_fit_sensitivity(double opd_nm, double shift_rad) noexcept {
    return normalized_fits(opd_nm, {shift_rad, shift_rad, shift_rad});
}

Rgb renderer_xyz_to_rec709(const Xyz& c) noexcept {
    const double v[3] = {c.X, c.Y, c.Z};
    Rgb out;
    for (int i = 0; i < 3; ++i) {
        channel(out, i) = xyz_to_rec709[i][0] * v[0] + xyz_to_rec709[i][1] * v[1] + xyz_to_rec709[i][2] * v[2];
    }
    return out;
}

CyclesSensitivityTable::CyclesSensitivityTable(Observer observer) {
    // intern/cycles/doc/precompute/thin_film_table.py (Blender 5.0): endfreq = 60, N = 1022,
    // freqs = linspace(0, π (N - 1) / endfreq, N) [1/µm], S(f) = cmf(1000 / f) / f², rfft.
    constexpr double df = pi / 60.0;
    std::array<std::array<double, 3>, samples> s{};
    for (int n = 1; n < samples; ++n) {
        const double f = df * n;
        const Xyz c = monochromatic_xyz(1000.0 / f, observer);
        s[static_cast<std::size_t>(n)] = {c.X / (f * f), c.Y / (f * f), c.Z / (f * f)};
    }
    for (int k = 0; k < size; ++k) {
        std::array<Complex, 3> sum{};
        for (int n = 0; n < samples; ++n) {
            // e^{-2πi k n / N}, the reduced product keeps the angle's argument small.
            const double angle = -2.0 * pi * static_cast<double>((k * n) % samples) / samples;
            const Complex w(std::cos(angle), std::sin(angle));
            for (int c = 0; c < 3; ++c) sum[c] += s[static_cast<std::size_t>(n)][c] * w;
        }
        m_xyz[static_cast<std::size_t>(k)] = sum;
    }
    // scene/shader.cpp compute_thin_film_table: RGB = XYZ→RGB × the entry (re and im), each
    // channel divided by its DC term's real part.
    std::array<double, 3> dc{};
    for (int k = 0; k < size; ++k) {
        const auto& x = m_xyz[static_cast<std::size_t>(k)];
        auto& out = m_rgb[static_cast<std::size_t>(k)];
        for (int i = 0; i < 3; ++i) {
            out[i] = xyz_to_rec709[i][0] * x[0] + xyz_to_rec709[i][1] * x[1] + xyz_to_rec709[i][2] * x[2];
        }
        if (k == 0) {
            for (int i = 0; i < 3; ++i) dc[i] = out[i].real();
        }
        for (int i = 0; i < 3; ++i) out[i] /= dc[i];
    }
}

std::array<Complex, 3> CyclesSensitivityTable::at(double opd_nm) const noexcept {
    // bsdf_util.h iridescence_lookup_sensitivity: x = 2π OPD / 60000; kernel/util/lookup_table.h
    // lookup_table_read: x clamped to [0, 1] × (size - 1), linear between entries.
    const double x = std::clamp(2.0 * pi * opd_nm / 60000.0, 0.0, 1.0) * (size - 1);
    const int i = std::min(static_cast<int>(x), size - 1);
    const int j = std::min(i + 1, size - 1);
    const double t = x - i;
    std::array<Complex, 3> out;
    for (int c = 0; c < 3; ++c) {
        out[c] = (1.0 - t) * m_rgb[static_cast<std::size_t>(i)][c] + t * m_rgb[static_cast<std::size_t>(j)][c];
    }
    return out;
}

const CyclesSensitivityTable& cycles_sensitivity_table() {
    static const CyclesSensitivityTable table(Observer::cie1931_2deg);
    return table;
}

// --- the models -----------------------------------------------------------------------------

double gltf_fresnel0_to_ior(double f0) noexcept {
    // KHR_materials_iridescence, Fresnel0ToIor ("assume air interface for top").
    const double s = std::sqrt(f0);
    return (1.0 + s) / (1.0 - s);
}

double gltf_ior_to_fresnel0(double transmitted_ior, double incident_ior) noexcept {
    const double r = (transmitted_ior - incident_ior) / (transmitted_ior + incident_ior);
    return r * r;
}

double airy_series_reflectance(double r12, double r23, double phase_rad, int orders) noexcept {
    const Series s = series(r12 * r12, r23 * r23);
    double sum = s.c0;
    double cm = s.c1;
    for (int m = 1; m <= orders; ++m) {
        sum += 2.0 * cm * std::cos(m * phase_rad);
        cm *= s.ratio;
    }
    return sum;
}

Rgb gltf_iridescence(double outside_ior, double film_ior, const Rgb& base_f0, double thickness_nm,
                     double cos_theta) noexcept {
    // KHR_materials_iridescence, evalIridescence (glTF-Sample-Renderer iridescence.glsl).
    // "Force iridescenceIor -> outsideIOR when thinFilmThickness -> 0.0" over 0..0.03 (nm).
    const double n1 = mix(outside_ior, film_ior, smoothstep(0.0, 0.03, thickness_nm));
    const double sin2_2 = (outside_ior / n1) * (outside_ior / n1) * (1.0 - cos_theta * cos_theta);
    const double cos2_2 = 1.0 - sin2_2;
    if (cos2_2 < 0.0) return {1.0, 1.0, 1.0};  // total internal reflection
    const double cos_theta2 = std::sqrt(cos2_2);
    const double R12 = schlick(gltf_ior_to_fresnel0(n1, outside_ior), cos_theta);
    const double T121 = 1.0 - R12;
    const double phi12 = n1 < outside_ior ? pi : 0.0;
    const double phi21 = pi - phi12;
    const double opd = 2.0 * n1 * thickness_nm * cos_theta2;
    std::array<double, 3> phi{}, cm{}, I{};
    std::array<double, 3> r123{};
    for (std::size_t c = 0; c < 3; ++c) {
        const double base_ior = gltf_fresnel0_to_ior(std::clamp(channel(base_f0, static_cast<int>(c)), 0.0, 0.9999));
        const double R23 = schlick(gltf_ior_to_fresnel0(base_ior, n1), cos_theta2);
        const double phi23 = base_ior < n1 ? pi : 0.0;
        phi[c] = phi21 + phi23;
        const double R123 = std::clamp(R12 * R23, 1e-5, 0.9999);
        r123[c] = std::sqrt(R123);
        const double Rs = T121 * T121 * R23 / (1.0 - R123);
        I[c] = R12 + Rs;  // C0, the DC term, added as it is to every channel
        cm[c] = Rs - T121;
    }
    for (int m = 1; m <= 2; ++m) {
        // evalSensitivity(m OPD, m phi) with phi per channel: each XYZ component takes the shift
        // of the channel in its position (the reference's vec3 shift), then XYZ → Rec.709.
        const Rgb sm = renderer_xyz_to_rec709(normalized_fits(m * opd, {m * phi[0], m * phi[1], m * phi[2]}));
        for (std::size_t c = 0; c < 3; ++c) {
            cm[c] *= r123[c];
            I[c] += cm[c] * 2.0 * channel(sm, static_cast<int>(c));
        }
    }
    return {std::max(I[0], 0.0), std::max(I[1], 0.0), std::max(I[2], 0.0)};
}

Rgb belcour_iridescence(double ambient_ior, double film_ior, const ChannelIndices& base,
                        double thickness_nm, double cos_theta) noexcept {
    // Belcour & Barla 2017, supplemental shader IridescenceTerm: its film parameter Dinc [µm] is
    // the optical thickness 2 n1 d (the shader's OPD is Dinc cos θ2), and "eta_2 -> 1.0 when
    // Dinc -> 0.0" by smoothstep(0.0, 0.03, Dinc): the film index tends to the ambient's over
    // 2 n1 d in 0..30 nm, cos θ2 from the blended index, OPD from the film's own.
    const double optical_thickness_nm = 2.0 * film_ior * thickness_nm;
    const double n1 = mix(ambient_ior, film_ior, smoothstep(0.0, 30.0, optical_thickness_nm));
    const double sin_theta0 = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    const double snell = ambient_ior * sin_theta0;
    const double cos2_1 = 1.0 - (snell / n1) * (snell / n1);
    if (cos2_1 < 0.0) return {1.0, 1.0, 1.0};
    const double opd = optical_thickness_nm * std::sqrt(cos2_1);
    const Xyz s0 = gaussian_fit_sensitivity(0.0, 0.0);
    const int channels = same(base) ? 1 : 3;
    Rgb out;
    for (int c = 0; c < channels; ++c) {
        Xyz I;
        for (const Faces& f : exact_faces(ambient_ior, n1, base[static_cast<std::size_t>(c)], cos_theta)) {
            const Series s = series(f.R12, f.R23);
            const double phi = std::arg(f.phasor);
            // depol(): the mean of s and p.
            I.X += 0.5 * s.c0 * s0.X;
            I.Y += 0.5 * s.c0 * s0.Y;
            I.Z += 0.5 * s.c0 * s0.Z;
            double cm = s.c1;
            for (int m = 1; m <= 3; ++m) {
                const Xyz sm = gaussian_fit_sensitivity(m * opd, m * phi);
                I.X += 0.5 * 2.0 * cm * sm.X;
                I.Y += 0.5 * 2.0 * cm * sm.Y;
                I.Z += 0.5 * 2.0 * cm * sm.Z;
                cm *= s.ratio;
            }
        }
        const Rgb rgb = clamp01(renderer_xyz_to_rec709(I));
        if (channels == 1) return rgb;
        channel(out, c) = channel(rgb, c);
    }
    return out;
}

Rgb cycles_iridescence(double ambient_ior, double film_ior, const ChannelIndices& base,
                       double thickness_nm, double cos_theta) noexcept {
    // intern/cycles/kernel/closure/bsdf_util.h, fresnel_iridescence (Blender 5.0): below 1 nm the
    // film index blends to the ambient's by smoothstep(0, 1, thickness).
    double n1 = film_ior;
    if (thickness_nm < 1.0) n1 = mix(ambient_ior, film_ior, smoothstep(0.0, 1.0, thickness_nm));
    const double sin_theta0 = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    const double snell = ambient_ior * sin_theta0;
    const double cos2_1 = 1.0 - (snell / n1) * (snell / n1);
    if (cos2_1 < 0.0) return {1.0, 1.0, 1.0};  // TIR at the top interface
    const double opd = 2.0 * n1 * thickness_nm * std::sqrt(cos2_1);
    const CyclesSensitivityTable& table = cycles_sensitivity_table();
    std::array<std::array<Complex, 3>, 3> sensitivity;
    for (int m = 1; m <= 3; ++m) sensitivity[static_cast<std::size_t>(m - 1)] = table.at(m * opd);
    Rgb out;
    for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (const Faces& f : exact_faces(ambient_ior, n1, base[static_cast<std::size_t>(c)], cos_theta)) {
            // iridescence_airy_summation: R = C0 + Σ_{m=1}^{3} C_m 2 Re(e^{imφ} conj(S(m OPD))).
            const Series s = series(f.R12, f.R23);
            double R = s.c0;
            double cm = s.c1;
            Complex accumulator = f.phasor;
            for (int m = 1; m <= 3; ++m) {
                const Complex S = sensitivity[static_cast<std::size_t>(m - 1)][static_cast<std::size_t>(c)];
                R += cm * 2.0 * (accumulator.real() * S.real() + accumulator.imag() * S.imag());
                accumulator *= f.phasor;
                cm *= s.ratio;
            }
            sum += 0.5 * R;  // mix(R_s, R_p, 0.5)
        }
        channel(out, c) = std::clamp(sum, 0.0, 1.0);  // saturate
    }
    return out;
}

// --- inputs, colours ------------------------------------------------------------------------

RendererFilmInputs renderer_film_inputs(const SingleFilm& film) {
    if (!film.ambient.is_lossless()) throw Error("renderer film: the ambient must not absorb (k = 0)");
    if (!film.film.is_lossless()) {
        throw Error("renderer film: the film '" + film.film.name() +
                    "' absorbs (k > 0); the renderers' film models take a real film index");
    }
    RendererFilmInputs in;
    in.ambient_ior = film.ambient.index(renderer_ior_wavelength_nm).real();
    in.film_ior = film.film.index(renderer_ior_wavelength_nm).real();
    if (film.substrate.is_lossless()) {
        const double n2 = film.substrate.index(renderer_ior_wavelength_nm).real();
        in.base = {Complex(n2), Complex(n2), Complex(n2)};
        const double f0 = gltf_ior_to_fresnel0(n2, 1.0);
        in.gltf_base_f0 = {f0, f0, f0};
    } else {
        for (std::size_t c = 0; c < 3; ++c) in.base[c] = film.substrate.index(renderer_channel_wavelengths_nm[c]);
        const Colorimeter colorimeter;
        const Xyz f0 = colorimeter.xyz_of([&](double lambda) {
            const Complex n = film.substrate.index(lambda);
            return std::norm((1.0 - n) / (1.0 + n));
        });
        in.gltf_base_f0 = colorimeter.linear_rgb(f0);
    }
    return in;
}

Rgb renderer_film_rgb(RendererFilmModel model, const RendererFilmInputs& in, double thickness_nm,
                      double angle_rad) noexcept {
    const double c = std::cos(angle_rad);
    switch (model) {
        case RendererFilmModel::gltf:
            return gltf_iridescence(in.ambient_ior, in.film_ior, in.gltf_base_f0, thickness_nm, c);
        case RendererFilmModel::belcour:
            return belcour_iridescence(in.ambient_ior, in.film_ior, in.base, thickness_nm, c);
        case RendererFilmModel::cycles:
            return cycles_iridescence(in.ambient_ior, in.film_ior, in.base, thickness_nm, c);
    }
    return {};
}

FilmColor renderer_film_color(RendererFilmModel model, const RendererFilmInputs& inputs,
                              double thickness_nm, double angle_rad) noexcept {
    const Rgb rgb = renderer_film_rgb(model, inputs, thickness_nm, angle_rad);
    // Rec.709 → XYZ relative to its white, then scaled to the white of D65's tabulated spectrum
    // (the default Colorimeter's, 1e-4 from the xy of the white), so RGB (1, 1, 1) is that white.
    static const Colorimeter colorimeter;
    const Xyz x = srgb().to_xyz(rgb);
    const Xyz& w = srgb().white_xyz();
    const Xyz& d65 = colorimeter.white();
    return {{x.X * d65.X / w.X, x.Y * d65.Y / w.Y, x.Z * d65.Z / w.Z}, rgb};
}

Rgb renderer_sensitivity_white(RendererFilmModel model) noexcept {
    if (model == RendererFilmModel::cycles) {
        const auto s = cycles_sensitivity_table().at(0.0);
        return {s[0].real(), s[1].real(), s[2].real()};
    }
    return renderer_xyz_to_rec709(gaussian_fit_sensitivity(0.0, 0.0));
}

// --- the error study ------------------------------------------------------------------------

void validate_renderer_error_study(const ErrorStudyOptions& options, double films,
                                   std::string_view thickness_name, std::string_view angles_name,
                                   std::string_view films_name) {
    // The options' own checks, on a one-sample grid of the same steps.
    ErrorStudyOptions one = options;
    if (std::isfinite(one.max_thickness_nm) && one.max_thickness_nm >= 0.0) one.max_thickness_nm = 0.0;
    if (std::isfinite(one.max_angle_deg) && one.max_angle_deg >= 0.0 && one.max_angle_deg < 90.0) {
        one.max_angle_deg = 0.0;
    }
    validate_error_study(one);
    std::vector<WorkFactor> spectra{{std::string(thickness_name), error_study_thickness_count(options)},
                                    {std::string(angles_name), error_study_angle_count(options)}};
    if (films != 1.0) spectra.push_back({std::string(films_name), films, "films"});
    spectra.push_back({"the exact model", 1.0, "spectrum per sample"});
    check_color_work(spectra);
}

FilmErrorMap renderer_film_error_map(RendererFilmModel model, const SingleFilm& film,
                                     const ErrorStudyOptions& options) {
    validate_renderer_error_study(options);
    const RendererFilmInputs inputs = renderer_film_inputs(film);
    return error_map(film, options, [&](double t, double theta, const Colorimeter&) {
        return renderer_film_color(model, inputs, t, theta).xyz;
    });
}

FilmErrorMap thesis_film_error_map(const SingleFilm& film, const ErrorStudyOptions& options) {
    validate_error_study(options);
    check_thesis_single_film(film);
    const double k = options.k.value_or(thesis_matched_k(film));
    return error_map(film, options, [&](double t, double theta, const Colorimeter& colorimeter) {
        return colorimeter.xyz_of([&](double lambda) {
            return thesis_single_film_reflectance(film, t, lambda, theta, k, std::nullopt);
        });
    });
}

FilmErrorMap fourier_film_error_map(const SingleFilm& film, const ErrorStudyOptions& options) {
    validate_renderer_error_study(options);
    const FourierFilm fourier(film, fourier_colorimeter_for(film, Colorimeter()));
    return error_map(film, options, [&](double t, double theta, const Colorimeter&) {
        return fourier.xyz(t, std::cos(theta));
    });
}

FilmErrorRegions summarize_film_error(const std::string& name, const FilmErrorMap& map) {
    FilmErrorRegions out;
    ErrorStudyResult& r = out.summary;
    r.name = name;
    r.samples = map.delta_e.size();
    if (map.delta_e.empty()) return out;
    const double max_thickness = map.thickness_step_nm * static_cast<double>(map.thickness_count - 1);
    const auto band_count = std::max<std::size_t>(
        static_cast<std::size_t>(std::ceil(max_thickness / 100.0 - 1e-9)), 1);
    std::vector<double> band_sum(band_count, 0.0), band_2(band_count, 0.0), band_5(band_count, 0.0);
    std::vector<std::size_t> band_n(band_count, 0);
    double total = 0.0;
    for (std::size_t a = 0; a < map.angle_count; ++a) {
        double sum = 0.0, worst = 0.0, above_2 = 0.0, above_5 = 0.0;
        for (std::size_t i = 0; i < map.thickness_count; ++i) {
            const double d = map.delta_e[a * map.thickness_count + i];
            const double t = map.thickness_step_nm * static_cast<double>(i);
            sum += d;
            worst = std::max(worst, d);
            above_2 += d > 2.0 ? 1.0 : 0.0;
            above_5 += d > 5.0 ? 1.0 : 0.0;
            const std::size_t band = std::min(static_cast<std::size_t>(t / 100.0), band_count - 1);
            band_sum[band] += d;
            band_2[band] += d > 2.0 ? 1.0 : 0.0;
            band_5[band] += d > 5.0 ? 1.0 : 0.0;
            ++band_n[band];
            if (d > r.max) {
                r.max = d;
                r.worst_thickness_nm = t;
                r.worst_angle_deg = map.angle_step_deg * static_cast<double>(a);
            }
        }
        const auto n = static_cast<double>(map.thickness_count);
        r.angles_deg.push_back(map.angle_step_deg * static_cast<double>(a));
        r.mean_by_angle.push_back(sum / n);
        r.max_by_angle.push_back(worst);
        out.above_2_by_angle.push_back(above_2 / n);
        out.above_5_by_angle.push_back(above_5 / n);
        out.above_2 += above_2;
        out.above_5 += above_5;
        total += sum;
    }
    for (std::size_t b = 0; b < band_count; ++b) {
        const double n = band_n[b] ? static_cast<double>(band_n[b]) : 1.0;
        r.mean_by_thickness_band.push_back(band_sum[b] / n);
        out.above_2_by_band.push_back(band_2[b] / n);
        out.above_5_by_band.push_back(band_5[b] / n);
    }
    const auto count = static_cast<double>(r.samples);
    r.mean = total / count;
    r.median = percentile(map.delta_e, 0.5);
    r.p95 = percentile(map.delta_e, 0.95);
    out.above_2 /= count;
    out.above_5 /= count;
    return out;
}

std::vector<StudyFilm> renderer_study_films() {
    const Material air = *find_material("air");
    const std::pair<const char*, const Material*> substrates[] = {
        {"air", find_material("air")},
        {"water", find_material("water")},
        {"glass", find_material("fused-silica")},
        {"gold", find_material("gold")},
    };
    std::vector<StudyFilm> films;
    for (const double n : {1.2, 1.33, 1.5, 2.0}) {
        const std::string index = format_shortest(n);
        for (const auto& [name, substrate] : substrates) {
            std::string label = "n";
            label += index;
            label += "-on-";
            label += name;
            films.push_back({std::move(label),
                             SingleFilm{air, Material::constant("film " + index, n), *substrate},
                             !substrate->is_lossless()});
        }
    }
    return films;
}

}  // namespace irid
