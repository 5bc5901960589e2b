#include "analysis/precision_advice.h"

#include <cmath>

#include <fmt/format.h>
#include <glm/glm.hpp>

#include "analysis/periodicity.h"
#include "common/spec_constants.h"

namespace fg {

namespace {

struct Coordinate {
    double magnitude;
    std::string pointer;
    std::string node_id;
};

}  // namespace

double float_spacing(double x) {
    x = std::abs(x);
    if (x < 1e-30) return 0.0;
    return std::ldexp(1.0, static_cast<int>(std::floor(std::log2(x))) - 23);
}

PrecisionAdvice float_precision_advice(const IrGraph& ir) {
    const SceneSettings& scene = ir.scene;
    std::vector<Coordinate> coordinates = {{glm::length(scene.camera.position), "/scene/camera/position", ""}};
    // A periodic scene's bounds are "everywhere" (looping_lattice's radius is 1e6), but the runtime
    // wraps the head by whole periods and a far point's hit threshold grows with its distance, so
    // only the bounds of a scene that does not repeat say where the march works.
    if (!analyse_periodicity(ir).period)
        coordinates.push_back({glm::length(scene.bounds_center) + scene.bounds_radius, "/scene/bounds/center", ""});
    // A shape translated into the bounds is where rays meet it (p - offset is computed at the
    // offset's magnitude); one translated outside them is never reached.
    for (const IrNode& n : ir.nodes) {
        if (!n.def || n.def->type != "xform.translate" || n.inputs.size() < 2) continue;
        const IrInput& offset = n.inputs[1];
        const Constant* value = offset.kind == IrInput::Kind::Constant ? &offset.constant
                                : offset.kind == IrInput::Kind::Param && offset.param >= 0 &&
                                          offset.param < static_cast<int>(ir.params.size())
                                    ? &ir.params[static_cast<std::size_t>(offset.param)].value
                                    : nullptr;
        if (!value) continue;
        const glm::dvec3 at(value->v[0], value->v[1], value->v[2]);
        if (glm::length(at - scene.bounds_center) <= scene.bounds_radius)
            coordinates.push_back({glm::length(at), offset.pointer.empty() ? n.pointer : offset.pointer, n.id});
    }

    PrecisionAdvice a;
    for (const auto& c : coordinates)
        if (c.magnitude > a.magnitude) {
            a.magnitude = c.magnitude;
            a.where = c.pointer;
            a.node_id = c.node_id;
        }
    a.spacing = float_spacing(a.magnitude);
    a.viewing_distance = glm::length(scene.camera.target - scene.camera.position);
    const double pixel_tan = 2.0 * std::tan(glm::radians(scene.camera.fov_deg) / 2.0) / kAdvicePixelsAcross;
    a.hit_threshold = find_global_knob("epsilon")->value * pixel_tan * a.viewing_distance;
    a.bounds_radius = scene.bounds_radius;
    a.too_coarse = a.spacing > kMaxSpacingPerHitThreshold * a.hit_threshold || a.spacing > kMaxSpacingPerBoundsRadius * a.bounds_radius;
    return a;
}

void advise_precision(const IrGraph& ir, Diagnostics& diag) {
    if (ir.scene.double_precision) return;
    const PrecisionAdvice a = float_precision_advice(ir);
    if (!a.too_coarse) return;
    diag.warning(fmt::format("coordinates near {:.3g} are {:.3g} apart in float: more than a quarter of the hit threshold "
                             "({:.3g}, {:.4g} from the camera to its target) or 1/4096 of the bounds radius ({:.4g}), so "
                             "surfaces will render as noise; set \"precision\": \"double\" in \"scene\" (or compile with "
                             "--precision double)",
                             a.magnitude, a.spacing, a.hit_threshold, a.viewing_distance, a.bounds_radius),
                 a.where, a.node_id);
}

}  // namespace fg
