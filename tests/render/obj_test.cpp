#include <irid/error.h>
#include <irid/render/geometry.h>

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <system_error>
#include <utility>

#include <unistd.h>

namespace irid::render {
namespace {
namespace fs = std::filesystem;

/// A fresh folder per test for its OBJ files, removed afterwards.
class Obj : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::temp_directory_path() /
                ("irid_obj_test_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(m_dir, ignored);
    }
    /// Writes text to <folder>/<name> and returns the path.
    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path path = m_dir / name;
        std::ofstream out(path, std::ios::binary);
        out << text;
        return path;
    }
    /// The message of the irid::Error reading `text` throws ("" when none), with the file's
    /// folder removed so that messages start "<name>:<line>:".
    std::string error_reading(const std::string& text, const std::string& name = "bad.obj") const {
        const fs::path path = write(name, text);
        try {
            (void)TriangleMesh::read_obj(path);
        } catch (const Error& e) {
            std::string message = e.what();
            const std::string folder = m_dir.string() + "/";
            if (message.rfind(folder, 0) == 0) message.erase(0, folder.size());
            return message;
        }
        return {};
    }
    fs::path m_dir;
};

/// A unit square in z = 0 as four vertices, with uvs and one normal.
const std::string square_vertices =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\n"
    "vn 0 0 3\n";

/// The hit of a ray straight down onto (x, y, 0).
SurfaceHit down_onto(const TriangleMesh& mesh, double x, double y) {
    SurfaceHit hit;
    EXPECT_TRUE(mesh.intersect({{x, y, 1}, {0, 0, -1}}, 0.0, 10.0, hit)) << x << " " << y;
    return hit;
}

TEST_F(Obj, PositionOnlyFacesGiveBarycentricUv) {
    const TriangleMesh mesh = TriangleMesh::read_obj(write("a.obj", square_vertices + "f 1 2 3\n"));
    EXPECT_EQ(mesh.triangle_count(), 1u);
    EXPECT_TRUE(mesh.normals().empty());
    EXPECT_TRUE(mesh.uvs().empty());
    // (0.75, 0.25) = 0.25 p0 + 0.5 p1 + 0.25 p2.
    const SurfaceHit hit = down_onto(mesh, 0.75, 0.25);
    EXPECT_NEAR(hit.u, 0.5, 1e-14);
    EXPECT_NEAR(hit.v, 0.25, 1e-14);
    EXPECT_EQ(hit.normal, (Vec3{0, 0, 1}));  // counter-clockwise seen from +z
}

TEST_F(Obj, TextureCoordinateFaces) {
    const TriangleMesh mesh =
        TriangleMesh::read_obj(write("b.obj", square_vertices + "f 1/1 2/2 3/3\n"));
    ASSERT_EQ(mesh.uvs().size(), 3u);
    EXPECT_TRUE(mesh.normals().empty());
    const SurfaceHit hit = down_onto(mesh, 0.75, 0.25);
    EXPECT_NEAR(hit.u, 1.5, 1e-14);  // uv = 2 (x, y)
    EXPECT_NEAR(hit.v, 0.5, 1e-14);
}

TEST_F(Obj, NormalFacesAndFullFaces) {
    const TriangleMesh n_only =
        TriangleMesh::read_obj(write("c.obj", square_vertices + "f 1//1 2//1 3//1\n"));
    ASSERT_EQ(n_only.normals().size(), 3u);
    EXPECT_TRUE(n_only.uvs().empty());
    EXPECT_EQ(n_only.normals()[0], (Vec3{0, 0, 1}));  // normalised
    const TriangleMesh full =
        TriangleMesh::read_obj(write("d.obj", square_vertices + "vn 1 0 0\nf 1/1/1 2/2/2 3/3/1\n"));
    ASSERT_EQ(full.normals().size(), 3u);
    ASSERT_EQ(full.uvs().size(), 3u);
    const SurfaceHit hit = down_onto(full, 0.75, 0.25);  // b = (0.25, 0.5, 0.25)
    EXPECT_NEAR(hit.u, 1.5, 1e-14);
    const Vec3 expected = normalize(Vec3{0, 0, 0.25} + Vec3{0.5, 0, 0} + Vec3{0, 0, 0.25});
    EXPECT_NEAR(length(hit.shading_normal - expected), 0.0, 1e-14);
}

