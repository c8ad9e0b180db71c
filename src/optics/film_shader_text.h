#pragma once

// Literals for the shader chunks FilmShader writes (film_shader_glsl.cpp): constants that read
// back to the same float the CPU mirror uses.

#include <array>
#include <string>
#include <string_view>

namespace irid::film_shader_text {

/// A float literal that reads back to the same float (9 significant digits; always with a point
/// or an exponent, as GLSL ES 3.00 §4.1.5 and WGSL's abstract floats both accept).
[[nodiscard]] std::string float_literal(double v);

/// "vec3(r, g, b)" of three float literals (`type` "vec3f" for WGSL).
[[nodiscard]] std::string vec3_literal(const std::array<double, 3>& v, std::string_view type = "vec3");

}  // namespace irid::film_shader_text
