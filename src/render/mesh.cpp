// Triangle meshes: validation, the watertight triangle test, the binned-SAH BVH and its
// traversal, and the UV sphere. The Wavefront OBJ reader is in obj_reader.cpp.

#include <irid/color/numeric_table.h>
#include <irid/error.h>
#include <irid/render/geometry.h>
#include <irid/text_input.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <utility>
#include <vector>

namespace irid::render {
namespace {

// --- BVH parameters -------------------------------------------------------------------------

/// Bins per axis of the binned SAH build (Wald 2007 finds 16 close to a full sweep).
inline constexpr int sah_bins = 16;
/// Cost of visiting an interior node relative to one triangle test [dimensionless]: a tuning
/// constant of the SAH (MacDonald & Booth 1990). On bench/render_geometry_bench.cpp, costs 0.5,
/// 1 and 2 with leaves of at most 4 or 8 triangles all traced within 3 % of each other.
inline constexpr double sah_traversal_cost = 1.0;
/// Largest leaf [triangles]: larger nodes are split even when the SAH prefers a leaf.
inline constexpr int max_leaf_triangles = 8;
/// Depth below which splits are by object median instead of the SAH, which bounds the depth of
/// any tree to 48 + log2(max_triangles) < 72 whatever the triangle distribution.
inline constexpr int sah_max_depth = 48;
/// Traversal stack entries: at least the deepest tree's depth.
inline constexpr int traversal_stack_size = 96;

/// Unit roundoff of double, 2^-53, and the conservative slab factor 1 + 2γ(3) of Ize,
/// "Robust BVH Ray Traversal", JCGT 2(2), 2013 (as in Aabb::intersect).
inline constexpr double unit_roundoff = std::numeric_limits<double>::epsilon() / 2.0;
inline constexpr double slab_exit_factor =
    1.0 + 2.0 * (3.0 * unit_roundoff / (1.0 - 3.0 * unit_roundoff));

// --- The watertight triangle test (Woop, Benthin & Wald, JCGT 2(1), 2013) ----------------

/// The per-ray constants of the watertight test: the axis kz of the direction's largest
/// component becomes the ray's z, kx and ky follow it cyclically (swapped when d[kz] < 0 to keep
/// the winding), and the shear (sx, sy, sz) maps the direction onto (0, 0, 1).
struct PreparedRay {
    Vec3 origin;
    int kx, ky, kz;
    double sx, sy, sz;
    Vec3 inv_direction;
    std::array<bool, 3> negative;
};

PreparedRay prepare(const Ray& ray) noexcept {
    const Vec3 d = ray.direction;
    const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    const int kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    int kx = (kz + 1) % 3;
    int ky = (kx + 1) % 3;
    if (d[kz] < 0.0) std::swap(kx, ky);
    PreparedRay r;
    r.origin = ray.origin;
    r.kx = kx;
    r.ky = ky;
    r.kz = kz;
    r.sx = d[kx] / d[kz];
    r.sy = d[ky] / d[kz];
    r.sz = 1.0 / d[kz];
    r.inv_direction = {1.0 / d.x, 1.0 / d.y, 1.0 / d.z};
    r.negative = {r.inv_direction.x < 0.0, r.inv_direction.y < 0.0, r.inv_direction.z < 0.0};
    return r;
}

/// The vertex relative to the ray origin, permuted to (kx, ky, kz).
struct Permuted {
    double x, y, z;
};
Permuted permute(Vec3 v, const PreparedRay& r) noexcept {
    const std::array<double, 3> a{v.x, v.y, v.z};
    return {a[static_cast<std::size_t>(r.kx)], a[static_cast<std::size_t>(r.ky)],
            a[static_cast<std::size_t>(r.kz)]};
}

/// The ray's distance t to the triangle's plane and the barycentrics b1, b2 of vertices p1, p2
/// when the ray's line passes through the triangle (edges included), for any t; false when it
/// passes outside or the triangle is degenerate as seen along the ray.
bool hit_triangle(const PreparedRay& r, Vec3 p0, Vec3 p1, Vec3 p2, double& t, double& b1,
                  double& b2) noexcept {
    const Permuted a = permute(p0 - r.origin, r);
    const Permuted b = permute(p1 - r.origin, r);
    const Permuted c = permute(p2 - r.origin, r);
    // Shear so that the ray runs along +z.
    const double ax = a.x - r.sx * a.z, ay = a.y - r.sy * a.z;
    const double bx = b.x - r.sx * b.z, by = b.y - r.sy * b.z;
    const double cx = c.x - r.sx * c.z, cy = c.y - r.sy * c.z;
    // Scaled barycentrics: edge functions of the 2-D triangle at the origin.
    double u = cx * by - cy * bx;
    double v = ax * cy - ay * cx;
    double w = bx * ay - by * ax;
    if (u == 0.0 || v == 0.0 || w == 0.0) {
        // On an edge, or a product that cancelled: decide in extended precision (the paper's
        // fallback from float to double, here from double to the x87 80-bit long double).
        using Wide = long double;
        u = static_cast<double>(Wide(cx) * Wide(by) - Wide(cy) * Wide(bx));
        v = static_cast<double>(Wide(ax) * Wide(cy) - Wide(ay) * Wide(cx));
        w = static_cast<double>(Wide(bx) * Wide(ay) - Wide(by) * Wide(ax));
    }
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
    const double det = u + v + w;
    if (det == 0.0) return false;
    const double az = r.sz * a.z, bz = r.sz * b.z, cz = r.sz * c.z;
    const double inv_det = 1.0 / det;
    t = (u * az + v * bz + w * cz) * inv_det;
    b1 = v * inv_det;
    b2 = w * inv_det;
    return true;
}

/// The slab test of a BVH node against [t_min, t_max], conservative as Aabb::intersect.
bool hit_box(const Aabb& box, const PreparedRay& r, double t_min, double t_max) noexcept {
    const double x0 = (box.lo.x - r.origin.x) * r.inv_direction.x;
    const double x1 = (box.hi.x - r.origin.x) * r.inv_direction.x;
    const double y0 = (box.lo.y - r.origin.y) * r.inv_direction.y;
    const double y1 = (box.hi.y - r.origin.y) * r.inv_direction.y;
    const double z0 = (box.lo.z - r.origin.z) * r.inv_direction.z;
    const double z1 = (box.hi.z - r.origin.z) * r.inv_direction.z;
    const double enter_x = r.negative[0] ? x1 : x0, exit_x = (r.negative[0] ? x0 : x1);
    const double enter_y = r.negative[1] ? y1 : y0, exit_y = (r.negative[1] ? y0 : y1);
    const double enter_z = r.negative[2] ? z1 : z0, exit_z = (r.negative[2] ? z0 : z1);
    // Comparisons written so that a NaN (0 · ∞, the origin on the slab plane of a parallel ray)
    // leaves the interval unchanged.
    if (enter_x > t_min) t_min = enter_x;
    if (enter_y > t_min) t_min = enter_y;
    if (enter_z > t_min) t_min = enter_z;
    if (exit_x * slab_exit_factor < t_max) t_max = exit_x * slab_exit_factor;
    if (exit_y * slab_exit_factor < t_max) t_max = exit_y * slab_exit_factor;
    if (exit_z * slab_exit_factor < t_max) t_max = exit_z * slab_exit_factor;
    // A relative slack of 1e-6 in t: a ray from 4e7 away grazing a sliver 1.8e7 long and 1 wide
    // missed its box by more than the slab factor allows while the watertight triangle test hit
    // the sliver (fuzz finding obj-4; 1e-9 was not enough, the cause is not yet understood). The
    // slack only visits a few more boxes; the exact test and the nearest t decide the hit.
    return t_min <= t_max + 1e-6 * (std::abs(t_max) + std::abs(t_min));
}

// --- BVH construction -----------------------------------------------------------------------

struct Builder {
    const std::vector<Aabb>& boxes;
    const std::vector<Vec3>& centroids;
    std::vector<std::int32_t>& ids;
    std::vector<TriangleMesh::BvhNode>& nodes;
    int max_depth_reached = 0;

