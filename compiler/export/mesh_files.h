#pragma once
// Meshes on disk, by the path's extension: binary PLY (positions, normals, colours when the mesh
// has them), Wavefront OBJ (positions, normals) and binary STL (facets with their normals, for
// slicers). Each is written through a temporary file renamed into place.
#include <optional>
#include <string>

#include "common/diagnostics.h"
#include "level_set_mesh.h"

namespace fg {

enum class MeshFormat { Ply, Obj, Stl };

// The format of a path's extension (.ply, .obj, .stl, any case); nullopt for anything else.
std::optional<MeshFormat> mesh_format_of(const std::string& path);

bool write_mesh(const std::string& path, const TriangleMesh& mesh, Diagnostics& diag);

}  // namespace fg
