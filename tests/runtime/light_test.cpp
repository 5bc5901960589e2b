// The light nodes against closed-form answers, on real frames (the `light` AOV: specular rgb,
// shadow alpha): a sphere over a plane lit at 45 degrees casts its shadow where the geometry puts
// it, with a penumbra as wide as the light's angular size makes it at each edge; a highlight peaks
// where the normal halves the angle between the light and the camera; auxiliary lights light by the
// same terms, a point light by the inverse square of its distance, its shadow cast from its point.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <fmt/format.h>

#include <Imath/half.h>

#include "frame/aov_images.h"
#include "offline/jittered_samples.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

constexpr std::uint32_t kSize = 160;
constexpr double kFovDeg = 40.0;

// The `light` AOV of the left eye as floats, four per pixel.
std::vector<float> light_aov(const RenderedFrame& f) {
    const auto& bytes = f.aovs_left.at(test::aov_index("light"));
    std::vector<float> out(bytes.size() / sizeof(Imath::half));
    for (std::size_t i = 0; i < out.size(); ++i) {
        Imath::half h;
        std::memcpy(&h, bytes.data() + i * sizeof h, sizeof h);
        out[i] = h;
    }
    return out;
}

// Channel value i of a half-float AOV image.
double half_at(const std::vector<std::byte>& bytes, std::size_t i) {
    Imath::half h;
    std::memcpy(&h, bytes.data() + i * sizeof h, sizeof h);
    return static_cast<double>(h);
}

// The `position` AOV: xyz world position, w the distance along the ray (not finite: a miss).
std::vector<float> world_positions(const RenderedFrame& f) {
    const auto& bytes = f.aovs_left[test::aov_index("position")];
    std::vector<float> world(bytes.size() / sizeof(float));
    std::memcpy(world.data(), bytes.data(), bytes.size());
    return world;
}

RenderedFrame render(const Pack& pack) {
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    return r.render(r.scene_camera(), 0.0);
}

// A sphere of `radius` at `height` over the plane y = 0, lit at 45 degrees from +x by a light of
// `angle_deg` radius; the camera 3 above the point x = -1, looking straight down. `never_negative`
// clamps the distance at 0 inside, as the Mandelbox's and other folding fractals' estimates are.
Pack sphere_over_a_plane(double radius, double height, double angle_deg, double start, bool never_negative = false, int rays = 1) {
    return test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "sphere over a plane",
      "nodes": [
        {{"id": "at", "type": "xform.translate", "inputs": {{"offset": [0.0, {1}, 0.0]}}}},
        {{"id": "ball", "type": "prim.sphere", "inputs": {{"p": "at.p", "radius": {0}}}}},
        {{"id": "ground", "type": "prim.plane"}},
        {{"id": "both", "type": "op.union", "inputs": {{"a": "ball.distance", "b": "ground.distance"}}}},
        {{"id": "outside", "type": "math.max", "inputs": {{"a": "both.distance", "b": 0.0}}}},
        {{"id": "shadow", "type": "light.soft_shadow", "inputs": {{"angle": {2}, "start": {4}, "max_distance": 6.0, "steps": 256, "rays": {6}}}}}
      ],
      "outputs": {{"distance": "{5}", "shadow": "shadow.shadow"}},
      "scene": {{"camera": {{"position": [-1, 3, 0], "target": [-1, 0, 0], "up": [0, 0, -1], "fov_deg": {3}}},
                "light": {{"direction": [0.70710678, 0.70710678, 0]}}, "bounds": {{"radius": 20}}}}
    }})", radius, height, angle_deg, kFovDeg, start, never_negative ? "outside.value" : "both.distance", rays));
}