    /// Builds the subtree over ids[begin, end) and returns its node index.
    std::int32_t build(std::int32_t begin, std::int32_t end, int depth) {
        max_depth_reached = std::max(max_depth_reached, depth);
        const auto index = static_cast<std::int32_t>(nodes.size());
        nodes.emplace_back();
        Aabb bounds, centroid_bounds;
        for (std::int32_t i = begin; i < end; ++i) {
            bounds.expand(boxes[static_cast<std::size_t>(ids[static_cast<std::size_t>(i)])]);
            centroid_bounds.expand(
                centroids[static_cast<std::size_t>(ids[static_cast<std::size_t>(i)])]);
        }
        nodes[static_cast<std::size_t>(index)].bounds = bounds;
        const std::int32_t count = end - begin;
        const Vec3 spread = centroid_bounds.extent();
        const int widest =
            spread.x >= spread.y ? (spread.x >= spread.z ? 0 : 2) : (spread.y >= spread.z ? 1 : 2);
        // Nothing to separate: one triangle, or all centroids at one point.
        if (count == 1 || !(spread[widest] > 0.0)) return make_leaf(index, begin, count);

        std::int32_t middle = -1;
        int axis = widest;
        const double area = bounds.surface_area();
        if (depth < sah_max_depth && area > 0.0) {
            const SahSplit split = best_sah_split(begin, end, centroid_bounds, area);
            // Costs scaled by the node's area: leaf = count · area (triangle cost 1),
            // split = traversal · area + Σ count_side · area_side.
            if (count <= max_leaf_triangles &&
                !(split.scaled_cost < static_cast<double>(count) * area)) {
                return make_leaf(index, begin, count);
            }
            if (split.axis >= 0) {
                axis = split.axis;
                const double lo = centroid_bounds.lo[axis];
                const double scale = sah_bins / centroid_bounds.extent()[axis];
                const auto first = ids.begin() + begin;
                const auto last = ids.begin() + end;
                middle = static_cast<std::int32_t>(
                    std::partition(first, last,
                                   [&](std::int32_t id) {
                                       return bin_of(centroids[static_cast<std::size_t>(id)][axis],
                                                     lo, scale) <= split.bin;
                                   }) -
                    ids.begin());
            }
        } else if (count <= max_leaf_triangles) {
            return make_leaf(index, begin, count);
        }
        if (middle <= begin || middle >= end) {
            // Object median along the widest centroid axis.
            axis = widest;
            middle = begin + count / 2;
            std::nth_element(ids.begin() + begin, ids.begin() + middle, ids.begin() + end,
                             [&](std::int32_t a, std::int32_t b) {
                                 return centroids[static_cast<std::size_t>(a)][axis] <
                                        centroids[static_cast<std::size_t>(b)][axis];
                             });
        }
        build(begin, middle, depth + 1);
        const std::int32_t second = build(middle, end, depth + 1);
        TriangleMesh::BvhNode& node = nodes[static_cast<std::size_t>(index)];
        node.offset = second;
        node.count = 0;
        node.axis = axis;
        return index;
    }

