#pragma once
// The environment as the shaders read it (shaders/environment.glsl): one storage buffer of 32-bit
// words holding the image, its diffuse irradiance as spherical harmonics, and the tables that draw
// directions in proportion to its brightness:
//   0, 1         width, height
//   2            the word the specular lobe's section starts at (environment_gloss.h)
//   4 .. 39      nine vec4: the irradiance E(n) / pi as order-2 spherical harmonics (Ramamoorthi and
//                Hanrahan 2001), the cosine lobe folded in: what a white diffuse surface reflects
//   40 ..        the rows' cumulative distribution (height + 1 floats, 0 .. 1), then each row's
//                columns' (width + 1 floats each), by luminance times the row's sin(theta)
//   then         the texels, RGBA half floats packed two to a word, row by row from the top
//   then         the specular lobe's section
// A uniform environment is a small image of radiance 1; the scene's colour scales either.
#include <cstdint>
#include <vector>

#include "pack/environment_image.h"

namespace fg {

inline constexpr std::uint32_t kEnvironmentHarmonicsAt = 4, kEnvironmentTablesAt = 40;

std::vector<std::uint32_t> environment_words(const EnvironmentImage& image);
// The uniform sky: 64 x 32 texels of radiance 1.
EnvironmentImage uniform_environment();

}  // namespace fg
