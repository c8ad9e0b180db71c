#include <irid/color/colorimeter.h>
#include <irid/color/difference.h>
#include <irid/color/spaces.h>

#include <cmath>

namespace irid {
namespace {

Mat3 xyz_to_rgb_under(const Xyz& white, const RgbSpace& rgb, ChromaticAdaptation adaptation) {
    const Xyz& rgb_white = rgb.white_xyz();
    const bool same_white = std::abs(xyz_to_xy(white).x - rgb.white().x) < 1e-12 &&
                            std::abs(xyz_to_xy(white).y - rgb.white().y) < 1e-12;
    if (same_white) return rgb.from_xyz_matrix();
    return rgb.from_xyz_matrix() * adaptation_matrix(white, rgb_white, adaptation);
}

}  // namespace

Colorimeter::Colorimeter(const DenseSpectrum& illuminant, Observer observer, const RgbSpace& rgb,
                         ChromaticAdaptation adaptation)
    : m_white(illuminant_white(illuminant, observer)),
      m_observer(observer),
      m_rgb(rgb),
      m_xyz_to_rgb(xyz_to_rgb_under(m_white, rgb, adaptation)) {
    const ColorMatchingFunctions& cmf = color_matching_functions(observer);
    const double k = 1.0 / illuminant.dot(cmf.y);
    for (int i = 0; i < dense_sample_count; ++i) {
        m_weight_x[i] = k * illuminant[i] * cmf.x[i];
        m_weight_y[i] = k * illuminant[i] * cmf.y[i];
        m_weight_z[i] = k * illuminant[i] * cmf.z[i];
    }
}

Xyz Colorimeter::xyz(const DenseSpectrum& reflectance) const noexcept {
    return {reflectance.dot(m_weight_x), reflectance.dot(m_weight_y), reflectance.dot(m_weight_z)};
}

Rgb Colorimeter::linear_rgb(const Xyz& c) const noexcept {
    const Vec3 v = m_xyz_to_rgb * Vec3{c.X, c.Y, c.Z};
    return {v[0], v[1], v[2]};
}

Lab Colorimeter::lab(const Xyz& c) const noexcept { return xyz_to_lab(c, m_white); }

double delta_e_2000_of(const Colorimeter& colorimeter, const Xyz& a, const Xyz& b) noexcept {
    return delta_e_2000(colorimeter.lab(a), colorimeter.lab(b));
}

}  // namespace irid
