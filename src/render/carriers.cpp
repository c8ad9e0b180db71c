#include "carriers.h"

#include <irid/color/illuminant.h>
#include <irid/color/matrix.h>
#include <irid/color/observer.h>
#include <irid/color/rgb.h>

namespace irid::render {
namespace {

/// The colorimeter's XYZ → linear RGB as a matrix, read off its action on the unit vectors.
Mat3 xyz_to_rgb_of(const Colorimeter& c) {
    const Rgb x = c.linear_rgb({1, 0, 0});
    const Rgb y = c.linear_rgb({0, 1, 0});
    const Rgb z = c.linear_rgb({0, 0, 1});
    return Mat3::from_columns({x.r, x.g, x.b}, {y.r, y.g, y.b}, {z.r, z.g, z.b});
}

}  // namespace

SpectralBasis::SpectralBasis()
    : m_colorimeter(illuminant_d65(), Observer::cie1931_2deg, srgb()),
      m_rgb_to_xyz(inverse(xyz_to_rgb_of(m_colorimeter), "the sRGB colorimeter")) {
    // RGB of the three colour-matching functions taken as spectra, as the columns of M; the
    // combinations B = CMF · M⁻¹ then have RGB(B_c) = e_c.
    const auto& cmf = color_matching_functions(Observer::cie1931_2deg);
    std::array<Rgb, 3> rgb_of_cmf;
    for (int k = 0; k < 3; ++k) {
        const Xyz c = m_colorimeter.xyz_of([&](double lambda) {
            const int i = static_cast<int>(lambda) - lambda_min_nm;
            return k == 0 ? cmf.x[i] : (k == 1 ? cmf.y[i] : cmf.z[i]);
        });
        rgb_of_cmf[k] = m_colorimeter.linear_rgb(c);
    }
    const Mat3 m = Mat3::from_columns({rgb_of_cmf[0].r, rgb_of_cmf[0].g, rgb_of_cmf[0].b},
                                      {rgb_of_cmf[1].r, rgb_of_cmf[1].g, rgb_of_cmf[1].b},
                                      {rgb_of_cmf[2].r, rgb_of_cmf[2].g, rgb_of_cmf[2].b});
    const Mat3 m_inv = inverse(m, "the colour-matching functions' RGB");
    for (int c = 0; c < 3; ++c) {
        for (int i = 0; i < dense_sample_count; ++i) {
            m_basis[c][i] = cmf.x[i] * m_inv[0][c] + cmf.y[i] * m_inv[1][c] + cmf.z[i] * m_inv[2][c];
        }
    }
}

SpectralCarrier SpectralBasis::from_rgb(const Rgb3& rgb) const noexcept {
    const double w = std::max(0.0, std::min({rgb[0], rgb[1], rgb[2]}));
    const double r = rgb[0] - w, g = rgb[1] - w, b = rgb[2] - w;
    SpectralCarrier s;
    for (int i = 0; i < dense_sample_count; ++i)
        s.v[i] = w + r * m_basis[0][i] + g * m_basis[1][i] + b * m_basis[2][i];
    return s;
}

Xyz SpectralBasis::xyz(const SpectralCarrier& s) const noexcept {
    return m_colorimeter.xyz_of(
        [&](double lambda) { return s.v[static_cast<int>(lambda) - lambda_min_nm]; });
}

Xyz SpectralBasis::xyz(const RgbCarrier& c) const noexcept {
    const irid::Vec3 x = m_rgb_to_xyz * irid::Vec3{c.v[0], c.v[1], c.v[2]};
    return {x[0], x[1], x[2]};
}

}  // namespace irid::render
