#pragma once
// The images the AOV pass writes per eye (shaders/aov.comp), as the frame graph declares them and
// the OpenEXR writer reads them back.
#include <span>
#include <string>

#include "frame_graph.h"

namespace fg {

struct AovImage {
    const char* binding;    // the shader's image: "fg_position"
    const char* name;       // the frame graph's image is "aov.<name>.<eye>"
    ImageFormat format;
    const char* about;
};

std::span<const AovImage> aov_images();
// Whether a scene of these effects has the image: the light, reflection and refraction terms only
// where it uses them (their EXR channels are left out too); the rest always.
bool aov_image_needed(const AovImage& image, const EffectSet& effects);
std::string aov_image_name(const AovImage& image, const std::string& eye);

}  // namespace fg
