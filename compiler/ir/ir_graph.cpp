#include "ir_graph.h"

namespace fg {

int IrGraph::find(const std::string& id) const {
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].id == id) return static_cast<int>(i);
    return -1;
}

ValueType IrGraph::output_type(const IrInput& in) const { return in.source_type; }

}  // namespace fg
