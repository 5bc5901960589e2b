#pragma once
// A triangle mesh of a level set's zero crossing (OpenVDB's volumeToMesh), with vertex normals
// from the level set's gradient and, when asked, vertex colours.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>
#include <openvdb/openvdb.h>

#include "cpu/cpu_evaluator.h"

namespace fg {

struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;                 // unit, outward
    std::vector<glm::u8vec3> colors;                // empty, or one per position
    std::vector<glm::uvec3> triangles;              // counter-clockwise seen from outside
};

// adaptivity 0 keeps every voxel's polygons; up to 1 merges flat regions into fewer, larger ones.
TriangleMesh mesh_level_set(const openvdb::FloatGrid& grid, double adaptivity);

// colour(p) for every vertex, in `threads` threads; each thread gets its own colour function from
// make_colour (the CPU twin is not shared across threads).
using ColourFunction = std::function<glm::dvec3(const glm::dvec3& p, const glm::dvec3& normal)>;
void colour_vertices(TriangleMesh& mesh, const std::function<ColourFunction()>& make_colour, int threads);
// Every vertex coloured by the graph's albedo where the renderer would colour it, as 8-bit sRGB
// (vertex colours are read as display-encoded). The renderer's march stops where the estimate
// falls under half of a pixel's half-width (its default hit rule); a vertex of a part without an
// inside sits half a voxel out, where a fractal's orbit trap, and so its palette, can differ a
// lot. So each vertex first steps in along its normal as the march would, by the estimate times
// `scale` (the export's conservative factor), until under a quarter voxel (the renderer's rule at
// a pixel one voxel across) or one voxel in, then takes the CPU twin's `albedo` there.
void colour_by_albedo(TriangleMesh& mesh, const CpuEvaluator& scene, double scale, double voxel_size, int threads);

}  // namespace fg
