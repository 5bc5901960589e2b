#pragma once
// OpenEXR frames for compositors (Nuke, Blender, Fusion, DaVinci): one file per frame, one part per
// eye (a mono panorama has one), each with the AOV pass's images as layers:
//   R G B A          the HDR beauty before the tone map (half, scene-linear, exposed)
//   Z                camera depth in metres: along the view axis, along the ray in a panorama; misses +inf
//   P.X P.Y P.Z      world position (float)
//   N.X N.Y N.Z      unit normal (half), 0 for misses
//   AO.Y diffuse.Y   ambient occlusion and the light's diffuse factor (half)
//   albedo.R/G/B     surface colour (half)
//   trap.X/Y/Z/W     the fractal's orbit trap (half)
// and the standard camera attributes worldToCamera and (perspective) worldToNDC, or envmap latlong
// for panoramas. Lossless compression: ZIP by default, PIZ on request.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "frame/stereo_rig.h"

namespace fg {

enum class ExrCompression { Zip, Piz, None };
bool parse_exr_compression(const std::string& text, ExrCompression& out);
const char* exr_compression_name(ExrCompression c);

// OpenEXR's matrices act on row vectors (p' = p M): m[row][column].
using ExrMatrix = std::array<std::array<double, 4>, 4>;

struct ExrCamera {
    ExrMatrix world_to_camera{};               // left-handed: +x right, +y up, +z the view direction; metres
    std::optional<ExrMatrix> world_to_ndc;     // perspective only: (0,0) top left, (1,1) bottom right
};
// The camera of a view: its origin and axes in world (scene) units, world_scale scene units per metre.
ExrCamera exr_camera(const View& view, double world_scale, bool perspective);
// p' = p M with the homogeneous divide, as OpenEXR's readers apply the matrices.
glm::dvec3 exr_transform(const glm::dvec3& p, const ExrMatrix& rows);

struct ExrPart {
    std::string view;                        // "left", "right" or "centre"
    std::uint32_t width = 0, height = 0;
    // The AOV images of this eye at the output size, in aov_images() order and their formats.
    std::span<const std::vector<std::byte>> aovs;
    ExrCamera camera;
    bool panorama = false;
};

// The whole file in memory (frames are written atomically with their verification record).
// Throws std::runtime_error if OpenEXR refuses.
std::vector<std::uint8_t> encode_exr(std::span<const ExrPart> parts, ExrCompression compression);

}  // namespace fg