// The solution r of 0.25 (1 + r)^2 (2 - r) = level (soft_shadow.glsl's profile), by bisection.
double passage_at(double level) {
    double lo = -1.0, hi = 1.0;
    for (int i = 0; i < 60; ++i) {
        double mid = 0.5 * (lo + hi);
        (0.25 * (1 + mid) * (1 + mid) * (2 - mid) < level ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

class Light : public RuntimeTest {};

}  // namespace

TEST_F(Light, a_sphere_over_a_plane_casts_the_shadow_the_geometry_puts_with_its_penumbra) {
    // Sphere of radius 0.3 at height 1 over the plane y = 0, the light 45 degrees up from +x, a
    // light of 2 degrees' radius; the camera 3 above the shadow, looking straight down.
    const double radius = 0.3, height = 1.0, angle_deg = 2.0;
    Pack pack = sphere_over_a_plane(radius, height, angle_deg, 0.002);
    RenderedFrame f = render(pack);
    const std::vector<float> light = light_aov(f);
    // The plane's x at a column of the centre row (z = 0).
    const double half_width = 3.0 * std::tan(glm::radians(kFovDeg / 2.0));
    auto x_of = [&](double column) { return -1.0 + (column / kSize - 0.5) * 2.0 * half_width; };
    const std::size_t row = kSize / 2;
    std::vector<double> shadow(kSize);
    for (std::size_t x = 0; x < kSize; ++x) shadow[x] = light[4 * (row * kSize + x) + 3];
    // Where the row crosses a level, in columns (pixel centres at x + 0.5), between two columns.
    auto crossing = [&](double level, std::size_t from, std::size_t to) {
        for (std::size_t x = from; x + 1 < to; ++x)
            if ((shadow[x] - level) * (shadow[x + 1] - level) <= 0.0 && shadow[x] != shadow[x + 1])
                return x + 0.5 + (level - shadow[x]) / (shadow[x + 1] - shadow[x]);
        return -1.0;
    };
    const double pixel = 2.0 * half_width / kSize;
    // The geometric shadow: the sphere's shadow along x spans [-h - r / cos 45, -h + r / cos 45].
    const double far_edge = -height - radius * std::sqrt(2.0), near_edge = -height + radius * std::sqrt(2.0);
    std::size_t centre = static_cast<std::size_t>((-height + 1.0) / (2.0 * half_width) * kSize + kSize / 2.0);
    ASSERT_LT(shadow[centre], 0.01) << "the shadow's centre is lit";
    const double far50 = x_of(crossing(0.5, 2, centre)), near50 = x_of(crossing(0.5, centre, kSize - 10));
    // The penumbra: a light of angular radius a seen past the sphere from t away spans 2 t tan(a)
    // across the ray, 2 t tan(a) / cos 45 along the plane; 10 % to 90 % of it is the profile's share.
    const glm::dvec3 sphere(0.0, height, 0.0);
    auto width = [&](double edge_x) {
        const double t = std::sqrt(glm::dot(sphere - glm::dvec3(edge_x, 0, 0), sphere - glm::dvec3(edge_x, 0, 0)) - radius * radius);
        return (passage_at(0.9) - passage_at(0.1)) * t * std::tan(glm::radians(angle_deg)) * std::sqrt(2.0);
    };
    const double far_width = std::abs(x_of(crossing(0.9, 2, centre)) - x_of(crossing(0.1, 2, centre)));
    const double near_width = std::abs(x_of(crossing(0.9, centre, kSize - 10)) - x_of(crossing(0.1, centre, kSize - 10)));
    std::string figures = fmt::format(
        "shadow edges at x = {:.4f} and {:.4f} (geometry {:.4f}, {:.4f}); penumbrae 10-90 % {:.4f} and {:.4f} wide "
        "(geometry {:.4f}, {:.4f}); a pixel is {:.4f}",
        far50, near50, far_edge, near_edge, far_width, near_width, width(far_edge), width(near_edge), pixel);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_NEAR(far50, far_edge, pixel) << figures;
    EXPECT_NEAR(near50, near_edge, pixel) << figures;
    EXPECT_NEAR(far_width, width(far_edge), pixel) << figures;
    EXPECT_NEAR(near_width, width(near_edge), pixel) << figures;
    EXPECT_GT(far_width, near_width + pixel) << "the penumbra widens with the distance to the occluder: " << figures;
}

TEST_F(Light, a_distance_that_never_goes_negative_still_casts_a_full_shadow) {
    // Inside a folding fractal the estimate stays near 0, never below: the shadow ray cannot read
    // how deep it went, and the cone profile would stop at half shadow. How far the ray goes on at
    // the surface stands in for the depth: the sphere's shadow is dark again, its edges in place.
    Pack pack = sphere_over_a_plane(0.3, 1.0, 2.0, 0.002, true);
    const std::vector<float> light = light_aov(render(pack));
    const double half_width = 3.0 * std::tan(glm::radians(kFovDeg / 2.0)), pixel = 2.0 * half_width / kSize;
    const std::size_t row = kSize / 2, centre = static_cast<std::size_t>(kSize / 2.0);   // x = -1 under the camera
    std::vector<double> shadow(kSize);
    for (std::size_t x = 0; x < kSize; ++x) shadow[x] = light[4 * (row * kSize + x) + 3];
    // The 50 % level's columns either side of the centre.
    std::size_t far = centre, near = centre;
    while (far > 0 && shadow[far] < 0.5) --far;
    while (near + 1 < kSize && shadow[near] < 0.5) ++near;
    const double far_x = -1.0 + (far + 0.5 - kSize / 2.0) * pixel, near_x = -1.0 + (near + 0.5 - kSize / 2.0) * pixel;
    const std::string figures = fmt::format("shadow at the centre {:.3f}; 50 % at x = {:.4f} and {:.4f} (geometry {:.4f}, {:.4f}; a pixel is {:.4f})",
                                            shadow[centre], far_x, near_x, -1.0 - 0.3 * std::sqrt(2.0), -1.0 + 0.3 * std::sqrt(2.0), pixel);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_LT(shadow[centre], 0.02) << figures;
    EXPECT_NEAR(far_x, -1.0 - 0.3 * std::sqrt(2.0), 2.0 * pixel) << figures;
    EXPECT_NEAR(near_x, -1.0 + 0.3 * std::sqrt(2.0), 2.0 * pixel) << figures;
}

TEST_F(Light, accumulated_samples_make_the_shadow_a_true_area_light) {
    // The sphere over the plane under a light of 4 degrees' radius. Each of 64 samples marches one
    // sharp ray towards a point of the light's disc; their mean must be the share of the disc a plane
    // point sees past the sphere, integrated here from closed-form ray-sphere intersections.
    const double radius = 0.3, height = 1.0, angle_deg = 4.0, start = 0.002;
    Pack pack = sphere_over_a_plane(radius, height, angle_deg, start);
    HeadlessRenderer r(test::shared_context(), pack, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const std::size_t row = kSize / 2;
    auto shadow_row = [&](const RenderedFrame& f) {
        const std::vector<float> light = light_aov(f);
        std::vector<double> out(kSize);
        for (std::size_t x = 0; x < kSize; ++x) out[x] = light[4 * (row * kSize + x) + 3];
        return out;
    };
    const std::vector<double> cone = shadow_row(r.render(r.scene_camera(), 0.0));
    r.set_light_sample(5u);
    const std::vector<double> one_sample = shadow_row(r.render(r.scene_camera(), 0.0));
    r.set_light_sample(std::nullopt);
    const std::vector<double> area = shadow_row(render_samples(r, r.scene_camera(), 0.0, 0, 64));
    // Four rays a sample, a lattice over the disc shifted by the sample's point: 16 samples of them
    // against 16 of one ray.
    Pack four_rays = sphere_over_a_plane(radius, height, angle_deg, start, false, 4);
    HeadlessRenderer r4(test::shared_context(), four_rays, test::aov_frame(kSize), test::eye_at_camera(kSize));
    const std::vector<double> area16 = shadow_row(render_samples(r, r.scene_camera(), 0.0, 0, 16));
    const std::vector<double> area16_four = shadow_row(render_samples(r4, r4.scene_camera(), 0.0, 0, 16));

    // The share of the light's disc (radius tan a one unit along the light, as the node samples it)
    // seen from the plane at x, past the sphere.
    const glm::dvec3 light = glm::normalize(glm::dvec3(1.0, 1.0, 0.0)), sphere(0.0, height, 0.0);
    const glm::dvec3 side(0.0, 0.0, 1.0), up = glm::cross(light, side);
    auto seen = [&](double x) {
        const glm::dvec3 origin(x, start, 0.0);
        int clear = 0, all = 0;
        const int n = 160;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double u = (i + 0.5) / n * 2.0 - 1.0, v = (j + 0.5) / n * 2.0 - 1.0;
                if (u * u + v * v > 1.0) continue;
                const glm::dvec3 d = glm::normalize(light + std::tan(glm::radians(angle_deg)) * (u * side + v * up));
                const double along = glm::dot(sphere - origin, d);
                const double miss2 = glm::dot(sphere - origin, sphere - origin) - along * along;
                ++all;
                clear += along <= 0.0 || miss2 >= radius * radius;
            }
        return static_cast<double>(clear) / all;
    };
    const double half_width = 3.0 * std::tan(glm::radians(kFovDeg / 2.0));
    auto x_of = [&](double column) { return -1.0 + (column / kSize - 0.5) * 2.0 * half_width; };
    double area_error = 0.0, area_worst = 0.0, cone_error = 0.0, error16 = 0.0, error16_four = 0.0;
    int penumbra = 0, umbra = 0, soft_in_one_sample = 0;
    for (std::size_t x = 2; x + 2 < kSize; ++x) {
        // The pixel's samples spread over its width: the reference averages four points across it.
        double reference = 0.0;
        for (int s = 0; s < 4; ++s) reference += 0.25 * seen(x_of(x + (s + 0.5) / 4.0));
        if (one_sample[x] > 0.0 && one_sample[x] < 1.0) ++soft_in_one_sample;
        if (reference == 0.0) ++umbra;
        if (reference <= 0.01 || reference >= 0.99) continue;
        ++penumbra;
        area_error += std::abs(area[x] - reference);
        area_worst = std::max(area_worst, std::abs(area[x] - reference));
        cone_error += std::abs(cone[x] - reference);
        error16 += std::abs(area16[x] - reference);
        error16_four += std::abs(area16_four[x] - reference);
    }
    error16 /= std::max(penumbra, 1);
    error16_four /= std::max(penumbra, 1);
    area_error /= std::max(penumbra, 1);
    cone_error /= std::max(penumbra, 1);
    const std::string figures = fmt::format(
        "{} penumbra pixels, {} umbra; 64 samples against the disc's visible share: mean error {:.4f}, worst {:.4f}; "
        "the single frame's cone-angle profile: mean error {:.4f}; soft values in one sample: {}",
        penumbra, umbra, area_error, area_worst, cone_error, soft_in_one_sample);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    ASSERT_GT(penumbra, 20) << figures;
    EXPECT_EQ(soft_in_one_sample, 0) << "a sample's shadow ray is sharp: " << figures;
    EXPECT_LT(area_error, 0.02) << figures;
    EXPECT_LT(area_worst, 0.08) << figures;
    EXPECT_LT(area_error, 0.6 * cone_error) << "the area light is closer to the disc's share than the cone profile: " << figures;
    const std::string rays = fmt::format("16 samples: one ray a sample {:.4f} from the disc's share on average, four rays {:.4f}",
                                         error16, error16_four);
    RecordProperty("rays", rays);
    std::printf("%s\n", rays.c_str());
    EXPECT_LT(error16_four, 0.6 * error16) << rays;
    EXPECT_LT(error16_four, 0.02) << rays;
}

TEST_F(Light, a_highlight_peaks_where_the_normal_halves_the_light_and_the_view) {
    const glm::dvec3 camera(0.0, 0.0, 4.0), light = glm::normalize(glm::dvec3(1.0, 1.0, 1.0));
    Pack pack = test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "glossy ball",
      "nodes": [
        {{"id": "ball", "type": "prim.sphere", "inputs": {{"radius": 1.0}}}},
        {{"id": "gloss", "type": "light.specular", "inputs": {{"roughness": 0.15}}}}
      ],
      "outputs": {{"distance": "ball.distance", "specular": "gloss.specular"}},
      "scene": {{"camera": {{"position": [0, 0, 4], "target": [0, 0, 0], "fov_deg": {0}}},
                "light": {{"direction": [{1}, {1}, {1}]}}}}
    }})", kFovDeg, light.x));
    RenderedFrame f = render(pack);
    const std::vector<float> aov = light_aov(f);
    std::size_t brightest = 0;
    for (std::size_t i = 1; i < aov.size() / 4; ++i)
        if (aov[4 * i] > aov[4 * brightest]) brightest = i;
    // The point whose normal halves the light and the direction to the camera from it.
    glm::dvec3 n = glm::normalize(light + glm::normalize(camera));
    for (int i = 0; i < 50; ++i) n = glm::normalize(light + glm::normalize(camera - n));
    const double tan_half = std::tan(glm::radians(kFovDeg / 2.0));
    const double column = (0.5 + 0.5 * n.x / (camera.z - n.z) / tan_half) * kSize;
    const double row = (0.5 - 0.5 * n.y / (camera.z - n.z) / tan_half) * kSize;
    const double seen_column = static_cast<double>(brightest % kSize) + 0.5, seen_row = static_cast<double>(brightest / kSize) + 0.5;
    std::string figures = fmt::format("highlight peak at pixel ({:.1f}, {:.1f}), the halfway normal's point at ({:.1f}, {:.1f}); "
                                      "peak specular {:.2f}",
                                      seen_column, seen_row, column, row, aov[4 * brightest]);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_NEAR(seen_column, column, 1.5) << figures;
    EXPECT_NEAR(seen_row, row, 1.5) << figures;
    EXPECT_GT(aov[4 * brightest], 1.0) << "a rough-0.15 GGX lobe peaks well above 1: " << figures;
}

