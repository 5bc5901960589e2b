// fgc export's level set and mesh against the renderer's own frames. The graph is a power-3
// Mandelbulb smooth-unioned with a Mandelbox: the bulb's estimate has an inside, the box's has
// none, so the export must take each by its own surface rule to keep both. Six views along the
// axes are rendered as OpenEXR (read by OpenEXR's reader): every hit's world position must lie on
// the exported surface, the hits' bounding box must be the mesh's, and the vertex colours must be
// the albedo pass where the renderer sees them.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fstream>
#include <unordered_map>

#include <openvdb/tools/Interpolation.h>

#include "exr_parts.h"
#include "export/level_set_mesh.h"
#include "export/narrow_band_sampler.h"
#include "export/signed_band.h"
#include "export/surface_rule.h"
#include "offline/path_render.h"
#include "runtime_test_support.h"
#include "scratch_dir.h"

using namespace fg;

namespace {

// From 7 units out along +x, -x, +y, -y, +z, -z, one view a second.
const char* kSixViews = R"({
  "format": "fractograph-camera-path", "version": 1, "fps": 1, "interpolation": "linear",
  "keyframes": [
    {"time": 0, "position": [7, 0, 0], "target": [0, 0, 0]},
    {"time": 1, "position": [-7, 0, 0], "target": [0, 0, 0]},
    {"time": 2, "position": [0, 7, 0], "target": [0, 0, 0], "up": [0, 0, 1]},
    {"time": 3, "position": [0, -7, 0], "target": [0, 0, 0], "up": [0, 0, 1]},
    {"time": 4, "position": [0, 0, 7], "target": [0, 0, 0]},
    {"time": 5, "position": [0, 0, -7], "target": [0, 0, 0]}
  ]
})";

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// The mesh's vertices bucketed by voxel, for the nearest vertex to a point.
class VertexBuckets {
public:
    VertexBuckets(const TriangleMesh& mesh, double cell) : mesh_(mesh), cell_(cell) {
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) buckets_[key(cell_of(mesh.positions[i]))].push_back(i);
    }
    // The nearest vertex within `reach` cells, or -1.
    long nearest(const glm::dvec3& p, int reach) const {
        const glm::ivec3 c = cell_of(p);
        long best = -1;
        double best_d = 1e30;
        for (int x = -reach; x <= reach; ++x)
            for (int y = -reach; y <= reach; ++y)
                for (int z = -reach; z <= reach; ++z) {
                    auto it = buckets_.find(key(c + glm::ivec3(x, y, z)));
                    if (it == buckets_.end()) continue;
                    for (std::size_t i : it->second)
                        if (double d = glm::distance(glm::dvec3(mesh_.positions[i]), p); d < best_d) best_d = d, best = static_cast<long>(i);
                }
        return best;
    }

private:
    glm::ivec3 cell_of(const glm::dvec3& p) const { return glm::ivec3(glm::floor(p / cell_)); }
    static std::int64_t key(const glm::ivec3& c) {
        return (static_cast<std::int64_t>(c.x + 4096) << 26) | (static_cast<std::int64_t>(c.y + 4096) << 13) | (c.z + 4096);
    }
    const TriangleMesh& mesh_;
    double cell_;
    std::unordered_map<std::int64_t, std::vector<std::size_t>> buckets_;
};

}  // namespace