TEST_F(Obj, NegativeIndicesCountBackFromTheLastDefined) {
    const TriangleMesh relative = TriangleMesh::read_obj(
        write("e.obj", "v 0 0 0\nv 9 9 9\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nf -3/-1 -2/-1 -1/-1\n"));
    ASSERT_EQ(relative.triangle_count(), 1u);
    const auto& t = relative.triangles()[0];
    EXPECT_EQ(relative.positions()[static_cast<std::size_t>(t[0])], (Vec3{9, 9, 9}));
    EXPECT_EQ(relative.positions()[static_cast<std::size_t>(t[1])], (Vec3{1, 0, 0}));
    EXPECT_EQ(relative.positions()[static_cast<std::size_t>(t[2])], (Vec3{0, 1, 0}));
    // Relative to the line: the second face's −3 is the fourth vertex.
    const TriangleMesh twice = TriangleMesh::read_obj(
        write("f.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 0 0\nf -3 -2 -1\n"));
    ASSERT_EQ(twice.triangle_count(), 2u);
    const auto& second = twice.triangles()[1];
    EXPECT_EQ(twice.positions()[static_cast<std::size_t>(second[0])], (Vec3{1, 0, 0}));
    EXPECT_EQ(twice.positions()[static_cast<std::size_t>(second[2])], (Vec3{5, 0, 0}));
}

TEST_F(Obj, PolygonsAreFanTriangulated) {
    const TriangleMesh quad =
        TriangleMesh::read_obj(write("g.obj", square_vertices + "f 1/1 2/2 3/3 4/4\n"));
    ASSERT_EQ(quad.triangle_count(), 2u);
    // Both halves of the square are covered, uv = 2 (x, y) throughout.
    for (const auto& [x, y] : {std::pair{0.8, 0.1}, std::pair{0.1, 0.8}, std::pair{0.4, 0.5}}) {
        const SurfaceHit hit = down_onto(quad, x, y);
        EXPECT_NEAR(hit.u, 2 * x, 1e-14);
        EXPECT_NEAR(hit.v, 2 * y, 1e-14);
    }
    // A regular hexagon: 4 triangles whose areas sum to (3√3/2) r².
    std::string hexagon;
    for (int k = 0; k < 6; ++k) {
        const double a = k * std::numbers::pi / 3.0;
        hexagon += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    }
    hexagon += "f 1 2 3 4 5 6\n";
    const TriangleMesh hex = TriangleMesh::read_obj(write("h.obj", hexagon));
    ASSERT_EQ(hex.triangle_count(), 4u);
    double area = 0.0;
    for (const auto& t : hex.triangles()) {
        const Vec3 p0 = hex.positions()[static_cast<std::size_t>(t[0])];
        const Vec3 p1 = hex.positions()[static_cast<std::size_t>(t[1])];
        const Vec3 p2 = hex.positions()[static_cast<std::size_t>(t[2])];
        EXPECT_EQ(p0, hex.positions()[static_cast<std::size_t>(hex.triangles()[0][0])]);  // fan
        area += 0.5 * length(cross(p1 - p0, p2 - p0));
    }
    EXPECT_NEAR(area, 1.5 * std::sqrt(3.0), 1e-5);  // coordinates printed to 6 decimals
}

TEST_F(Obj, IndependentIndicesAreUnifiedIntoVertices) {
    // A cube: 8 positions, 6 face normals, each corner used by 3 faces with 3 normals → 24
    // unified vertices, 12 triangles, flat shading per face.
    const std::string cube =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n"
        "f 1//1 4//1 3//1 2//1\nf 5//2 6//2 7//2 8//2\nf 1//3 2//3 6//3 5//3\n"
        "f 4//4 8//4 7//4 3//4\nf 1//5 5//5 8//5 4//5\nf 2//6 3//6 7//6 6//6\n";
    const TriangleMesh mesh = TriangleMesh::read_obj(write("cube.obj", cube));
    EXPECT_EQ(mesh.triangle_count(), 12u);
    EXPECT_EQ(mesh.positions().size(), 24u);
    ASSERT_EQ(mesh.normals().size(), 24u);
    // Every face's winding normal points outward and equals its vertex normals.
    const std::array<Vec3, 6> outward{
        {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}}};
    for (const Vec3 out : outward) {
        const Vec3 centre = Vec3{0.5, 0.5, 0.5} + 0.5 * out;
        SurfaceHit hit;
        ASSERT_TRUE(
            mesh.intersect({centre + 2.0 * out + Vec3{0.01, 0.02, 0.03}, -out}, 0, 10, hit));
        EXPECT_EQ(hit.normal, out);
        EXPECT_EQ(hit.shading_normal, out);
    }
    // The same position with the same normal is one vertex, not two.
    const TriangleMesh shared = TriangleMesh::read_obj(
        write("s.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n"));
    EXPECT_EQ(shared.positions().size(), 4u);
}

