#include <irid/error.h>
#include <irid/render/camera.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace irid::render {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

template <class F>
std::string error_message(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return {};
}

double angle_between(Vec3 a, Vec3 b) {
    return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0, 1.0));
}

TEST(Camera, CentreRayIsTheForwardDirectionFromTheEye) {
    const Vec3 eye{1, 2, 3}, at{4, -2, 15};
    const Camera cam(eye, at, {0, 1, 0}, 40.0, 16.0 / 9.0);
    const Ray r = cam.ray(0.5, 0.5);
    EXPECT_EQ(r.origin, eye);
    const Vec3 expected = normalize(at - eye);
    EXPECT_NEAR(r.direction.x, expected.x, 1e-15);
    EXPECT_NEAR(r.direction.y, expected.y, 1e-15);
    EXPECT_NEAR(r.direction.z, expected.z, 1e-15);
    EXPECT_EQ(cam.eye(), eye);
    EXPECT_NEAR(length(cam.forward() - expected), 0.0, 1e-15);
}

TEST(Camera, EdgeRaysMakeTheVerticalFovAndTheAspect) {
    for (const double fov : {1.0, 30.0, 60.0, 90.0, 150.0}) {
        for (const double aspect : {0.5, 1.0, 1.5, 2.35}) {
            const Camera cam({0, 0, 0}, {0.3, -0.2, -1}, {0, 1, 0}, fov, aspect);
            // Top-middle to bottom-middle: the vertical field of view.
            EXPECT_NEAR(angle_between(cam.ray(0.5, 0).direction, cam.ray(0.5, 1).direction),
                        fov * deg, 1e-12)
                << fov << " " << aspect;
            // Left-middle to right-middle: 2 atan(aspect tan(fov / 2)).
            EXPECT_NEAR(angle_between(cam.ray(0, 0.5).direction, cam.ray(1, 0.5).direction),
                        2.0 * std::atan(aspect * std::tan(0.5 * fov * deg)), 1e-12);
            // The corners: image-plane offsets ±aspect tan(fov/2), ±tan(fov/2) at distance 1.
            const Ray corner = cam.ray(1, 1);
            const double f = dot(corner.direction, cam.forward());
            EXPECT_NEAR(dot(corner.direction, cam.right()) / f, aspect * std::tan(0.5 * fov * deg),
                        1e-12);
            EXPECT_NEAR(dot(corner.direction, cam.up()) / f, -std::tan(0.5 * fov * deg), 1e-12);
            for (const double sx : {0.0, 0.3, 1.0}) {
                for (const double sy : {0.0, 0.7, 1.0}) {
                    EXPECT_NEAR(length(cam.ray(sx, sy).direction), 1.0, 1e-15);
                }
            }
        }
    }
}

TEST(Camera, UpIsUpAndRightIsRightInTheImage) {
    // Looking down −z with +y up: +x is to the right (a right-handed frame).
    const Camera cam({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 50.0, 1.5);
    EXPECT_GT(cam.ray(0.5, 0.0).direction.y, 0.1);   // top row looks up
    EXPECT_LT(cam.ray(0.5, 1.0).direction.y, -0.1);  // bottom row looks down
    EXPECT_LT(cam.ray(0.0, 0.5).direction.x, -0.1);  // left column looks left
    EXPECT_GT(cam.ray(1.0, 0.5).direction.x, 0.1);
    const Ray top_left = cam.ray(0, 0);
    EXPECT_LT(top_left.direction.x, 0.0);
    EXPECT_GT(top_left.direction.y, 0.0);
    EXPECT_NEAR(length(cam.up() - Vec3{0, 1, 0}), 0.0, 1e-15);
    EXPECT_NEAR(length(cam.right() - Vec3{1, 0, 0}), 0.0, 1e-15);
    // An up vector that is not perpendicular to the view is made so, keeping its side.
    const Camera tilted({0, 0, 0}, {0, -1, -1}, {0, 1, 0}, 50.0, 1.0);
    EXPECT_NEAR(dot(tilted.up(), tilted.forward()), 0.0, 1e-15);
    EXPECT_GT(tilted.up().y, 0.0);
    EXPECT_GT(tilted.ray(0.5, 0.0).direction.y, tilted.ray(0.5, 1.0).direction.y);
}

TEST(Camera, RejectsInvalidParameters) {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Vec3 o{0, 0, 0}, at{0, 0, -1}, up{0, 1, 0};
    EXPECT_NE(error_message([&] { Camera(o, o, up, 45, 1); }).find("must be distinct"),
              std::string::npos);
    EXPECT_NE(error_message([&] {
                  Camera(o, at, {0, 0, 2}, 45, 1);
              }).find("parallel"),
              std::string::npos);
    EXPECT_NE(error_message([&] {
                  Camera(o, at, {0, 0, 0}, 45, 1);
              }).find("up"),
              std::string::npos);
    for (const double fov : {0.0, 180.0, -10.0, nan, inf}) {
        EXPECT_NE(error_message([&] { Camera(o, at, up, fov, 1); }).find("vertical_fov_deg"),
                  std::string::npos)
            << fov;
    }
    for (const double aspect : {0.0, -1.0, nan, inf}) {
        EXPECT_NE(error_message([&] { Camera(o, at, up, 45, aspect); }).find("aspect"),
                  std::string::npos)
            << aspect;
    }
    EXPECT_NE(error_message([&] {
                  Camera({nan, 0, 0}, at, up, 45, 1);
              }).find("eye"),
              std::string::npos);
    EXPECT_NE(error_message([&] {
                  Camera(o, {0, inf, 0}, up, 45, 1);
              }).find("look_at"),
              std::string::npos);
    EXPECT_NO_THROW(Camera(o, at, up, 179.9, 1e-3));
}

}  // namespace
}  // namespace irid::render
