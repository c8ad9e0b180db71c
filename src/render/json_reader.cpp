// The scene files' JSON reading: a strict object reader, the checks nlohmann's parser leaves
// to its caller (a key given twice, a number beyond a double), and --set overrides.

#include "json_reader.h"

#include <irid/error.h>
#include <irid/text_input.h>

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

namespace irid::render::json {
namespace {

/// "line L, column C" of the character at `offset`.
std::string position_of(std::string_view text, std::size_t offset) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < std::min(offset, text.size()); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return fmt::format("line {}, column {}", line, column);
}

}  // namespace

std::string shown(const Json& v) {
    // Bytes that are not UTF-8 (a --set value can hold any) are shown as U+FFFD.
    std::string text = v.dump(-1, ' ', false, Json::error_handler_t::replace);
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return text;
}

ObjectReader::ObjectReader(const Json& object, std::string path, const std::string& source,
                           std::vector<std::string_view> keys)
    : m_object(object), m_path(std::move(path)), m_source(source) {
    if (!object.is_object())
        fail(m_path.empty() ? "the scene" : m_path, "must be an object ({...})");
    for (const auto& item : object.items()) {
        if (std::find(keys.begin(), keys.end(), item.key()) == keys.end()) {
            throw Error(fmt::format("{}: unknown key {}; valid keys{}: {}", m_source,
                                    quote_untrusted(key_path(item.key()), 60),
                                    m_path.empty() ? "" : " in '" + m_path + "'",
                                    fmt::join(keys, ", ")));
        }
    }
}

const Json* ObjectReader::find(std::string_view key) const {
    const auto it = m_object.find(std::string(key));
    return it == m_object.end() ? nullptr : &*it;
}

void ObjectReader::number(std::string_view key, double& out, double lo, double hi) const {
    const Json* v = find(key);
    if (!v) return;
    if (!v->is_number()) fail(key_path(key), fmt::format("must be a number in [{}, {}]", lo, hi));
    const double x = v->get<double>();
    if (!std::isfinite(x) || x < lo || x > hi)
        fail(key_path(key), fmt::format("is {}; allowed: [{}, {}]", x, lo, hi));
    out = x;
}

void ObjectReader::positive(std::string_view key, double& out, double hi) const {
    const Json* v = find(key);
    if (!v) return;
    const double x = v->is_number() ? v->get<double>() : std::nan("");
    if (!std::isfinite(x) || x <= 0.0 || x > hi)
        fail(key_path(key), fmt::format("is {}; allowed: (0, {}]", shown(*v), hi));
    out = x;
}

void ObjectReader::integer(std::string_view key, int& out, int lo, int hi) const {
    const Json* v = find(key);
    if (!v) return;
    if (!v->is_number_integer())
        fail(key_path(key), fmt::format("must be an integer in [{}, {}]", lo, hi));
    const bool too_big =
        v->is_number_unsigned() && v->get<std::uint64_t>() > static_cast<std::uint64_t>(hi);
    const auto x = too_big ? static_cast<long long>(hi) + 1 : v->get<long long>();
    if (x < lo || x > hi)
        fail(key_path(key), fmt::format("is {}; allowed: [{}, {}]", shown(*v), lo, hi));
    out = static_cast<int>(x);
}

void ObjectReader::boolean(std::string_view key, bool& out) const {
    const Json* v = find(key);
    if (!v) return;
    if (!v->is_boolean()) fail(key_path(key), "must be true or false");
    out = v->get<bool>();
}

void ObjectReader::text(std::string_view key, std::string& out) const {
    const Json* v = find(key);
    if (!v) return;
    if (!v->is_string()) fail(key_path(key), "must be a string");
    out = v->get<std::string>();
}

void ObjectReader::vec3(std::string_view key, std::array<double, 3>& out, double lo,
                        double hi) const {
    const Json* v = find(key);
    if (!v) return;
    const std::string allowed = fmt::format("an array of 3 numbers in [{}, {}]", lo, hi);
    if (!v->is_array() || v->size() != 3) fail(key_path(key), "must be " + allowed);
    for (std::size_t i = 0; i < 3; ++i) {
        const Json& e = (*v)[i];
        const double x = e.is_number() ? e.get<double>() : std::nan("");
        if (!std::isfinite(x) || x < lo || x > hi)
            fail(key_path(key), fmt::format("is {}; must be {}", shown(*v), allowed));
        out[i] = x;
    }
}

std::string ObjectReader::key_path(std::string_view key) const {
    return m_path.empty() ? std::string(key) : m_path + "." + std::string(key);
}

void ObjectReader::fail(const std::string& key_path, const std::string& what) const {
    throw Error(fmt::format("{}: '{}' {}", m_source, key_path, what));
}

/// "line L, column C" of a parse error. nlohmann's parse_error::byte is one past the last
/// character read; when that character closes a string (the parser wanted something else, as a
/// comma before the next key), the column given is the string's opening quote, where editors
/// and other JSON tools put it.
std::string line_column(std::string_view text, std::size_t byte) {
    std::size_t end = std::min(text.size(), byte > 0 ? byte - 1 : 0);
    if (end < text.size() && end > 0 && text[end] == '"') {
        std::size_t i = end;
        while (i > 0 && !(text[i - 1] == '"' && (i < 2 || text[i - 2] != '\\'))) --i;
        if (i > 0) end = i - 1;
    }
    return position_of(text, end);
}

