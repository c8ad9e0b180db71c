#pragma once

// Helpers of the geometry tests (geometry_test.cpp, mesh_test.cpp).

#include <irid/error.h>
#include <irid/render/geometry.h>

#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <string>

namespace irid::render::test {

inline constexpr double pi = std::numbers::pi;

/// The message of the irid::Error that f throws, or "" when it throws none.
template <class F>
std::string error_message(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return {};
}

inline void expect_near(Vec3 a, Vec3 b, double tol, const std::string& what = {}) {
    EXPECT_NEAR(a.x, b.x, tol) << what;
    EXPECT_NEAR(a.y, b.y, tol) << what;
    EXPECT_NEAR(a.z, b.z, tol) << what;
}

inline Vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> g(0.0, 1.0);
    while (true) {
        const Vec3 v{g(rng), g(rng), g(rng)};
        if (length(v) > 1e-6) return normalize(v);
    }
}

inline Vec3 random_point(std::mt19937& rng, double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    return {u(rng), u(rng), u(rng)};
}

}  // namespace irid::render::test
