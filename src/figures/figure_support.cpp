#include "figure_support.h"

#include <irid/error.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace irid::figures::detail {

namespace {

std::string trim(std::string_view s) {
    std::size_t a = 0;
    std::size_t b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return std::string(s.substr(a, b - a));
}

/// A whole string as a finite double, or false.
bool parse_double(std::string_view text, double& out) {
    const std::string s = trim(text);
    if (s.empty()) return false;
    const char* first = s.data();
    const char* last = s.data() + s.size();
    if (*first == '+') ++first;
    const auto [end, ec] = std::from_chars(first, last, out);
    return ec == std::errc() && end == last && std::isfinite(out);
}

std::vector<std::string> split_list(std::string_view text) {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        items.push_back(trim(text.substr(start, comma == std::string_view::npos
                                                    ? std::string_view::npos
                                                    : comma - start)));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return items;
}

std::string range_text(double lo, double hi) {
    return "a number in [" + shortest(lo) + ", " + shortest(hi) + "]";
}

}  // namespace

Options::Options(const FigureRequest& request, std::initializer_list<std::string_view> known_keys)
    : m_figure(request.name) {
    for (const auto& [key, value] : request.options) {
        if (std::find(known_keys.begin(), known_keys.end(), key) == known_keys.end()) {
            std::vector<std::string> keys(known_keys.begin(), known_keys.end());
            throw FigureRequestError(m_figure + ": unknown option \"" + key + "\"; allowed: " +
                        (keys.empty() ? std::string("none") : join(keys, ", ")));
        }
        m_values.emplace_back(key, value);
    }
}

const std::string* Options::find(std::string_view key) const noexcept {
    for (auto it = m_values.rbegin(); it != m_values.rend(); ++it) {
        if (it->first == key) return &it->second;
    }
    return nullptr;
}

bool Options::has(std::string_view key) const noexcept {
    return find(key) != nullptr;
}

std::string Options::text(std::string_view key, std::string_view fallback) const {
    const std::string* v = find(key);
    return v != nullptr ? *v : std::string(fallback);
}

void Options::fail(std::string_view key, std::string_view value, std::string_view what,
                   std::string_view allowed) const {
    throw FigureRequestError(m_figure + ": option " + std::string(key) + "=" + std::string(value) + ": " +
                std::string(what) + "; allowed: " + std::string(allowed));
}

std::string Options::choice(std::string_view key, std::initializer_list<std::string_view> allowed,
                            std::string_view fallback) const {
    return choice(key, std::vector<std::string>(allowed.begin(), allowed.end()), fallback);
}

std::string Options::choice(std::string_view key, const std::vector<std::string>& allowed,
                            std::string_view fallback) const {
    const std::string* v = find(key);
    if (v == nullptr) return std::string(fallback);
    if (std::find(allowed.begin(), allowed.end(), *v) == allowed.end()) {
        fail(key, *v, "not a known value", join(allowed, ", "));
    }
    return *v;
}

double Options::number(std::string_view key, double fallback, double lo, double hi) const {
    const std::string* v = find(key);
    if (v == nullptr) return fallback;
    double x = 0.0;
    if (!parse_double(*v, x)) fail(key, *v, "not a number", range_text(lo, hi));
    if (x < lo || x > hi) fail(key, *v, "out of range", range_text(lo, hi));
    return x;
}

int Options::integer(std::string_view key, int fallback, int lo, int hi) const {
    const std::string* v = find(key);
    if (v == nullptr) return fallback;
    const std::string s = trim(*v);
    int x = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
    const std::string allowed =
        "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (s.empty() || ec != std::errc() || end != s.data() + s.size()) {
        fail(key, *v, "not an integer", allowed);
    }
    if (x < lo || x > hi) fail(key, *v, "out of range", allowed);
    return x;
}

std::vector<std::string> Options::list(std::string_view key, std::string_view fallback) const {
    const std::string* v = find(key);
    const std::string_view source = v != nullptr ? std::string_view(*v) : fallback;
    std::vector<std::string> items = split_list(source);
    for (const std::string& item : items) {
        if (item.empty()) {
            fail(key, source, "an empty item in the list",
                 "a comma-separated list of non-empty items");
        }
    }
    return items;
}

std::vector<double> Options::numbers(std::string_view key, std::string_view fallback, double lo,
                                     double hi, std::size_t count) const {
    const std::vector<std::string> items = list(key, fallback);
    const std::string source = text(key, fallback);
    const std::string allowed =
        (count == 0 ? std::string("comma-separated numbers")
                    : std::to_string(count) + " comma-separated numbers") +
        ", each in [" + shortest(lo) + ", " + shortest(hi) + "]";
    if (count != 0 && items.size() != count) {
        fail(key, source, "expected " + std::to_string(count) + " values, got " +
                              std::to_string(items.size()), allowed);
    }
    std::vector<double> values;
    values.reserve(items.size());
    for (const std::string& item : items) {
        double x = 0.0;
        if (!parse_double(item, x)) fail(key, source, "\"" + item + "\" is not a number", allowed);
        if (x < lo || x > hi) fail(key, source, item + " is out of range", allowed);
        values.push_back(x);
    }
    return values;
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) out += separator;
        out += items[i];
    }
    return out;
}

std::string fixed(double value, int decimals) {
    decimals = std::clamp(decimals, 0, 17);
    if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;
    std::array<char, 64> buffer{};
    std::snprintf(buffer.data(), buffer.size(), "%.*f", decimals, value);
    return buffer.data();
}

std::string shortest(double value) {
    std::array<char, 64> buffer{};
    const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    if (ec != std::errc()) return "?";
    return std::string(buffer.data(), end);
}

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

}  // namespace irid::figures::detail
