#include "mesh_files.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

namespace fg {

namespace {

// PLY and STL are little-endian, as is every machine this runs on.
template <typename T>
void put(std::ostream& out, const T& value) {
    out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

void write_ply(std::ostream& out, const TriangleMesh& m) {
    const bool colours = !m.colors.empty();
    out << "ply\nformat binary_little_endian 1.0\ncomment written by Fractograph (fgc export)\n"
        << "element vertex " << m.positions.size() << "\n"
        << "property float x\nproperty float y\nproperty float z\n"
        << "property float nx\nproperty float ny\nproperty float nz\n"
        << (colours ? "property uchar red\nproperty uchar green\nproperty uchar blue\n" : "")
        << "element face " << m.triangles.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        put(out, m.positions[i]);
        put(out, m.normals[i]);
        if (colours) put(out, m.colors[i]);
    }
    for (const auto& t : m.triangles) {
        put(out, std::uint8_t{3});
        put(out, t);
    }
}

void write_obj(std::ostream& out, const TriangleMesh& m) {
    out << "# written by Fractograph (fgc export)\n";
    for (const auto& p : m.positions) out << fmt::format("v {} {} {}\n", p.x, p.y, p.z);
    for (const auto& n : m.normals) out << fmt::format("vn {} {} {}\n", n.x, n.y, n.z);
    for (const auto& t : m.triangles)   // OBJ counts from 1
        out << fmt::format("f {0}//{0} {1}//{1} {2}//{2}\n", t.x + 1, t.y + 1, t.z + 1);
}

void write_stl(std::ostream& out, const TriangleMesh& m) {
    char header[80] = {};
    std::strncpy(header, "binary STL written by Fractograph (fgc export)", sizeof(header) - 1);
    out.write(header, sizeof(header));
    put(out, static_cast<std::uint32_t>(m.triangles.size()));
    for (const auto& t : m.triangles) {
        const glm::vec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
        // The normal is recomputed by STL checkers from the float corners. Where two corners are
        // a rounding error apart (sheets of the surface touching in a voxel), its direction is
        // the rounding's own, so it is rounded as admesh, the checker slicers' users run, rounds
        // it: each cross product term is the first product rounded to float minus the second in
        // double. A cross product below 1e-12 is no direction at all: a zero normal.
        const glm::vec3 e1 = b - a, e2 = c - a;
        auto term = [](float x1, float y2, float x2, float y1) {
            return static_cast<float>(static_cast<float>(double{x1} * y2) - double{x2} * y1);
        };
        const glm::dvec3 n(term(e1.y, e2.z, e1.z, e2.y), term(e1.z, e2.x, e1.x, e2.z), term(e1.x, e2.y, e1.y, e2.x));
        const double length = glm::length(n);
        put(out, length >= 1e-12 ? glm::vec3(n / length) : glm::vec3(0.0f));
        put(out, a);
        put(out, b);
        put(out, c);
        put(out, std::uint16_t{0});
    }
}

}  // namespace

std::optional<MeshFormat> mesh_format_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".ply") return MeshFormat::Ply;
    if (ext == ".obj") return MeshFormat::Obj;
    if (ext == ".stl") return MeshFormat::Stl;
    return std::nullopt;
}

bool write_mesh(const std::string& path, const TriangleMesh& mesh, Diagnostics& diag) {
    const auto format = mesh_format_of(path);
    if (!format) {
        diag.error(fmt::format("{}: unknown mesh format (use .ply, .obj or .stl)", path));
        return false;
    }
    const std::string temporary = path + ".partial";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (*format == MeshFormat::Ply) write_ply(out, mesh);
        else if (*format == MeshFormat::Obj) write_obj(out, mesh);
        else write_stl(out, mesh);
        out.close();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            diag.error(fmt::format("cannot write {}", path));
            return false;
        }
    }
    std::filesystem::rename(temporary, path);
    return true;
}

}  // namespace fg
