// Scene files: the built-in scenes, every kind of bad value, and overrides.
#include <irid/error.h>
#include <irid/render/scene.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>
#include <string_view>

#include <unistd.h>

namespace irid::render {
namespace {

/// The message of the irid::Error thrown by f, or "" when it throws none.
template <class F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

#define EXPECT_CONTAINS(text, part) \
    EXPECT_NE(std::string(text).find(part), std::string::npos) << "message: " << (text)

TEST(Scene, BuiltinScenesAreTheThreeOfTheThesis) {
    const auto names = builtin_scene_names();
    ASSERT_EQ(names.size(), 3u);
    EXPECT_EQ(load_scene("morpho").kind, SceneKind::morpho);
    EXPECT_EQ(load_scene("oil-slick").kind, SceneKind::oil_slick);
    EXPECT_EQ(load_scene("soap-bubbles").kind, SceneKind::soap_bubbles);
}

// The compiled-in scenes are the files under scenes/, read here independently of irid.
TEST(Scene, BuiltinScenesCarryTheValuesOfTheirFiles) {
    for (const std::string name : {"oil-slick", "soap-bubbles", "morpho"}) {
        std::ifstream in(std::string(IRID_SCENES_DIR) + "/" + name + ".json");
        ASSERT_TRUE(in) << name;
        const nlohmann::json j = nlohmann::json::parse(in);
        const Scene s = load_scene(name);
        EXPECT_EQ(s.image.width, j["image"]["width"].get<int>());
        EXPECT_EQ(s.image.spp, j["image"]["spp"].get<int>());
        EXPECT_DOUBLE_EQ(s.camera.fov_deg, j["camera"]["fov_deg"].get<double>());
        EXPECT_DOUBLE_EQ(s.light.sun_intensity, j["light"]["sun_intensity"].get<double>());
        EXPECT_EQ(clip_method_name(s.render.clip), j["render"]["clip"].get<std::string>());
        EXPECT_DOUBLE_EQ(s.render.rolloff_knee, j["render"]["rolloff_knee"].get<double>());
        EXPECT_DOUBLE_EQ(s.light.turbidity, j["light"]["turbidity"].get<double>());
        EXPECT_EQ(s.light.sky == SkyModel::preetham ? "preetham" : "gradient",
                  j["light"]["sky"].get<std::string>());
        if (name == "oil-slick") {
            EXPECT_DOUBLE_EQ(s.oil.max_thickness_nm, j["oil"]["max_thickness_nm"].get<double>());
        }
        if (name == "soap-bubbles") {
            ASSERT_EQ(s.soap.bubbles.size(), j["soap"]["bubbles"].size());
            EXPECT_DOUBLE_EQ(s.soap.bubbles[1].radius,
                             j["soap"]["bubbles"][1]["radius"].get<double>());
        }
        if (name == "morpho") {
            EXPECT_EQ(s.morpho.periods, j["morpho"]["periods"].get<int>());
        }
    }
}

TEST(Scene, JsonSyntaxErrorsNameTheSourceLineAndColumn) {
    const std::string text = "{\n  \"scene\": \"morpho\",\n  \"image\": { \"width\": 10,, }\n}\n";
    const std::string m = error_of([&] { (void)parse_scene(text, "bad.json"); });
    EXPECT_CONTAINS(m, "bad.json");
    EXPECT_CONTAINS(m, "line 3, column 26");
    EXPECT_CONTAINS(m, "syntax error");
}

// The column is where the offending token starts (here the string "height", which a comma
// should have preceded), as other JSON tools report it, not the token's last character.
TEST(Scene, JsonSyntaxErrorsPointAtTheStartOfTheOffendingToken) {
    const std::string text = R"({"scene": "morpho", "image": {"width": 16 "height": 12}})";
    EXPECT_CONTAINS(error_of([&] { (void)parse_scene(text, "s.json"); }), "line 1, column 43");
    const std::string number = "{\n  \"scene\": \"morpho\",\n  \"image\": {\"width\": 1x6}\n}";
    // In 1x6 the x (column 23) is the first character that cannot continue the number.
    EXPECT_CONTAINS(error_of([&] { (void)parse_scene(number, "n.json"); }), "line 3, column 23");
}

TEST(Scene, UnknownKeysAreErrorsListingTheValidOnes) {
    const std::string m =
        error_of([] { (void)parse_scene(R"({"scene": "morpho", "morpho": {"d3_nm": 1}})", "s"); });
    EXPECT_CONTAINS(m, "unknown key 'morpho.d3_nm'");
    EXPECT_CONTAINS(m, "d1_nm");
    EXPECT_CONTAINS(error_of([] { (void)parse_scene(R"({"scene": "morpho", "colour": 1})", "s"); }),
                    "unknown key 'colour'");
}

TEST(Scene, ValuesOutOfRangeNameTheKeyPathAndTheRange) {
    EXPECT_CONTAINS(error_of([] {
                        (void)parse_scene(R"({"scene": "morpho", "image": {"width": 0}})", "s");
                    }),
                    "'image.width' is 0; allowed: [1, 16384]");
    EXPECT_CONTAINS(error_of([] {
                        (void)parse_scene(R"({"scene": "oil-slick", "oil": {"k1": -1}})", "s");
                    }),
                    "'oil.k1' is -1; allowed: [0, 100]");
    EXPECT_CONTAINS(error_of([] {
                        (void)parse_scene(
                            R"({"scene": "soap-bubbles", "soap": {"bubbles": [{"radius": 0}]}})",
                            "s");
                    }),
                    "'soap.bubbles.0.radius' is 0");
    EXPECT_CONTAINS(error_of([] {
                        (void)parse_scene(R"({"scene": "morpho", "camera": {"eye": "x"}})", "s");
                    }),
                    "'camera.eye' must be an array of 3 numbers");
    EXPECT_CONTAINS(error_of([] {
                        (void)parse_scene(R"({"scene": "morpho", "render": {"path": "rgb"}})", "s");
                    }),
                    "allowed: table, spectral");
    EXPECT_CONTAINS(error_of([] { (void)parse_scene(R"({"image": {}})", "s"); }),
                    "'scene' is missing");
}

TEST(Scene, ValuesTheRendererCannotUseAreRefusedWhenTheSceneIsRead) {
    EXPECT_CONTAINS(error_of([] { (void)load_scene("soap-bubbles", {"soap.film=gold"}); }),
                    "'soap.film' is 'gold', an absorbing material");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("oil-slick", {"oil.film=unobtainium"}); }),
                    "'oil.film'");
    EXPECT_EQ(load_scene("oil-slick", {"oil.film=1.45"}).oil.film, "1.45");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"render.space=cmyk"}); }),
                    "'render.space' is \"cmyk\"; allowed: srgb");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"render.clip=nearest"}); }),
                    "'render.clip'");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("soap-bubbles", {"soap.floor_checker=-1"}); }),
                    "'soap.floor_checker' is -1");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("soap-bubbles", {"soap.bubbles.0.radius=-2"}); }),
                    "is -2; allowed: (0, 10000]");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"image.width=18446744073709551615"}); }),
                    "is 18446744073709551615; allowed: [1, 16384]");
}

