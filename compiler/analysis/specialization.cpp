#include "specialization.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "common/spec_constants.h"

namespace fg {

SpecializationLayout assign_specialization(IrGraph& ir, double step_scale) {
    SpecializationLayout out;
    for (const auto& k : kGlobalKnobs) {
        ManifestSpecConstant s;
        s.id = k.id;
        s.name = std::string(k.name);
        s.type = k.type;
        s.value = k.name == "step_scale" ? step_scale : k.name == "step_fraction" ? ir.scene.step_fraction : k.value;
        // Shorter steps need more of them to reach the same surface.
        if (k.name == "max_steps" || k.name == "cone_steps" || k.name == "fine_steps" || k.name == "reproject_fixup_steps")
            s.value = std::min(k.max, std::ceil(k.value / ir.scene.step_fraction));
        s.min = k.min;
        s.max = k.max;
        s.doc = std::string(k.doc);
        out.constants.push_back(s);
    }
    std::uint32_t next = kFirstNodeKnobId;
    for (auto& n : ir.nodes) {
        ManifestFractal fractal;
        fractal.node = n.id;
        fractal.type = n.def->type;
        fractal.running_derivative = n.def->running_derivative;
        for (std::size_t i = 0; i < n.inputs.size(); ++i) {
            auto& in = n.inputs[i];
            const auto& port = n.def->inputs[i];
            if (in.kind != IrInput::Kind::Knob) continue;
            in.knob_id = next++;
            ManifestSpecConstant s;
            s.id = in.knob_id;
            s.name = fmt::format("{}.{}", port.knob, n.id);
            s.type = port.type.concrete.value_or(ValueType::Float);
            s.value = in.constant.v[0];
            s.min = port.min;
            s.max = port.max;
            s.doc = port.doc;
            out.constants.push_back(s);
            if (port.knob == "bias") fractal.bias_spec = in.knob_id;
            if (port.knob == "iterations") fractal.iterations_spec = in.knob_id;
        }
        if (!n.def->running_derivative.empty()) out.fractals.push_back(fractal);
    }
    return out;
}

}  // namespace fg
