#pragma once

// Ray-tracing geometry for irid's renderer: vectors, rays, affine transforms, bounding boxes, the
// sphere, the plane, and triangle meshes with a bounding volume hierarchy and an OBJ reader.
//
// Conventions: right-handed coordinates, +y up in the thesis scenes; lengths in scene units (the
// scenes choose them). Ray directions are unit vectors, so t is a distance. Intersection routines
// report the nearest hit with t in the open interval (t_min, t_max); they never offset rays
// against self-intersection: the caller passes t_min (e.g. 1e-6 × the scene's size).
//
// Objects validate their parameters when built (throwing irid::Error naming the parameter and
// what is allowed); intersection routines are noexcept, allocate nothing and check nothing.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <vector>

namespace irid::render {

// --- Vectors ------------------------------------------------------------------------------------

/// A point, direction or normal in scene units (or a dimensionless triple).
struct Vec3 {
    double x = 0, y = 0, z = 0;

    /// Component i: 0 → x, 1 → y, 2 → z (precondition 0 <= i <= 2).
    [[nodiscard]] constexpr double operator[](int i) const noexcept {
        return i == 0 ? x : (i == 1 ? y : z);
    }
    constexpr Vec3& operator+=(Vec3 b) noexcept {
        x += b.x;
        y += b.y;
        z += b.z;
        return *this;
    }
    constexpr Vec3& operator-=(Vec3 b) noexcept {
        x -= b.x;
        y -= b.y;
        z -= b.z;
        return *this;
    }
    constexpr Vec3& operator*=(double s) noexcept {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    constexpr Vec3& operator/=(double s) noexcept {
        x /= s;
        y /= s;
        z /= s;
        return *this;
    }
    friend constexpr bool operator==(Vec3, Vec3) noexcept = default;
};

[[nodiscard]] constexpr Vec3 operator+(Vec3 a, Vec3 b) noexcept {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
[[nodiscard]] constexpr Vec3 operator-(Vec3 a, Vec3 b) noexcept {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
[[nodiscard]] constexpr Vec3 operator-(Vec3 a) noexcept {
    return {-a.x, -a.y, -a.z};
}
[[nodiscard]] constexpr Vec3 operator*(Vec3 a, double s) noexcept {
    return {a.x * s, a.y * s, a.z * s};
}
[[nodiscard]] constexpr Vec3 operator*(double s, Vec3 a) noexcept {
    return {s * a.x, s * a.y, s * a.z};
}
[[nodiscard]] constexpr Vec3 operator/(Vec3 a, double s) noexcept {
    return {a.x / s, a.y / s, a.z / s};
}
/// Component-wise product (colours, scale factors).
[[nodiscard]] constexpr Vec3 operator*(Vec3 a, Vec3 b) noexcept {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
/// Component-wise product, by name.
[[nodiscard]] constexpr Vec3 mul(Vec3 a, Vec3 b) noexcept {
    return a * b;
}

[[nodiscard]] constexpr double dot(Vec3 a, Vec3 b) noexcept {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
[[nodiscard]] constexpr Vec3 cross(Vec3 a, Vec3 b) noexcept {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
[[nodiscard]] inline double length(Vec3 a) noexcept {
    return std::sqrt(dot(a, a));
}
/// a / |a|. Precondition: a is non-zero and finite.
[[nodiscard]] inline Vec3 normalize(Vec3 a) noexcept {
    return a / length(a);
}
/// The mirror direction d - 2 (d·n) n of d about the unit normal n.
[[nodiscard]] constexpr Vec3 reflect(Vec3 d, Vec3 n) noexcept {
    return d - 2.0 * dot(d, n) * n;
}

[[nodiscard]] constexpr Vec3 component_min(Vec3 a, Vec3 b) noexcept {
    return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}
[[nodiscard]] constexpr Vec3 component_max(Vec3 a, Vec3 b) noexcept {
    return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}
[[nodiscard]] inline bool is_finite(Vec3 a) noexcept {
    return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

// --- Rays and boxes -----------------------------------------------------------------------------

/// The half-line origin + t direction, t >= 0; direction is unit length (a precondition of every
/// intersection routine, which is what makes t a distance).
struct Ray {
    Vec3 origin;
    Vec3 direction;

    [[nodiscard]] constexpr Vec3 at(double t) const noexcept { return origin + t * direction; }
};

/// An axis-aligned box [lo, hi]. Default-constructed it is empty (lo = +∞, hi = -∞), the identity
/// of expand().
struct Aabb {
    Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
    Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
            -std::numeric_limits<double>::infinity()};

    /// True when the box contains no point (some lo > hi).
    [[nodiscard]] constexpr bool empty() const noexcept {
        return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z;
    }
    constexpr void expand(Vec3 p) noexcept {
        lo = component_min(lo, p);
        hi = component_max(hi, p);
    }
    constexpr void expand(const Aabb& b) noexcept {
        lo = component_min(lo, b.lo);
        hi = component_max(hi, b.hi);
    }
    [[nodiscard]] constexpr Vec3 centroid() const noexcept { return 0.5 * (lo + hi); }
    [[nodiscard]] constexpr Vec3 extent() const noexcept { return hi - lo; }
    /// 2 (dx dy + dy dz + dz dx); 0 for an empty box.
    [[nodiscard]] constexpr double surface_area() const noexcept {
        if (empty()) return 0.0;
        const Vec3 d = extent();
        return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
    [[nodiscard]] constexpr bool contains(Vec3 p) const noexcept {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
               p.z <= hi.z;
    }
    /// True when the ray meets the box for some t in [t_min, t_max] (slab test, Kay & Kajiya
    /// 1986). Conservative: the exit distance is enlarged by a few ulps so that rounding never
    /// loses a box a ray grazes (Ize, "Robust BVH Ray Traversal", JCGT 2(2), 2013).
    [[nodiscard]] bool intersect(const Ray& ray, double t_min, double t_max) const noexcept;
};

// --- Transforms ---------------------------------------------------------------------------------

/// An affine transform: p' = linear · p + translation; normals transform by the inverse transpose.
/// Always invertible: every factory validates its parameters, and compositions of invertible
/// maps are invertible. The inverse of the linear part is kept beside it.
struct Transform {
    /// Row-major 3×3 linear part; identity by default.
    std::array<std::array<double, 3>, 3> linear{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    Vec3 translation;
    /// The inverse of `linear`, row-major.
    std::array<std::array<double, 3>, 3> inverse_linear{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

    [[nodiscard]] static Transform identity() noexcept { return {}; }
    /// p' = p + offset. Requires finite components.
    [[nodiscard]] static Transform translate(Vec3 offset);
    /// p' = (sx px, sy py, sz pz). Requires finite, non-zero factors (negative ones mirror).
    [[nodiscard]] static Transform scale(Vec3 factors);
    /// Rotation by `degrees` about `axis` through the origin, counter-clockwise looking down the
    /// axis toward the origin (right-hand rule; Rodrigues' formula). Requires a finite non-zero
    /// axis and finite degrees.
    [[nodiscard]] static Transform rotate_deg(Vec3 axis, double degrees);
    /// A general affine map from its row-major linear part and translation. Requires finite
    /// entries and |det linear| > 1e-300 (invertible).
    [[nodiscard]] static Transform from_matrix(const std::array<std::array<double, 3>, 3>& linear,
                                               Vec3 translation);

    /// The composition that applies *this first, then next: next.point(this->point(p)).
    [[nodiscard]] Transform then(const Transform& next) const noexcept;
    /// The inverse map.
    [[nodiscard]] Transform inverse() const noexcept;

    /// linear · p + translation.
    [[nodiscard]] Vec3 point(Vec3 p) const noexcept;
    /// linear · v (directions and tangents: no translation).
    [[nodiscard]] Vec3 vector(Vec3 v) const noexcept;
    /// inverse_linear^T · n: perpendicular to every transformed tangent of the surface n was
    /// perpendicular to. Not renormalised (it is linear in n): normalize() it where a unit
    /// normal is needed.
    [[nodiscard]] Vec3 normal(Vec3 n) const noexcept;
    /// det linear: negative when the transform mirrors (and so reverses triangle winding).
    [[nodiscard]] double determinant() const noexcept;
};

// --- Surfaces -----------------------------------------------------------------------------------

/// What a ray hit.
struct SurfaceHit {
    double t = 0;
    Vec3 position;
    /// Geometric normal, unit; sphere: outward; plane: its normal; mesh: by winding,
    /// normalize(cross(p1 - p0, p2 - p0)) (counter-clockwise vertices face the viewer). Never
    /// flipped toward the ray: compare with the ray direction to tell the side.
    Vec3 normal;
    /// Interpolated vertex normals (unit) for meshes that have them; else equal to `normal`.
    Vec3 shading_normal;
    /// Sphere: u = azimuth/(2π) in [0,1) (right-handed about +y: u = 0 toward +x, 0.25 toward
    /// -z), v = (1 + (p−c)·y/r)/2 in [0,1] (0 at the bottom, 1 at the top).
    /// Plane: coordinates of (p − point) along its two tangent axes, in scene units.
    /// Mesh: OBJ texture coordinates if the mesh has them, else the barycentrics (b1, b2) of
    /// p = (1 − b1 − b2) p0 + b1 p1 + b2 p2.
    double u = 0, v = 0;
    /// Triangle index for meshes (into the triangles the mesh was built from); -1 otherwise.
    int primitive = -1;
};

/// A sphere. Hits from outside and from inside (where the far root is the nearest t > t_min).
class Sphere {
public:
    /// Requires a finite center and a finite radius > 0; else irid::Error.
    Sphere(Vec3 center, double radius);

    /// The nearest hit with t in (t_min, t_max); hit is written only when true is returned.
    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const noexcept;

    [[nodiscard]] Vec3 center() const noexcept { return m_center; }
    [[nodiscard]] double radius() const noexcept { return m_radius; }
    [[nodiscard]] Aabb bounds() const noexcept;

private:
    Vec3 m_center;
    double m_radius;
};

/// An ellipsoid with its semi-axes along x, y and z: ((x − cx)/a)² + ((y − cy)/b)² +
/// ((z − cz)/c)² = 1. A ray is intersected in the frame where the ellipsoid is the unit sphere
/// (the map is affine, so t is the same in both frames); the normal is the gradient of the
/// implicit function, normalize((p − c) / s²). u, v are the unit sphere's of that frame.
class Ellipsoid {
public:
    /// Requires a finite center and finite semi-axes > 0; else irid::Error.
    Ellipsoid(Vec3 center, Vec3 semi_axes);

    /// The nearest hit with t in (t_min, t_max); hit is written only when true is returned.
    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const noexcept;

    [[nodiscard]] Vec3 center() const noexcept { return m_center; }
    [[nodiscard]] Vec3 semi_axes() const noexcept { return m_axes; }
    [[nodiscard]] Aabb bounds() const noexcept { return {m_center - m_axes, m_center + m_axes}; }

private:
    Vec3 m_center, m_axes;
    Sphere m_unit{{0, 0, 0}, 1.0};
};

/// An infinite plane through `point` with unit normal `normal`, and two unit tangent axes u, v
/// with u × v = normal for its texture coordinates.
class Plane {
public:
    /// u_axis is made orthogonal to the normal (Gram–Schmidt) and unit; v = normal × u.
    /// Requires finite vectors, a non-zero normal, and u_axis not parallel to it (the angle
    /// between them at least 1e-6 rad); else irid::Error.
    Plane(Vec3 point, Vec3 normal, Vec3 u_axis = {1, 0, 0});

    /// The hit with t in (t_min, t_max); rays parallel to the plane miss. Two-sided.
    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const noexcept;

    [[nodiscard]] Vec3 point() const noexcept { return m_point; }
    [[nodiscard]] Vec3 normal() const noexcept { return m_normal; }
    [[nodiscard]] Vec3 u_axis() const noexcept { return m_u; }
    [[nodiscard]] Vec3 v_axis() const noexcept { return m_v; }

private:
    Vec3 m_point;
    Vec3 m_normal;
    Vec3 m_u;
    Vec3 m_v;
};

/// A triangle mesh with a bounding volume hierarchy.
///
/// Triangle test: the watertight ray/triangle intersection of Woop, Benthin and Wald, "Watertight
/// Ray/Triangle Intersection", JCGT 2(1), 2013: no ray passes between two triangles that share
/// an edge. Two-sided. Degenerate (zero-area) triangles are kept and never hit.
/// BVH: binned surface-area heuristic (16 bins per axis, all three axes; Wald, "On fast
/// construction of SAH-based bounding volume hierarchies", IEEE RT 2007), at most 8 triangles per
/// leaf, object-median splits below depth 48, flattened depth-first into one array; traversal is
/// iterative with a fixed stack, nearer child first, for the nearest hit and for any hit.
class TriangleMesh {
public:
    /// The largest mesh irid builds or reads [triangles]: about 1.2 GB of triangles and BVH
    /// (~120 bytes per triangle) plus the vertices.
    static constexpr std::size_t max_triangles = 10'000'000;
    /// The largest coordinate a vertex may have [scene units]: a triangle's cross product and a
    /// BVH box's surface area grow as the square of the coordinates and overflow a double
    /// (1.8e308) beyond about 1e154; 1e150 keeps both finite (scenes stay within ±1e4).
    static constexpr double max_coordinate = 1e150;

    /// `normals` and `uvs` are per vertex (same count as positions) or empty. Validates: at least
    /// one triangle and at most max_triangles; finite positions within ±max_coordinate; indices
    /// in [0, positions.size()); at least one triangle of non-zero area; finite non-zero normals
    /// (stored normalised); finite uvs. Then builds the BVH. Triangles of zero area (three
    /// vertices on a line, as OBJ exports often hold) are kept but never hit: they have no
    /// normal.
    TriangleMesh(std::vector<Vec3> positions, std::vector<std::array<int, 3>> triangles,
                 std::vector<Vec3> normals = {}, std::vector<std::array<double, 2>> uvs = {});

    /// Reads a Wavefront OBJ file: `v`, `vn`, `vt`, and `f` with `i`, `i/t`, `i//n`, `i/t/n`
    /// vertices (1-based, negative = relative to the last defined; vertices must be defined before
    /// use), polygons fan-triangulated, `#` comments, blank lines, `\` line continuation; `o`,
    /// `g`, `s`, `usemtl`, `mtllib`, `l`, `p` lines ignored. Vertices that index positions, uvs
    /// and normals independently are unified (duplicated as needed). Normals (uvs) are kept only
    /// when every face vertex has one. Throws irid::Error "<file>:<line>: <what>; <what is
    /// allowed>" for bad input, and for more than max_triangles triangles.
    [[nodiscard]] static TriangleMesh read_obj(const std::filesystem::path& file);
    /// As above with a lower budget: at most min(triangle_limit, max_triangles) triangles, and
    /// three times as many `v`, `vt` and `vn` lines each.
    [[nodiscard]] static TriangleMesh read_obj(const std::filesystem::path& file,
                                               std::size_t triangle_limit);

    /// A UV sphere: `slices` segments in azimuth (>= 3), `stacks` bands in latitude (>= 2),
    /// 2 · slices · (stacks − 1) triangles wound outward, vertices on the sphere with outward
    /// unit normals and uvs following Sphere's (u, v) convention (the seam duplicated).
    [[nodiscard]] static TriangleMesh uv_sphere(Vec3 center, double radius, int slices, int stacks);

    /// The mesh with positions mapped by t.point, normals by t.normal (renormalised); a mirroring
    /// transform (det < 0) swaps each triangle's last two vertices so that the winding normal
    /// keeps its side of the surface.
    [[nodiscard]] TriangleMesh transformed(const Transform& t) const;

    /// The nearest hit with t in (t_min, t_max), through the BVH. Among hits at exactly equal t
    /// the lowest triangle index wins, as in intersect_brute_force.
    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const noexcept;
    /// Whether any triangle is hit with t in (t_min, t_max): for shadow rays.
    bool occluded(const Ray& ray, double t_min, double t_max) const noexcept;
    /// The nearest hit by testing every triangle in index order (the reference and the baseline
    /// the BVH is measured against); same result as intersect().
    bool intersect_brute_force(const Ray& ray, double t_min, double t_max,
                               SurfaceHit& hit) const noexcept;

    [[nodiscard]] std::size_t triangle_count() const noexcept { return m_triangles.size(); }
    [[nodiscard]] Aabb bounds() const noexcept;
    [[nodiscard]] const std::vector<Vec3>& positions() const noexcept { return m_positions; }
    [[nodiscard]] const std::vector<std::array<int, 3>>& triangles() const noexcept {
        return m_triangles;
    }
    /// Unit vertex normals, or empty.
    [[nodiscard]] const std::vector<Vec3>& normals() const noexcept { return m_normals; }
    [[nodiscard]] const std::vector<std::array<double, 2>>& uvs() const noexcept { return m_uvs; }
    [[nodiscard]] std::size_t bvh_node_count() const noexcept { return m_nodes.size(); }
    /// Depth of the deepest BVH leaf (the root alone is depth 0).
    [[nodiscard]] int bvh_depth() const noexcept { return m_depth; }

    /// A node of the flattened BVH. Interior: the first child follows at index + 1, the second
    /// is at `offset`. Leaf (count > 0): triangles [offset, offset + count) of the BVH order.
    struct BvhNode {
        Aabb bounds;
        std::int32_t offset = 0;
        std::int32_t count = 0;
        std::int32_t axis = 0;
    };

private:
    /// A triangle's vertices in BVH order, for the traversal's cache.
    struct TriangleVertices {
        Vec3 p0, p1, p2;
    };
    void build_bvh();
    void finish_hit(int triangle, double t, double b1, double b2, SurfaceHit& hit) const noexcept;

    std::vector<Vec3> m_positions;
    std::vector<std::array<int, 3>> m_triangles;
    std::vector<Vec3> m_normals;
    std::vector<std::array<double, 2>> m_uvs;
    std::vector<BvhNode> m_nodes;
    std::vector<TriangleVertices> m_bvh_vertices;  ///< triangles in BVH order
    std::vector<std::int32_t> m_bvh_ids;           ///< BVH order → triangle index
    /// True when the triangle's cross product is not zero (only such triangles are hit).
    [[nodiscard]] bool has_area(std::size_t triangle) const noexcept;
    int m_depth = 0;
};

}  // namespace irid::render
