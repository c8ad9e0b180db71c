// TriangleMesh::read_obj: the Wavefront OBJ reader (v, vt, vn and f lines; polygons fanned
// into triangles), with every limit and every damaged line an error naming file:line.

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
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <utility>
#include <vector>

namespace irid::render {
namespace {

class ObjReader {
public:
    explicit ObjReader(std::string name) : m_name(std::move(name)) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw Error(m_name + ":" + std::to_string(m_line) + ": " + what);
    }

    void set_line(int line) noexcept { m_line = line; }

    double number(std::string_view token, const char* usage) const {
        double value = 0.0;
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(value)) {
            fail(quote_untrusted(token, 24) + " is not a finite number; " + usage);
        }
        return value;
    }

    /// Resolves a 1-based or negative (relative) OBJ index to 0-based among `count` defined.
    int index(std::string_view token, std::size_t count, const char* what) const {
        long long value = 0;
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (ec != std::errc() || end != token.data() + token.size()) {
            fail(std::string(what) + " index " + quote_untrusted(token, 24) +
                 " is not an integer; a face vertex is i, i/t, i//n or i/t/n with 1-based "
                 "indices, negative ones counting back from the last defined");
        }
        const auto n = static_cast<long long>(count);
        if (value > 0 && value <= n) return static_cast<int>(value - 1);
        if (value < 0 && -value <= n) return static_cast<int>(n + value);
        if (n == 0) {
            fail(std::string(what) + " index " + std::to_string(value) + " is out of range: no " +
                 what + " is defined before this line");
        }
        fail(std::string(what) + " index " + std::to_string(value) + " is out of range: " +
             std::to_string(n) + " defined before this line; allowed 1 to " + std::to_string(n) +
             ", or -1 to -" + std::to_string(n) + " counting back from the last");
    }

private:
    std::string m_name;
    int m_line = 0;
};

/// The whitespace-separated tokens of a line.
std::vector<std::string_view> split_tokens(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) tokens.push_back(line.substr(start, i - start));
    }
    return tokens;
}

