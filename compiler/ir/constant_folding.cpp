#include "constant_folding.h"

#include <cmath>
#include <fmt/format.h>
#include <functional>

#include "cpu/cpu_evaluator.h"

namespace fg {

namespace {

bool finite(const Constant& c) {
    for (int i = 0; i < component_count(c.type); ++i)
        if (!std::isfinite(c.v[static_cast<std::size_t>(i)])) return false;
    return true;
}

void replace_uses(IrGraph& ir, int node, int port, const Constant& value) {
    auto patch = [&](IrInput& in) {
        if (in.kind == IrInput::Kind::Node && in.node == node && in.port == port) {
            in.kind = IrInput::Kind::Constant;
            // Widen to what the consumer receives (int -> float is the only conversion).
            in.constant = Constant::vector(in.type, value.v);
            in.source_type = in.type;
            in.node = -1;
        }
    };
    for (auto& n : ir.nodes)
        for (auto& in : n.inputs) patch(in);
    for (auto& [_, in] : ir.outputs) patch(in);
}

}  // namespace

int remove_dead_nodes(IrGraph& ir) {
    std::vector<bool> live(ir.nodes.size(), false);
    std::function<void(const IrInput&)> mark = [&](const IrInput& in) {
        if (in.kind != IrInput::Kind::Node || live[static_cast<std::size_t>(in.node)]) return;
        live[static_cast<std::size_t>(in.node)] = true;
        for (const auto& sub : ir.nodes[static_cast<std::size_t>(in.node)].inputs) mark(sub);
    };
    for (const auto& [_, in] : ir.outputs) mark(in);
    std::vector<int> remap(ir.nodes.size(), -1);
    std::vector<IrNode> kept;
    for (std::size_t i = 0; i < ir.nodes.size(); ++i)
        if (live[i]) {
            remap[i] = static_cast<int>(kept.size());
            kept.push_back(std::move(ir.nodes[i]));
        }
    int removed = static_cast<int>(ir.nodes.size() - kept.size());
    ir.nodes = std::move(kept);
    auto fix = [&](IrInput& in) {
        if (in.kind == IrInput::Kind::Node) in.node = remap[static_cast<std::size_t>(in.node)];
    };
    for (auto& n : ir.nodes)
        for (auto& in : n.inputs) fix(in);
    for (auto& [_, in] : ir.outputs) fix(in);
    return removed;
}

FoldingStats fold_constants(IrGraph& ir, Diagnostics& diag) {
    FoldingStats stats;
    for (std::size_t i = 0; i < ir.nodes.size(); ++i) {
        const IrNode& n = ir.nodes[i];
        auto outs = CpuEvaluator::evaluate_constant_node(n);
        if (!outs) continue;
        bool ok = true;
        for (std::size_t o = 0; o < outs->size(); ++o) {
            Constant c = (*outs)[o].to_constant(n.output_types[o]);
            if (!finite(c)) {
                diag.error(fmt::format("node \"{}\" computes {} for output \"{}\" from its constant inputs", n.id,
                                       c.text(), n.def->outputs[o].name),
                           n.pointer, n.id);
                ok = false;
                continue;
            }
            replace_uses(ir, static_cast<int>(i), static_cast<int>(o), c);
        }
        if (ok) ++stats.folded;
    }
    stats.removed = remove_dead_nodes(ir);
    return stats;
}

}  // namespace fg
