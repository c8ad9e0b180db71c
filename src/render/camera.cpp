#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/render/camera.h>

#include <cmath>
#include <numbers>
#include <string>

namespace irid::render {
namespace {

/// Smallest angle between the up vector and the view direction [rad]: closer to parallel, the
/// image's right axis forward × up loses most of its digits.
inline constexpr double min_up_angle_rad = 1e-6;

std::string text(Vec3 v) {
    return "(" + format_shortest(v.x) + ", " + format_shortest(v.y) + ", " + format_shortest(v.z) +
           ")";
}

}  // namespace

Camera::Camera(Vec3 eye, Vec3 look_at, Vec3 up, double vertical_fov_deg, double aspect)
    : m_eye(eye), m_vertical_fov_deg(vertical_fov_deg), m_aspect(aspect) {
    if (!is_finite(eye)) throw Error("Camera: eye " + text(eye) + " must be finite");
    if (!is_finite(look_at)) throw Error("Camera: look_at " + text(look_at) + " must be finite");
    if (!is_finite(up)) throw Error("Camera: up " + text(up) + " must be finite");
    if (!std::isfinite(vertical_fov_deg) || !(vertical_fov_deg > 0.0 && vertical_fov_deg < 180.0)) {
        throw Error("Camera: vertical_fov_deg " + format_shortest(vertical_fov_deg) +
                    " must be in (0, 180) degrees");
    }
    if (!std::isfinite(aspect) || !(aspect > 0.0)) {
        throw Error("Camera: aspect " + format_shortest(aspect) +
                    " (width / height) must be finite and > 0");
    }
    const Vec3 view = look_at - eye;
    const double view_length = length(view);
    if (!(view_length > 0.0) || !std::isfinite(view_length)) {
        throw Error("Camera: eye " + text(eye) + " and look_at " + text(look_at) +
                    " must be distinct (and their distance finite)");
    }
    const double up_length = length(up);
    if (!(up_length > 0.0) || !std::isfinite(up_length)) {
        throw Error("Camera: up " + text(up) + " must be non-zero");
    }
    m_forward = view / view_length;
    const Vec3 side = cross(m_forward, up / up_length);  // |side| = sin of the angle
    if (!(length(side) >= std::sin(min_up_angle_rad))) {
        throw Error("Camera: up " + text(up) + " is parallel to the view direction " +
                    text(m_forward) + "; it must make an angle of at least 1e-6 rad with it");
    }
    m_right = normalize(side);
    m_up = cross(m_right, m_forward);
    m_half_height = std::tan(0.5 * vertical_fov_deg * (std::numbers::pi / 180.0));
    m_half_width = aspect * m_half_height;
}

Ray Camera::ray(double sx, double sy) const noexcept {
    const double x = (2.0 * sx - 1.0) * m_half_width;
    const double y = (1.0 - 2.0 * sy) * m_half_height;
    return {m_eye, normalize(m_forward + x * m_right + y * m_up)};
}

}  // namespace irid::render
