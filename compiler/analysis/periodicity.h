#pragma once
// Periodicity: whether the scene repeats through space, and with what period. A scene whose every
// use of the sample position goes through an `xform.repeat` node with a constant period (the same
// one everywhere) is periodic on every axis: its distance, colours and lighting are the same at p
// and at p + k * period. The runtime wraps the head by whole periods in such scenes, so an endless
// flight keeps its coordinates small and the image does not drift with float precision.
#include <array>
#include <optional>
#include <string>

#include "ir/ir_graph.h"

namespace fg {

struct Periodicity {
    std::optional<std::array<double, 3>> period;   // set when periodic on all three axes
    std::string reason;                            // why not, naming the node: for `fgc info` and tests
};

Periodicity analyse_periodicity(const IrGraph& ir);

}  // namespace fg
