#include "path_params.h"

#include <algorithm>
#include <fmt/format.h>

namespace fg {

bool check_path_params(const CameraPath& path, const PackManifest& manifest, Diagnostics& diag) {
    bool ok = true;
    std::string names;
    for (const auto& p : manifest.params) names += (names.empty() ? "" : ", ") + p.name;
    for (std::size_t i = 0; i < path.keys().size(); ++i)
        for (const auto& [name, value] : path.keys()[i].params) {
            const std::string field = fmt::format("/keyframes/{}/params/{}", i, name);
            const ManifestParam* p = manifest.find_param(name);
            if (!p) {
                ok = false;
                diag.error(fmt::format("the pack has no parameter \"{}\"; its parameters are: {}", name,
                                       names.empty() ? "(none)" : names),
                           field);
                continue;
            }
            const auto size = static_cast<std::size_t>(component_count(p->type));
            if (value.size() != size) {
                ok = false;
                diag.error(fmt::format("{} is a {}: expected {} number{}, got {}", name, type_name(p->type), size,
                                       size == 1 ? "" : "s", value.size()),
                           field);
                continue;
            }
            for (double x : value)
                if ((p->min && x < *p->min) || (p->max && x > *p->max)) {
                    ok = false;
                    diag.error(fmt::format("{} = {} is outside its range [{}, {}]", name, x, p->min.value_or(-1e300),
                                           p->max.value_or(1e300)),
                               field);
                    break;
                }
        }
    return ok;
}

Constant keyed_param_value(const ManifestParam& param, const std::vector<double>& value) {
    Constant c = param.value;
    for (std::size_t i = 0; i < value.size() && i < 4; ++i) {
        double x = value[i];
        if (param.min) x = std::max(x, *param.min);
        if (param.max) x = std::min(x, *param.max);
        c.v[i] = x;
    }
    return c;
}

}  // namespace fg
