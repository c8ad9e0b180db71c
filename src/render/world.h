#pragma once

// The renderer's world: a Scene turned into geometry, textures, lights and colour tables, and
// the integrator that traces a ray through it. Private to irid_render.

#include "carriers.h"
#include "film_table.h"

#include <irid/io/image.h>
#include <irid/optics/film.h>
#include <irid/optics/film_color.h>
#include <irid/optics/fourier_film.h>
#include <irid/optics/multilayer.h>
#include <irid/optics/thesis_models.h>
#include <irid/render/camera.h>
#include <irid/render/geometry.h>
#include <irid/render/scene.h>
#include <irid/render/sky.h>
#include <irid/texture/noise.h>

#include <memory>
#include <numbers>
#include <optional>
#include <vector>

namespace irid::render {

inline constexpr double pi = std::numbers::pi;

inline Vec3 to_vec(const Vec3Param& v) { return {v[0], v[1], v[2]}; }

/// A flat wing: a polygon in a plane, in the wing's own 2-D coordinates (a along the span, b
/// along the body), with the edges of the outer margin marked.
struct Wing {
    Vec3 origin, axis_a, axis_b, normal;
    std::vector<std::array<double, 2>> outline;
    std::vector<bool> outer_edge;  // edge i runs from outline[i] to outline[i + 1]
    double length = 1;             // the wing's length, for the margin
    std::array<double, 4> bounds{};  // a_min, a_max, b_min, b_max of the outline
    /// The forewing's dark margin widens towards its apex (a → length).
    bool forewing = false;
    /// Veins: segments in the wing's 2-D coordinates, and their half-width.
    std::vector<std::array<std::array<double, 2>, 2>> veins;
    double vein_half_width = 0;
    /// Distance from the root over which the veins fade in.
    double vein_start = 0;

    /// Whether (a, b) lies on the wing; if so, `margin` is its distance to the outer edges as
    /// a fraction of the wing's length (scaled so the forewing's border widens to the apex).
    [[nodiscard]] bool contains(double a, double b, double& margin) const;
    /// How much of a vein covers (a, b), 0 to 1.
    [[nodiscard]] double vein_cover(double a, double b) const;
};

/// A group of spheres (an antenna) tested only when a ray meets their bounding box.
struct SphereChain {
    std::vector<Sphere> spheres;
    Aabb bounds;
};

/// What a ray hit.
enum class SurfaceKind { none, pavement, bubble, floor, wing, wing_mesh, body, background };

struct Hit {
    SurfaceHit surface;
    SurfaceKind kind = SurfaceKind::none;
    int index = -1;
    /// For wings: the distance to the outer margin in units of the wing's length (divided, on
    /// a forewing, by the margin's widening towards the apex).
    double margin_distance = 1;
    /// For wings: how much of a vein covers the hit, 0 (none) to 1 (its centre line).
    double vein = 0;
};

/// The neighbouring pixel's rays of a camera ray, for the footprint of a film's thickness.
struct RayDifferential {
    Ray dx, dy;
    /// Fraction of a pixel one sample stands for along each axis (1/√spp).
    double stratum = 1;
};

struct ThicknessSample {
    double t_nm = 0;
    double footprint_nm = 0;
};

class World {
public:
    explicit World(const Scene& scene);

    [[nodiscard]] const Scene& scene() const noexcept { return m_scene; }
    [[nodiscard]] const Camera& camera() const noexcept { return m_camera; }
    [[nodiscard]] const SpectralBasis& basis() const noexcept { return *m_basis; }

    [[nodiscard]] bool intersect(const Ray& ray, double t_min, double t_max, Hit& hit) const noexcept;
    /// Any opaque surface between the point and the sun? (Bubbles and oil let light through.)
    [[nodiscard]] bool sun_blocked(Vec3 p) const noexcept;

    /// The environment's radiance towards -direction (the sky or image, plus the sun's disc), as
    /// linear Rec. 709 RGB relative to D65.
    [[nodiscard]] Rgb3 environment(Vec3 direction, bool with_sun = true) const noexcept;
    /// The sun reflected by a rough mirror whose mirror direction is r (unit): the disc
    /// convolved with a lobe of angular deviation sigma [rad], the disc taken as a lobe of its
    /// own variance (s²/4 per axis), so the total is 1/κ = sigma² + s²/4; the lobe is the von
    /// Mises–Fisher density on the sphere, κ/(2π(1 − e^{−2κ})) e^{κ(cos δ − 1)}, δ the angle
    /// between r and the sun: the sun's radiance × its solid angle × that density, which
    /// integrates over the sphere to the disc's radiance × solid angle exactly. The glint's
    /// colour is sun_rgb() (or the sun's spectrum) times this.
    [[nodiscard]] double sun_lobe(Vec3 r, double sigma) const noexcept;
    [[nodiscard]] Rgb3 sun_rgb() const noexcept { return m_sun_rgb; }
    /// The environment as the spectral path carries it: the Preetham sky's CIE daylight
    /// spectrum (and the Preetham sun's spectrum in the sun's disc), or the RGB environment's
    /// spectrum (SpectralBasis::from_rgb).
    void environment_spectrum(Vec3 direction, SpectralCarrier& out, bool with_sun = true) const noexcept;
    /// sun_lobe × the sun's spectrum (the spectral path's glint).
    void sun_glint_spectrum(Vec3 r, double sigma, SpectralCarrier& out) const noexcept;
    /// The diffuse lighting a surface with normal n at p receives, as RGB (the sun with its
    /// shadow, plus the mean sky): albedo × this is the radiance it reflects.
    [[nodiscard]] Rgb3 diffuse_light(Vec3 p, Vec3 n) const noexcept;