TEST(Scene, ViewAndSkyKeysAreCheckedWhenTheSceneIsRead) {
    EXPECT_CONTAINS(error_of([] { (void)load_scene("oil-slick", {"render.view=filmic"}); }),
                    "'render.view' is \"filmic\"; allowed: rolloff, thesis");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("oil-slick", {"render.rolloff_knee=1"}); }),
                    "'render.rolloff_knee' is 1; allowed: [0, 0.95]");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("oil-slick", {"light.sky=hosek"}); }),
                    "'light.sky' is \"hosek\"; allowed: gradient, preetham");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("soap-bubbles", {"light.turbidity=1"}); }),
                    "'light.turbidity' is 1; allowed: [2, 10]");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("soap-bubbles", {"light.sky_scale=0"}); }),
                    "'light.sky_scale' is 0; allowed: (0, 100]");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"light.ground_albedo=[0,2,0]"}); }),
                    "'light.ground_albedo' is [0,2,0]");
    // The Preetham sky needs the sun above the horizon; the gradient does not.
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"light.sun_direction=[1,-0.2,0]"}); }),
                    "with light.sky = preetham the sun must be above the horizon");
    EXPECT_EQ(load_scene("morpho", {"light.sky=gradient", "light.sun_direction=[1,-0.2,0]"}).light.sky,
              SkyModel::gradient);
    const Scene s = load_scene("oil-slick", {"render.view=thesis", "light.turbidity=6.5"});
    EXPECT_EQ(s.render.view, ViewTransform::thesis);
    EXPECT_EQ(s.light.turbidity, 6.5);
}

