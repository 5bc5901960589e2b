#pragma once
// Emits the scene's part of every pass: the Params block, node knob constants, the node bodies the
// graph uses (each once), custom-code functions, and the two entry points the pass templates call:
//   float fg_scene_distance(vec3 p)                      only what the distance needs
//   FgSurface fg_scene_surface(vec3 p, vec3 fg_to_camera, vec3 fg_normal)   everything else
//   FgSurface fg_scene_view_terms(...)   only the terms that read the view (shading reuse)
//   FgLightTerms fg_scene_light_terms(..., fg_light, fg_light_distance)   diffuse, shadow and specular
//       towards any light (scenes with auxiliary lights)
//   vec4 fg_scene_volume(vec3 p, out float distance)   the medium's colour and density, and the
//       scene's distance (graphs that bind volume_density)
// With scene.precision "double" the bodies are lowered to double (double_lowering.h) and evaluated
// at fg_anchor() + p: the passes march in float relative to the camera, whose position the frame
// uniforms hold in double (hi + lo floats), so positions keep their digits at any zoom.
#include <functional>
#include <set>
#include <string>

#include "glsl_writer.h"
#include "graph/node_library.h"
#include "ir/ir_graph.h"

namespace fg {

class SceneCodegen {
public:
    SceneCodegen(const IrGraph& ir, const NodeLibrary& library) : ir_(ir), library_(library) {}

    bool double_precision() const { return double_; }
    // #defines naming the outputs the graph binds (FG_OUT_ALBEDO ...), for the shade template.
    void output_defines(GlslWriter& w) const;
    // Params block, knob constants, prelude and the bodies the distance needs.
    void declarations(GlslWriter& w) const;
    void distance_function(GlslWriter& w) const;
    // The other bodies the surface outputs need (shade nodes call fg_scene_distance), and
    // fg_scene_surface.
    void surface_function(GlslWriter& w) const;
    // vec4 fg_scene_trap(vec3 p): the orbit trap of the first fractal the distance uses, for the
    // AOV pass (vec4(0) without one); FG_HAS_TRAP_OUTPUT says whether there is one.
    void trap_function(GlslWriter& w) const;

private:
    // Where a function's body is evaluated: the implicit inputs each one sees.
    enum class Context { Distance, Surface, LightTerms };

    const IrGraph& ir_;
    const NodeLibrary& library_;
    bool double_ = ir_.scene.double_precision;

    // The type's GLSL name in this scene's precision, a body in it, and a float-typed value
    // (uniform, knob) converted to it.
    std::string type_of(ValueType t) const;
    std::string lowered(const std::string& glsl) const;
    std::string in_precision(const std::string& value, ValueType t) const;

    // Nodes the distance (or the surface outputs) need, by IR index.
    std::vector<bool> needed_by(const std::vector<const IrInput*>& roots) const;
    std::vector<const IrInput*> surface_roots() const;
    // The medium's outputs (volume_density, volume_color): evaluated along rays, not at the hit.
    std::vector<const IrInput*> volume_roots() const;
    void volume_function(GlslWriter& w) const;
    // Whether a value depends on the direction to the camera, and the scalar surface outputs that do.
    bool reads_to_camera(const IrInput& root) const;
    std::vector<const IrInput*> view_roots() const;
    // "FgSurface name(p, fg_to_camera, fg_normal) {" and, in double, the absolute point.
    void shading_function_head(GlslWriter& w, const char* name, const char* type = "FgSurface",
                               const char* extra_parameters = "") const;
    // An output's value in a shading function, or `fallback` where the graph binds none.
    std::string output_or(const char* name, const char* fallback, Context context) const;
    void light_terms_function(GlslWriter& w) const;
    // FgSurface fg_scene_view_terms(p, fg_to_camera, fg_normal): only the view_roots() outputs.
    void view_terms_function(GlslWriter& w, const std::function<std::string(const char*, const char*)>& field) const;
    // Bodies of the nodes in `want` whose type is not in `skip` (each type and instance once).
    void bodies(GlslWriter& w, const std::vector<bool>& want, const std::vector<bool>& skip) const;
    void function_body(GlslWriter& w, const std::vector<const IrInput*>& roots, Context context) const;
    std::string value_of(const IrInput& in, Context context) const;
    static std::string variable(int node, int port);
};

}  // namespace fg