TEST_F(Light, marched_ao_beside_a_sphere_on_a_plane_is_the_analytic_occlusion) {
    // A sphere of radius R resting on the plane y = 0 hides (R / D)^3 of a plane point's cosine-
    // weighted sky, D the distance to its centre (the form factor of a sphere above the horizon).
    // The same with the distance clamped at 0 inside, as a folding fractal's estimate is.
    const double radius = 0.5;
    for (bool never_negative : {false, true}) {
        Pack pack = test::compile_pack(fmt::format(R"({{
          "format": "fractograph-graph", "version": 1, "name": "ball on the ground",
          "nodes": [
            {{"id": "at", "type": "xform.translate", "inputs": {{"offset": [0.0, {0}, 0.0]}}}},
            {{"id": "ball", "type": "prim.sphere", "inputs": {{"p": "at.p", "radius": {0}}}}},
            {{"id": "ground", "type": "prim.plane"}},
            {{"id": "both", "type": "op.union", "inputs": {{"a": "ball.distance", "b": "ground.distance"}}}},
            {{"id": "outside", "type": "math.max", "inputs": {{"a": "both.distance", "b": 0.0}}}},
            {{"id": "sky", "type": "light.marched_ao", "inputs": {{"radius": 30.0, "rays": 64, "start": 0.002, "steps": 64}}}}
          ],
          "outputs": {{"distance": "{2}", "ao": "sky.ao"}},
          "scene": {{"camera": {{"position": [1.4, 2.4, 1.6], "target": [0.7, 0.0, 0.0], "fov_deg": {1}}},
                    "bounds": {{"radius": 80}}}}
        }})", radius, kFovDeg, never_negative ? "outside.value" : "both.distance"));
        RenderedFrame f = render(pack);
        const std::vector<float> world = world_positions(f);
        const auto& normals = f.aovs_left[test::aov_index("normal")];
        double worst = 0.0, worst_d = 0.0;
        std::size_t checked = 0;
        for (std::size_t i = 0; i < kSize * kSize; ++i) {
            const double x = world[4 * i], y = world[4 * i + 1], z = world[4 * i + 2];
            const double d = std::hypot(x, z);
            if (std::abs(y) > 1e-3 || d < 0.7 * radius || d > 3.0 * radius) continue;
            const double ao = half_at(normals, 4 * i + 3);
            const double expected = 1.0 - std::pow(radius / std::hypot(d, radius), 3.0);
            if (std::abs(ao - expected) > worst) worst = std::abs(ao - expected), worst_d = d;
            ++checked;
        }
        std::string figures = fmt::format("{}{} plane pixels 0.7 to 3 radii from the contact: AO at most {:.3f} from "
                                          "1 - (R/D)^3 (at {:.2f} radii)",
                                          never_negative ? "distance clamped at 0: " : "", checked, worst, worst_d / radius);
        RecordProperty(never_negative ? "figures_clamped" : "figures", figures);
        std::printf("%s\n", figures.c_str());
        EXPECT_GT(checked, 500u) << figures;
        // Clamped, the chords through the ball near the contact are short, its occlusion a little
        // light there (without the stand-in for the depth: 0.22).
        EXPECT_LE(worst, never_negative ? 0.06 : 0.05) << figures;
    }
}