/// What nlohmann's DOM parser accepts silently or reports without a position, found in the text
/// it has read: a key given twice in one object (the DOM keeps the last; a scene file with two
/// values for one key is a mistake, like an unknown key), and a number beyond the range of a
/// double (nlohmann reports "number overflow" with no line). Runs on text nlohmann has parsed
/// (or failed on only for such a number), comments included. Throws irid::Error with the key path
/// or the number, and its line and column.
void check_text(std::string_view text, const std::string& source) {
    struct Frame {
        bool object = false;
        std::string path;                                       // the key path of this container
        std::vector<std::pair<std::string, std::size_t>> keys;  // keys seen and where
        std::size_t index = 0;                                  // arrays: the element's index
        bool expect_key = true;
        std::string key;  // objects: the current key
    };
    std::vector<Frame> stack;
    const auto child_path = [&]() -> std::string {
        if (stack.empty()) return {};
        const Frame& f = stack.back();
        const std::string part = f.object ? f.key : std::to_string(f.index);
        return f.path.empty() ? part : f.path + "." + part;
    };
    std::size_t i = 0;
    const std::size_t n = text.size();
    while (i < n) {
        const char c = text[i];
        if (c == '/' && i + 1 < n && text[i + 1] == '/') {
            while (i < n && text[i] != '\n') ++i;
        } else if (c == '/' && i + 1 < n && text[i + 1] == '*') {
            const std::size_t end = text.find("*/", i + 2);
            i = end == std::string_view::npos ? n : end + 2;
        } else if (c == '{' || c == '[') {
            Frame f;
            f.object = c == '{';
            f.path = child_path();
            stack.push_back(std::move(f));
            ++i;
        } else if (c == '}' || c == ']') {
            if (!stack.empty()) stack.pop_back();
            ++i;
        } else if (c == ',') {
            if (!stack.empty()) {
                if (stack.back().object)
                    stack.back().expect_key = true;
                else
                    ++stack.back().index;
            }
            ++i;
        } else if (c == ':') {
            if (!stack.empty()) stack.back().expect_key = false;
            ++i;
        } else if (c == '"') {
            const std::size_t start = i++;
            while (i < n && text[i] != '"') i += text[i] == '\\' ? 2 : 1;
            ++i;
            if (!stack.empty() && stack.back().object && stack.back().expect_key) {
                Frame& f = stack.back();
                const Json decoded = Json::parse(text.substr(start, i - start), nullptr, false);
                f.key = decoded.is_string() ? decoded.get<std::string>() : std::string{};
                for (const auto& [seen, at] : f.keys) {
                    if (seen == f.key) {
                        throw Error(fmt::format(
                            "{}: the key {} is given twice, at {} and at {}; give each key once",
                            source, quote_untrusted(child_path(), 80), position_of(text, at),
                            position_of(text, start)));
                    }
                }
                f.keys.emplace_back(f.key, start);
            }
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            const std::size_t start = i;
            while (i < n &&
                   std::string_view("+-.0123456789eE").find(text[i]) != std::string_view::npos)
                ++i;
            const std::string number(text.substr(start, i - start));
            if (std::isinf(std::strtod(number.c_str(), nullptr))) {
                throw Error(fmt::format(
                    "{}: the number {} at {} is beyond the range of a double (about 1.8e308)",
                    source, quote_untrusted(number), position_of(text, start)));
            }
        } else {
            ++i;
        }
    }
}

/// Replaces the value at a dotted key path ("soap.bubbles.0.radius").
void apply_override(Json& root, const std::string& assignment, const std::string& source) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw Error(fmt::format("{}: override {} must be key.path=value", source,
                                quote_untrusted(assignment, 60)));
    const std::string key = assignment.substr(0, eq);
    const std::string text = assignment.substr(eq + 1);
    Json value = Json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (value.is_discarded()) value = text;  // a bare string: render.path=spectral

    Json* node = &root;
    std::size_t start = 0;
    while (true) {
        const auto dot = key.find('.', start);
        const std::string part = key.substr(start, dot == std::string::npos ? dot : dot - start);
        if (part.empty())
            throw Error(fmt::format("{}: override key {} has an empty part", source,
                                    quote_untrusted(key, 60)));
        if (node->is_array()) {
            std::size_t index = 0;
            const auto [p, ec] = std::from_chars(part.data(), part.data() + part.size(), index);
            if (ec != std::errc{} || p != part.data() + part.size() || index >= node->size())
                throw Error(fmt::format("{}: override key {}: {} must be an index below {}", source,
                                        quote_untrusted(key, 60), quote_untrusted(part),
                                        node->size()));
            node = &(*node)[index];
        } else {
            if (!node->is_object() && !node->is_null())
                throw Error(fmt::format("{}: override key {}: {} is not inside an object", source,
                                        quote_untrusted(key, 60), quote_untrusted(part)));
            node = &(*node)[part];
        }
        if (dot == std::string::npos) break;
        start = dot + 1;
    }
    *node = std::move(value);
}

}  // namespace irid::render::json
