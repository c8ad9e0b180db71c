// The Preetham–Shirley–Smits daylight sky and sun (irid/render/sky.h).
#include <irid/error.h>
#include <irid/render/sky.h>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace irid::render {
namespace {

constexpr double pi = std::numbers::pi;

/// A coefficient linear in the turbidity: slope · T + intercept.
struct Linear {
    double slope, intercept;
    [[nodiscard]] double at(double t) const noexcept { return slope * t + intercept; }
};

/// Preetham 1999 Appendix A.2: A…E for the luminance Y and the chromaticities x and y, each
/// slope · T + intercept (the paper's 5 × 2 matrices, one row per coefficient).
constexpr Linear coeff_Y[5] = {
    {0.1787, -1.4630}, {-0.3554, 0.4275}, {-0.0227, 5.3251}, {0.1206, -2.5771}, {-0.0670, 0.3703}};
constexpr Linear coeff_x[5] = {
    {-0.0193, -0.2592}, {-0.0665, 0.0008}, {-0.0004, 0.2125}, {-0.0641, -0.8989}, {-0.0033, 0.0452}};
constexpr Linear coeff_y[5] = {
    {-0.0167, -0.2608}, {-0.0950, 0.0092}, {-0.0079, 0.2102}, {-0.0441, -1.6537}, {-0.0109, 0.0529}};

/// Preetham 1999 Appendix A.2: the zenith chromaticity x_z = (T², T, 1) M (θs³, θs², θs, 1)ᵀ;
/// rows of M for T², T and 1.
constexpr double zenith_x[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                   {-0.02903, 0.06377, -0.03202, 0.00394},
                                   {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr double zenith_y[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                   {-0.04214, 0.08970, -0.04153, 0.00516},
                                   {0.15346, -0.26756, 0.06670, 0.26688}};

PerezCoefficients perez_at(const Linear (&c)[5], double t) noexcept {
    return {c[0].at(t), c[1].at(t), c[2].at(t), c[3].at(t), c[4].at(t)};
}

double zenith_polynomial(const double (&m)[3][4], double t, double theta_s) noexcept {
    const double th[4] = {theta_s * theta_s * theta_s, theta_s * theta_s, theta_s, 1.0};
    const double tt[3] = {t * t, t, 1.0};
    double sum = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) sum += tt[i] * m[i][j] * th[j];
    return sum;
}

// --- The sun (Preetham 1999 Appendix A.1; the data are Iqbal 1983's) -----------------------

/// The extraterrestrial sun's spectral radiance [W m⁻² sr⁻¹ nm⁻¹], 380–750 nm every 10 nm
/// (Preetham 1999 Appendix A.1, its table of spectral quantities for sunlight).
constexpr double solar_first_nm = 380, solar_step_nm = 10;
constexpr double solar_radiance[38] = {
    16559.0, 16233.7, 21127.5, 25888.2, 25829.1, 24232.3, 26760.5, 29658.3, 30545.4, 30057.5,
    30663.7, 28830.4, 28712.1, 27825.0, 27100.6, 27233.6, 26361.3, 25503.8, 25060.2, 25311.6,
    25355.9, 25134.2, 24631.5, 24173.2, 23685.3, 23212.1, 22827.7, 22339.8, 21970.2, 21526.7,
    21097.9, 20728.3, 20240.4, 19870.8, 19427.2, 19072.4, 18628.9, 18259.2};

/// An absorption coefficient tabulated at irregular wavelengths [nm → cm⁻¹], linear between
/// them and 0 outside.
struct Tabulated {
    const double* nm;
    const double* k;
    int n;
    [[nodiscard]] double at(double lambda) const noexcept {
        if (lambda < nm[0] || lambda > nm[n - 1]) return 0.0;
        int i = 0;
        while (i + 2 < n && lambda > nm[i + 1]) ++i;
        const double f = (lambda - nm[i]) / (nm[i + 1] - nm[i]);
        return k[i] + f * (k[i + 1] - k[i]);
    }
};

/// Ozone's absorption coefficient k_o [cm⁻¹] (Preetham 1999 Appendix A.1, after Iqbal 1983).
constexpr double ozone_nm[] = {300, 305, 310, 315, 320, 325, 330, 335, 340, 345, 350, 355, 445,
                               450, 455, 460, 465, 470, 475, 480, 485, 490, 495, 500, 505, 510,
                               515, 520, 525, 530, 535, 540, 545, 550, 555, 560, 565, 570, 575,
                               580, 585, 590, 595, 600, 605, 610, 620, 630, 640, 650, 660, 670,
                               680, 690, 700, 710, 720, 730, 740, 750, 760, 770, 780, 790};
constexpr double ozone_k[] = {10.0,  4.8,   2.7,   1.35,  0.8,   0.38,  0.16,  0.075, 0.04,
                              0.019, 0.007, 0.0,   0.003, 0.003, 0.004, 0.006, 0.008, 0.009,
                              0.012, 0.014, 0.017, 0.021, 0.025, 0.03,  0.035, 0.04,  0.045,
                              0.048, 0.057, 0.063, 0.07,  0.075, 0.08,  0.085, 0.095, 0.103,
                              0.11,  0.12,  0.122, 0.12,  0.118, 0.115, 0.12,  0.125, 0.13,
                              0.12,  0.105, 0.09,  0.079, 0.067, 0.057, 0.048, 0.036, 0.028,
                              0.023, 0.018, 0.014, 0.011, 0.01,  0.009, 0.007, 0.004, 0.0,
                              0.0};
static_assert(std::size(ozone_nm) == std::size(ozone_k));
/// Mixed gases' absorption coefficient k_g [cm⁻¹] (the oxygen band at 760 nm; ibid.).
constexpr double gas_nm[] = {759, 760, 770, 771};
constexpr double gas_k[] = {0.0, 3.0, 0.21, 0.0};
/// Water vapour's absorption coefficient k_wa [cm⁻¹] (ibid.).
constexpr double water_nm[] = {689, 690, 700, 710, 720, 730, 740, 750, 760, 770, 780, 790, 800};
constexpr double water_k[] = {0.0,   0.016,  0.024,  0.0125, 1.0,    0.87,  0.061,
                              0.001, 1.0e-5, 1.0e-5, 6.0e-4, 0.0175, 0.036};
static_assert(std::size(water_nm) == std::size(water_k));

/// Preetham 1999 Appendix A.1's atmosphere: ozone 0.35 cm, precipitable water 2 cm, the
/// aerosols' Ångström exponent 1.3.
constexpr double ozone_cm = 0.35, water_cm = 2.0, angstrom_alpha = 1.3;

void check_turbidity(double turbidity) {
    if (!(turbidity >= PreethamSky::min_turbidity && turbidity <= PreethamSky::max_turbidity))
        throw Error(fmt::format("Preetham sky: turbidity is {}; allowed: [{}, {}]", turbidity,
                                PreethamSky::min_turbidity, PreethamSky::max_turbidity));
}

}  // namespace

double perez(const PerezCoefficients& p, double cos_theta, double gamma) noexcept {
    const double c = std::clamp(cos_theta, 0.0, 1.0);
    // e^{B / cos θ} → 0 at the horizon for B < 0 (every turbidity in range).
    const double first = 1.0 + p.a * (c > 0 ? std::exp(p.b / c) : (p.b < 0 ? 0.0 : 1.0));
    const double cg = std::cos(gamma);
    return first * (1.0 + p.c * std::exp(p.d * gamma) + p.e * cg * cg);
}

PreethamCoefficients preetham_coefficients(double t) noexcept {
    return {perez_at(coeff_Y, t), perez_at(coeff_x, t), perez_at(coeff_y, t)};
}

double preetham_zenith_luminance(double t, double theta_s) noexcept {
    const double chi = (4.0 / 9.0 - t / 120.0) * (pi - 2.0 * theta_s);
    return (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
}

Xy preetham_zenith_chromaticity(double t, double theta_s) noexcept {
    return {zenith_polynomial(zenith_x, t, theta_s), zenith_polynomial(zenith_y, t, theta_s)};
}

DenseSpectrum preetham_sun_radiance(double turbidity, double theta_s) {
    check_turbidity(turbidity);
    if (!(theta_s >= 0.0 && theta_s <= pi / 2))
        throw Error(fmt::format("Preetham sun: zenith angle {} rad; allowed: [0, π/2]", theta_s));
    const double theta_deg = theta_s * 180.0 / pi;
    // Relative optical mass (Kasten 1966, as Preetham 1999 Appendix A.1 gives it).
    const double m = 1.0 / (std::cos(theta_s) + 0.15 * std::pow(93.885 - theta_deg, -1.253));
    const double beta = 0.04608 * turbidity - 0.04586;
    const Tabulated ozone{ozone_nm, ozone_k, static_cast<int>(std::size(ozone_nm))};
    const Tabulated gas{gas_nm, gas_k, static_cast<int>(std::size(gas_nm))};
    const Tabulated water{water_nm, water_k, static_cast<int>(std::size(water_nm))};
    return DenseSpectrum::from_function([&](double lambda) {
        const double pos = std::clamp((lambda - solar_first_nm) / solar_step_nm, 0.0, 37.0);
        const int i = std::min(static_cast<int>(pos), 36);
        const double f = pos - i;
        const double sol = solar_radiance[i] + f * (solar_radiance[i + 1] - solar_radiance[i]);
        const double um = lambda / 1000.0;
        const double tau_rayleigh = std::exp(-0.008735 * std::pow(um, -4.08) * m);
        const double tau_aerosol = std::exp(-beta * std::pow(um, -angstrom_alpha) * m);
        const double tau_ozone = std::exp(-ozone.at(lambda) * ozone_cm * m);
        const double kg = gas.at(lambda) * m;
        const double tau_gas = std::exp(-1.41 * kg / std::pow(1.0 + 118.93 * kg, 0.45));
        const double kw = water.at(lambda) * water_cm * m;
        const double tau_water = std::exp(-0.2385 * kw / std::pow(1.0 + 20.07 * kw, 0.45));
        return sol * tau_rayleigh * tau_aerosol * tau_ozone * tau_gas * tau_water;
    });
}

PreethamSky::PreethamSky(double turbidity, std::array<double, 3> sun)
    : m_turbidity(turbidity), m_sun{}, m_sun_zenith(0) {
    check_turbidity(turbidity);
    const double len = std::sqrt(sun[0] * sun[0] + sun[1] * sun[1] + sun[2] * sun[2]);
    if (!(len > 0) || !std::isfinite(len) || !(sun[1] / len > 0))
        throw Error(fmt::format("Preetham sky: the sun direction ({}, {}, {}) must point above "
                                "the horizon (y > 0)",
                                sun[0], sun[1], sun[2]));
    for (int i = 0; i < 3; ++i) m_sun[i] = sun[i] / len;
    m_sun_zenith = std::acos(std::clamp(m_sun[1], -1.0, 1.0));
    m_coeff = preetham_coefficients(turbidity);
    const Xy z = preetham_zenith_chromaticity(turbidity, m_sun_zenith);
    // The zenith (θ = 0) sees the sun at γ = θs.
    m_scale_Y = preetham_zenith_luminance(turbidity, m_sun_zenith) / perez(m_coeff.Y, 1.0, m_sun_zenith);
    m_scale_x = z.x / perez(m_coeff.x, 1.0, m_sun_zenith);
    m_scale_y = z.y / perez(m_coeff.y, 1.0, m_sun_zenith);
}

Xyy PreethamSky::xyy(std::array<double, 3> d) const noexcept {
    const double cos_theta = std::clamp(d[1], 0.0, 1.0);
    // The view below the horizon is taken at the horizon: d's elevation set to 0.
    std::array<double, 3> v = d;
    if (d[1] < 0) {
        v[1] = 0;
        const double h = std::sqrt(v[0] * v[0] + v[2] * v[2]);
        if (h > 0) {
            v[0] /= h;
            v[2] /= h;
        } else {
            v = {1, 0, 0};
        }
    }
    const double cos_gamma = std::clamp(v[0] * m_sun[0] + v[1] * m_sun[1] + v[2] * m_sun[2], -1.0, 1.0);
    const double gamma = std::acos(cos_gamma);
    return {m_scale_x * perez(m_coeff.x, cos_theta, gamma),
            m_scale_y * perez(m_coeff.y, cos_theta, gamma),
            std::max(0.0, m_scale_Y * perez(m_coeff.Y, cos_theta, gamma))};
}

Xyz PreethamSky::xyz(std::array<double, 3> d) const noexcept {
    const Xyy c = xyy(d);
    if (!(c.y > 0)) return {};
    return {c.x * c.Y / c.y, c.Y, (1.0 - c.x - c.y) * c.Y / c.y};
}

}  // namespace irid::render