TEST_F(Light, a_glass_sphere_reflects_the_background_by_fresnels_law) {
    // A black sphere of glass (ior 1.5) before a flat background, no light: each pixel is the
    // background times the Fresnel reflectance at its angle (a convex body's mirror rays all escape).
    const glm::dvec3 camera(0.0, 0.0, 4.0), background(0.2, 0.5, 0.8);
    const double ior = 1.5;
    Pack pack = test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "glass ball",
      "nodes": [
        {{"id": "ball", "type": "prim.sphere", "inputs": {{"radius": 1.0}}}},
        {{"id": "mirror", "type": "light.reflection", "inputs": {{"ior": {0}}}}}
      ],
      "outputs": {{"distance": "ball.distance", "reflection": "mirror.reflection"}},
      "scene": {{"camera": {{"position": [0, 0, 4], "target": [0, 0, 0], "fov_deg": {1}}},
                "light": {{"color": [0, 0, 0], "ambient": [0, 0, 0]}}, "albedo": [0, 0, 0],
                "background": [{2}, {3}, {4}]}}
    }})", ior, kFovDeg, background.x, background.y, background.z));
    RenderedFrame f = render(pack);
    const std::size_t beauty = test::aov_index("beauty"), normal = test::aov_index("normal");
    const std::vector<float> world = world_positions(f);
    double worst = 0.0, worst_cos = 0.0;
    std::size_t checked = 0;
    for (std::size_t i = 0; i < kSize * kSize; ++i) {
        if (!std::isfinite(world[4 * i + 3])) continue;   // a miss
        const glm::dvec3 p(world[4 * i], world[4 * i + 1], world[4 * i + 2]);
        const glm::dvec3 n(half_at(f.aovs_left[normal], 4 * i), half_at(f.aovs_left[normal], 4 * i + 1),
                           half_at(f.aovs_left[normal], 4 * i + 2));
        const double cos_i = glm::dot(glm::normalize(n), glm::normalize(camera - p));
        if (cos_i < 0.2) continue;   // the rim, where a pixel spans a wide range of angles
        const double cos_t = std::sqrt(1.0 - (1.0 - cos_i * cos_i) / (ior * ior));
        const double rs = (cos_i - ior * cos_t) / (cos_i + ior * cos_t), rp = (cos_t - ior * cos_i) / (cos_t + ior * cos_i);
        const double expected = 0.5 * (rs * rs + rp * rp) * background.z;
        const double error = std::abs(half_at(f.aovs_left[beauty], 4 * i + 2) - expected) / expected;
        if (error > worst) worst = error, worst_cos = cos_i;
        ++checked;
    }
    std::string figures = fmt::format("{} pixels of the glass ball: at most {:.2f} % from Fresnel's reflectance times the "
                                      "background (at cos {:.2f})", checked, 100.0 * worst, worst_cos);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GT(checked, 2000u) << figures;
    EXPECT_LE(worst, 0.02) << figures;
}

