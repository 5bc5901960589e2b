#pragma once
// Environment images for tests: a lat-long OpenEXR painted by a function of the image's point.
#include <functional>
#include <string>

#include <glm/glm.hpp>

namespace fg::test {

// A lat-long OpenEXR of width x height in the temporary folder whose texel is colour(u, v) at its
// centre (v = 0 straight up, fgplay's equirect layout); its path.
std::string write_lat_long_exr(const std::string& name, int width, int height,
                               const std::function<glm::dvec3(double u, double v)>& colour);

}  // namespace fg::test