    std::int32_t make_leaf(std::int32_t index, std::int32_t begin, std::int32_t count) {
        TriangleMesh::BvhNode& node = nodes[static_cast<std::size_t>(index)];
        node.offset = begin;
        node.count = count;
        return index;
    }

    static int bin_of(double c, double lo, double scale) noexcept {
        // Compared as a double first: a NaN or a value beyond int must not reach the cast.
        const double x = (c - lo) * scale;
        if (!(x > 0.0)) return 0;
        if (!(x < sah_bins - 1.0)) return sah_bins - 1;
        return static_cast<int>(x);
    }

    struct SahSplit {
        int axis = -1;
        int bin = -1;  ///< bins [0, bin] go to the first child
        double scaled_cost = std::numeric_limits<double>::infinity();
    };

    SahSplit best_sah_split(std::int32_t begin, std::int32_t end, const Aabb& centroid_bounds,
                            double parent_area) const {
        SahSplit best;
        for (int axis = 0; axis < 3; ++axis) {
            const double extent = centroid_bounds.extent()[axis];
            if (!(extent > 0.0)) continue;
            const double lo = centroid_bounds.lo[axis];
            const double scale = sah_bins / extent;
            std::array<Aabb, sah_bins> bin_boxes{};
            std::array<std::int64_t, sah_bins> bin_counts{};
            for (std::int32_t i = begin; i < end; ++i) {
                const auto id = static_cast<std::size_t>(ids[static_cast<std::size_t>(i)]);
                const auto b = static_cast<std::size_t>(bin_of(centroids[id][axis], lo, scale));
                bin_boxes[b].expand(boxes[id]);
                ++bin_counts[b];
            }
            // Sweep from the right: the area × count of bins (k, sah_bins).
            std::array<double, sah_bins> right_cost{};
            Aabb right;
            std::int64_t right_count = 0;
            for (int k = sah_bins - 1; k > 0; --k) {
                right.expand(bin_boxes[static_cast<std::size_t>(k)]);
                right_count += bin_counts[static_cast<std::size_t>(k)];
                right_cost[static_cast<std::size_t>(k - 1)] =
                    right.surface_area() * static_cast<double>(right_count);
            }
            Aabb left;
            std::int64_t left_count = 0;
            for (int k = 0; k < sah_bins - 1; ++k) {
                left.expand(bin_boxes[static_cast<std::size_t>(k)]);
                left_count += bin_counts[static_cast<std::size_t>(k)];
                const std::int64_t total = end - begin;
                if (left_count == 0 || left_count == total) continue;
                const double cost = sah_traversal_cost * parent_area +
                                    left.surface_area() * static_cast<double>(left_count) +
                                    right_cost[static_cast<std::size_t>(k)];
                if (cost < best.scaled_cost) best = {axis, k, cost};
            }
        }
        return best;
    }
};

}  // namespace

// --- TriangleMesh ---------------------------------------------------------------------------

TriangleMesh::TriangleMesh(std::vector<Vec3> positions, std::vector<std::array<int, 3>> triangles,
                           std::vector<Vec3> normals, std::vector<std::array<double, 2>> uvs)
    : m_positions(std::move(positions)),
      m_triangles(std::move(triangles)),
      m_normals(std::move(normals)),
      m_uvs(std::move(uvs)) {
    if (m_triangles.empty()) {
        throw Error("TriangleMesh: triangles is empty; a mesh needs at least one triangle");
    }
    if (m_triangles.size() > max_triangles) {
        throw Error("TriangleMesh: " + std::to_string(m_triangles.size()) + " triangles; at most " +
                    std::to_string(max_triangles) + " are allowed");
    }
    const std::size_t n = m_positions.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 p = m_positions[i];
        if (!is_finite(p) || std::abs(p.x) > max_coordinate || std::abs(p.y) > max_coordinate ||
            std::abs(p.z) > max_coordinate) {
            throw Error("TriangleMesh: positions[" + std::to_string(i) +
                        "] must be finite and within +-1e150 on each axis");
        }
    }
    for (std::size_t i = 0; i < m_triangles.size(); ++i) {
        for (const int index : m_triangles[i]) {
            if (index < 0 || static_cast<std::size_t>(index) >= n) {
                throw Error(
                    "TriangleMesh: triangles[" + std::to_string(i) + "] index " +
                    std::to_string(index) + " is out of range; allowed 0 to " +
                    (n == 0 ? std::string("(none: positions is empty)") : std::to_string(n - 1)) +
                    " (" + std::to_string(n) + " positions)");
            }
        }
    }
    if (!m_normals.empty()) {
        if (m_normals.size() != n) {
            throw Error("TriangleMesh: normals has " + std::to_string(m_normals.size()) +
                        " entries; it must be empty or have one per position (" + std::to_string(n) +
                        ")");
        }
        for (std::size_t i = 0; i < n; ++i) {
            const double len = length(m_normals[i]);
            if (!is_finite(m_normals[i]) || !std::isfinite(len) || !(len > 0.0)) {
                throw Error("TriangleMesh: normals[" + std::to_string(i) +
                            "] must be finite and non-zero");
            }
            m_normals[i] = m_normals[i] / len;
        }
    }
    if (!m_uvs.empty()) {
        if (m_uvs.size() != n) {
            throw Error("TriangleMesh: uvs has " + std::to_string(m_uvs.size()) +
                        " entries; it must be empty or have one per position (" + std::to_string(n) +
                        ")");
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (!std::isfinite(m_uvs[i][0]) || !std::isfinite(m_uvs[i][1])) {
                throw Error("TriangleMesh: uvs[" + std::to_string(i) + "] must be finite");
            }
        }
    }
    build_bvh();
}

