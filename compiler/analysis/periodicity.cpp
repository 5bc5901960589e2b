#include "analysis/periodicity.h"

#include <fmt/format.h>

namespace fg {

namespace {

// What a value knows about the sample position: nothing (constant in space), only through a
// repetition of one period, or anything else.
struct Spatial {
    enum class Kind { Constant, Periodic, Aperiodic } kind = Kind::Constant;
    std::array<double, 3> period{0.0, 0.0, 0.0};
    std::string reason;
};

Spatial aperiodic(std::string reason) { return {Spatial::Kind::Aperiodic, {}, std::move(reason)}; }

// Two values used together: periodic only when their periods agree.
Spatial combine(const Spatial& a, const Spatial& b, const std::string& node) {
    if (a.kind == Spatial::Kind::Aperiodic) return a;
    if (b.kind == Spatial::Kind::Aperiodic) return b;
    if (a.kind == Spatial::Kind::Constant) return b;
    if (b.kind == Spatial::Kind::Constant) return a;
    if (a.period != b.period)
        return aperiodic(fmt::format("node \"{}\" combines repetitions with different periods", node));
    return a;
}

}  // namespace

Periodicity analyse_periodicity(const IrGraph& ir) {
    std::vector<Spatial> nodes(ir.nodes.size());
    // `reader`: the node reading the input (null for a graph output).
    auto of_input = [&](const IrInput& in, const std::string& node, const IrNode* reader) -> Spatial {
        switch (in.kind) {
            case IrInput::Kind::Node: return nodes[static_cast<std::size_t>(in.node)];
            case IrInput::Kind::Implicit:
                // Only the position is absolute; the direction to the camera and normals move with
                // the wrap, light and time do not depend on where the head is. The library's
                // shading nodes read the position only to sample the scene's own distance around
                // it, so they repeat with the scene (custom code might not).
                if (in.implicit != ImplicitSource::Position) return {};
                if (reader && reader->def && reader->def->context == NodeContext::Shade && !reader->custom_def) return {};
                return aperiodic(fmt::format("node \"{}\" reads the position without a repetition", node));
            default: return {};
        }
    };
    for (std::size_t i = 0; i < ir.nodes.size(); ++i) {
        const IrNode& n = ir.nodes[i];
        if (n.def && n.def->type == "xform.repeat" && n.inputs.size() >= 2) {
            const IrInput& p = n.inputs[0];
            const IrInput& period = n.inputs[1];
            const bool from_position = p.kind == IrInput::Kind::Implicit && p.implicit == ImplicitSource::Position;
            if (from_position && period.kind == IrInput::Kind::Constant && period.constant.v[0] > 0.0 &&
                period.constant.v[1] > 0.0 && period.constant.v[2] > 0.0) {
                nodes[i] = {Spatial::Kind::Periodic, {period.constant.v[0], period.constant.v[1], period.constant.v[2]}, ""};
                continue;
            }
            if (from_position && period.kind != IrInput::Kind::Constant) {
                nodes[i] = aperiodic(fmt::format("node \"{}\" repeats with a period that is not a constant", n.id));
                continue;
            }
        }
        Spatial s;
        for (const auto& in : n.inputs) s = combine(s, of_input(in, n.id, &n), n.id);
        nodes[i] = s;
    }
    Periodicity out;
    auto distance = ir.outputs.find("distance");
    if (distance == ir.outputs.end()) {
        out.reason = "the graph has no distance output";
        return out;
    }
    Spatial all = of_input(distance->second, "distance", nullptr);
    if (all.kind == Spatial::Kind::Constant) {
        out.reason = "the distance does not depend on the position";
        return out;
    }
    // Colours and lighting must repeat with the distance, or the image would change at a wrap.
    for (const auto& [name, in] : ir.outputs) all = combine(all, of_input(in, name, nullptr), "output " + name);
    if (all.kind != Spatial::Kind::Periodic) {
        out.reason = all.reason;
        return out;
    }
    out.period = all.period;
    return out;
}

}  // namespace fg
