#pragma once

// The thesis' three scenes (Smits 1990 §3.5–3.7: the oil slick of Figure 7, the soap bubbles of
// Figure 8 and the Morpho butterfly of Figure 9) as parameter sets read from JSON.
//
// Every parameter has a name (its JSON key path, e.g. "oil.max_thickness_nm"), a default and an
// allowed range; scenes/*.json list all of them with their defaults. Reading a scene checks each
// value once and names the file, the key path and the allowed range when one is wrong; an
// unknown key is an error, not ignored.
//
// Units: lengths in the scene in scene units (metres by convention), film thicknesses in nm,
// angles in degrees. Colours are linear RGB with Rec. 709 / sRGB primaries and the D65 white,
// as reflectances (albedo, 0–1) or as multiples of the D65 white (lights).

#include <irid/gamut/clip.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace irid::render {

using Vec3Param = std::array<double, 3>;
using RgbParam = std::array<double, 3>;

enum class SceneKind { oil_slick, soap_bubbles, morpho };

/// How film colour reaches the image: the thesis' way (§3.3: a colour table per film, colours
/// multiplied as RGB), a spectrum per ray (reflectance evaluated per hit at 1 nm, every product
/// taken wavelength by wavelength, XYZ at the end), or the exact film's colour per hit by the
/// Fourier series (irid/optics/fourier_film.h), multiplied as RGB like the table path but with
/// no table (the exact optics only; the Morpho wing, a stack, keeps its angle table).
enum class ColorPath { table, spectral, fourier };
/// "table", "spectral", "fourier".
[[nodiscard]] std::string_view color_path_name(ColorPath path) noexcept;

/// Which physics gives the film's reflectance: the thesis' closed forms (eq. 21/22 with eq. 24
/// for single films, eq. 25 with eq. 29 for the Morpho) or the exact optics (Airy with Fresnel
/// amplitudes, transfer matrices).
enum class OpticsModel { thesis, exact };

/// Thin-film anti-aliasing: none, or the film's colour averaged over the thickness range the
/// pixel covers (the footprint from the neighbouring pixels' rays).
enum class FilmAntialias { none, footprint };

/// From the scene's light to the display (docs/RENDER.md, "From scene light to a display"):
/// - rolloff: exposure → the highlight roll-off on luminance (irid/gamut/tone.h: the identity
///   up to `rolloff_knee`, Reinhard et al. 2002's L/(1 + L) above it, tending to white) → the
///   gamut method `clip` → the encoding;
/// - thesis: exposure → the gamut method → the encoding, as the thesis does (every luminance
///   above the display's white is clipped to it);
/// - aces2: exposure → ACES2065-1 (Bradford from D65) → the ACES 2.0 Output Transform for
///   `display` (irid/gamut/display_transform.h, its own tonescale and gamut compression; no
///   gamut method) → the encoding.
enum class ViewTransform { rolloff, thesis, aces2 };

/// "rolloff", "thesis", "aces2".
[[nodiscard]] std::string_view view_transform_name(ViewTransform view) noexcept;

/// The environment's sky when no environment image is given: the two-colour gradient, or the
/// Preetham–Shirley–Smits daylight sky (irid/render/sky.h) with the sun's colour from the same
/// paper.
enum class SkyModel { gradient, preetham };

struct ImageParams {
    int width = 1024;
    int height = 768;
    /// Samples per pixel, stratified on a √spp × √spp grid when spp is a square.
    int spp = 4;
};

struct CameraParams {
    Vec3Param eye{0, 1, 4};
    Vec3Param look_at{0, 0, 0};
    Vec3Param up{0, 1, 0};
    double fov_deg = 40;
};

struct RenderParams {
    ColorPath path = ColorPath::table;
    OpticsModel optics = OpticsModel::exact;
    FilmAntialias antialias = FilmAntialias::footprint;
    /// Bounce limit for reflection and transmission.
    int max_depth = 6;
    std::uint64_t seed = 1;
    /// The destination RGB space, and the gamut clip (read by its `irid clip` name, once).
    std::string space = "srgb";
    ClipMethod clip = ClipMethod::smits;
    /// Exposure: the linear image is scaled by this before the view transform.
    double exposure = 1.0;
    /// The view transform and the roll-off's knee (the scene luminance, white = 1, up to which
    /// the roll-off is the identity).
    ViewTransform view = ViewTransform::rolloff;
    double rolloff_knee = 0.4;
    /// The display of view aces2 (irid/gamut/aces2_display.h: a built-in name or a custom form).
    /// With view aces2, `space` defaults to the display's encoding (default_display_encoding).
    std::string display = "sdr-100nit-rec709";
    /// Gaussian reconstruction filter: radius in pixels and standard deviation in pixels.
    double filter_radius = 1.5;
    double filter_sigma = 0.5;
};