bool TriangleMesh::has_area(std::size_t triangle) const noexcept {
    const auto& tri = m_triangles[triangle];
    const Vec3 p0 = m_positions[static_cast<std::size_t>(tri[0])];
    const Vec3 n = cross(m_positions[static_cast<std::size_t>(tri[1])] - p0,
                         m_positions[static_cast<std::size_t>(tri[2])] - p0);
    return n.x != 0.0 || n.y != 0.0 || n.z != 0.0;
}

void TriangleMesh::build_bvh() {
    // Only triangles with an area go into the BVH: one of zero area has no normal to shade with.
    std::vector<std::int32_t> ids;
    ids.reserve(m_triangles.size());
    for (std::size_t i = 0; i < m_triangles.size(); ++i) {
        if (has_area(i)) ids.push_back(static_cast<std::int32_t>(i));
    }
    if (ids.empty()) {
        throw Error("TriangleMesh: every one of the " + std::to_string(m_triangles.size()) +
                    " triangles has zero area (its vertices lie on a line); a mesh needs one "
                    "with an area");
    }
    const std::size_t count = ids.size();
    std::vector<Aabb> boxes(m_triangles.size());
    std::vector<Vec3> centroids(m_triangles.size());
    for (const std::int32_t id : ids) {
        Aabb b;
        for (const int v : m_triangles[static_cast<std::size_t>(id)])
            b.expand(m_positions[static_cast<std::size_t>(v)]);
        boxes[static_cast<std::size_t>(id)] = b;
        centroids[static_cast<std::size_t>(id)] = b.centroid();
    }
    m_nodes.clear();
    m_nodes.reserve(2 * count - 1);  // a binary tree with count leaves at most
    Builder builder{boxes, centroids, ids, m_nodes};
    builder.build(0, static_cast<std::int32_t>(count), 0);
    m_depth = builder.max_depth_reached;
    m_nodes.shrink_to_fit();
    m_bvh_ids = std::move(ids);
    m_bvh_vertices.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const auto& tri = m_triangles[static_cast<std::size_t>(m_bvh_ids[i])];
        m_bvh_vertices[i] = {m_positions[static_cast<std::size_t>(tri[0])],
                             m_positions[static_cast<std::size_t>(tri[1])],
                             m_positions[static_cast<std::size_t>(tri[2])]};
    }
}