/// A unified vertex: position, uv and normal indices (−1 when absent).
struct VertexKey {
    int p, t, n;
    bool operator==(const VertexKey&) const noexcept = default;
};
struct VertexKeyHash {
    std::size_t operator()(const VertexKey& k) const noexcept {
        // Multiplicative mixing with the 64-bit golden-ratio constant 2^64/φ (Knuth, TAOCP
        // vol. 3, §6.4).
        std::uint64_t h = static_cast<std::uint32_t>(k.p);
        h = h * 0x9E3779B97F4A7C15ULL + static_cast<std::uint32_t>(k.t);
        h = h * 0x9E3779B97F4A7C15ULL + static_cast<std::uint32_t>(k.n);
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

}  // namespace

TriangleMesh TriangleMesh::read_obj(const std::filesystem::path& file) {
    return read_obj(file, max_triangles);
}

TriangleMesh TriangleMesh::read_obj(const std::filesystem::path& file, std::size_t triangle_limit) {
    const std::size_t max_obj_triangles = std::min(triangle_limit, max_triangles);
    // `v`, `vt` and `vn` lines each: three per triangle.
    const std::size_t max_obj_vertices = 3 * max_obj_triangles;
    const std::string name = file.string();
    // A regular file only: a mesh path comes from a scene file, and a FIFO there would block.
    const std::string text = read_text_file(file, "Wavefront OBJ mesh");
    if (text.find_first_not_of(" \t\r\n") == std::string::npos)
        throw Error(name + ": the file is empty; expected a Wavefront OBJ mesh with at least one face");

    ObjReader reader(name);
    std::vector<Vec3> obj_positions, obj_normals;
    std::vector<std::array<double, 2>> obj_uvs;
    std::vector<Vec3> positions, normals;
    std::vector<std::array<double, 2>> uvs;
    std::vector<std::array<int, 3>> triangles;
    std::unordered_map<VertexKey, int, VertexKeyHash> unified;
    bool every_vertex_has_uv = true, every_vertex_has_normal = true;
    std::vector<int> face;

    static constexpr const char* v_usage =
        "'v' takes x y z, optionally w or r g b (3, 4 or 6 numbers)";
    static constexpr const char* vn_usage = "'vn' takes x y z (3 numbers, not all 0)";
    static constexpr const char* vt_usage = "'vt' takes u, optionally v and w (1 to 3 numbers)";

    std::string line;
    int line_number = 0;
    std::size_t next = 0;
    // The next physical line of the text, without its line break (false at the end).
    const auto next_line = [&](std::string_view& out) {
        if (next >= text.size()) return false;
        std::size_t end = text.find('\n', next);
        if (end == std::string::npos) end = text.size();
        out = std::string_view(text).substr(next, end - next);
        if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
        next = end + 1;
        ++line_number;
        return true;
    };
    std::string_view physical;
    while (next_line(physical)) {
        const int statement_line = line_number;
        line.assign(physical);
        // A backslash at the end of a line continues the statement on the next line.
        while (!line.empty() && line.back() == '\\') {
            line.back() = ' ';
            if (!next_line(physical)) break;
            line += physical;
        }
        reader.set_line(statement_line);
        std::string_view view(line);
        if (const auto hash = view.find('#'); hash != std::string_view::npos) {
            view = view.substr(0, hash);
        }
        const std::vector<std::string_view> tokens = split_tokens(view);
        if (tokens.empty()) continue;
        const std::string_view key = tokens[0];
        const std::size_t args = tokens.size() - 1;
        if (key == "v") {
            if (args != 3 && args != 4 && args != 6) {
                reader.fail("'v' with " + std::to_string(args) + " numbers; " + v_usage);
            }
            Vec3 p{reader.number(tokens[1], v_usage), reader.number(tokens[2], v_usage),
                   reader.number(tokens[3], v_usage)};
            for (std::size_t k = 4; k <= args; ++k) (void)reader.number(tokens[k], v_usage);
            if (obj_positions.size() >= max_obj_vertices) {
                reader.fail("more than " + std::to_string(max_obj_vertices) +
                            " 'v' lines; irid reads meshes of at most " +
                            std::to_string(max_obj_triangles) + " triangles and " +
                            std::to_string(max_obj_vertices) + " vertices");
            }
            obj_positions.push_back(p);
        } else if (key == "vn") {
            if (args != 3)
                reader.fail("'vn' with " + std::to_string(args) + " numbers; " + vn_usage);
            const Vec3 n{reader.number(tokens[1], vn_usage), reader.number(tokens[2], vn_usage),
                         reader.number(tokens[3], vn_usage)};
            const double len = length(n);
            if (!(len > 0.0) || !std::isfinite(len)) {
                reader.fail("normal of zero length; " + std::string(vn_usage));
            }
            if (obj_normals.size() >= max_obj_vertices) {
                reader.fail("more than " + std::to_string(max_obj_vertices) +
                            " 'vn' lines; irid reads meshes of at most " +
                            std::to_string(max_obj_vertices) + " vertices");
            }
            obj_normals.push_back(n);
        } else if (key == "vt") {
            if (args < 1 || args > 3) {
                reader.fail("'vt' with " + std::to_string(args) + " numbers; " + vt_usage);
            }
            const double u = reader.number(tokens[1], vt_usage);
            const double v = args >= 2 ? reader.number(tokens[2], vt_usage) : 0.0;
            if (args == 3) (void)reader.number(tokens[3], vt_usage);
            if (obj_uvs.size() >= max_obj_vertices) {
                reader.fail("more than " + std::to_string(max_obj_vertices) +
                            " 'vt' lines; irid reads meshes of at most " +
                            std::to_string(max_obj_vertices) + " vertices");
            }
            obj_uvs.push_back({u, v});
        } else if (key == "f") {
            if (args < 3) {
                reader.fail("face with " + std::to_string(args) +
                            " vertices; a face needs at least 3 (polygons are fan-triangulated)");
            }
            face.clear();
            for (std::size_t k = 1; k <= args; ++k) {
                const std::string_view ref = tokens[k];
                // Split "i", "i/t", "i//n", "i/t/n".
                std::array<std::string_view, 3> parts{};
                std::size_t part_count = 0;
                std::size_t start = 0;
                bool too_many = false;
                while (true) {
                    const std::size_t slash = ref.find('/', start);
                    if (part_count == 3) {
                        too_many = true;
                        break;
                    }
                    parts[part_count++] =
                        ref.substr(start, slash == std::string_view::npos ? std::string_view::npos
                                                                          : slash - start);
                    if (slash == std::string_view::npos) break;
                    start = slash + 1;
                }
                if (too_many || parts[0].empty() || (part_count == 2 && parts[1].empty()) ||
                    (part_count == 3 && parts[2].empty())) {
                    reader.fail("face vertex " + quote_untrusted(ref, 24) +
                                " is malformed; allowed forms: i, i/t, i//n, i/t/n");
                }
                VertexKey vk{reader.index(parts[0], obj_positions.size(), "position"), -1, -1};
                if (part_count >= 2 && !parts[1].empty()) {
                    vk.t = reader.index(parts[1], obj_uvs.size(), "texture coordinate");
                }
                if (part_count == 3) vk.n = reader.index(parts[2], obj_normals.size(), "normal");
                if (vk.t < 0) every_vertex_has_uv = false;
                if (vk.n < 0) every_vertex_has_normal = false;
                const auto [it, inserted] =
                    unified.try_emplace(vk, static_cast<int>(positions.size()));
                if (inserted) {
                    positions.push_back(obj_positions[static_cast<std::size_t>(vk.p)]);
                    normals.push_back(vk.n >= 0 ? obj_normals[static_cast<std::size_t>(vk.n)]
                                                : Vec3{0, 0, 1});
                    uvs.push_back(vk.t >= 0 ? obj_uvs[static_cast<std::size_t>(vk.t)]
                                            : std::array<double, 2>{0.0, 0.0});
                }
                face.push_back(it->second);
            }
            if (triangles.size() + (face.size() - 2) > max_obj_triangles) {
                reader.fail("more than " + std::to_string(max_obj_triangles) +
                            " triangles; irid reads meshes of at most " +
                            std::to_string(max_obj_triangles) + " triangles");
            }
            for (std::size_t k = 1; k + 1 < face.size(); ++k) {
                triangles.push_back({face[0], face[k], face[k + 1]});
            }
        } else if (key == "o" || key == "g" || key == "s" || key == "usemtl" || key == "mtllib" ||
                   key == "l" || key == "p") {
            continue;
        } else {
            reader.fail("unknown statement " + quote_untrusted(key, 24) +
                        "; allowed: v, vn, vt, f, and o, g, s, usemtl, mtllib, l, p (ignored), "
                        "# comments");
        }
    }
    if (triangles.empty()) {
        throw Error(name + ": no face ('f' line) in " + std::to_string(line_number) +
                    " lines; a mesh needs at least one");
    }
    if (!every_vertex_has_normal) normals.clear();
    if (!every_vertex_has_uv) uvs.clear();
    try {
        return TriangleMesh(std::move(positions), std::move(triangles), std::move(normals),
                            std::move(uvs));
    } catch (const Error& e) {
        throw Error(name + ": " + e.what());
    }
}

}  // namespace irid::render