TEST_F(Light, an_auxiliary_directional_light_lights_as_the_main_one_does) {
    // The same scene lit once by the main light and once by an auxiliary light in its place: the
    // shade pass evaluates the graph's shadow and specular towards each by the same code.
    auto pack_lit_by = [](const std::string& light) {
        return test::compile_pack(fmt::format(R"({{
          "format": "fractograph-graph", "version": 1, "name": "sphere over a plane",
          "nodes": [
            {{"id": "at", "type": "xform.translate", "inputs": {{"offset": [0.0, 0.8, 0.0]}}}},
            {{"id": "ball", "type": "prim.sphere", "inputs": {{"p": "at.p", "radius": 0.4}}}},
            {{"id": "ground", "type": "prim.plane"}},
            {{"id": "both", "type": "op.union", "inputs": {{"a": "ball.distance", "b": "ground.distance"}}}},
            {{"id": "shadow", "type": "light.soft_shadow", "inputs": {{"angle": 3.0, "start": 0.002, "max_distance": 6.0, "steps": 128}}}},
            {{"id": "gloss", "type": "light.specular", "inputs": {{"roughness": 0.3}}}}
          ],
          "outputs": {{"distance": "both.distance", "shadow": "shadow.shadow", "specular": "gloss.specular"}},
          "scene": {{"camera": {{"position": [0, 2.5, 3], "target": [0, 0.3, 0], "fov_deg": 50}},
                    "light": {{"direction": [0.70710678, 0.70710678, 0], "ambient": 0.1, {}}}, "albedo": 0.6, "bounds": {{"radius": 20}}}}
        }})", light));
    };
    const RenderedFrame main_light = render(pack_lit_by(R"("color": [1.2, 1.0, 0.8])"));
    const RenderedFrame auxiliary = render(pack_lit_by(
        R"("color": 0, "auxiliary": [{"direction": [0.70710678, 0.70710678, 0], "color": [1.2, 1.0, 0.8]}])"));
    const auto& a = main_light.aovs_left[test::aov_index("beauty")];
    const auto& b = auxiliary.aovs_left[test::aov_index("beauty")];
    double worst = 0.0, brightest = 0.0;
    for (std::size_t i = 0; i < kSize * kSize * 4; ++i) {
        if (i % 4 == 3) continue;
        worst = std::max(worst, std::abs(half_at(a, i) - half_at(b, i)) / std::max(half_at(a, i), 0.05));
        brightest = std::max(brightest, half_at(a, i));
    }
    std::string figures = fmt::format("beauty lit by the auxiliary light at most {:.3f} % from the main light's (brightest {:.2f})",
                                      100.0 * worst, brightest);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GT(brightest, 0.5) << "the scene is lit: " << figures;
    EXPECT_LE(worst, 0.002) << figures;
}