Aabb TriangleMesh::bounds() const noexcept {
    return m_nodes.front().bounds;
}

void TriangleMesh::finish_hit(int triangle, double t, double b1, double b2,
                              SurfaceHit& hit) const noexcept {
    const auto& tri = m_triangles[static_cast<std::size_t>(triangle)];
    const auto i0 = static_cast<std::size_t>(tri[0]);
    const auto i1 = static_cast<std::size_t>(tri[1]);
    const auto i2 = static_cast<std::size_t>(tri[2]);
    const Vec3 p0 = m_positions[i0], p1 = m_positions[i1], p2 = m_positions[i2];
    const double b0 = 1.0 - b1 - b2;
    hit.t = t;
    // On the triangle by construction (more accurate than origin + t · direction).
    hit.position = b0 * p0 + b1 * p1 + b2 * p2;
    const Vec3 n = cross(p1 - p0, p2 - p0);
    hit.normal = normalize(n);
    hit.shading_normal = hit.normal;
    if (!m_normals.empty()) {
        const Vec3 s = b0 * m_normals[i0] + b1 * m_normals[i1] + b2 * m_normals[i2];
        const double len = length(s);
        if (len > 0.0) hit.shading_normal = s / len;
    }
    if (!m_uvs.empty()) {
        hit.u = b0 * m_uvs[i0][0] + b1 * m_uvs[i1][0] + b2 * m_uvs[i2][0];
        hit.v = b0 * m_uvs[i0][1] + b1 * m_uvs[i1][1] + b2 * m_uvs[i2][1];
    } else {
        hit.u = b1;
        hit.v = b2;
    }
    hit.primitive = triangle;
}

