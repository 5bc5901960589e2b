#pragma once
// The environment as a GGX specular lobe reflects it in a frame (the split sum of Karis 2013): the
// image prefiltered by the lobe at five roughnesses, and the lobe's reflectance as a table. The
// shaders (environment.glsl) read them from the environment's buffer, at the word its header's
// third word names:
//   0 ..         the table: for 32 roughnesses (rows) by 32 cosines between the normal and the
//                view (columns), at texel centres, two floats (A, B): a white light from every
//                direction reflects F0 * A + B, with F0 the reflectance head-on (Schlick's Fresnel,
//                the height-correlated Smith visibility, as light.specular)
//   2048 ..      five levels, four words each: width, height, the word its texels start at, 0
//   then         each level's texels, as the image's: half floats two to a word, row by row
// Level k holds the image convolved with the lobe of roughness 0.2 (k + 1) seen head-on.
#include <cstdint>
#include <vector>

#include "pack/environment_image.h"

namespace fg {

inline constexpr std::uint32_t kGlossTableSize = 32, kGlossLevels = 5;

// Appends the section to `words` (an environment's buffer) and sets its header's third word.
void append_environment_gloss(const EnvironmentImage& image, std::vector<std::uint32_t>& words);

}  // namespace fg