/// The light: a sun (a directional light with a visible disc) and an environment, either a
/// procedural sky over a ground (the gradient or the Preetham sky) or a latitude–longitude image.
struct LightParams {
    /// The sky: "gradient" (sky_zenith, sky_horizon and ground below) or "preetham" (the
    /// analytic daylight sky of the sun's elevation and `turbidity`, its luminance in kcd/m²
    /// times sky_scale and environment_intensity as Y, the D65 white's luminance being 1; the
    /// sun's colour from the same model; below the horizon a diffuse ground of albedo
    /// `ground_albedo` lit by the sun and the sky).
    SkyModel sky = SkyModel::gradient;
    /// The Preetham sky's turbidity (2 very clear, 10 hazy) and its scale [1 / (kcd/m²)].
    double turbidity = 3.0;
    double sky_scale = 0.1;
    RgbParam ground_albedo{0.2, 0.2, 0.2};
    /// Direction towards the sun, any non-zero length (the renderer normalises it).
    Vec3Param sun_direction{-0.4, 0.8, 0.5};
    /// Irradiance of the sun on a surface facing it, as a multiple of the D65 white (of its
    /// luminance, for the Preetham sun's colour).
    double sun_intensity = 2.5;
    /// Angular radius of the sun's disc seen in reflections [deg].
    double sun_radius_deg = 1.5;
    RgbParam sky_zenith{0.25, 0.45, 0.95};
    RgbParam sky_horizon{0.85, 0.9, 1.0};
    RgbParam ground{0.25, 0.23, 0.2};
    /// An optional latitude–longitude environment image (EXR/HDR linear, or PNG/TIFF sRGB),
    /// relative to the scene file; replaces the procedural sky and ground.
    std::string environment_image;
    /// Multiplies the environment (procedural or image).
    double environment_intensity = 1.0;
};

/// Smits 1990 §3.5, eq. 27–28: t = t_max e^(−k₁(x² + y² + k₂ turb(x, y))) on the pavement,
/// x and y measured in units of `radius` from `center`.
struct OilParams {
    Vec3Param center{0, 0, 0};
    double radius = 1.0;
    double max_thickness_nm = 1500;
    double k1 = 1.2;
    double k2 = 0.8;
    /// Turbulence frequency: turb is evaluated at (x, y) × turbulence_scale.
    double turbulence_scale = 1.6;
    /// Below this the oil is too thin to see and the pavement is bare [nm].
    double min_thickness_nm = 20;
    /// The film (a material name of the optics: mineral-oil, water, ...).
    std::string film = "mineral-oil";
    /// "wet": the oil floats on a water layer over the asphalt; "dry": it lies on the asphalt.
    std::string substrate = "wet";
    /// The asphalt's refractive index under a dry film: an assumed value typical of bitumen
    /// binders, a parameter of the scene rather than a measured constant.
    double asphalt_index = 1.6;
};

/// The pavement: asphalt with bumps made as the thesis says (two noise calls set the scale and
/// the roughness of the bumps, fine bumps on top), applied as bump mapping through dnoise.
struct PavementParams {
    RgbParam albedo{0.09, 0.085, 0.08};
    /// Spatial frequency of the noise that modulates the bumps' scale [1/scene unit].
    double bump_frequency = 6;
    /// The bumps' slope amplitude (0 = flat).
    double bump_height = 0.05;
    /// Frequency and slope amplitude of the fine bumps.
    double fine_frequency = 60;
    double fine_height = 0.012;
    /// Albedo variation from noise (0 = uniform).
    double albedo_variation = 0.35;
    /// The wet surface's micro-roughness, as the angular standard deviation of its specular lobe
    /// [degrees, 0–20]: the sun's reflection is the disc spread by a normalised spherical
    /// Gaussian (von Mises–Fisher) lobe about the mirror direction (0 = a perfect mirror, the
    /// disc's hard edge).
    double roughness_deg = 0.0;
};

struct BubbleParams {
    Vec3Param center{0, 0, 0};
    double radius = 1;
    /// Film thickness at the top and at the bottom [nm]: it grows with depth below the top as
    /// the film drains (height normalised 0 at the bottom to 1 at the top).
    double top_thickness_nm = 10;
    double bottom_thickness_nm = 900;
    /// The exponent of the profile: t = top + (bottom − top)(1 − h)^exponent.
    double profile_exponent = 1.3;
    /// Turbulence added to the thickness [nm] and its frequency [1/radius].
    double turbulence_nm = 250;
    double turbulence_scale = 3;
};

struct SoapParams {
    std::vector<BubbleParams> bubbles;
    /// The film material (soap-film, water, ...).
    std::string film = "soap-film";
    /// A floor under the bubbles: y of the plane, its albedo and its checker scale (0 = plain).
    double floor_y = -1.2;
    RgbParam floor_albedo{0.55, 0.55, 0.55};
    RgbParam floor_albedo_alt{0.25, 0.25, 0.28};
    double floor_checker = 1.0;
};

