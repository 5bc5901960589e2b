#include "cpu_evaluator.h"

#include <fmt/format.h>
#include <functional>
#include <set>

#include "cpu_glsl.h"

namespace fg {

namespace {
// Shade-context bodies call fg_scene_distance(); it answers with the evaluator that is shading.
thread_local const CpuEvaluator* tl_shading = nullptr;
}  // namespace

namespace glsl {
double fg_scene_distance(vec3 p) { return tl_shading ? tl_shading->distance(p) : 1e30; }
}  // namespace glsl

CpuShadingScope::CpuShadingScope(const CpuEvaluator& scene) : previous_(tl_shading) { tl_shading = &scene; }
CpuShadingScope::~CpuShadingScope() { tl_shading = previous_; }

CpuEvaluator::CpuEvaluator(const IrGraph& ir) : ir_(&ir) {}

std::optional<CpuEvaluator> CpuEvaluator::create(const IrGraph& ir, Diagnostics& diag) {
    CpuEvaluator ev(ir);
    for (const auto& n : ir.nodes) {
        if (n.inputs.size() > kMaxNodeInputs) {
            diag.error(fmt::format("node \"{}\" ({}) has {} inputs; the CPU twin takes at most {}", n.id, n.def->type,
                                   n.inputs.size(), kMaxNodeInputs),
                       n.pointer, n.id);
            return std::nullopt;
        }
        std::shared_ptr<const CpuFormula> formula;
        if (n.formula && !(formula = CpuFormula::create(n.formula, n.id, n.pointer, diag))) return std::nullopt;
        ev.formulas_.push_back(formula);
        CpuNodeFunction f = n.custom_def ? nullptr : find_cpu_node(n.def->type, n.generic);
        if (!f && !formula) {
            diag.error(fmt::format("node \"{}\" ({}) has no CPU twin{}", n.id, n.def->type,
                                   n.custom_def ? ": custom GLSL runs only on the GPU" : ""),
                       n.pointer, n.id);
            return std::nullopt;
        }
        ev.functions_.push_back(f);
        ev.slot_offset_.push_back(ev.slot_count_);
        ev.slot_count_ += n.def->outputs.size();
    }
    for (const auto& p : ir.params) ev.params_.push_back(CpuValue::of(p.value));
    ev.surface_moves_.assign(ir.nodes.size(), {-1, 0.0});
    std::vector<const IrInput*> all_roots;
    for (const auto& [name, in] : ir.outputs) {
        all_roots.push_back(&in);
        if (name == "distance") ev.distance_root_ = in;
    }
    ev.distance_plan_ = ev.plan_for({&ev.distance_root_});
    ev.all_plan_ = ev.plan_for(all_roots);
    for (std::size_t i = 0; i < ir.nodes.size(); ++i)
        if (!ir.nodes[i].shade_only) ev.unshaded_plan_.nodes.push_back(static_cast<int>(i));
    return ev;
}

CpuEvaluator::Plan CpuEvaluator::plan_for(const std::vector<const IrInput*>& roots) const {
    std::set<int> needed;
    std::function<void(const IrInput&)> need = [&](const IrInput& in) {
        if (in.kind != IrInput::Kind::Node || !needed.insert(in.node).second) return;
        for (const auto& sub : ir_->nodes[static_cast<std::size_t>(in.node)].inputs) need(sub);
    };
    for (const auto* r : roots) need(*r);
    Plan plan;
    plan.nodes.assign(needed.begin(), needed.end());  // IR order is dependency order
    return plan;
}

bool CpuEvaluator::set_param(const std::string& name, const Constant& value) {
    for (std::size_t i = 0; i < ir_->params.size(); ++i)
        if (ir_->params[i].name == name) {
            params_[i] = CpuValue::of(value);
            return true;
        }
    return false;
}

bool CpuEvaluator::set_knob(const std::string& spec_name, double value) {
    auto dot = spec_name.find('.');
    if (dot == std::string::npos) return false;
    std::string knob = spec_name.substr(0, dot), node = spec_name.substr(dot + 1);
    int idx = ir_->find(node);
    if (idx < 0) return false;
    const auto& n = ir_->nodes[static_cast<std::size_t>(idx)];
    for (std::size_t i = 0; i < n.inputs.size(); ++i)
        if (n.inputs[i].kind == IrInput::Kind::Knob && n.def->inputs[i].knob == knob) {
            knobs_[{idx, static_cast<int>(i)}] = value;
            return true;
        }
    return false;
}

namespace {
int distance_port(const IrNode& n) {
    const PortDefinition* port = n.def->find_output("distance");
    return port ? static_cast<int>(port - n.def->outputs.data()) : -1;
}
}  // namespace

bool CpuEvaluator::move_surface(int node, double offset) {
    const int port = distance_port(ir_->nodes.at(static_cast<std::size_t>(node)));
    if (port < 0) return false;
    surface_moves_[static_cast<std::size_t>(node)] = {port, offset};
    return true;
}

CpuEvaluator CpuEvaluator::part(int node) const {
    CpuEvaluator copy = *this;
    copy.distance_root_ = IrInput{};
    copy.distance_root_.kind = IrInput::Kind::Node;
    copy.distance_root_.node = node;
    copy.distance_root_.port = std::max(0, distance_port(ir_->nodes.at(static_cast<std::size_t>(node))));
    copy.distance_plan_ = copy.plan_for({&copy.distance_root_});
    return copy;
}

CpuValue CpuEvaluator::read(const IrInput& in, const std::vector<CpuValue>& slots, const glm::dvec3& p,
                            const CpuShadeInputs* shade) const {
    CpuValue v;
    switch (in.kind) {
        case IrInput::Kind::Node: v = slots[slot_offset_[static_cast<std::size_t>(in.node)] + static_cast<std::size_t>(in.port)]; break;
        case IrInput::Kind::Param: v = params_[static_cast<std::size_t>(in.param)]; break;
        case IrInput::Kind::Constant:
        case IrInput::Kind::Knob: v = CpuValue::of(in.constant); break;
        case IrInput::Kind::Implicit:
            switch (in.implicit) {
                case ImplicitSource::Position: v = CpuValue::of(p); break;
                case ImplicitSource::Time: v = CpuValue::of(time_); break;
                case ImplicitSource::Light: {
                    v = CpuValue::of(ir_->scene.light.direction);
                    break;
                }
                // The main light is directional: as far as a float goes.
                case ImplicitSource::LightDistance: v = CpuValue::of(kDirectionalLightDistance); break;
                case ImplicitSource::LightSample: v = CpuValue::of(glm::dvec3(0.0)); break;   // a single frame
                case ImplicitSource::ToCamera: v = CpuValue::of(shade ? shade->to_camera : glm::dvec3(0, 0, 1)); break;
                case ImplicitSource::Normal: v = CpuValue::of(shade ? shade->normal : glm::dvec3(0, 1, 0)); break;
                case ImplicitSource::None: break;
            }
            break;
    }
    // int -> float widening is the only conversion the IR allows; both are doubles here.
    return v;
}

void CpuEvaluator::run(const Plan& plan, std::vector<CpuValue>& slots, const glm::dvec3& p,
                       const CpuShadeInputs* shade) const {
    CpuValue args[kMaxNodeInputs];
    for (int idx : plan.nodes) {
        const auto& n = ir_->nodes[static_cast<std::size_t>(idx)];
        for (std::size_t i = 0; i < n.inputs.size(); ++i) {
            args[i] = read(n.inputs[i], slots, p, shade);
            if (n.inputs[i].kind == IrInput::Kind::Knob) {
                auto k = knobs_.find({idx, static_cast<int>(i)});
                if (k != knobs_.end()) args[i] = CpuValue::of(k->second);
            }
        }
        CpuValue* out = &slots[slot_offset_[static_cast<std::size_t>(idx)]];
        if (const auto& formula = formulas_[static_cast<std::size_t>(idx)]) formula->run(args, out);
        else functions_[static_cast<std::size_t>(idx)](args, out);
        if (const auto& [port, offset] = surface_moves_[static_cast<std::size_t>(idx)]; port >= 0) out[port].v.x -= offset;
    }
}

double CpuEvaluator::distance(const glm::dvec3& p) const {
    ++evaluations_;
    std::vector<CpuValue> slots(slot_count_);
    run(distance_plan_, slots, p, nullptr);
    return read(distance_root_, slots, p, nullptr).f();
}

glm::dvec3 CpuEvaluator::normal(const glm::dvec3& p, double h) const {
    glm::dvec3 n(distance(p + glm::dvec3(h, 0, 0)) - distance(p - glm::dvec3(h, 0, 0)),
                 distance(p + glm::dvec3(0, h, 0)) - distance(p - glm::dvec3(0, h, 0)),
                 distance(p + glm::dvec3(0, 0, h)) - distance(p - glm::dvec3(0, 0, h)));
    double len = glm::length(n);
    return len > 0 ? n / len : glm::dvec3(0, 1, 0);
}

std::vector<CpuValue> CpuEvaluator::evaluate_nodes(const glm::dvec3& p) const {
    std::vector<CpuValue> slots(slot_count_);
    run(unshaded_plan_, slots, p, nullptr);
    return slots;
}

std::optional<CpuValue> CpuEvaluator::output(const std::string& name, const glm::dvec3& p,
                                             const CpuShadeInputs& shade) const {
    auto it = ir_->outputs.find(name);
    if (it == ir_->outputs.end()) return std::nullopt;
    std::vector<CpuValue> slots(slot_count_);
    const CpuEvaluator* previous = tl_shading;
    tl_shading = this;
    run(all_plan_, slots, p, &shade);
    tl_shading = previous;
    return read(it->second, slots, p, &shade);
}

CpuSurface CpuEvaluator::surface(const glm::dvec3& p, const CpuShadeInputs& shade) const {
    std::vector<CpuValue> slots(slot_count_);
    const CpuEvaluator* previous = tl_shading;
    tl_shading = this;
    run(all_plan_, slots, p, &shade);
    tl_shading = previous;
    CpuSurface s;
    s.albedo = ir_->scene.albedo;
    auto get = [&](const char* name) -> std::optional<CpuValue> {
        auto it = ir_->outputs.find(name);
        if (it == ir_->outputs.end()) return std::nullopt;
        return read(it->second, slots, p, &shade);
    };
    if (auto v = get("albedo")) s.albedo = v->v3();
    if (auto v = get("diffuse")) s.diffuse = v->f();
    if (auto v = get("ao")) s.ao = v->f();
    if (auto v = get("sss")) s.sss = v->f();
    if (auto v = get("rim")) s.rim = v->f();
    if (auto v = get("emission")) s.emission = v->v3();
    if (auto v = get("shadow")) s.shadow = v->f();
    if (auto v = get("specular")) s.specular = v->v3();
    if (auto v = get("specular_color")) s.specular_color = v->v3();
    if (auto v = get("roughness")) s.roughness = v->f();
    if (auto v = get("reflection")) s.reflection = v->v3();
    if (auto v = get("transmission")) s.transmission = v->v3();
    if (auto v = get("ior")) s.ior = v->f();
    if (auto v = get("absorption")) s.absorption = v->v3();
    return s;
}

std::optional<std::vector<CpuValue>> CpuEvaluator::evaluate_constant_node(const IrNode& node) {
    if (node.custom_def || node.shade_only) return std::nullopt;  // formulas too: they iterate on p
    CpuNodeFunction f = find_cpu_node(node.def->type, node.generic);
    if (!f) return std::nullopt;
    std::vector<CpuValue> args;
    for (const auto& in : node.inputs) {
        if (in.kind != IrInput::Kind::Constant) return std::nullopt;
        args.push_back(CpuValue::of(in.constant));
    }
    std::vector<CpuValue> outs(node.def->outputs.size());
    f(args.data(), outs.data());
    return outs;
}

}  // namespace fg
