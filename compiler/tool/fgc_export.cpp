// fgc export: a graph's surface as an OpenVDB level set sampled by the CPU twin on a sparse narrow
// band, and meshes of it (PLY, OBJ, STL); or the shards of a job array merged into one.
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>
#include <memory>
#include <ranges>
#include <unistd.h>

#include "compiler.h"
#include "export/export_estimate.h"
#include "export/level_set_files.h"
#include "export/level_set_mesh.h"
#include "export/mesh_files.h"
#include "export/narrow_band_sampler.h"
#include "export/signed_band.h"
#include "export/surface_rule.h"
#include "fgc_commands.h"
#include "progress_bar.h"

namespace fg::fgc {

namespace {

std::string bytes_text(double bytes) {
    if (bytes >= 1024.0 * 1024 * 1024) return fmt::format("{:.1f} GiB", bytes / (1024.0 * 1024 * 1024));
    return fmt::format("{:.0f} MiB", bytes / (1024.0 * 1024));
}

std::string seconds_text(double s) {
    if (s >= 3600) return fmt::format("{:.1f} h", s / 3600);
    if (s >= 60) return fmt::format("{:.1f} min", s / 60);
    return fmt::format("{:.1f} s", s);
}

std::uint64_t half_the_memory() {
    return static_cast<std::uint64_t>(::sysconf(_SC_PHYS_PAGES)) * static_cast<std::uint64_t>(::sysconf(_SC_PAGE_SIZE)) / 2;
}

// "I/N" with 0 <= I < N.
bool parse_shard(const std::string& text, NarrowBandSettings& s, Diagnostics& diag) {
    if (text.empty()) return true;
    auto slash = text.find('/');
    int i = -1, n = 0;
    bool ok = slash != std::string::npos &&
              std::from_chars(text.data(), text.data() + slash, i).ptr == text.data() + slash &&
              std::from_chars(text.data() + slash + 1, text.data() + text.size(), n).ptr == text.data() + text.size();
    if (!ok || n < 1 || i < 0 || i >= n) {
        diag.error(fmt::format("--shard {}: expected I/N with 0 <= I < N, e.g. 0/4", text));
        return false;
    }
    s.shard = i;
    s.shards = n;
    return true;
}

// Every output path is checked before any work: a format we cannot write or a folder we cannot
// write into is an error now, not after hours of sampling.
bool check_outputs(const ExportOptions& o, const std::string& vdb, Diagnostics& diag) {
    // A level set named otherwise would be a .vdb that no program opens as one.
    if (std::filesystem::path(vdb).extension() != ".vdb") {
        diag.error(fmt::format("-o {}: a level set is written as .vdb (meshes go to --mesh)", vdb));
        return false;
    }
    bool ok = can_write(vdb, "-o", diag);
    for (const auto& m : o.meshes) {
        if (!mesh_format_of(m)) {
            diag.error(fmt::format("--mesh {}: unknown mesh format (use .ply, .obj or .stl)", m));
            ok = false;
        } else {
            ok = can_write(m, "--mesh", diag) && ok;
        }
    }
    return ok;
}

// The region to sample: --box, else the scene's bounds (the cube around its bounding sphere).
std::optional<ExportBox> export_box(const IrGraph& ir, const std::vector<double>& box, Diagnostics& diag) {
    if (!box.empty()) {
        ExportBox b{{box[0], box[1], box[2]}, {box[3], box[4], box[5]}};
        if (b.min.x < b.max.x && b.min.y < b.max.y && b.min.z < b.max.z) return b;
        diag.error(fmt::format("--box {}: the first corner must be below the second on every axis (x0 y0 z0 x1 y1 z1)",
                               fmt::join(box, ",")));
        return std::nullopt;
    }
    const auto scene = ir.source.find("scene");
    if (scene == ir.source.end() || !scene->contains("bounds")) {
        diag.error("no /scene/bounds in the graph and no --box: give the region to export, e.g. --box -1,-1,-1,1,1,1");
        return std::nullopt;
    }
    const glm::dvec3 r(ir.scene.bounds_radius);
    return ExportBox{ir.scene.bounds_center - r, ir.scene.bounds_center + r};
}

// --param name=value for scalar parameters; the values the export used, for the metadata.
std::optional<std::map<std::string, std::string>> apply_params(const IrGraph& ir, CpuEvaluator& ev,
                                                                const std::vector<std::string>& params, Diagnostics& diag) {
    std::map<std::string, std::string> values;
    for (const auto& p : ir.params) values[p.name] = p.value.text();
    for (const auto& text : params) {
        auto eq = text.find('=');
        const std::string name = text.substr(0, eq);
        const ParamDecl* decl = nullptr;
        for (const auto& p : ir.params)
            if (p.name == name) decl = &p;
        double x = 0.0;
        if (eq == std::string::npos || !decl ||
            std::from_chars(text.data() + eq + 1, text.data() + text.size(), x).ptr != text.data() + text.size() ||
            (decl->type != ValueType::Float && decl->type != ValueType::Int)) {
            diag.error(fmt::format("--param {}: expected NAME=NUMBER for a float or int parameter of the graph ({})", text,
                                   values.empty() ? "it has none" : fmt::format("it has {}", fmt::join(std::views::keys(values), ", "))));
            return std::nullopt;
        }
        ev.set_param(name, Constant::scalar(decl->type, x));
        values[name] = fmt::format("{:g}", x);
    }
    return values;
}

void add_metadata(openvdb::FloatGrid& grid, const std::string& graph, const IrGraph& ir,
                  const std::map<std::string, std::string>& params, const ExportField& field,
                  const NarrowBandSettings& s) {
    grid.setName("surface");
    grid.insertMeta("fractograph.graph", openvdb::StringMetadata(ir.name));
    grid.insertMeta("fractograph.graph_file", openvdb::StringMetadata(graph));
    for (const auto& [name, value] : params) grid.insertMeta("fractograph.param." + name, openvdb::StringMetadata(value));
    const auto& box = field.box();
    grid.insertMeta("fractograph.box_min", openvdb::Vec3DMetadata(openvdb::Vec3d(box.min.x, box.min.y, box.min.z)));
    grid.insertMeta("fractograph.box_max", openvdb::Vec3DMetadata(openvdb::Vec3d(box.max.x, box.max.y, box.max.z)));
    grid.insertMeta("fractograph.voxel_size", openvdb::DoubleMetadata(s.voxel_size));
    grid.insertMeta("fractograph.half_width_voxels", openvdb::DoubleMetadata(s.half_width));
    grid.insertMeta("fractograph.distance_scale", openvdb::DoubleMetadata(field.scale()));
    grid.insertMeta("fractograph.offset", openvdb::DoubleMetadata(field.offset()));
    grid.insertMeta("fractograph.compiler", openvdb::StringMetadata(std::string("fgc ") + kCompilerVersion));
    if (s.shards > 1) grid.insertMeta("fractograph.shard", openvdb::StringMetadata(fmt::format("{}/{}", s.shard, s.shards)));
}

void print_level_set(const std::string& path, const openvdb::FloatGrid& grid) {
    const openvdb::CoordBBox b = grid.evalActiveVoxelBoundingBox();
    fmt::print("wrote {}: {} active voxels, index bounds {} {} {} to {} {} {}, voxel size {:g}\n", path,
               grid.activeVoxelCount(), b.min().x(), b.min().y(), b.min().z(), b.max().x(), b.max().y(), b.max().z(),
               grid.voxelSize()[0]);
}

// The meshes asked for, coloured by the graph's albedo when asked (and a graph is there).
bool write_meshes(const ExportOptions& o, const openvdb::FloatGrid& grid, const CpuEvaluator* scene, double scale,
                  Diagnostics& diag) {
    if (o.meshes.empty()) return true;
    TriangleMesh mesh = mesh_level_set(grid, o.adaptivity);
    if (o.colors && scene) colour_by_albedo(mesh, *scene, scale, grid.voxelSize()[0], o.threads);
    for (const auto& path : o.meshes) {
        if (!write_mesh(path, mesh, diag)) return false;
        fmt::print("wrote {}: {} vertices, {} triangles{}\n", path, mesh.positions.size(), mesh.triangles.size(),
                   mesh.colors.empty() || mesh_format_of(path) != MeshFormat::Ply ? "" : ", vertex colours");
    }
    return true;
}

int merge(const ExportOptions& o) {
    Diagnostics diag;
    if (o.output.empty()) diag.error("--merge needs -o, the whole level set to write");
    if (diag.has_errors() || !check_outputs(o, o.output, diag)) return report(diag, "fgc export");
    std::vector<openvdb::FloatGrid::Ptr> shards;
    for (const auto& path : o.merge)
        if (auto grid = read_level_set(path, diag)) shards.push_back(grid);
    if (diag.has_errors()) return report(diag, "fgc export");
    auto whole = merge_shards(shards, o.merge, diag);
    if (whole) {
        const auto width = whole->getMetadata<openvdb::DoubleMetadata>("fractograph.half_width_voxels");
        make_signed_band(*whole, width ? width->value() : o.half_width, o.threads);
    }
    if (!whole || !write_level_set(o.output, whole, diag)) return report(diag, "fgc export");
    print_level_set(o.output, *whole);
    return write_meshes(o, *whole, nullptr, 1.0, diag) ? 0 : report(diag, "fgc export");
}

}  // namespace

int export_level_set(const Common& c, const std::string& graph, const ExportOptions& o) {
    // Each line as it happens, in order with the progress bar on stderr, also into a batch log.
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    if (!o.merge.empty()) return merge(o);
    Diagnostics diag;
    if (graph.empty()) {
        fmt::print(stderr, "fgc export: error: give a graph to sample, or --merge with the shards to merge\n");
        return 1;
    }
    NarrowBandSettings settings;
    settings.half_width = o.half_width;
    settings.threads = o.threads;
    const std::string vdb = o.output.empty() ? std::filesystem::path(graph).replace_extension(".vdb").string() : o.output;
    if (!parse_shard(o.shard, settings, diag) || !check_outputs(o, vdb, diag)) return report(diag, graph);

    auto scene = load_cpu_scene(c, graph, diag);
    if (!scene) return report(diag, graph);
    const IrGraph* ir = scene->ir.get();
    CpuEvaluator* ev = &*scene->evaluator;
    auto params = apply_params(*ir, *ev, o.params, diag);
    auto box = export_box(*ir, o.box, diag);
    if (!params || !box) return report(diag, graph);
    const glm::dvec3 size = box->size();
    const double longest = std::max(size.x, std::max(size.y, size.z));
    settings.voxel_size = o.voxel_size > 0.0 ? o.voxel_size : longest / o.resolution;
    // OpenVDB's voxel coordinates are 32-bit: far beyond any memory, but a number still to refuse.
    const double farthest = std::max(glm::length(box->min), glm::length(box->max)) / settings.voxel_size;
    if (farthest > 1e9) {
        diag.error(fmt::format("--voxel-size {:g}: the box reaches {:.3g} voxels from the origin, beyond OpenVDB's 32-bit "
                               "coordinates", settings.voxel_size, farthest));
        return report(diag, graph);
    }
    std::vector<ExportPart> parts;
    ExportField field = export_surface_field(*ev, *box, settings.voxel_size, o.offset.value_or(0.0), o.threads, parts, diag);
    const double hit = 0.5 * settings.voxel_size;

    const ExportEstimate e = estimate_export(field, settings, !o.meshes.empty());
    const std::uint64_t limit = o.max_memory ? o.max_memory : half_the_memory();
    const std::string resolution = fmt::format("{} {:g} ({:.0f} voxels across the box's longest side)",
                                               o.voxel_size > 0.0 ? "--voxel-size" : "--resolution",
                                               o.voxel_size > 0.0 ? o.voxel_size : o.resolution, longest / settings.voxel_size);
    fmt::print("{}: {}: estimate {:.3g} voxels in the narrow band (growth exponent {:.2f}), {} peak memory, {} on {} "
               "thread{}{}\n",
               graph, resolution, e.active_voxels, e.dimension, bytes_text(e.bytes), seconds_text(e.seconds), o.threads,
               o.threads == 1 ? "" : "s", settings.shards > 1 ? fmt::format(" for shard {}", o.shard) : "");
    if (e.bytes > static_cast<double>(limit)) {
        diag.error(fmt::format("{} needs about {} of memory, over --max-memory {}: choose a larger voxel size, a smaller "
                               "--box, or split the box into --shard I/N slabs",
                               resolution, bytes_text(e.bytes), bytes_text(static_cast<double>(limit))));
        return report(diag, graph);
    }
    for (const auto& part : parts)
        if (!part.has_inside())
            fmt::print("{}: node \"{}\" has no inside ({:.1f} % of its band is negative: its estimate measures the distance "
                       "to the set): its surface is taken where it falls under half a voxel, {:g}, as the renderer's hit "
                       "threshold takes it under a pixel's footprint\n",
                       graph, part.id, 100.0 * part.inside_share, hit);
    if (o.dry_run) return 0;

    std::unique_ptr<ProgressBar> bar;
    std::size_t shown = 0;
    auto progress = [&](std::size_t done, std::size_t total) {
        if (!bar) bar = std::make_unique<ProgressBar>(static_cast<int>(total), stderr, "blocks");
        for (; shown < done; ++shown) bar->advance(false);
    };
    NarrowBandStats stats;
    auto grid = sample_narrow_band(field, settings, o.quiet ? std::function<void(std::size_t, std::size_t)>{} : progress, &stats);
    if (bar) bar->finish();
    fmt::print("sampled {} leaves, {} distance evaluations in {}\n", stats.leaves, stats.evaluations, seconds_text(stats.seconds));
    // A shard's slab is swept once merged: its distances near the slab's faces need its neighbours.
    if (settings.shards == 1) make_signed_band(*grid, settings.half_width, o.threads);
    add_metadata(*grid, graph, *ir, *params, field, settings);
    if (!write_level_set(vdb, grid, diag)) return report(diag, graph);
    print_level_set(vdb, *grid);
    return write_meshes(o, *grid, ev, field.scale(), diag) ? 0 : report(diag, graph);
}

}  // namespace fg::fgc