TEST_F(Obj, CommentsBlankLinesGroupsAndLineEndings) {
    const std::string text =
        "# a comment\r\n"
        "mtllib scene.mtl\r\n"
        "o square\r\n"
        "\r\n"
        "   \t \r\n"
        "g half\r\n"
        "v 0 0 0 # trailing comment\r\n"
        "v 1 0 0 1.0\r\n"          // w
        "v 1 1 0 0.5 0.5 0.5\r\n"  // r g b colour
        "v 0 1 \\\r\n"             // continued on the next line
        "  0\r\n"
        "usemtl shiny\r\n"
        "s off\r\n"
        "l 1 2\r\n"
        "f 1 2 \\\n3 4\n";
    const TriangleMesh mesh = TriangleMesh::read_obj(write("i.obj", text));
    EXPECT_EQ(mesh.triangle_count(), 2u);
    EXPECT_EQ(mesh.positions().size(), 4u);
    const SurfaceHit hit = down_onto(mesh, 0.2, 0.9);
    EXPECT_NEAR(hit.t, 1.0, 1e-15);
}

TEST_F(Obj, NormalsAndUvsAreDroppedUnlessEveryVertexHasThem) {
    const TriangleMesh mesh =
        TriangleMesh::read_obj(write("j.obj", square_vertices + "f 1/1/1 2/2/1 3/3/1\nf 1 3 4\n"));
    EXPECT_EQ(mesh.triangle_count(), 2u);
    EXPECT_TRUE(mesh.normals().empty());
    EXPECT_TRUE(mesh.uvs().empty());
}

