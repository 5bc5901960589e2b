#pragma once
// A scene that surrounds the camera, for panoramas (data/panorama_room.json): a floor under the
// whole lower half of the image, a ball ahead, a box behind (across the equirectangular seam)
// and a ring to the right.
#include <ostream>
#include <string>

#include "frame/projection.h"
#include "runtime_test_support.h"

namespace fg::test {

inline std::string room_graph() { return read_source_file("tests/runtime/data/panorama_room.json"); }

}  // namespace fg::test

namespace fg {
// Test names and failure messages say "ods", not "4-byte object <02-00 00-00>".
inline void PrintTo(Projection p, std::ostream* os) { *os << projection_name(p); }
}  // namespace fg
