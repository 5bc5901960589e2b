#include "graph.h"

namespace fg {

const GraphNode* Graph::find_node(const std::string& id) const {
    for (const auto& n : nodes)
        if (n.id == id) return &n;
    return nullptr;
}

const ParamDecl* Graph::find_param(const std::string& param) const {
    for (const auto& p : params)
        if (p.name == param) return &p;
    return nullptr;
}

const std::vector<GraphOutputSpec>& graph_output_specs() {
    static const std::vector<GraphOutputSpec> specs{
        {"distance", ValueType::Float, true, "signed distance to the surface (required)"},
        {"albedo", ValueType::Vec3, false, "surface colour before lighting"},
        {"diffuse", ValueType::Float, false, "diffuse light factor; unbound: Lambert from finite-difference normals"},
        {"ao", ValueType::Float, false, "ambient occlusion factor in [0, 1]"},
        {"sss", ValueType::Float, false, "subsurface scattering factor"},
        {"rim", ValueType::Float, false, "rim light factor"},
        {"emission", ValueType::Vec3, false, "emitted colour, added after lighting"},
        {"shadow", ValueType::Float, false, "how much of the light reaches the point, in [0, 1] (light.soft_shadow); scales diffuse and specular"},
        {"specular", ValueType::Vec3, false, "specular reflectance towards the camera (light.specular), times the light's colour and the shadow"},
        {"specular_color", ValueType::Vec3, false, "the specular lobe's reflectance head-on (light.specular): where bound, the environment reflects in the lobe"},
        {"roughness", ValueType::Float, false, "the specular lobe's roughness, 0 to 1 (light.specular); unbound: 0.35"},
        {"reflection", ValueType::Vec3, false, "mirror reflectance (light.reflection): the share of the scene seen in the mirror direction that the point reflects"},
        {"transmission", ValueType::Vec3, false, "the share of the light refracted through the body that the point passes on (light.refraction)"},
        {"ior", ValueType::Float, false, "the body's refractive index where it refracts; unbound: 1.5"},
        {"absorption", ValueType::Vec3, false, "absorption per world unit inside a refracting body (Beer-Lambert); unbound: 0"},
        {"volume_density", ValueType::Float, false, "extinction per world unit of a glowing medium around the surface (light.iteration_fog), evaluated along each eye ray up to the hit"},
        {"volume_color", ValueType::Vec3, false, "the light the medium gives per unit of optical depth where volume_density is bound; unbound: white"},
    };
    return specs;
}

}  // namespace fg
