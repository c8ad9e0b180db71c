// The renderer: samples → integrator → reconstruction filter → colour pipeline.
#include "carriers.h"
#include "world.h"

#include <irid/color/difference.h>
#include <irid/color/illuminant.h>
#include <irid/color/measure.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/error.h>
#include <irid/gamut/batch.h>
#include <irid/gamut/clip.h>
#include <irid/gamut/display_transform.h>
#include <irid/gamut/tone.h>
#include <irid/render/render.h>

#include <fmt/core.h>
#include <fmt/ranges.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numbers>
#include <numeric>

namespace irid::render {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
/// Paths whose weight falls below this stop at the environment instead of branching on.
constexpr double min_path_weight = 2e-3;
/// Rays one camera ray may spawn: films split every ray in two, and nested bubbles seen near
/// grazing incidence (R ≈ T) would otherwise branch 2^depth times. Beyond the budget a branch
/// ends at the environment; the order of traversal is fixed, so the cut is deterministic.
constexpr int max_rays_per_camera_ray = 512;

// --- Random numbers: a hash of (seed, pixel, sample, dimension) --------------------------------

/// SplitMix64's finaliser (Steele, Lea & Flood 2014), a bijection of 64-bit words.
constexpr std::uint64_t mix(std::uint64_t z) noexcept {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double uniform(std::uint64_t seed, std::uint64_t pixel, int sample, int dimension) noexcept {
    const std::uint64_t h =
        mix(mix(mix(seed ^ 0x51a7e1d2ULL) + pixel) + (static_cast<std::uint64_t>(sample) << 8 |
                                                      static_cast<std::uint64_t>(dimension)));
    return static_cast<double>(h >> 11) * 0x1.0p-53;
}

/// Unpolarised Fresnel reflectance of a dielectric surface (Born & Wolf §1.5.2).
double fresnel_dielectric(double cos_i, double n) noexcept {
    cos_i = std::clamp(cos_i, 0.0, 1.0);
    const double sin_t2 = (1 - cos_i * cos_i) / (n * n);
    if (sin_t2 >= 1) return 1;
    const double cos_t = std::sqrt(1 - sin_t2);
    const double rs = (cos_i - n * cos_t) / (cos_i + n * cos_t);
    const double rp = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

Rgb3 scale(const Rgb3& a, const Rgb3& b) noexcept { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }

// --- The three colour paths ----------------------------------------------------------------------

struct TableOps {
    using Carrier = RgbCarrier;
    const World& world;
    [[nodiscard]] Carrier rgb(const Rgb3& c) const noexcept { return {c}; }
    [[nodiscard]] Carrier environment(Vec3 d, bool with_sun = true) const noexcept {
        return {world.environment(d, with_sun)};
    }
    [[nodiscard]] Carrier sun_glint(Vec3 r, double sigma) const noexcept {
        const double w = world.sun_lobe(r, sigma);
        const Rgb3 c = world.sun_rgb();
        return {{c[0] * w, c[1] * w, c[2] * w}};
    }
    [[nodiscard]] Carrier film(const ThicknessSample& t, double cos_theta) const noexcept {
        return {world.film_table().at(t.t_nm, t.footprint_nm, cos_theta)};
    }
    [[nodiscard]] Carrier wing(double theta_deg) const noexcept {
        return {world.wing_table().at(theta_deg)};
    }
    [[nodiscard]] Xyz xyz(const Carrier& c) const noexcept { return world.basis().xyz(c); }
};

/// The table path's RGB products with the film's colour by the Fourier series per hit.
struct FourierOps : TableOps {
    [[nodiscard]] Carrier film(const ThicknessSample& t, double cos_theta) const noexcept {
        return {world.film_fourier(t, cos_theta)};
    }
};

struct SpectralOps {
    using Carrier = SpectralCarrier;
    const World& world;
    [[nodiscard]] Carrier rgb(const Rgb3& c) const noexcept { return world.basis().from_rgb(c); }
    [[nodiscard]] Carrier environment(Vec3 d, bool with_sun = true) const noexcept {
        Carrier s;
        world.environment_spectrum(d, s, with_sun);
        return s;
    }
    [[nodiscard]] Carrier sun_glint(Vec3 r, double sigma) const noexcept {
        Carrier s;
        world.sun_glint_spectrum(r, sigma, s);
        return s;
    }
    [[nodiscard]] Carrier film(const ThicknessSample& t, double cos_theta) const {
        Carrier s;
        world.film_spectrum(t, cos_theta, s);
        return s;
    }
    [[nodiscard]] Carrier wing(double theta_deg) const noexcept {
        Carrier s;
        world.wing_spectrum(theta_deg, s);
        return s;
    }
    [[nodiscard]] Xyz xyz(const Carrier& c) const noexcept { return world.basis().xyz(c); }
};

// --- The integrator ------------------------------------------------------------------------------

template <class Ops>
class Integrator {
public:
    using C = typename Ops::Carrier;

    Integrator(const World& world, Ops ops)
        : m_world(world), m_ops(ops), m_scene(world.scene()), m_eps(world.epsilon()) {}

    std::uint64_t rays = 0;

    /// A camera ray and everything it spawns.
    C trace_camera_ray(const Ray& ray, const RayDifferential* diff) {
        m_budget = max_rays_per_camera_ray;
        return trace(ray, 0, 1.0, diff);
    }

private:
    C trace(const Ray& ray, int depth, double weight, const RayDifferential* diff) {
        ++rays;
        --m_budget;
        Hit hit;
        if (!m_world.intersect(ray, m_eps, infinity, hit))
            return m_ops.environment(ray.direction);
        const Vec3 d = ray.direction;
        const Vec3 p = hit.surface.position;
        Vec3 n = hit.surface.normal;
        if (dot(n, d) > 0) n = -n;  // facing the ray
        switch (hit.kind) {
            case SurfaceKind::pavement: return pavement(p, d, n, diff);
            case SurfaceKind::bubble: return bubble(hit, p, d, n, depth, weight, diff);
            case SurfaceKind::floor:
                return m_ops.rgb(scale(m_world.floor_albedo(p), m_world.diffuse_light(p, n)));
            case SurfaceKind::background:
                return m_ops.rgb(scale(m_world.background_albedo(p), m_world.diffuse_light(p, n)));
            case SurfaceKind::body:
                return m_ops.rgb(scale(m_scene.morpho.body_albedo, m_world.diffuse_light(p, n)));
            case SurfaceKind::wing:
            case SurfaceKind::wing_mesh: return wing(hit, p, d, n);
            case SurfaceKind::none: break;
        }
        return C::constant(0.0);
    }

    /// The thickness range a sample covers: the thickness at the neighbouring pixels' rays
    /// where they meet the surface's tangent plane, times the sample's share of the pixel.
    template <class F>
    double footprint(const RayDifferential* diff, Vec3 p, Vec3 n, double t0, F&& thickness_at) const {
        if (!diff || m_scene.render.antialias == FilmAntialias::none) return 0.0;
        double spread = 0;
        for (const Ray* r : {&diff->dx, &diff->dy}) {
            const double denom = dot(r->direction, n);
            if (std::abs(denom) < 1e-9) return 0.0;
            const double t = dot(p - r->origin, n) / denom;
            if (!(t > 0)) return 0.0;
            spread = std::max(spread, std::abs(thickness_at(r->at(t)) - t0));
        }
        return spread * diff->stratum;
    }

    C pavement(Vec3 p, Vec3 d, Vec3 n, const RayDifferential* diff) {
        Vec3 nb;
        Rgb3 albedo;
        m_world.pavement(p, nb, albedo);
        if (dot(nb, d) > 0) nb = n;
        Vec3 r = reflect(d, nb);
        if (r.y <= 0) r = reflect(d, n);
        const double cos_theta = std::clamp(-dot(d, nb), 0.0, 1.0);
        ++rays;  // the reflected ray, which meets only the environment above the plane
        // A rough wet surface spreads the sun's disc into a lobe about the mirror direction.
        const double roughness = m_scene.pavement.roughness_deg * std::numbers::pi / 180.0;
        const C env = roughness > 0.0 ? m_ops.environment(r, false) + m_ops.sun_glint(r, roughness)
                                      : m_ops.environment(r);
        const C diffuse = m_ops.rgb(scale(albedo, m_world.diffuse_light(p, nb)));
        const double t = m_world.oil_thickness_nm(p);
        if (t > 0) {
            const ThicknessSample ts{
                t, footprint(diff, p, n, t, [&](Vec3 q) { return m_world.oil_thickness_nm(q); })};
            const C R = m_ops.film(ts, cos_theta);
            // Light the film does not reflect crosses it to the pavement and crosses it again on
            // the way back.
            const C T = R.complement();
            return R * env + T * T * diffuse;
        }
        const double F = fresnel_dielectric(
            cos_theta, m_scene.oil.substrate == "wet" ? water_index : m_scene.oil.asphalt_index);
        return env * F + diffuse * (1.0 - F);
    }

    C bubble(const Hit& hit, Vec3 p, Vec3 d, Vec3 n, int depth, double weight,
             const RayDifferential* diff) {
        const double cos_theta = std::clamp(-dot(d, n), 0.0, 1.0);
        const double t = m_world.bubble_thickness_nm(hit.index, p);
        const ThicknessSample ts{t, footprint(diff, p, n, t, [&](Vec3 q) {
                                     return m_world.bubble_thickness_nm(hit.index, q);
                                 })};
        const C R = m_ops.film(ts, cos_theta);
        const C T = R.complement();
        const Vec3 r = reflect(d, n);
        const double wr = weight * R.max_value();
        const double wt = weight * T.max_value();
        C reflected, transmitted;
        if (depth + 1 < m_scene.render.max_depth && wr > min_path_weight && m_budget > 0) {
            reflected = trace(Ray{p + m_eps * n, r}, depth + 1, wr, nullptr);
        } else {
            ++rays;
            reflected = m_ops.environment(r);
        }
        // The film is thin: the transmitted ray goes on in the same direction.
        if (depth + 1 < m_scene.render.max_depth && wt > min_path_weight && m_budget > 0) {
            transmitted = trace(Ray{p - m_eps * n, d}, depth + 1, wt, nullptr);
        } else {
            ++rays;
            transmitted = m_ops.environment(d);
        }
        return R * reflected + T * transmitted;
    }

    C wing(const Hit& hit, Vec3 p, Vec3 d, Vec3 n) {
        const MorphoSceneParams& m = m_scene.morpho;
        const Vec3 nb = m_world.wing_normal(p, n);
        const double cos_view = std::clamp(-dot(d, nb), 0.0, 1.0);
        const double theta_deg = std::acos(cos_view) * 180.0 / std::numbers::pi;
        const Rgb3 light = m_world.diffuse_light(p, nb);
        const C base = m_ops.rgb(scale(m.base_albedo, light));
        if (hit.margin_distance < m.margin) return base;
        // The scales' multilayer colour at the viewing angle (Smits 1990 §3.7), lit like the
        // wing's surface, over the melanin base; veins carry no blue scales.
        return m_ops.wing(theta_deg) * m_ops.rgb(light) * (1.0 - 0.85 * hit.vein) + base;
    }

    /// Water at 589 nm (IAPWS 1997 formulation, 20 °C): n = 1.333.
    static constexpr double water_index = 1.333;

    const World& m_world;
    Ops m_ops;
    const Scene& m_scene;
    double m_eps;
    int m_budget = max_rays_per_camera_ray;
};

// --- Sampling and reconstruction -------------------------------------------------------------

struct Sample {
    float ox, oy;  // position in the pixel, [0, 1)
    float X, Y, Z;
};

/// The smallest m > √n with gcd(m, n) = 1: s ↦ s·m mod n is then a permutation of 0..n−1.
int coprime_step(int n) {
    int m = static_cast<int>(std::sqrt(static_cast<double>(n))) + 1;
    while (std::gcd(m, n) != 1) ++m;
    return m;
}

template <class Ops>
std::uint64_t trace_tile(const World& world, Ops ops, int x0, int y0, int x1, int y1,
                         std::vector<Sample>& samples) {
    const Scene& s = world.scene();
    const int W = s.image.width, H = s.image.height, spp = s.image.spp;
    const int grid = static_cast<int>(std::lround(std::sqrt(static_cast<double>(spp))));
    const bool square = grid * grid == spp;
    const int step = coprime_step(spp);
    const double exposure = s.render.exposure;
    Integrator<Ops> integrator(world, ops);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const std::uint64_t pixel = static_cast<std::uint64_t>(y) * W + x;
            const int shift = static_cast<int>(uniform(s.render.seed, pixel, 0, 63) * spp);
            for (int k = 0; k < spp; ++k) {
                const double u1 = uniform(s.render.seed, pixel, k, 0);
                const double u2 = uniform(s.render.seed, pixel, k, 1);
                double jx, jy;
                if (square) {  // jittered grid
                    jx = (k % grid + u1) / grid;
                    jy = (k / grid + u2) / grid;
                } else {  // Latin hypercube: one sample per row and per column
                    jx = (k + u1) / spp;
                    jy = ((k * step + shift) % spp + u2) / spp;
                }
                const double sx = (x + jx) / W, sy = (y + jy) / H;
                RayDifferential diff{world.camera().ray(sx + 1.0 / W, sy),
                                     world.camera().ray(sx, sy + 1.0 / H),
                                     1.0 / std::sqrt(static_cast<double>(spp))};
                const auto c = integrator.trace_camera_ray(world.camera().ray(sx, sy), &diff);
                Xyz xyz = ops.xyz(c);
                if (!std::isfinite(xyz.X) || !std::isfinite(xyz.Y) || !std::isfinite(xyz.Z))
                    xyz = {};
                samples[pixel * spp + k] =
                    Sample{static_cast<float>(jx), static_cast<float>(jy),
                           static_cast<float>(xyz.X * exposure), static_cast<float>(xyz.Y * exposure),
                           static_cast<float>(xyz.Z * exposure)};
            }
        }
    }
    return integrator.rays;
}

}  // namespace