bool TriangleMesh::intersect(const Ray& ray, double t_min, double t_max,
                             SurfaceHit& hit) const noexcept {
    const PreparedRay r = prepare(ray);
    double best_t = t_max, best_b1 = 0.0, best_b2 = 0.0;
    std::int32_t best_id = -1;
    std::array<std::int32_t, traversal_stack_size> stack;
    int top = 0;
    std::int32_t current = 0;
    while (true) {
        const BvhNode& node = m_nodes[static_cast<std::size_t>(current)];
        // The box's entry distance carries its own rounding: a box flat along the ray's axis
        // can enter a few ulps beyond the very hit it holds, so the cull allows for it (the
        // exact comparison of t below keeps the answer exact).
        if (hit_box(node.bounds, r, t_min, best_t > 0.0 ? best_t * slab_exit_factor : best_t)) {
            if (node.count > 0) {
                for (std::int32_t i = node.offset; i < node.offset + node.count; ++i) {
                    const TriangleVertices& tri = m_bvh_vertices[static_cast<std::size_t>(i)];
                    double t, b1, b2;
                    if (!hit_triangle(r, tri.p0, tri.p1, tri.p2, t, b1, b2)) continue;
                    const std::int32_t id = m_bvh_ids[static_cast<std::size_t>(i)];
                    // Ties at equal t go to the lowest index, as in the brute-force loop.
                    if (t > t_min && (t < best_t || (t == best_t && id < best_id))) {
                        best_t = t;
                        best_b1 = b1;
                        best_b2 = b2;
                        best_id = id;
                    }
                }
            } else {
                // Nearer child first: the first child holds the lower side of the split axis.
                const bool second_first = r.negative[static_cast<std::size_t>(node.axis)];
                stack[static_cast<std::size_t>(top++)] = second_first ? current + 1 : node.offset;
                current = second_first ? node.offset : current + 1;
                continue;
            }
        }
        if (top == 0) break;
        current = stack[static_cast<std::size_t>(--top)];
    }
    if (best_id < 0) return false;
    finish_hit(best_id, best_t, best_b1, best_b2, hit);
    return true;
}

bool TriangleMesh::occluded(const Ray& ray, double t_min, double t_max) const noexcept {
    const PreparedRay r = prepare(ray);
    std::array<std::int32_t, traversal_stack_size> stack;
    int top = 0;
    std::int32_t current = 0;
    while (true) {
        const BvhNode& node = m_nodes[static_cast<std::size_t>(current)];
        // Widened as in intersect: a hit just short of t_max may sit in a box entered beyond it.
        if (hit_box(node.bounds, r, t_min, t_max > 0.0 ? t_max * slab_exit_factor : t_max)) {
            if (node.count > 0) {
                for (std::int32_t i = node.offset; i < node.offset + node.count; ++i) {
                    const TriangleVertices& tri = m_bvh_vertices[static_cast<std::size_t>(i)];
                    double t, b1, b2;
                    if (hit_triangle(r, tri.p0, tri.p1, tri.p2, t, b1, b2) && t > t_min &&
                        t < t_max) {
                        return true;
                    }
                }
            } else {
                const bool second_first = r.negative[static_cast<std::size_t>(node.axis)];
                stack[static_cast<std::size_t>(top++)] = second_first ? current + 1 : node.offset;
                current = second_first ? node.offset : current + 1;
                continue;
            }
        }
        if (top == 0) break;
        current = stack[static_cast<std::size_t>(--top)];
    }
    return false;
}