TEST_F(Light, a_point_light_falls_off_with_the_square_of_its_distance_and_shadows_only_what_lies_before_it) {
    // A point light 1.2 above the plane y = 0, a ball of radius 0.2 at half its height below it and
    // a large ball of radius 1 above it, beyond the light: the plane is lit by I cos(theta) / d^2,
    // the small ball's shadow is the disc its tangent cone cuts, and the large ball shadows nothing
    // (a march towards a directional light would pass it). The camera looks down from between them.
    const double light_height = 1.2, ball_height = 0.6, ball_radius = 0.2, intensity = 2.0, albedo = 0.5;
    Pack pack = test::compile_pack(fmt::format(R"({{
      "format": "fractograph-graph", "version": 1, "name": "point light",
      "nodes": [
        {{"id": "low", "type": "xform.translate", "inputs": {{"offset": [0.0, {1}, 0.0]}}}},
        {{"id": "ball", "type": "prim.sphere", "inputs": {{"p": "low.p", "radius": {2}}}}},
        {{"id": "high", "type": "xform.translate", "inputs": {{"offset": [0.0, 3.5, 0.0]}}}},
        {{"id": "cover", "type": "prim.sphere", "inputs": {{"p": "high.p", "radius": 1.0}}}},
        {{"id": "ground", "type": "prim.plane"}},
        {{"id": "balls", "type": "op.union", "inputs": {{"a": "ball.distance", "b": "cover.distance"}}}},
        {{"id": "all", "type": "op.union", "inputs": {{"a": "balls.distance", "b": "ground.distance"}}}},
        {{"id": "shadow", "type": "light.soft_shadow", "inputs": {{"angle": 0.3, "start": 0.002, "max_distance": 10.0, "steps": 256}}}}
      ],
      "outputs": {{"distance": "all.distance", "shadow": "shadow.shadow"}},
      "scene": {{"camera": {{"position": [0, 1.9, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 90}},
                "light": {{"color": 0, "ambient": 0, "auxiliary": [{{"position": [0, {0}, 0], "color": {3}}}]}},
                "albedo": {4}, "bounds": {{"radius": 20}}}}
    }})", light_height, ball_height, ball_radius, intensity, albedo));
    RenderedFrame f = render(pack);
    const std::vector<float> world = world_positions(f);
    const auto& beauty = f.aovs_left[test::aov_index("beauty")];
    // The tangent cone from the light to the ball meets the plane at this radius.
    const double shadow_radius = light_height * std::tan(std::asin(ball_radius / (light_height - ball_height)));
    const double pixel = 2.0 * 1.9 / kSize;
    double worst = 0.0, worst_r = 0.0;
    std::size_t lit = 0;
    // Along the centre row: where the light falls to half of what reaches the plane unshadowed.
    double edge = -1.0, previous_r = 0.0, previous_share = 0.0;
    const std::size_t row = kSize / 2;
    for (std::size_t i = 0; i < kSize * kSize; ++i) {
        const glm::dvec3 p(world[4 * i], world[4 * i + 1], world[4 * i + 2]);
        if (std::abs(p.y) > 0.05) continue;   // the ball (a hit lies up to the pixel's footprint above the plane)
        const glm::dvec3 to_light = glm::dvec3(0.0, light_height, 0.0) - p;
        const double d = glm::length(to_light);
        const double expected = albedo * intensity * (to_light.y / d) / (d * d);
        const double share = half_at(beauty, 4 * i) / expected;
        const double r = std::hypot(p.x, p.z);
        if (i / kSize == row && p.x > 0.0) {
            if (edge < 0.0 && previous_share < 0.5 && share >= 0.5 && previous_r > 0.0)
                edge = previous_r + (0.5 - previous_share) / (share - previous_share) * (r - previous_r);
            previous_r = r, previous_share = share;
        }
        if (r < shadow_radius + 4.0 * pixel) continue;   // outside the penumbra
        if (std::abs(share - 1.0) > worst) worst = std::abs(share - 1.0), worst_r = r;
        ++lit;
    }
    std::string figures = fmt::format("{} lit plane pixels at most {:.2f} % from I cos / d^2 (at r = {:.3f}); the shadow's edge at "
                                      "r = {:.4f}, the tangent cone's {:.4f} (a pixel is {:.4f})",
                                      lit, 100.0 * worst, worst_r, edge, shadow_radius, pixel);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GT(lit, 10000u) << figures;
    EXPECT_LE(worst, 0.01) << figures;
    EXPECT_NEAR(edge, shadow_radius, pixel) << figures;
}