TEST(ExportMatchesRender, a_bulb_and_box_union_keeps_both_shapes_where_the_renderer_sees_them_with_their_albedo) {
    const Pack pack = test::compile_pack(test::read_source_file("tests/export/graphs/bulb_box_union.json"));
    auto cpu = test::cpu_scene(pack);
    ASSERT_TRUE(cpu && cpu->evaluator);

    // The export, as fgc export makes it at --resolution 128 with --colors.
    Diagnostics diag;
    const glm::dvec3 r(cpu->ir.scene.bounds_radius);
    const ExportBox box{cpu->ir.scene.bounds_center - r, cpu->ir.scene.bounds_center + r};
    NarrowBandSettings band;
    band.voxel_size = 2.0 * r.x / 128.0;
    std::vector<ExportPart> parts;
    const ExportField field = export_surface_field(*cpu->evaluator, box, band.voxel_size, 0.0, band.threads, parts, diag);
    ASSERT_EQ(parts.size(), 2u);
    for (const auto& part : parts) EXPECT_EQ(part.has_inside(), part.id == "bulb") << part.id << " " << part.inside_share;
    auto grid = sample_narrow_band(field, band);
    make_signed_band(*grid, band.half_width, band.threads);
    TriangleMesh mesh = mesh_level_set(*grid, 0.0);
    colour_by_albedo(mesh, *cpu->evaluator, field.scale(), band.voxel_size, band.threads);
    ASSERT_FALSE(mesh.positions.empty());

    // The six views, 160x160 per eye (a pixel is 0.8 voxels across at the shape), as EXR files.
    Diagnostics path_diag;
    auto path = CameraPath::parse(nlohmann::json::parse(kSixViews), 1.0, path_diag);
    ASSERT_TRUE(path) << path_diag.format();
    PathRenderSettings settings;
    settings.projection = Projection::Perspective;
    settings.width = settings.height = 160;
    settings.format = OutputFormat::Exr;
    PathRenderer renderer(test::shared_context(), pack, *path, settings);
    test::ScratchDir dir{"fg_export_render"};

    openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> surface(*grid);
    const double h = band.voxel_size;
    VertexBuckets vertices(mesh, h);
    glm::dvec3 hits_min(1e30), hits_max(-1e30), albedo_sum(0.0), vertex_sum(0.0);
    std::size_t hits = 0, outside = 0, inside = 0, on_surface = 0;
    for (int frame = 0; frame < 6; ++frame) {
        const std::string file = (dir / fmt::format("view{}.exr", frame)).string();
        {
            auto bytes = renderer.encode(renderer.render_frame(frame));
            std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        }
        const auto left = test::read_exr(file, {"Z", "P.X", "P.Y", "P.Z", "albedo.R", "albedo.G", "albedo.B"}).at(0);
        for (int y = 0; y < left.height; ++y)
            for (int x = 0; x < left.width; ++x) {
                if (std::isinf(left.at("Z", x, y))) continue;
                const glm::dvec3 p(left.at("P.X", x, y), left.at("P.Y", x, y), left.at("P.Z", x, y));
                ++hits;
                hits_min = glm::min(hits_min, p);
                hits_max = glm::max(hits_max, p);
                // A hit outside the exported solid is a shape the export lost. One inside it is a
                // ray that passed a gap narrower than a voxel, which the level set cannot hold.
                const double d = surface.wsSample(openvdb::Vec3d(p.x, p.y, p.z));
                outside += d > 2.0 * h;
                inside += d < -2.0 * h;
                const long v = vertices.nearest(p, 2);
                // Colours are compared where the renderer's surface is the export's.
                if (std::abs(d) > h || v < 0) continue;
                ++on_surface;
                albedo_sum += glm::dvec3(left.at("albedo.R", x, y), left.at("albedo.G", x, y), left.at("albedo.B", x, y));
                const glm::u8vec3 c = mesh.colors[static_cast<std::size_t>(v)];
                vertex_sum += glm::dvec3(srgb_to_linear(c.r / 255.0), srgb_to_linear(c.g / 255.0), srgb_to_linear(c.b / 255.0));
            }
    }
    glm::dvec3 mesh_min(1e30), mesh_max(-1e30);
    for (const auto& p : mesh.positions) mesh_min = glm::min(mesh_min, glm::dvec3(p)), mesh_max = glm::max(mesh_max, glm::dvec3(p));
    const glm::dvec3 albedo = albedo_sum / static_cast<double>(on_surface);
    const glm::dvec3 colour = vertex_sum / static_cast<double>(on_surface);
    RecordProperty("hits", fmt::format("{} hits over six views: {} within a voxel of the exported surface, {} "
                                       "more than 2 voxels outside it, {} inside it (through gaps under a voxel)",
                                       hits, on_surface, outside, inside));
    RecordProperty("bounds", fmt::format("hits x {:.3f}..{:.3f} y {:.3f}..{:.3f} z {:.3f}..{:.3f}; mesh x {:.3f}..{:.3f} y "
                                         "{:.3f}..{:.3f} z {:.3f}..{:.3f}; voxel {:.4f}", hits_min.x, hits_max.x, hits_min.y,
                                         hits_max.y, hits_min.z, hits_max.z, mesh_min.x, mesh_max.x, mesh_min.y, mesh_max.y,
                                         mesh_min.z, mesh_max.z, h));
    RecordProperty("colours", fmt::format("albedo pass mean (linear) {:.4f} {:.4f} {:.4f}, nearest vertex colours {:.4f} {:.4f} {:.4f}",
                                          albedo.r, albedo.g, albedo.b, colour.r, colour.g, colour.b));
    EXPECT_GT(hits, 6u * 160 * 160 / 5) << "the shape should fill part of every view";
    EXPECT_LE(outside, hits / 1000) << "hits on shapes the export lost";
    EXPECT_GT(on_surface, hits / 3);
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(mesh_min[a], hits_min[a], 2.0 * h) << "axis " << a;
        EXPECT_NEAR(mesh_max[a], hits_max[a], 2.0 * h) << "axis " << a;
        EXPECT_NEAR(colour[a] / albedo[a], 1.0, 0.03) << "channel " << a;
    }
}