TEST(Scene, SampleCountsBeyondTheBufferLimitAreRefused) {
    const std::string m = error_of([] {
        (void)load_scene("morpho", {"image.width=4096", "image.height=4096", "image.spp=16"});
    });
    EXPECT_CONTAINS(m, "'image.spp' is 16");
    EXPECT_CONTAINS(m, "268435456 samples; at most 134217728");
}

TEST(Scene, ImagesBeyondThePixelLimitAreRefused) {
    const std::string m = error_of([] {
        (void)parse_scene(R"({"scene": "morpho", "image": {"width": 16384, "height": 16384}})",
                          "s");
    });
    EXPECT_CONTAINS(m, "268435456 pixels");
    EXPECT_CONTAINS(m, "at most 67108864");
}

TEST(Scene, OverridesReplaceValuesAtTheirKeyPaths) {
    const Scene s = load_scene("soap-bubbles", {"soap.bubbles.1.radius=0.5", "render.path=spectral",
                                                "camera.eye=[1, 2, 3]", "image.spp=9"});
    EXPECT_DOUBLE_EQ(s.soap.bubbles[1].radius, 0.5);
    EXPECT_EQ(s.render.path, ColorPath::spectral);
    EXPECT_EQ(s.camera.eye, (Vec3Param{1, 2, 3}));
    EXPECT_EQ(s.image.spp, 9);
    EXPECT_CONTAINS(error_of([] { (void)load_scene("soap-bubbles", {"soap.bubbles.7.radius=1"}); }),
                    "must be an index below 3");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"morpho.colour=1"}); }),
                    "unknown key 'morpho.colour'");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"image.width"}); }),
                    "must be key.path=value");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"image.width=big"}); }),
                    "'image.width' must be an integer");
}

TEST(Scene, UnknownScenesListTheBuiltinOnes) {
    const std::string m = error_of([] { (void)load_scene("no-such-scene.json"); });
    EXPECT_CONTAINS(m, "no-such-scene.json");
    EXPECT_CONTAINS(m, "morpho, oil-slick, soap-bubbles");
}

TEST(Scene, AKeyGivenTwiceIsAnErrorNamingBothPlaces) {
    const std::string text = "{\n  \"scene\": \"oil-slick\",\n  \"oil\": {\"k1\": 1, \"k1\": 2}\n}\n";
    EXPECT_EQ(error_of([&] { (void)parse_scene(text, "dup.json"); }),
              "dup.json: the key 'oil.k1' is given twice, at line 3, column 11 and at line 3, "
              "column 20; give each key once");
    // At the top level, in a nested array's object, and after a comment that looks like a key.
    EXPECT_CONTAINS(error_of([] {
                        (void)parse_scene(R"({"scene": "morpho", "scene": "morpho"})", "s");
                    }),
                    "the key 'scene' is given twice");
    EXPECT_CONTAINS(error_of([] {
                        (void)parse_scene(R"({"scene": "soap-bubbles", "soap": {"bubbles": [
                            {"radius": 1}, {"radius": 1, /* "radius": 0 */ "radius": 2}]}})",
                                          "s");
                    }),
                    "the key 'soap.bubbles.1.radius' is given twice");
    // The same name in two objects, or as a string value, is not a duplicate.
    EXPECT_EQ(error_of([] {
                  (void)parse_scene(R"({"scene": "morpho", "render": {"clip": "smits"},
                                        "morpho": {"wing_mesh": ""}, "image": {"spp": 1}})",
                                    "s");
              }),
              "");
    // Escaped and plain spellings of one key are one key.
    EXPECT_CONTAINS(error_of([] { (void)parse_scene(R"({"scene": "morpho", "sc\u0065ne": "morpho"})", "s"); }),
                    "given twice");
}

TEST(Scene, ANumberBeyondADoubleIsNamedWithItsPosition) {
    EXPECT_EQ(error_of([] {
                  (void)parse_scene("{\"scene\": \"oil-slick\",\n \"oil\": {\"k1\": 1e999}}", "big.json");
              }),
              "big.json: the number '1e999' at line 2, column 16 is beyond the range of a double "
              "(about 1.8e308)");
    EXPECT_CONTAINS(error_of([] { (void)parse_scene(R"({"scene": "morpho", "image": {"spp": -1e400}})", "s"); }),
                    "the number '-1e400' at line 1, column 38");
}

