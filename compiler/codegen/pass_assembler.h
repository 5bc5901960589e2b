#pragma once
// Puts a pass together: the runtime's pass template (runtime/frame/shaders/<pass>.comp) with the
// effect defines, the global knobs, the shared template code (common.glsl) and the scene's code.
// A template's header says what it needs and when it runs:
//   //! pass: post
//   //! needs: distance | surface
//   //! when: always | any-effect fog glow vignette foveation
//   //! include: tail_queue.glsl      (optional, repeatable)
#include <optional>
#include <string>
#include <vector>

#include "common/diagnostics.h"
#include "common/effects.h"
#include "glsl_writer.h"
#include "pack/manifest.h"
#include "scene_codegen.h"

namespace fg {

struct PassTemplate {
    std::string name;
    std::string file;                  // e.g. "shade.comp"
    std::string text;
    bool needs_surface = false;
    bool needs_scene = true;      // `needs: nothing`: a pass that never evaluates the scene gets none of its code
    bool needs_trap = false;      // `needs: surface trap`: also fg_scene_trap (the AOV pass)
    std::vector<Effect> when_any;      // empty: always
    std::vector<std::string> includes; // shared template files pasted after common.glsl
    std::vector<std::string> scene_includes;   // `include-after-scene:` files that call the scene's functions
    bool runs_with(const EffectSet& effects) const;
};

// All pass templates embedded in this build, parsed.
const std::vector<PassTemplate>& pass_templates();
const std::string& common_template();
const std::string& shared_template(const std::string& file);   // throws if not embedded

struct AssembledPass {
    std::string name;
    std::string glsl;
    SourceMap source_map;
};

// `spec` gives the pack's defaults of the global knobs (step_scale = 1 / Lipschitz bound).
AssembledPass assemble_pass(const PassTemplate& pass, const EffectSet& effects, const SceneCodegen& scene,
                            const std::vector<ManifestSpecConstant>& spec);

}  // namespace fg
