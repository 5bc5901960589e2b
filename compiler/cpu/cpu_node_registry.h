#pragma once
// Every library node's body compiled as C++ (double precision), looked up by type and generic
// instance. Generated at build time by fg_nodegen from nodes/ (see nodes/CMakeLists.txt).
#include <optional>
#include <span>
#include <string_view>

#include "common/value_type.h"
#include "cpu_value.h"

namespace fg {

using CpuNodeFunction = void (*)(const CpuValue* inputs, CpuValue* outputs);
// A node's tangent rule: `tangents` holds one tangent per input of its rule, `out` receives one per
// output of its rule (graph/node_definition.h, TangentRule).
using CpuTangentFunction = void (*)(const CpuValue* inputs, const CpuValue* tangents, CpuValue* out);

struct CpuNodeEntry {
    std::string_view type;                // "math.add"
    std::optional<ValueType> generic;     // the T instance, for generic nodes
    CpuNodeFunction function;
    CpuTangentFunction tangent;           // nullptr: the node has no tangent rule
};

std::span<const CpuNodeEntry> cpu_node_entries();  // generated
CpuNodeFunction find_cpu_node(std::string_view type, std::optional<ValueType> generic);
CpuTangentFunction find_cpu_tangent(std::string_view type, std::optional<ValueType> generic);

}  // namespace fg
