#pragma once
// The CPU twin of the pack's scene (double precision, from the graph the pack carries) watching
// the head: `--check-collisions` in view and xr reports how close the head came and whether it
// was ever inside a surface.
#include <memory>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "pack/pack_reader.h"

namespace fg {

class CollisionWitness {
public:
    // Throws std::runtime_error when the graph has no CPU twin (custom GLSL nodes).
    explicit CollisionWitness(const Pack& pack);
    ~CollisionWitness();

    void observe(const glm::dvec3& head);
    double closest() const { return closest_; }
    int frames() const { return frames_; }
    int frames_inside() const { return inside_; }
    std::string summary() const;

private:
    struct Twin;
    std::unique_ptr<Twin> twin_;
    double closest_ = 1e300;
    int frames_ = 0, inside_ = 0;
};

}  // namespace fg
