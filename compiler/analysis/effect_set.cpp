#include "effect_set.h"

namespace fg {

EffectSet find_effects(const IrGraph& ir) {
    EffectSet e;
    auto note_input = [&](const IrInput& in) {
        if (in.kind == IrInput::Kind::Implicit && in.implicit == ImplicitSource::Normal) e.add(Effect::Normals);
        if (in.kind == IrInput::Kind::Node) {
            const auto& src = ir.nodes[static_cast<std::size_t>(in.node)];
            const auto& port = src.def->outputs[static_cast<std::size_t>(in.port)];
            if (port.effect) e.add(*port.effect);
        }
    };
    for (const auto& n : ir.nodes) {
        for (auto eff : n.def->effects) e.add(eff);
        for (const auto& in : n.inputs) note_input(in);
    }
    for (const auto& [name, in] : ir.outputs) note_input(in);

    // The shade pass's lighting model: an unbound diffuse falls back to Lambert on the normal.
    if (ir.outputs.count("diffuse")) e.add(Effect::Diffuse);
    else e.add(Effect::Normals);
    if (ir.outputs.count("ao")) e.add(Effect::AmbientOcclusion);
    if (ir.outputs.count("sss")) e.add(Effect::Subsurface);
    if (ir.outputs.count("rim")) e.add(Effect::Rim);
    if (ir.outputs.count("emission")) e.add(Effect::Emission);
    if (ir.outputs.count("shadow")) e.add(Effect::Shadow);
    if (ir.outputs.count("specular")) e.add(Effect::Specular);
    // The bounce leaves along the shade pass's own normal.
    if (ir.outputs.count("reflection")) e.add(Effect::Reflection), e.add(Effect::Normals);
    if (ir.outputs.count("transmission")) e.add(Effect::Refraction), e.add(Effect::Normals);
    if (ir.outputs.count("volume_density")) e.add(Effect::Volume);

    const auto& s = ir.scene;
    if (s.fog) e.add(Effect::Fog);
    if (s.glow) e.add(Effect::Glow);
    if (s.vignette) e.add(Effect::Vignette);
    if (s.foveation) e.add(Effect::Foveation);
    if (s.has_background_gradient()) e.add(Effect::BackgroundGradient);
    if (!s.light.auxiliary.empty()) e.add(Effect::Lights);
    if (s.environment) e.add(Effect::Environment), e.add(Effect::Normals);
    return e;
}

}  // namespace fg
