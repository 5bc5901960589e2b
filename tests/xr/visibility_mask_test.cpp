// The lens mask from XR_KHR_visibility_mask's hidden triangles.
#include <gtest/gtest.h>

#include "xr/visibility_mask.h"

namespace fg::xr {
namespace {

TEST(VisibilityMask, AHiddenCornerTriangleHidesExactlyThePixelsInsideIt) {
    Fov fov{-1.0, 1.0, -1.0, 1.0};
    // The top-left half-square corner: x + y > 0 measured from (-1, 1), legs of length 1.
    std::vector<float> vertices = {-1.0f, 1.0f, 0.0f, 1.0f, -1.0f, 0.0f};
    VisibilityMask m = rasterize_hidden_triangles(vertices, {0, 1, 2}, fov, 8, 8);
    EXPECT_EQ(m.triangles, 1u);
    EXPECT_EQ(m.visible[0], 0) << "the top-left pixel is behind the lens housing";
    EXPECT_EQ(m.visible[7], 1) << "the top-right pixel is seen";
    EXPECT_EQ(m.visible[63], 1) << "the bottom-right pixel is seen";
    EXPECT_EQ(m.visible[7 * 8], 1) << "the bottom-left pixel is seen";
    // Pixel centres strictly inside the triangle x' + y' < 1 (in units of the leg): 4x4 block's
    // upper-left half, 10 of 64.
    EXPECT_NEAR(m.hidden_fraction(), 10.0 / 64.0, 1e-12);
}

TEST(VisibilityMask, WindingDoesNotMatter) {
    Fov fov{-1.0, 1.0, -1.0, 1.0};
    std::vector<float> vertices = {-1.0f, 1.0f, 0.0f, 1.0f, -1.0f, 0.0f};
    VisibilityMask a = rasterize_hidden_triangles(vertices, {0, 1, 2}, fov, 16, 16);
    VisibilityMask b = rasterize_hidden_triangles(vertices, {0, 2, 1}, fov, 16, 16);
    EXPECT_EQ(a.visible, b.visible);
}

TEST(VisibilityMask, OutOfRangeIndicesHideNothingAndDoNotCrash) {
    Fov fov{-1.0, 1.0, -1.0, 1.0};
    VisibilityMask m = rasterize_hidden_triangles({0.0f, 0.0f}, {0, 5, 9}, fov, 4, 4);
    EXPECT_EQ(m.triangles, 0u);
    EXPECT_EQ(m.hidden_fraction(), 0.0);
}

}  // namespace
}  // namespace fg::xr

namespace fg::xr {
namespace {

TEST(VisibilityMask, TheEnclosingLensHidesNoVisiblePixelAndSkipsSomeHiddenOnes) {
    // An octagon: the four corners cut at 30 % of each side, as the test runtime's headset.
    Fov fov{-1.0, 1.0, -1.0, 1.0};
    std::vector<float> v = {-1.0f, 1.0f, -0.4f, 1.0f, -1.0f, 0.4f,   1.0f, 1.0f, 1.0f, 0.4f, 0.4f, 1.0f,
                            1.0f, -1.0f, 0.4f, -1.0f, 1.0f, -0.4f,   -1.0f, -1.0f, -1.0f, -0.4f, -0.4f, -1.0f};
    VisibilityMask mask = rasterize_hidden_triangles(v, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, fov, 64, 64);
    LensEllipse lens = enclosing_lens(mask, LensEllipse{0.5, 0.5, 0.5, 0.5});
    ASSERT_GT(lens.radius_u, 0.0);
    auto kept = visible_pixels(lens, 64, 64);
    std::size_t skipped = 0;
    for (std::size_t i = 0; i < kept.size(); ++i) {
        if (mask.visible[i]) EXPECT_EQ(kept[i], 1) << "a pixel the headset shows would not be marched: " << i;
        if (!kept[i]) ++skipped;
    }
    EXPECT_GT(skipped, 0u);
}

TEST(VisibilityMask, NothingHiddenMeansNoLens) {
    VisibilityMask mask = rasterize_hidden_triangles({}, {}, Fov{-1.0, 1.0, -1.0, 1.0}, 8, 8);
    EXPECT_EQ(enclosing_lens(mask, LensEllipse{0.5, 0.5, 0.5, 0.5}).radius_u, 0.0);
}

}  // namespace
}  // namespace fg::xr