    /// The pavement's bumped normal and albedo at a point of the ground plane.
    void pavement(Vec3 p, Vec3& normal, Rgb3& albedo) const noexcept;
    /// The oil's thickness at a point of the pavement (eq. 28), 0 where there is none.
    [[nodiscard]] double oil_thickness_nm(Vec3 p) const noexcept;
    /// A bubble's thickness at a point of its surface.
    [[nodiscard]] double bubble_thickness_nm(int bubble, Vec3 p) const noexcept;
    [[nodiscard]] Vec3 wing_normal(Vec3 p, Vec3 n) const noexcept;
    [[nodiscard]] Rgb3 floor_albedo(Vec3 p) const noexcept;
    [[nodiscard]] Rgb3 background_albedo(Vec3 p) const noexcept;

    // The films' physics for the spectral path and the tables for the table path.
    /// The film's model: the exact Airy film or the thesis' single film (K matched).
    [[nodiscard]] const FilmModel& film() const noexcept { return *m_film_model; }
    [[nodiscard]] const FilmTable& film_table() const noexcept { return *m_film_table; }
    [[nodiscard]] const AngleTable<Rgb3>& wing_table() const noexcept { return m_wing_rgb; }
    /// The wing's reflectance spectrum at θ [deg] for the spectral path: the thesis' model
    /// evaluated per call (the blend in closed form, morpho_blend_reflectance_continuous), the
    /// exact stack interpolated from a table of spectra every degree (101 transfer matrices
    /// per angle are too slow per ray).
    void wing_spectrum(double theta_deg, SpectralCarrier& out) const noexcept;
    /// The film's reflectance spectrum at a thickness (mean over the footprint) and angle.
    void film_spectrum(const ThicknessSample& t, double cos_theta, SpectralCarrier& out) const;
    /// The film's linear RGB by the Fourier series (the fourier path), the mean over the
    /// footprint taken as film_spectrum takes it.
    [[nodiscard]] Rgb3 film_fourier(const ThicknessSample& t, double cos_theta) const noexcept;

    [[nodiscard]] double epsilon() const noexcept { return m_epsilon; }
    [[nodiscard]] double table_seconds() const noexcept { return m_table_seconds; }

private:
    void build_tables();
    void build_oil_slick();
    void build_soap_bubbles();
    void build_morpho();
    void build_morpho_wings(double half);
    void build_wing_tables();
    void build_preetham();
    /// The material named `text`; errors name the scene and `key`.
    [[nodiscard]] Material material(const std::string& key, const std::string& text) const;

    const Scene& m_scene;
    Camera m_camera;
    std::unique_ptr<SpectralBasis> m_basis;
    ValueNoise m_noise;
    ValueNoise m_noise2;

    // Geometry.
    std::optional<Plane> m_ground;
    std::vector<Sphere> m_bubbles;
    std::vector<Sphere> m_body;
    std::vector<Ellipsoid> m_body_parts;
    std::vector<SphereChain> m_antennae;
    std::vector<Wing> m_wings;
    std::optional<TriangleMesh> m_wing_mesh;

    // Light.
    Vec3 m_sun;
    double m_cos_sun_radius = 1;
    double m_sun_radiance = 0;
    Rgb3 m_ambient{};
    std::optional<io::Image> m_environment;
    /// The sun's colour (RGB with Y = 1; white but for the Preetham sun) and, for the spectral
    /// path, its spectrum relative to D65 with Y = 1.
    Rgb3 m_sun_rgb{1, 1, 1};
    SpectralCarrier m_sun_spectrum = SpectralCarrier::constant(1.0);
    /// The Preetham sky: the model, the daylight basis S0, S1, S2 relative to D65 and their
    /// XYZ (so both colour paths see the same sky), and the ground's radiance below the horizon.
    std::optional<PreethamSky> m_sky;
    std::array<SpectralCarrier, 3> m_daylight{};
    std::array<Xyz, 3> m_daylight_xyz{};
    Rgb3 m_ground_radiance{};
    /// The Preetham sky's weights along a direction: the scale k and M1, M2 of
    /// k (S0 + M1 S1 + M2 S2) / S_D65.
    struct SkyWeights {
        double k = 0, m1 = 0, m2 = 0;
    };
    [[nodiscard]] SkyWeights sky_weights(Vec3 d) const noexcept;

    // Films.
    std::optional<SingleFilm> m_film;
    std::shared_ptr<const FilmModel> m_film_model;
    std::optional<FilmTable> m_film_table;
    std::optional<FourierFilm> m_fourier_film;
    double m_max_thickness_nm = 0;
    MorphoParameters m_wing_params;
    MorphoBlend m_wing_blend;
    AngleTable<Rgb3> m_wing_rgb;
    AngleTable<std::array<double, dense_sample_count>> m_wing_spectra;

    double m_epsilon = 1e-6;
    double m_table_seconds = 0;
};

}  // namespace irid::render
