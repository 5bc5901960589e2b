#include "cpu_node_registry.h"

namespace fg {

CpuNodeFunction find_cpu_node(std::string_view type, std::optional<ValueType> generic) {
    for (const auto& e : cpu_node_entries())
        if (e.type == type && e.generic == generic) return e.function;
    return nullptr;
}

CpuTangentFunction find_cpu_tangent(std::string_view type, std::optional<ValueType> generic) {
    for (const auto& e : cpu_node_entries())
        if (e.type == type && e.generic == generic) return e.tangent;
    return nullptr;
}

}  // namespace fg
