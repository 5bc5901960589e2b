#include "aov_pixels.h"

#include <cstring>

#include <Imath/half.h>

#include "runtime_test_support.h"

namespace fg::test {

double aov_half(const RenderedFrame& f, const std::string& name, std::size_t i, int c) {
    Imath::half h;
    std::memcpy(&h, f.aovs_left.at(aov_index(name)).data() + (4 * i + c) * sizeof h, sizeof h);
    return static_cast<double>(h);
}

glm::dvec4 aov_position(const RenderedFrame& f, std::size_t i) {
    float p[4];
    std::memcpy(p, f.aovs_left.at(aov_index("position")).data() + 4 * i * sizeof(float), sizeof p);
    return {p[0], p[1], p[2], p[3]};
}

}  // namespace fg::test