TEST_F(Obj, EveryErrorNamesTheFileAndLine) {
    struct Case {
        std::string text;
        std::string message;
    };
    const Case cases[] = {
        {"v 0 0 0\nv 1 x 0\n", "bad.obj:2: 'x' is not a finite number; 'v' takes x y z"},
        {"v 0 0 nan\n", "bad.obj:1: 'nan' is not a finite number"},
        {"v 0 0 1e999\n", "bad.obj:1: '1e999' is not a finite number"},
        {"v 0 0\n", "bad.obj:1: 'v' with 2 numbers; 'v' takes x y z, optionally w or r g b"},
        {"vn 0 0 0\n", "bad.obj:1: normal of zero length; 'vn' takes x y z (3 numbers, not all 0)"},
        {"vn 1 0\n", "bad.obj:1: 'vn' with 2 numbers"},
        {"vt\n", "bad.obj:1: 'vt' with 0 numbers; 'vt' takes u, optionally v and w"},
        {"vt 0 0 0 0\n", "bad.obj:1: 'vt' with 4 numbers"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
         "bad.obj:4: position index 4 is out of range: 3 defined before this line; allowed 1 to "
         "3, or -1 to -3 counting back from the last"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "bad.obj:4: position index -4 is out of range"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "bad.obj:4: position index 0 is out of range"},
        {"f 1 2 3\nv 0 0 0\n",
         "bad.obj:1: position index 1 is out of range: no position is defined before this line"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\n",
         "bad.obj:4: texture coordinate index 1 is out of range: no texture coordinate is"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n",
         "bad.obj:5: normal index 2 is out of range: 1 defined before this line"},
        {"v 0 0 0\nv 1 0 0\nf 1 2\n",
         "bad.obj:3: face with 2 vertices; a face needs at least 3 (polygons are "
         "fan-triangulated)"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/1/1/1\n",
         "bad.obj:4: face vertex '3/1/1/1' is malformed; allowed forms: i, i/t, i//n, i/t/n"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/\n", "bad.obj:4: face vertex '3/' is malformed"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 /3\n", "bad.obj:4: face vertex '/3' is malformed"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3x\n",
         "bad.obj:4: position index '3x' is not an integer; a face vertex is i, i/t, i//n or "
         "i/t/n"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2.5\n", "bad.obj:4: position index '2.5' is not"},
        {"v 0 0 0\ncurv 0 1 1 2\n",
         "bad.obj:2: unknown statement 'curv'; allowed: v, vn, vt, f, and o, g, s, usemtl, "
         "mtllib, l, p (ignored), # comments"},
        {"# only vertices\nv 0 0 0\nv 1 0 0\n",
         "bad.obj: no face ('f' line) in 3 lines; a mesh needs at least one"},
        // An empty file is named as such, not reported at a line 0.
        {"", "bad.obj: the file is empty; expected a Wavefront OBJ mesh with at least one face"},
        {"\n \n", "bad.obj: the file is empty"},
        // Untrusted bytes are quoted short and escaped: another file's line, a long token, and
        // a terminal escape sequence.
        {"root:$y$j9T$abcdefghijklmnopqrstuvwxyz0123456789:19000:0:99999:7:::\n",
         "bad.obj:1: unknown statement 'root:$y$j9T$abcdefghijkl...'; allowed:"},
        {"v 0 0 " + std::string(1000000, '7') + "x\n",
         "bad.obj:1: '777777777777777777777777...' is not a finite number"},
        {"\x1b[2J\x1b]0;pwned\x07 0 0\n",
         "bad.obj:1: unknown statement '\\x1b[2J\\x1b]0;pwned\\x07'; allowed:"},
    };
    for (const Case& c : cases) {
        const std::string message = error_reading(c.text);
        EXPECT_EQ(message.rfind(c.message, 0), 0u)
            << "input:\n"
            << c.text << "\nmessage: " << message << "\nexpected: " << c.message;
    }
}

TEST_F(Obj, UnreadableFilesAndTheSizeLimit) {
    try {
        (void)TriangleMesh::read_obj(m_dir / "missing.obj");
        ADD_FAILURE() << "no error for a missing file";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("missing.obj: no such file; expected a Wavefront OBJ mesh"),
                  std::string::npos)
            << message;
    }
    // A FIFO is refused at once (a scene names the mesh; nobody may ever write to the FIFO).
    ASSERT_EQ(::mkfifo((m_dir / "fifo.obj").c_str(), 0600), 0);
    try {
        (void)TriangleMesh::read_obj(m_dir / "fifo.obj");
        ADD_FAILURE() << "no error for a FIFO";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("fifo.obj: is not a regular file (a FIFO)"),
                  std::string::npos)
            << e.what();
    }
    try {
        (void)TriangleMesh::read_obj(m_dir);
        ADD_FAILURE() << "no error for a directory";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
    }
    // A budget of 2 triangles: a quad fits, a pentagon (3 triangles) does not, and neither do
    // more than 6 positions.
    const fs::path quad = write("quad.obj", square_vertices + "f 1 2 3 4\n");
    EXPECT_EQ(TriangleMesh::read_obj(quad, 2).triangle_count(), 2u);
    const fs::path pentagon =
        write("pentagon.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.5 1.5 0\nv 0 1 0\nf 1 2 3 4 5\n");
    try {
        (void)TriangleMesh::read_obj(pentagon, 2);
        ADD_FAILURE() << "no error above the triangle budget";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "pentagon.obj:6: more than 2 triangles; irid reads meshes of at most 2"),
                  std::string::npos)
            << e.what();
    }
    const fs::path many =
        write("many.obj", "v 0 0 0\nv 0 0 0\nv 0 0 0\nv 0 0 0\nv 0 0 0\nv 0 0 0\nv 0 0 0\n");
    try {
        (void)TriangleMesh::read_obj(many, 2);
        ADD_FAILURE() << "no error above the vertex budget";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("many.obj:7: more than 6 'v' lines"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(TriangleMesh::max_triangles, 10'000'000u);
}

// --- Findings of the OBJ fuzzer (tests/fuzz/regressions/obj, docs/RELIABILITY.md) ---------

/// Every ray from four directions towards each vertex, each edge's midpoint and each
/// triangle's centroid: the BVH's nearest hit is the brute-force loop's (same t, same triangle,
/// ties to the lowest index), occluded() agrees, and every hit has a unit normal.
void expect_bvh_matches_brute_force(const TriangleMesh& mesh) {
    const Aabb box = mesh.bounds();
    const Vec3 centre = 0.5 * (box.lo + box.hi);
    const double reach = 2.0 * length(box.hi - box.lo) + 1.0;
    std::vector<Vec3> targets;
    const auto& p = mesh.positions();
    for (const auto& tri : mesh.triangles()) {
        const Vec3 a = p[static_cast<std::size_t>(tri[0])], b = p[static_cast<std::size_t>(tri[1])],
                   c = p[static_cast<std::size_t>(tri[2])];
        targets.insert(targets.end(), {a, b, c, 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a),
                                       (a + b + c) / 3.0});
    }
    const Vec3 from[] = {{1, 0.3, 0.2}, {-0.2, 1, 0.4}, {0.1, -0.3, 1}, {-1, -1, -1}};
    int rays = 0;
    for (const Vec3& target : targets) {
        for (const Vec3& f : from) {
            const Vec3 origin = centre + reach * normalize(f);
            const Ray ray{origin, normalize(target - origin)};
            SurfaceHit bvh, brute;
            const bool hit = mesh.intersect(ray, 0.0, 4.0 * reach, bvh);
            ASSERT_EQ(hit, mesh.intersect_brute_force(ray, 0.0, 4.0 * reach, brute));
            EXPECT_EQ(mesh.occluded(ray, 0.0, 4.0 * reach), hit);
            ++rays;
            if (!hit) continue;
            EXPECT_EQ(bvh.t, brute.t);
            EXPECT_EQ(bvh.primitive, brute.primitive);
            EXPECT_NEAR(length(bvh.normal), 1.0, 1e-12) << "triangle " << bvh.primitive;
        }
    }
    EXPECT_GT(rays, 0);
}