bool TriangleMesh::intersect_brute_force(const Ray& ray, double t_min, double t_max,
                                         SurfaceHit& hit) const noexcept {
    const PreparedRay r = prepare(ray);
    double best_t = t_max, best_b1 = 0.0, best_b2 = 0.0;
    int best_id = -1;
    for (std::size_t i = 0; i < m_triangles.size(); ++i) {
        if (!has_area(i)) continue;  // as in the BVH
        const auto& tri = m_triangles[i];
        double t, b1, b2;
        if (hit_triangle(r, m_positions[static_cast<std::size_t>(tri[0])],
                         m_positions[static_cast<std::size_t>(tri[1])],
                         m_positions[static_cast<std::size_t>(tri[2])], t, b1, b2) &&
            t > t_min && t < best_t) {
            best_t = t;
            best_b1 = b1;
            best_b2 = b2;
            best_id = static_cast<int>(i);
        }
    }
    if (best_id < 0) return false;
    finish_hit(best_id, best_t, best_b1, best_b2, hit);
    return true;
}

TriangleMesh TriangleMesh::transformed(const Transform& t) const {
    std::vector<Vec3> positions(m_positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) positions[i] = t.point(m_positions[i]);
    std::vector<Vec3> normals(m_normals.size());
    for (std::size_t i = 0; i < normals.size(); ++i) {
        normals[i] = normalize(t.normal(m_normals[i]));
    }
    std::vector<std::array<int, 3>> triangles = m_triangles;
    if (t.determinant() < 0.0) {
        for (auto& tri : triangles) std::swap(tri[1], tri[2]);
    }
    return TriangleMesh(std::move(positions), std::move(triangles), std::move(normals), m_uvs);
}

TriangleMesh TriangleMesh::uv_sphere(Vec3 center, double radius, int slices, int stacks) {
    if (!is_finite(center)) throw Error("TriangleMesh::uv_sphere: center must be finite");
    if (!std::isfinite(radius) || !(radius > 0.0)) {
        throw Error("TriangleMesh::uv_sphere: radius " + format_shortest(radius) +
                    " must be finite and > 0");
    }
    if (slices < 3 || stacks < 2) {
        throw Error("TriangleMesh::uv_sphere: slices " + std::to_string(slices) + " and stacks " +
                    std::to_string(stacks) + " must be >= 3 and >= 2");
    }
    const auto triangle_total =
        2 * static_cast<std::size_t>(slices) * static_cast<std::size_t>(stacks - 1);
    if (triangle_total > max_triangles) {
        throw Error(
            "TriangleMesh::uv_sphere: 2 slices (stacks - 1) = " + std::to_string(triangle_total) +
            " triangles; at most " + std::to_string(max_triangles) + " are allowed");
    }
    const auto columns = static_cast<std::size_t>(slices) + 1;
    std::vector<Vec3> positions, normals;
    std::vector<std::array<double, 2>> uvs;
    positions.reserve(columns * static_cast<std::size_t>(stacks + 1));
    normals.reserve(positions.capacity());
    uvs.reserve(positions.capacity());
    for (int j = 0; j <= stacks; ++j) {
        // Polar angle from +y; the poles exact.
        const double theta = std::numbers::pi * j / stacks;
        const double y = j == 0 ? 1.0 : (j == stacks ? -1.0 : std::cos(theta));
        const double ring = (j == 0 || j == stacks) ? 0.0 : std::sin(theta);
        for (int i = 0; i <= slices; ++i) {
            // Azimuth right-handed about +y, from +x toward −z, as Sphere's u; the seam column
            // i = slices repeats i = 0 with u = 1.
            const double phi = 2.0 * std::numbers::pi * (i == slices ? 0 : i) / slices;
            const Vec3 n{ring * std::cos(phi), y, -ring * std::sin(phi)};
            positions.push_back(center + radius * n);
            normals.push_back(n);
            uvs.push_back({static_cast<double>(i) / slices, 0.5 * (1.0 + y)});
        }
    }
    std::vector<std::array<int, 3>> triangles;
    triangles.reserve(triangle_total);
    const auto at = [&](int j, int i) { return j * static_cast<int>(columns) + i; };
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            const int a = at(j, i), b = at(j + 1, i), c = at(j + 1, i + 1), d = at(j, i + 1);
            // The quad a b c d runs counter-clockwise seen from outside.
            if (j != stacks - 1) triangles.push_back({a, b, c});
            if (j != 0) triangles.push_back({a, c, d});
        }
    }
    return TriangleMesh(std::move(positions), std::move(triangles), std::move(normals),
                        std::move(uvs));
}

}  // namespace irid::render
