#include "node_definition.h"

#include <algorithm>

namespace fg {

namespace {
struct ImplicitInfo {
    ImplicitSource source;
    std::string_view name;
    ValueType type;
    bool shade_only;
};
constexpr ImplicitInfo kImplicit[] = {
    {ImplicitSource::Position, "position", ValueType::Vec3, false},
    {ImplicitSource::Time, "time", ValueType::Float, false},
    {ImplicitSource::Light, "light", ValueType::Vec3, true},
    {ImplicitSource::LightDistance, "light_distance", ValueType::Float, true},
    {ImplicitSource::LightSample, "light_sample", ValueType::Vec3, true},
    {ImplicitSource::ToCamera, "to_camera", ValueType::Vec3, true},
    {ImplicitSource::Normal, "normal", ValueType::Vec3, true},
};
}  // namespace

std::string_view implicit_source_name(ImplicitSource s) {
    for (const auto& i : kImplicit)
        if (i.source == s) return i.name;
    return "none";
}
std::optional<ImplicitSource> parse_implicit_source(std::string_view s) {
    for (const auto& i : kImplicit)
        if (i.name == s) return i.source;
    return std::nullopt;
}
ValueType implicit_source_type(ImplicitSource s) {
    for (const auto& i : kImplicit)
        if (i.source == s) return i.type;
    return ValueType::Float;
}
bool implicit_source_is_shade_only(ImplicitSource s) {
    for (const auto& i : kImplicit)
        if (i.source == s) return i.shade_only;
    return false;
}

std::string NodeDefinition::function_name() const {
    if (!function.empty()) return function;
    std::string f = "fg_" + type;
    std::replace(f.begin(), f.end(), '.', '_');
    return f;
}

const PortDefinition* NodeDefinition::find_input(const std::string& name) const {
    for (const auto& p : inputs)
        if (p.name == name) return &p;
    return nullptr;
}

const PortDefinition* NodeDefinition::find_output(const std::string& name) const {
    for (const auto& p : outputs)
        if (p.name == name) return &p;
    return nullptr;
}

std::string NodeDefinition::namespace_name() const { return type.substr(0, type.find('.')); }

}  // namespace fg
