#pragma once

// The scene files' JSON: a strict reader of one object, the checks nlohmann's parser leaves to
// its caller, and --set overrides. Every failure throws irid::Error naming the source, the key
// path and what is allowed. Private to irid_render.

#include <fmt/core.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <array>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace irid::render::json {

using Json = nlohmann::json;

/// A JSON value for a message: its JSON text (control characters escaped, bytes that are not
/// UTF-8 shown as U+FFFD), cut short when long.
[[nodiscard]] std::string shown(const Json& v);

/// Reads one JSON object at a key path: refuses keys it does not know, then reads values by
/// name. A missing key leaves the output as it was (the default); a present one must be valid.
class ObjectReader {
public:
    /// `path` is the object's key path ("" for the root); `keys` are the keys it may hold.
    ObjectReader(const Json& object, std::string path, const std::string& source,
                 std::vector<std::string_view> keys);

    /// The value at `key`, or null when absent.
    [[nodiscard]] const Json* find(std::string_view key) const;

    /// A finite number in [lo, hi].
    void number(std::string_view key, double& out, double lo, double hi) const;
    /// A finite number in (0, hi].
    void positive(std::string_view key, double& out, double hi) const;
    /// An integer in [lo, hi].
    void integer(std::string_view key, int& out, int lo, int hi) const;
    void boolean(std::string_view key, bool& out) const;
    void text(std::string_view key, std::string& out) const;
    /// One of the named options.
    template <class Enum>
    void choice(std::string_view key, Enum& out,
                std::initializer_list<std::pair<std::string_view, Enum>> options) const {
        const Json* v = find(key);
        if (!v) return;
        std::vector<std::string_view> names;
        for (const auto& o : options) names.push_back(o.first);
        if (v->is_string()) {
            const std::string s = v->get<std::string>();
            for (const auto& o : options) {
                if (o.first == s) {
                    out = o.second;
                    return;
                }
            }
        }
        fail(key_path(key), fmt::format("is {}; allowed: {}", shown(*v), fmt::join(names, ", ")));
    }

    /// Three finite numbers, each in [lo, hi].
    void vec3(std::string_view key, std::array<double, 3>& out, double lo, double hi) const;

    /// "path.key".
    [[nodiscard]] std::string key_path(std::string_view key) const;
    /// Throws "source: 'key_path' what".
    [[noreturn]] void fail(const std::string& key_path, const std::string& what) const;

private:
    const Json& m_object;
    std::string m_path;
    const std::string& m_source;
};

/// "line L, column C" of a parse error at nlohmann's parse_error::byte (one past the last
/// character read), moved back to a string's opening quote where editors put it.
[[nodiscard]] std::string line_column(std::string_view text, std::size_t byte);

/// What nlohmann's DOM parser accepts silently or reports without a position: a key given twice
/// in one object, and a number beyond the range of a double. Runs on text nlohmann has parsed
/// (comments included) and throws with the key path or the number and its line and column.
void check_text(std::string_view text, const std::string& source);

/// Applies "key.path=value" to `root` ("soap.bubbles.0.radius=0.4"); a value that is not JSON
/// is taken as a string (render.path=spectral).
void apply_override(Json& root, const std::string& assignment, const std::string& source);

}  // namespace irid::render::json
