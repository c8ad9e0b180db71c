#pragma once

#include <irid/render/geometry.h>

namespace irid::render {

/// A pinhole camera with look-at.
///
/// The image plane lies at distance 1 along the view direction and spans
/// 2 tan(fov/2) · aspect by 2 tan(fov/2); image x grows to the right (forward × up) and image y
/// grows downward, so (0, 0) is the top-left corner and (1, 1) the bottom-right.
class Camera {
public:
    /// Validates: all inputs finite; eye != look_at; up non-zero and not parallel to the view
    /// direction (an angle of at least 1e-6 rad between them); 0 < vertical_fov_deg < 180;
    /// aspect (width / height) > 0 and finite. Throws irid::Error naming the parameter.
    Camera(Vec3 eye, Vec3 look_at, Vec3 up, double vertical_fov_deg, double aspect);

    /// The ray from the eye through the image-plane point (sx, sy) ∈ [0,1]², (0,0) = top-left
    /// corner, (1,1) = bottom-right; values outside [0,1] extrapolate the plane. Unit direction.
    [[nodiscard]] Ray ray(double sx, double sy) const noexcept;

    [[nodiscard]] Vec3 eye() const noexcept { return m_eye; }
    /// Unit view direction, normalize(look_at − eye).
    [[nodiscard]] Vec3 forward() const noexcept { return m_forward; }
    /// Unit image right, normalize(forward × up).
    [[nodiscard]] Vec3 right() const noexcept { return m_right; }
    /// Unit image up, right × forward: the given up made orthogonal to forward.
    [[nodiscard]] Vec3 up() const noexcept { return m_up; }
    [[nodiscard]] double vertical_fov_deg() const noexcept { return m_vertical_fov_deg; }
    [[nodiscard]] double aspect() const noexcept { return m_aspect; }

private:
    Vec3 m_eye;
    Vec3 m_forward;
    Vec3 m_right;
    Vec3 m_up;
    double m_vertical_fov_deg;
    double m_aspect;
    /// tan(fov/2) and aspect · tan(fov/2): half the image plane's height and width at distance 1.
    double m_half_height;
    double m_half_width;
};

}  // namespace irid::render