/// Smits 1990 §3.7, eq. 29: the wing's multilayer (d₁ air, d₂ chitin, l mullions) and the
/// blend over mullion thicknesses, on procedural wing outlines or an OBJ mesh.
struct MorphoSceneParams {
    double d1_nm = 150;
    double d2_nm = 50;
    double n_chitin = 1.56;
    int periods = 12;
    bool blend = true;
    double blend_min_nm = 50;
    double blend_max_nm = 150;
    int blend_samples = 101;
    /// The wings' dihedral: each wing is tilted up by this angle about the body axis [deg].
    double dihedral_deg = 25;
    /// Wing span (tip to tip) [scene units].
    double span = 3;
    /// Bumps of the wing surface: slope amplitude and frequency.
    double bump_height = 0.08;
    double bump_frequency = 9;
    /// Albedo of the melanin base under the scales (seen where the multilayer is dark).
    RgbParam base_albedo{0.01, 0.01, 0.015};
    /// Black wing margins as a fraction of the wing's length.
    double margin = 0.12;
    RgbParam body_albedo{0.05, 0.04, 0.03};
    RgbParam background_albedo{0.18, 0.3, 0.12};
    /// An OBJ mesh for the wings instead of the procedural outlines (relative to the scene file).
    std::string wing_mesh;
};

struct Scene {
    /// Where the scene came from ("oil-slick", or a file path), for messages.
    std::string source;
    std::filesystem::path directory;  // for relative paths in the scene
    SceneKind kind = SceneKind::oil_slick;
    ImageParams image;
    CameraParams camera;
    RenderParams render;
    LightParams light;
    OilParams oil;
    PavementParams pavement;
    SoapParams soap;
    MorphoSceneParams morpho;
};

/// The built-in scenes' names: oil-slick, soap-bubbles, morpho.
[[nodiscard]] std::vector<std::string> builtin_scene_names();
/// The JSON text of a built-in scene (scenes/<name>.json, compiled in), or nullopt.
[[nodiscard]] std::optional<std::string_view> builtin_scene_json(std::string_view name);

/// Reads a scene from JSON text after applying the overrides. `source` names it in messages;
/// relative paths in the scene are taken from `directory`. Throws irid::Error naming the source
/// with line and column for a JSON syntax error, or the key path and the allowed values for a
/// bad value or an unknown key.
///
/// An override is "key.path=value" ("oil.k1=2", "soap.bubbles.0.radius=0.5",
/// "render.path=spectral"): the value is JSON ("[0, 1, 2]", "true", "2.5") or else a bare
/// string; it replaces the value at the key path as if it were in the file.
[[nodiscard]] Scene parse_scene(std::string_view json_text, const std::string& source,
                                const std::filesystem::path& directory = {},
                                const std::vector<std::string>& overrides = {});
/// A built-in name or a JSON file, with overrides as parse_scene.
[[nodiscard]] Scene load_scene(const std::string& name_or_path,
                               const std::vector<std::string>& overrides = {});

/// The overrides ("image.width=W", "image.height=H") that set an image size: both when both are
/// given; one of them alone keeps the aspect ratio of `shape` (the scene as loaded with the
/// caller's other overrides), the other side rounded and clamped to [1, max_image_side]; none
/// when neither is given. The values are checked later, when the overrides are parsed.
[[nodiscard]] std::vector<std::string> image_size_overrides(const Scene& shape, std::optional<int> width,
                                                            std::optional<int> height);

/// Limits: images up to max_image_side pixels a side and max_pixels in all, up to max_spp
/// samples per pixel and max_samples in all.
inline constexpr int max_image_side = 16384;
inline constexpr long long max_pixels = 64LL * 1024 * 1024;
inline constexpr int max_spp = 1024;
/// width × height × spp: the renderer keeps every sample (20 bytes) until the filter has read it.
inline constexpr long long max_samples = 1LL << 27;
inline constexpr int max_bubbles = 64;
/// The exact Morpho's wing table (91 angles × blend samples × 471 wavelengths × (2 periods − 1)
/// transfer-matrix layers, built before the first ray) may take at most this many layer
/// evaluations. One takes about 0.2 µs on the machines of docs/PERFORMANCE.md (both
/// polarisations), so the limit is about 80 s on one core; the built-in scene (12 periods, 101
/// blend samples) takes 1.0e8. Parameters in range one by one can ask for 1.7e9 together.
inline constexpr double max_morpho_table_work = 4e8;
/// The work the exact Morpho's wing table of a scene asks for (0 for other scenes and optics).
[[nodiscard]] double morpho_table_work(const Scene& scene) noexcept;

[[nodiscard]] std::string_view scene_kind_name(SceneKind kind) noexcept;

}  // namespace irid::render
