#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/render/geometry.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

namespace irid::render {
namespace {

using Matrix3 = std::array<std::array<double, 3>, 3>;

/// Unit roundoff of double, 2^-53.
inline constexpr double unit_roundoff = std::numeric_limits<double>::epsilon() / 2.0;
/// γ(n) = n u / (1 − n u), the relative error bound of n rounded operations (Higham, Accuracy
/// and Stability of Numerical Algorithms, 2nd ed., 2002, Lemma 3.1).
constexpr double gamma_bound(int n) noexcept {
    return n * unit_roundoff / (1.0 - n * unit_roundoff);
}
/// Factor on a slab test's exit distance that makes it conservative: each slab distance
/// (b − o) · (1/d) carries three roundings (Ize 2013, §3: 1 + 2γ(3)).
inline constexpr double slab_exit_factor = 1.0 + 2.0 * gamma_bound(3);

std::string text(Vec3 v) {
    return "(" + format_shortest(v.x) + ", " + format_shortest(v.y) + ", " + format_shortest(v.z) +
           ")";
}

Vec3 multiply(const Matrix3& m, Vec3 v) noexcept {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Matrix3 multiply(const Matrix3& a, const Matrix3& b) noexcept {
    Matrix3 r{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
        }
    }
    return r;
}

double determinant3(const Matrix3& m) noexcept {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/// The inverse by the adjugate; precondition det != 0.
Matrix3 inverse3(const Matrix3& m) noexcept {
    const double inv_det = 1.0 / determinant3(m);
    Matrix3 r{};
    r[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * inv_det;
    r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * inv_det;
    r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * inv_det;
    r[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * inv_det;
    r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * inv_det;
    r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * inv_det;
    r[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * inv_det;
    r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * inv_det;
    r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * inv_det;
    return r;
}

Matrix3 transpose(const Matrix3& m) noexcept {
    return {
        {{m[0][0], m[1][0], m[2][0]}, {m[0][1], m[1][1], m[2][1]}, {m[0][2], m[1][2], m[2][2]}}};
}

/// cos and sin of an angle in degrees, exact at multiples of 90° (so that quarter turns map
/// axes onto axes without a 6e-17 residue).
std::pair<double, double> cos_sin_deg(double degrees) noexcept {
    const double reduced = std::remainder(degrees, 360.0);  // exact, in [-180, 180]
    if (reduced == 0.0) return {1.0, 0.0};
    if (reduced == 90.0) return {0.0, 1.0};
    if (reduced == -90.0) return {0.0, -1.0};
    if (reduced == 180.0 || reduced == -180.0) return {-1.0, 0.0};
    const double rad = reduced * (std::numbers::pi / 180.0);
    return {std::cos(rad), std::sin(rad)};
}

/// Smallest angle allowed between a plane's normal and its u axis [rad]: below it, the
/// Gram–Schmidt step loses most digits.
inline constexpr double min_axis_angle_rad = 1e-6;

/// Smallest |det| of Transform::from_matrix: below it the inverse overflows.
inline constexpr double min_abs_determinant = 1e-300;

}  // namespace

// --- Aabb ---------------------------------------------------------------------------------------

bool Aabb::intersect(const Ray& ray, double t_min, double t_max) const noexcept {
    for (int axis = 0; axis < 3; ++axis) {
        const double inv = 1.0 / ray.direction[axis];
        double t0 = (lo[axis] - ray.origin[axis]) * inv;
        double t1 = (hi[axis] - ray.origin[axis]) * inv;
        if (t0 > t1) std::swap(t0, t1);
        t1 *= slab_exit_factor;
        // A NaN (0 · ∞: the origin on a slab plane of a parallel ray) leaves the interval as is.
        if (t0 > t_min) t_min = t0;
        if (t1 < t_max) t_max = t1;
        if (t_min > t_max) return false;
    }
    return true;
}

// --- Transform ----------------------------------------------------------------------------------

Transform Transform::translate(Vec3 offset) {
    if (!is_finite(offset)) {
        throw Error("Transform::translate: offset " + text(offset) + " must be finite");
    }
    Transform t;
    t.translation = offset;
    return t;
}

Transform Transform::scale(Vec3 factors) {
    if (!is_finite(factors) || factors.x == 0.0 || factors.y == 0.0 || factors.z == 0.0) {
        throw Error("Transform::scale: factors " + text(factors) +
                    " must be finite and non-zero (negative factors mirror)");
    }
    Transform t;
    t.linear = {{{factors.x, 0, 0}, {0, factors.y, 0}, {0, 0, factors.z}}};
    t.inverse_linear = {
        {{1.0 / factors.x, 0, 0}, {0, 1.0 / factors.y, 0}, {0, 0, 1.0 / factors.z}}};
    return t;
}

Transform Transform::rotate_deg(Vec3 axis, double degrees) {
    if (!is_finite(axis) || dot(axis, axis) == 0.0 || !std::isfinite(length(axis))) {
        throw Error("Transform::rotate_deg: axis " + text(axis) + " must be finite and non-zero");
    }
    if (!std::isfinite(degrees)) {
        throw Error("Transform::rotate_deg: degrees " + format_shortest(degrees) +
                    " must be finite");
    }
    const Vec3 k = normalize(axis);
    const auto [c, s] = cos_sin_deg(degrees);
    const double one_c = 1.0 - c;
    // Rodrigues: R = c I + s [k]× + (1 − c) k kᵀ.
    Transform t;
    t.linear = {
        {{c + one_c * k.x * k.x, one_c * k.x * k.y - s * k.z, one_c * k.x * k.z + s * k.y},
         {one_c * k.y * k.x + s * k.z, c + one_c * k.y * k.y, one_c * k.y * k.z - s * k.x},
         {one_c * k.z * k.x - s * k.y, one_c * k.z * k.y + s * k.x, c + one_c * k.z * k.z}}};
    t.inverse_linear = transpose(t.linear);  // a rotation is orthogonal
    return t;
}

Transform Transform::from_matrix(const Matrix3& linear, Vec3 translation) {
    for (const auto& row : linear) {
        for (const double e : row) {
            if (!std::isfinite(e)) {
                throw Error("Transform::from_matrix: linear part entry " + format_shortest(e) +
                            " must be finite");
            }
        }
    }
    if (!is_finite(translation)) {
        throw Error("Transform::from_matrix: translation " + text(translation) + " must be finite");
    }
    const double det = determinant3(linear);
    if (!(std::abs(det) > min_abs_determinant)) {
        throw Error("Transform::from_matrix: determinant of the linear part " +
                    format_shortest(det) + " must satisfy |det| > 1e-300 (invertible)");
    }
    Transform t;
    t.linear = linear;
    t.translation = translation;
    t.inverse_linear = inverse3(linear);
    return t;
}

Transform Transform::then(const Transform& next) const noexcept {
    // next(this(p)) = N (L p + t) + n = (N L) p + (N t + n); inverse (N L)⁻¹ = L⁻¹ N⁻¹.
    Transform r;
    r.linear = multiply(next.linear, linear);
    r.translation = multiply(next.linear, translation) + next.translation;
    r.inverse_linear = multiply(inverse_linear, next.inverse_linear);
    return r;
}

Transform Transform::inverse() const noexcept {
    // p = L⁻¹ (p' − t) = L⁻¹ p' − L⁻¹ t.
    Transform r;
    r.linear = inverse_linear;
    r.inverse_linear = linear;
    r.translation = -multiply(inverse_linear, translation);
    return r;
}

Vec3 Transform::point(Vec3 p) const noexcept {
    return multiply(linear, p) + translation;
}

Vec3 Transform::vector(Vec3 v) const noexcept {
    return multiply(linear, v);
}

Vec3 Transform::normal(Vec3 n) const noexcept {
    const Matrix3& m = inverse_linear;  // (m)ᵀ · n
    return {m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z,
            m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
            m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z};
}

double Transform::determinant() const noexcept {
    return determinant3(linear);
}

// --- Sphere -------------------------------------------------------------------------------------

Sphere::Sphere(Vec3 center, double radius) : m_center(center), m_radius(radius) {
    if (!is_finite(center)) {
        throw Error("Sphere: center " + text(center) + " must be finite");
    }
    if (!std::isfinite(radius) || !(radius > 0.0)) {
        throw Error("Sphere: radius " + format_shortest(radius) + " must be finite and > 0");
    }
}

bool Sphere::intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const noexcept {
    // |o + t d − c|² = r²: a t² + 2 b t + c = 0 with a = d·d, b = (o − c)·d, c = |o − c|² − r².
    // The quarter discriminant b² − a c is evaluated as a (r² − |f|²), f = (o − c) − (b/a) d the
    // offset of the centre from the ray's closest point, which does not cancel catastrophically
    // for distant origins (Haines et al., "Precision Improvements for Ray/Sphere Intersection",
    // Ray Tracing Gems, 2019, ch. 7); the roots come from q = −(b + sign(b) √Δ) as q/a and c/q
    // (Press et al., Numerical Recipes, 3rd ed., §5.6).
    const Vec3 oc = ray.origin - m_center;
    const Vec3 d = ray.direction;
    const double a = dot(d, d);
    const double b = dot(oc, d);
    const double c = dot(oc, oc) - m_radius * m_radius;
    const Vec3 f = oc - (b / a) * d;
    const double delta = a * (m_radius * m_radius - dot(f, f));
    if (delta < 0.0) return false;
    const double q = -(b + std::copysign(std::sqrt(delta), b));
    double t0 = q / a;
    double t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    double t = t0;
    if (!(t > t_min && t < t_max)) {
        t = t1;
        if (!(t > t_min && t < t_max)) return false;
    }
    hit.t = t;
    hit.position = ray.at(t);
    const Vec3 local = (hit.position - m_center) / m_radius;
    hit.normal = normalize(local);
    hit.shading_normal = hit.normal;
    // Azimuth right-handed about +y: from +x toward −z.
    double u = std::atan2(-local.z, local.x) / (2.0 * std::numbers::pi);
    if (u < 0.0) u += 1.0;
    if (u >= 1.0) u = 0.0;  // −0 and a tiny negative azimuth round up to exactly 1
    hit.u = u;
    const double y = hit.normal.y;
    hit.v = 0.5 * (1.0 + (y > 1.0 ? 1.0 : (y < -1.0 ? -1.0 : y)));
    hit.primitive = -1;
    return true;
}

Aabb Sphere::bounds() const noexcept {
    const Vec3 r{m_radius, m_radius, m_radius};
    return {m_center - r, m_center + r};
}

// --- Ellipsoid ----------------------------------------------------------------------------------

Ellipsoid::Ellipsoid(Vec3 center, Vec3 semi_axes) : m_center(center), m_axes(semi_axes) {
    if (!is_finite(center)) throw Error("Ellipsoid: center " + text(center) + " must be finite");
    if (!is_finite(semi_axes) || !(semi_axes.x > 0.0 && semi_axes.y > 0.0 && semi_axes.z > 0.0)) {
        throw Error("Ellipsoid: semi-axes " + text(semi_axes) + " must be finite and > 0");
    }
}

bool Ellipsoid::intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const noexcept {
    const Vec3 o = ray.origin - m_center;
    const Ray local{{o.x / m_axes.x, o.y / m_axes.y, o.z / m_axes.z},
                    {ray.direction.x / m_axes.x, ray.direction.y / m_axes.y, ray.direction.z / m_axes.z}};
    SurfaceHit h;
    if (!m_unit.intersect(local, t_min, t_max, h)) return false;
    hit = h;
    hit.position = ray.at(h.t);
    const Vec3 p = hit.position - m_center;
    hit.normal = normalize(Vec3{p.x / (m_axes.x * m_axes.x), p.y / (m_axes.y * m_axes.y),
                                p.z / (m_axes.z * m_axes.z)});
    hit.shading_normal = hit.normal;
    return true;
}

// --- Plane --------------------------------------------------------------------------------------

Plane::Plane(Vec3 point, Vec3 normal, Vec3 u_axis) : m_point(point) {
    if (!is_finite(point)) throw Error("Plane: point " + text(point) + " must be finite");
    if (!is_finite(normal) || dot(normal, normal) == 0.0 || !std::isfinite(length(normal))) {
        throw Error("Plane: normal " + text(normal) + " must be finite and non-zero");
    }
    if (!is_finite(u_axis) || dot(u_axis, u_axis) == 0.0 || !std::isfinite(length(u_axis))) {
        throw Error("Plane: u_axis " + text(u_axis) + " must be finite and non-zero");
    }
    m_normal = normalize(normal);
    const Vec3 u = normalize(u_axis);
    const Vec3 tangent = u - dot(u, m_normal) * m_normal;
    // |tangent| = sin of the angle between u_axis and the normal.
    if (!(length(tangent) >= std::sin(min_axis_angle_rad))) {
        throw Error("Plane: u_axis " + text(u_axis) + " is parallel to the normal " + text(normal) +
                    "; it must make an angle of at least 1e-6 rad with it");
    }
    m_u = normalize(tangent);
    m_v = cross(m_normal, m_u);
}

bool Plane::intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const noexcept {
    const double denom = dot(ray.direction, m_normal);
    if (denom == 0.0) return false;
    const double t = dot(m_point - ray.origin, m_normal) / denom;
    if (!(t > t_min && t < t_max)) return false;
    hit.t = t;
    hit.position = ray.at(t);
    hit.normal = m_normal;
    hit.shading_normal = m_normal;
    const Vec3 offset = hit.position - m_point;
    hit.u = dot(offset, m_u);
    hit.v = dot(offset, m_v);
    hit.primitive = -1;
    return true;
}

}  // namespace irid::render