RenderResult render(const Scene& scene, const RenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    if (options.threads < 0)
        throw Error(fmt::format("render: threads is {}; it must be >= 0", options.threads));
    const RgbSpace* space = find_rgb_space(scene.render.space);
    if (!space) {
        throw Error(fmt::format("{}: 'render.space' is \"{}\"; allowed: {}", scene.source,
                                scene.render.space, fmt::join(rgb_space_names(), ", ")));
    }
    const ClipMethod method = scene.render.clip;

    // More threads than the machine has only queue (and make oneTBB warn).
    const int available = tbb::this_task_arena::max_concurrency();
    const int threads = options.threads == 0 ? available : std::min(options.threads, available);
    tbb::task_arena arena(threads);
    RenderResult result;
    const World world = arena.execute([&] { return World(scene); });

    const int W = scene.image.width, H = scene.image.height, spp = scene.image.spp;
    std::vector<Sample> samples(static_cast<std::size_t>(W) * H * spp);
    constexpr int tile = 32;
    const int tiles_x = (W + tile - 1) / tile, tiles_y = (H + tile - 1) / tile;
    const int tiles = tiles_x * tiles_y;
    std::vector<std::uint64_t> tile_rays(tiles, 0);
    std::atomic<int> done{0};
    arena.execute([&] {
        tbb::parallel_for(0, tiles, [&](int t) {
            const int x0 = (t % tiles_x) * tile, y0 = (t / tiles_x) * tile;
            const int x1 = std::min(W, x0 + tile), y1 = std::min(H, y0 + tile);
            switch (scene.render.path) {
                case ColorPath::table:
                    tile_rays[t] = trace_tile(world, TableOps{world}, x0, y0, x1, y1, samples);
                    break;
                case ColorPath::spectral:
                    tile_rays[t] = trace_tile(world, SpectralOps{world}, x0, y0, x1, y1, samples);
                    break;
                case ColorPath::fourier:
                    tile_rays[t] = trace_tile(world, FourierOps{{world}}, x0, y0, x1, y1, samples);
                    break;
            }
            const int n = ++done;
            if (options.progress) options.progress(n, tiles);
        });
    });

    // Reconstruction: a truncated Gaussian (its value at the radius subtracted, pbrt-v4's
    // GaussianFilter), separable, over the samples of every pixel within the radius.
    const double radius = scene.render.filter_radius, sigma = scene.render.filter_sigma;
    const double tail = std::exp(-radius * radius / (2 * sigma * sigma));
    auto gauss = [&](double d) {
        return std::max(0.0, std::exp(-d * d / (2 * sigma * sigma)) - tail);
    };
    const int reach = static_cast<int>(std::ceil(radius));
    result.xyz = io::Image::blank(W, H, 3);
    result.xyz.channel_names = {"X", "Y", "Z"};
    arena.execute([&] {
        tbb::parallel_for(0, H, [&](int y) {
            for (int x = 0; x < W; ++x) {
                double sum[3] = {0, 0, 0}, wsum = 0;
                for (int py = std::max(0, y - reach); py <= std::min(H - 1, y + reach); ++py) {
                    for (int px = std::max(0, x - reach); px <= std::min(W - 1, x + reach); ++px) {
                        const Sample* s = &samples[(static_cast<std::size_t>(py) * W + px) * spp];
                        for (int k = 0; k < spp; ++k) {
                            const double dx = static_cast<double>(px - x) + s[k].ox - 0.5;
                            const double dy = static_cast<double>(py - y) + s[k].oy - 0.5;
                            if (std::abs(dx) >= radius || std::abs(dy) >= radius) continue;
                            const double w = gauss(dx) * gauss(dy);
                            sum[0] += w * s[k].X;
                            sum[1] += w * s[k].Y;
                            sum[2] += w * s[k].Z;
                            wsum += w;
                        }
                    }
                }
                for (int c = 0; c < 3; ++c)
                    result.xyz.at(x, y, c) = wsum > 0 ? static_cast<float>(sum[c] / wsum) : 0.0f;
            }
        });
    });

    // XYZ (D65 white) → the destination's linear RGB → the clip → encoding.
    const Colorimeter destination(illuminant_d65(), Observer::cie1931_2deg, *space);
    result.linear = io::Image::blank(W, H, 3);
    result.linear.color_space = space->name() + "-linear";
    std::vector<float> rgb(static_cast<std::size_t>(W) * H * 3);
    std::uint64_t outside = 0;
    constexpr double tolerance = 1e-6;
    for (std::size_t i = 0; i < result.xyz.pixel_count(); ++i) {
        const Xyz c{result.xyz.pixels[3 * i], result.xyz.pixels[3 * i + 1],
                    result.xyz.pixels[3 * i + 2]};
        const Rgb l = destination.linear_rgb(c);
        const double v[3] = {l.r, l.g, l.b};
        bool out = false;
        for (int k = 0; k < 3; ++k) {
            rgb[3 * i + k] = static_cast<float>(v[k]);
            out = out || v[k] < -tolerance || v[k] > 1 + tolerance;
        }
        outside += out ? 1 : 0;
    }
    result.linear.pixels = rgb;
    // The view transform's roll-off (scene.h ViewTransform): the scene luminance Y through the
    // curve, the colour scaled with it, so its chromaticity (and hue) stays; what is then
    // outside the gamut's chroma is the gamut method's.
    if (scene.render.view == ViewTransform::rolloff) {
        const HighlightRolloff rolloff(scene.render.rolloff_knee);
        for (std::size_t i = 0; i < result.xyz.pixel_count(); ++i) {
            const double y = result.xyz.pixels[3 * i + 1];
            if (!(y > rolloff.knee())) continue;
            const double f = rolloff(y) / y;
            for (int k = 0; k < 3; ++k) rgb[3 * i + k] = static_cast<float>(rgb[3 * i + k] * f);
        }
    }
    result.display = io::Image::blank(W, H, 3);
    result.display.color_space = space->name();
    if (scene.render.view == ViewTransform::aces2) {
        // The scene's XYZ (D65 white) through the ACES 2.0 chain to the display's signal,
        // encoded; the transform keeps it inside the display, so no gamut method follows.
        const DisplayTransform view(DisplayTransformOptions{
            .view = "aces2", .display = scene.render.display, .source = "xyz", .target = space->name()});
        std::vector<float> signal = result.xyz.pixels;
        arena.execute([&] { view.apply(signal, signal, threads); });
        for (std::size_t i = 0; i < signal.size(); ++i)
            result.display.pixels[i] = std::clamp(signal[i], 0.0f, 1.0f);
    } else {
        // The displayed image must fit the display: aces-rgc with its final clip, as irid clip
        // does for images.
        const GamutClipper clipper(method, Gamut(*space, 1.0), display_clip_settings(method));
        arena.execute([&] { clip_batch(clipper, rgb, BatchOptions{threads}); });
        // Whole colours through the curve (HLG's acts on their luminance).
        const auto unit = [](double v) { return std::clamp(v, 0.0, 1.0); };
        for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
            const Rgb e = space->encode({unit(rgb[i]), unit(rgb[i + 1]), unit(rgb[i + 2])});
            result.display.pixels[i] = static_cast<float>(unit(e.r));
            result.display.pixels[i + 1] = static_cast<float>(unit(e.g));
            result.display.pixels[i + 2] = static_cast<float>(unit(e.b));
        }
    }

    result.stats.camera_rays = static_cast<std::uint64_t>(W) * H * spp;
    for (const auto r : tile_rays) result.stats.rays += r;
    result.stats.out_of_gamut_pixels = outside;
    result.stats.table_seconds = world.table_seconds();
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

ImageDifference delta_e_2000_images(const io::Image& a, const io::Image& b) {
    if (a.width != b.width || a.height != b.height || a.channels != 3 || b.channels != 3)
        throw Error(fmt::format("delta_e_2000_images: sizes differ ({}×{}×{} and {}×{}×{})",
                                a.width, a.height, a.channels, b.width, b.height, b.channels));
    const Xyz white = illuminant_white(illuminant_d65());
    std::vector<double> d(a.pixel_count());
    double sum = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        const Lab la = xyz_to_lab({a.pixels[3 * i], a.pixels[3 * i + 1], a.pixels[3 * i + 2]}, white);
        const Lab lb = xyz_to_lab({b.pixels[3 * i], b.pixels[3 * i + 1], b.pixels[3 * i + 2]}, white);
        d[i] = delta_e_2000(la, lb);
        sum += d[i];
    }
    ImageDifference r;
    if (d.empty()) return r;
    r.mean = sum / static_cast<double>(d.size());
    std::sort(d.begin(), d.end());
    r.p99 = percentile_of_sorted(d, 0.99);
    r.max = d.back();
    return r;
}

}  // namespace irid::render