fs::path regression(const char* name) { return fs::path(IRID_FUZZ_REGRESSIONS_DIR) / "obj" / name; }

TEST(ObjFuzzFindings, TiedAndNearlyTiedHitsAreTheBruteForceLoops) {
    // obj-1: a box flat along the ray entered a few ulps beyond the hit it held, and the BVH
    // culled it: another triangle at the same t, or one an ulp farther, came back.
    expect_bvh_matches_brute_force(TriangleMesh::read_obj(regression("bvh-tie-shared-edge.obj")));
    expect_bvh_matches_brute_force(TriangleMesh::read_obj(regression("bvh-near-tie-one-ulp.obj")));
}

TEST(ObjFuzzFindings, ZeroAreaTrianglesAreNeverHit) {
    // obj-2: three vertices on a line have no normal (it came out NaN); such a triangle is kept
    // but never hit, and a mesh of nothing else is refused.
    const TriangleMesh mixed = TriangleMesh::read_obj(regression("zero-area-triangle-bvh-disagrees.obj"));
    expect_bvh_matches_brute_force(mixed);
    const TriangleMesh line_and_square({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 1}, {2, 0, 1}},
                                       {{0, 1, 2}, {0, 2, 4}, {0, 4, 3}});
    SurfaceHit hit;
    // Straight down onto the middle vertex of the line: the square behind it is what is hit.
    ASSERT_TRUE(line_and_square.intersect({{1, 5, 0.0}, {0, -1, 0}}, 0.0, 10.0, hit));
    EXPECT_NE(hit.primitive, 0);
    EXPECT_NEAR(length(hit.normal), 1.0, 1e-15);
    try {
        (void)TriangleMesh::read_obj(regression("zero-area-triangle-hit.obj"));
        ADD_FAILURE() << "a mesh of one zero-area triangle was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("has zero area"), std::string::npos) << e.what();
    }
}

TEST(ObjFuzzFindings, CoordinatesNearTheRangeOfADoubleAreRefused) {
    // obj-3: 1e308 overflowed the BVH builder's centroids and extents, and NaN reached an int.
    try {
        (void)TriangleMesh::read_obj(regression("huge-coordinates-nan-bin.obj"));
        ADD_FAILURE() << "1e308 was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("within +-1e150"), std::string::npos) << e.what();
    }
    // Up to the limit the mesh is built and exact.
    const double big = 1e150;
    const TriangleMesh far({{big, 0, 0}, {big, 1, 0}, {big, 0, 1}, {-big, 0, 0}, {-big, 1, 0}, {-big, 0, 1}},
                           {{0, 1, 2}, {3, 4, 5}});
    SurfaceHit hit;
    ASSERT_TRUE(far.intersect({{0, 0.25, 0.25}, {1, 0, 0}}, 0.0, 2 * big, hit));
    EXPECT_EQ(hit.t, big);
    EXPECT_EQ(hit.primitive, 0);
}

}  // namespace
}  // namespace irid::render
