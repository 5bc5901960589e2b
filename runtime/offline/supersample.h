#pragma once
// Supersampling for offline frames: the frame graph renders factor x factor samples per output
// pixel, and the box filter here averages them in linear light (the images are sRGB-encoded), so
// edges against a bright background do not darken. Pure CPU integer-exact code: deterministic.
#include <cstdint>

#include "frame/image_output.h"

namespace fg {

Rgba8Image downsample(const Rgba8Image& image, std::uint32_t factor);
// Stacks images of the same width: ODS frames are top-bottom, left eye on top.
Rgba8Image top_bottom(const Rgba8Image& top, const Rgba8Image& bottom);

}  // namespace fg
