// The lens mask from XR_KHR_visibility_mask's hidden triangles.
#include <gtest/gtest.h>

#include "xr/lens_mask.h"

namespace fg::xr {
namespace {

TEST(LensMask, AHiddenCornerTriangleHidesExactlyThePixelsInsideIt) {
    Fov fov{-1.0, 1.0, -1.0, 1.0};
    // The top-left half-square corner: x + y > 0 measured from (-1, 1), legs of length 1.
    std::vector<float> vertices = {-1.0f, 1.0f, 0.0f, 1.0f, -1.0f, 0.0f};
    LensMask m = rasterize_hidden_triangles(vertices, {0, 1, 2}, fov, 8, 8);
    EXPECT_EQ(m.triangles, 1u);
    EXPECT_EQ(m.visible[0], 0) << "the top-left pixel is behind the lens housing";
    EXPECT_EQ(m.visible[7], 1) << "the top-right pixel is seen";
    EXPECT_EQ(m.visible[63], 1) << "the bottom-right pixel is seen";
    EXPECT_EQ(m.visible[7 * 8], 1) << "the bottom-left pixel is seen";
    // Pixel centres strictly inside the triangle x' + y' < 1 (in units of the leg): 4x4 block's
    // upper-left half, 10 of 64.
    EXPECT_NEAR(m.hidden_fraction(), 10.0 / 64.0, 1e-12);
}

TEST(LensMask, WindingDoesNotMatter) {
    Fov fov{-1.0, 1.0, -1.0, 1.0};
    std::vector<float> vertices = {-1.0f, 1.0f, 0.0f, 1.0f, -1.0f, 0.0f};
    LensMask a = rasterize_hidden_triangles(vertices, {0, 1, 2}, fov, 16, 16);
    LensMask b = rasterize_hidden_triangles(vertices, {0, 2, 1}, fov, 16, 16);
    EXPECT_EQ(a.visible, b.visible);
}

TEST(LensMask, OutOfRangeIndicesHideNothingAndDoNotCrash) {
    Fov fov{-1.0, 1.0, -1.0, 1.0};
    LensMask m = rasterize_hidden_triangles({0.0f, 0.0f}, {0, 5, 9}, fov, 4, 4);
    EXPECT_EQ(m.triangles, 0u);
    EXPECT_EQ(m.hidden_fraction(), 0.0);
}

}  // namespace
}  // namespace fg::xr
