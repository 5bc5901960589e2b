#include "surface_rule.h"

#include <algorithm>
#include <set>

#include "analysis/lipschitz_bound.h"
#include "narrow_band_sampler.h"

namespace fg {

namespace {

bool reads_distance(const IrInput& in, const IrGraph& ir) {
    if (in.kind != IrInput::Kind::Node) return false;
    const auto& outputs = ir.nodes[static_cast<std::size_t>(in.node)].def->outputs;
    return outputs[static_cast<std::size_t>(in.port)].name == "distance";
}

// The nodes the scene's distance is computed from.
std::set<int> distance_nodes(const IrGraph& ir) {
    std::set<int> nodes;
    std::vector<const IrInput*> todo;
    if (auto it = ir.outputs.find("distance"); it != ir.outputs.end()) todo.push_back(&it->second);
    while (!todo.empty()) {
        const IrInput* in = todo.back();
        todo.pop_back();
        if (in->kind != IrInput::Kind::Node || !nodes.insert(in->node).second) continue;
        for (const auto& sub : ir.nodes[static_cast<std::size_t>(in->node)].inputs) todo.push_back(&sub);
    }
    return nodes;
}

}  // namespace

std::vector<ExportPart> export_parts(const CpuEvaluator& scene, double scale, const ExportBox& box, double voxel_size,
                                     int threads) {
    const IrGraph& ir = scene.ir();
    const glm::dvec3 size = box.size();
    NarrowBandSettings pilot;
    pilot.voxel_size = std::max(voxel_size, std::max(size.x, std::max(size.y, size.z)) / 128.0);
    pilot.threads = threads;
    std::vector<ExportPart> parts;
    for (int i : distance_nodes(ir)) {
        const IrNode& n = ir.nodes[static_cast<std::size_t>(i)];
        if (!n.def->find_output("distance") ||
            std::any_of(n.inputs.begin(), n.inputs.end(), [&](const IrInput& in) { return reads_distance(in, ir); }))
            continue;
        NarrowBandStats stats;
        sample_narrow_band(ExportField(scene.part(i), scale, 0.0, box), pilot, {}, &stats);
        const double share = stats.active_voxels ? static_cast<double>(stats.inside_voxels) / static_cast<double>(stats.active_voxels) : 0.0;
        parts.push_back({i, n.id, share});
    }
    return parts;
}

CpuEvaluator with_surface_rules(CpuEvaluator scene, const std::vector<ExportPart>& parts, double scale, double offset) {
    for (const auto& part : parts)
        if (!part.has_inside()) scene.move_surface(part.node, offset / scale);
    return scene;
}

ExportField export_surface_field(const CpuEvaluator& scene, const ExportBox& box, double voxel_size, double offset,
                                 int threads, std::vector<ExportPart>& parts, Diagnostics& diag) {
    // The march steps d * step_factor / L; the same factor makes the estimate a distance that
    // does not overestimate, which the narrow band's skipping relies on.
    const double scale = scene.ir().scene.step_factor / analyse_lipschitz(scene.ir(), diag).bound;
    parts = export_parts(scene, scale, box, voxel_size, threads);
    return ExportField(with_surface_rules(scene, parts, scale, 0.5 * voxel_size), scale, offset, box);
}

}  // namespace fg
