#include "mandelbulber_primitives.h"

#include <fmt/format.h>
#include <regex>

#include "mandelbulber_axes.h"

namespace fg {

namespace {

using json = nlohmann::ordered_json;

json array(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

// One primitive's settings, read with the defaults Mandelbulber gives them.
class PrimitiveReader {
public:
    PrimitiveReader(const FractSettings& s, std::string name, Diagnostics& diag) : s_(s), name_(std::move(name)), diag_(diag) {}

    const FractValue* find(const std::string& key) const { return s_.find(name_ + "_" + key); }
    double number(const std::string& key, double fallback) { return read(key, fallback, fract_number, "a number"); }
    glm::dvec3 vector(const std::string& key, glm::dvec3 fallback) { return read(key, fallback, fract_vector, "three numbers"); }
    void only(const std::string& key, const char* neutral, const char* what) {
        if (const FractValue* v = find(key); v && v->text != neutral)
            fail(*v, key, fmt::format("{} is not imported ({})", v->text, what));
    }
    void fail(const FractValue& v, const std::string& key, const std::string& why) {
        diag_.error(fmt::format("line {}: {}_{}: {}", v.line, name_, key, why));
        ok_ = false;
    }
    bool ok() const { return ok_; }

private:
    template <typename T>
    T read(const std::string& key, T fallback, std::optional<T> (*parse)(const std::string&), const char* kind) {
        const FractValue* v = find(key);
        if (!v) return fallback;
        if (auto x = parse(v->text)) return *x;
        fail(*v, key, fmt::format("'{}' is not {}", v->text, kind));
        return fallback;
    }

    const FractSettings& s_;
    std::string name_;
    Diagnostics& diag_;
    bool ok_ = true;
};

bool is_zero_vector(const FractValue* v) { return !v || fract_vector(v->text) == glm::dvec3(0.0); }

}  // namespace

std::string import_primitives(const FractSettings& settings, json& nodes, const std::string& distance, Diagnostics& diag) {
    static const std::regex enabled_key(R"(primitive_([a-z]+)_(\d+)_enabled)");
    std::string out = distance;
    for (const auto& [key, value] : *settings.section("main_parameters")) {
        std::smatch m;
        if (!std::regex_match(key, m, enabled_key) || value.text != "true") continue;
        const std::string type = m[1], name = fmt::format("primitive_{}_{}", m[1].str(), m[2].str());
        if (type != "sphere" && type != "box" && type != "plane" && type != "torus") {
            diag.error(fmt::format("line {}: {}: a {} primitive is not imported (only spheres, boxes, planes and tori are)", value.line, key, type));
            continue;
        }
        PrimitiveReader r(settings, name, diag);
        r.only("empty", "false", "a hollow primitive");
        if (!is_zero_vector(r.find("repeat"))) r.only("repeat", "0 0 0", "a repeated primitive");
        r.only("boolean_operator", "0", "primitives join the fractal by a union");
        r.only("smooth_de_combine_enable", "false", "a smooth union");
        const glm::dvec3 position = r.vector("position", glm::dvec3(0.0)), angles = r.vector("rotation", glm::dvec3(0.0));
        if (!r.ok()) continue;
        // The shape sees the point moved to its position and turned by its rotation (Rz Ry Rx).
        const std::string id = name.substr(10);   // "sphere_1"
        std::string p = "position";
        if (position != glm::dvec3(0.0)) {
            nodes.push_back({{"id", id + "_at"}, {"type", "xform.translate"}, {"inputs", {{"offset", array(to_graph_axes(position))}}}});
            p = id + "_at.p";
        }
        if (const AxisAngle turn = graph_axis_angle(rotation_zyx(angles.z, angles.y, angles.x)); turn.degrees != 0.0 && type != "sphere") {
            // xform.rotate turns the shape by its angle: the point is turned back, by -angle.
            nodes.push_back({{"id", id + "_turn"}, {"type", "xform.rotate"},
                             {"inputs", {{"p", p}, {"axis", array(turn.axis)}, {"angle_deg", -turn.degrees}}}});
            p = id + "_turn.p";
        }
        json inputs{{"p", p}};
        std::string prim;
        if (type == "sphere") {
            prim = "prim.sphere";
            inputs["radius"] = r.number("radius", 1.0);
        } else if (type == "box") {
            // Mandelbulber's box: full sizes along its axes, rounded outwards by `rounding`.
            prim = "prim.box";
            const glm::dvec3 size = r.vector("size", glm::dvec3(1.0));
            const double rounding = r.number("rounding", 0.0);
            inputs["size"] = array(glm::abs(to_graph_axes(size)) * 0.5 + rounding);
            inputs["rounding"] = rounding;
        } else if (type == "plane") {
            prim = "prim.plane";   // its z = 0, facing +z: the graph's y
            inputs["normal"] = {0.0, 1.0, 0.0};
        } else {
            prim = "prim.torus";   // the ring in its xy plane, about z: the graph's y
            inputs["major"] = r.number("radius", 1.0);
            inputs["minor"] = r.number("tube_radius", 0.2);
            r.only("radius_lpow", "1", "a torus of another norm");
            r.only("tube_radius_lpow", "1", "a torus of another norm");
        }
        if (!r.ok()) continue;
        nodes.push_back({{"id", id}, {"type", prim}, {"inputs", inputs}});
        nodes.push_back({{"id", id + "_joined"}, {"type", "op.union"}, {"inputs", {{"a", out}, {"b", id + ".distance"}}}});
        out = id + "_joined.distance";
    }
    for (const char* key : {"all_primitives_position", "all_primitives_rotation"})
        if (const FractValue* v = settings.find(key); !is_zero_vector(v))
            diag.error(fmt::format("line {}: {}: {} is not imported (primitives moved together)", v->line, key, v->text));
    return out;
}

}  // namespace fg