TEST(Scene, ASectionOfAnotherSceneIsRefusedFromTheFileAndFromOverrides) {
    EXPECT_EQ(error_of([] { (void)load_scene("oil-slick", {"morpho.periods=5"}); }),
              "oil-slick: the override 'morpho.periods=5': 'morpho' is a section of the morpho "
              "scene; this scene is oil-slick, whose sections are scene, image, camera, render, "
              "light, oil, pavement");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"pavement.bump_height=0"}); }),
                    "'pavement' is a section of the oil-slick scene");
    EXPECT_CONTAINS(error_of([] {
                        (void)parse_scene(R"({"scene": "morpho", "soap": {"film": "water"}})", "m.json");
                    }),
                    "m.json: 'soap' is a section of the soap-bubbles scene; this scene is morpho");
    // Switching a file's scene with an override leaves the file's own section behind.
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"scene=oil-slick"}); }),
                    "'morpho' is a section of the morpho scene; this scene is oil-slick");
    // Each scene's own sections are accepted.
    EXPECT_EQ(load_scene("oil-slick", {"pavement.bump_height=0"}).pavement.bump_height, 0.0);
}

TEST(Scene, TheExactMorphosTableWorkIsBoundedBeforeRendering) {
    // The built-in scene's exact table: 91 angles × 11 blend samples × 471 wavelengths × 15
    // layers (8 chitin lamellae, 7 air gaps) of layer evaluations.
    const Scene exact = load_scene("morpho", {"render.optics=exact"});
    EXPECT_DOUBLE_EQ(morpho_table_work(exact), 91.0 * 11 * 471 * 15);
    EXPECT_LT(morpho_table_work(exact), max_morpho_table_work);
    // Each value in range, together too much: refused when read, naming both and the limit.
    const std::string m = error_of([] {
        (void)load_scene("morpho", {"render.optics=exact", "morpho.periods=100",
                                    "morpho.blend_samples=201"});
    });
    EXPECT_CONTAINS(m, "morpho.periods = 100 and morpho.blend_samples = 201");
    EXPECT_CONTAINS(m, "1.71e+09 layer evaluations");
    EXPECT_CONTAINS(m, "the limit is 4e+08");
    // The thesis' closed forms cost nothing like it, and other scenes none of it.
    EXPECT_EQ(morpho_table_work(load_scene("morpho", {"render.optics=thesis", "morpho.periods=100",
                                                      "morpho.blend_samples=201"})),
              0.0);
    EXPECT_EQ(morpho_table_work(load_scene("oil-slick", {"render.optics=exact"})), 0.0);
}

TEST(Scene, TheFourierPathIsForTheExactOptics) {
    EXPECT_EQ(load_scene("oil-slick", {"render.path=fourier"}).render.path, ColorPath::fourier);
    EXPECT_EQ(color_path_name(ColorPath::fourier), "fourier");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("oil-slick", {"render.path=fourier", "render.optics=thesis"}); }),
                    "'render.path' is \"fourier\", the exact film's colour; it needs render.optics \"exact\"");
}

TEST(Scene, AnOverrideThatIsNotUtf8IsAnErrorOfIrids) {
    // The scene fuzzer's scene-1: nlohmann's dump threw its own type_error on the bytes.
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"render.path=\xff"}); }),
                    "'render.path' is \"\xef\xbf\xbd\"; allowed: table, spectral, fourier");
    EXPECT_CONTAINS(error_of([] { (void)load_scene("morpho", {"render.p\xffth=1"}); }),
                    "unknown key 'render.p\\xffth'");
}

TEST(Scene, AFolderIsNotASceneFileButAPipeIs) {
    const std::string m = error_of([] { (void)load_scene("/"); });
    EXPECT_CONTAINS(m, "/: is a directory; expected a scene file (JSON)");
    // `irid render <(...)`: the scene arrives through a pipe named /dev/fd/N.
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const std::string_view json = *builtin_scene_json("morpho");
    ASSERT_EQ(::write(fds[1], json.data(), json.size()), static_cast<ssize_t>(json.size()));
    ::close(fds[1]);
    const Scene s = load_scene("/dev/fd/" + std::to_string(fds[0]));
    ::close(fds[0]);
    EXPECT_EQ(s.kind, SceneKind::morpho);
}

}  // namespace
}  // namespace irid::render
