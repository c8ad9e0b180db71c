#pragma once

// What the tests of the film shader's algorithm (FilmShader::evaluate) share: the default
// shader, the working space's RGB back to XYZ, and the reference as the chunk returns it.

#include <irid/color/matrix.h>
#include <irid/optics/film_shader.h>

#include <algorithm>
#include <cmath>

namespace irid::test {

inline const Colorimeter& d65_srgb() {
    static const Colorimeter c;
    return c;
}

inline const FilmShader& default_shader() {
    static const FilmShader s(d65_srgb(), "D65", "srgb");
    return s;
}

/// The working space's RGB back to XYZ (the inverse of the colorimeter's matrix, whose columns
/// are the images of the unit vectors).
inline Xyz to_xyz(const Colorimeter& c, const Rgb& rgb) {
    const Rgb x = c.linear_rgb(Xyz{1.0, 0.0, 0.0}), y = c.linear_rgb(Xyz{0.0, 1.0, 0.0}),
              z = c.linear_rgb(Xyz{0.0, 0.0, 1.0});
    const Mat3 m = Mat3::from_columns({x.r, x.g, x.b}, {y.r, y.g, y.b}, {z.r, z.g, z.b});
    const Vec3 v = inverse(m) * Vec3{rgb.r, rgb.g, rgb.b};
    return {v[0], v[1], v[2]};
}

/// A reference colour as the chunk returns it: linear RGB with negative channels (a saturated
/// film outside the working space) at 0, as three.js's own chunk clamps.
inline Xyz clamped(const Colorimeter& c, const Xyz& xyz) {
    Rgb rgb = c.linear_rgb(xyz);
    rgb.r = std::max(rgb.r, 0.0);
    rgb.g = std::max(rgb.g, 0.0);
    rgb.b = std::max(rgb.b, 0.0);
    return to_xyz(c, rgb);
}

/// glTF's F0 of a base index (KHR_materials_ior: F0 = ((n − 1)/(n + 1))², against air).
inline float f0_of(double n) {
    return static_cast<float>(std::pow((n - 1.0) / (n + 1.0), 2.0));
}

/// The base index the chunk derives from an F0, rounded as it rounds it.
inline double base_index_of(float f0) {
    const float s = std::sqrt(f0);
    return static_cast<double>((1.0f + s) / (1.0f - s));
}

/// A value as the chunk receives it: references take the float inputs too, since near grazing
/// incidence an ambient that matches the base or the film to a float's rounding still decides
/// the reflectance.
inline double as_float(double v) {
    return static_cast<double>(static_cast<float>(v));
}

}  // namespace irid::test
