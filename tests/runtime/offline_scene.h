#pragma once
// A scene that surrounds the camera, for panoramas (data/panorama_room.json): a floor under the
// whole lower half of the image, a ball ahead, a box behind (across the equirectangular seam)
// and a ring to the right.
#include <string>

#include "runtime_test_support.h"

namespace fg::test {

inline std::string room_graph() { return read_source_file("tests/runtime/data/panorama_room.json"); }

}  // namespace fg::test
