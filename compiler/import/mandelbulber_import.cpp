#include "mandelbulber_import.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <functional>
#include <set>

#include "mandelbulber_formulas.h"
#include "mandelbulber_primitives.h"

namespace fg {

namespace {

using json = nlohmann::ordered_json;

constexpr int kSlots = 9;   // Mandelbulber's formula slots, [fractal_1] to [fractal_9]

// Mandelbulber's z is up, the graph's y: (x, y, z) there is (x, z, -y) here (both right-handed).
json to_graph(const glm::dvec3& v) { return json::array({v.x, v.z, -v.y}); }

// Mandelbulber 2.10 and older (legacy_coordinate_system) drew with the picture's vertical axis
// reversed: what the same numbers give now, flipped top to bottom (measured against its renders).
// That flip is the world mirrored in y, y -> -y, seen with the camera's top reversed; every
// imported formula is symmetric under the mirror (the bulb's phi -> -phi, the folds'), so only the
// camera and a Julia constant move.
glm::dvec3 mirror_y(glm::dvec3 v) { return {v.x, -v.y, v.z}; }

bool is_equirectangular(const std::string& t) { return t == "equirectangular" || fract_number(t) == 2.0; }

// Main settings that change the shape and are imported only at the value that leaves it alone.
struct ShapeSetting {
    std::string key;
    std::function<bool(const std::string&)> neutral;
    const char* what;
};

std::vector<ShapeSetting> shape_settings() {
    auto number = [](double x) { return [x](const std::string& t) { return fract_number(t) == x; }; };
    auto vector = [](double x) { return [x](const std::string& t) { return fract_vector(t) == glm::dvec3(x); }; };
    auto text = [](const char* v) { return [v](const std::string& t) { return t == v; }; };
    std::vector<ShapeSetting> out{
        {"perspective_type", [](const std::string& t) { return fract_number(t) == 0.0 || is_equirectangular(t); },
         "only the three-point perspective and the equirectangular panorama are imported"},
        {"boolean_operators", text("false"), "boolean combinations of formulas"},
        {"fractal_constant_factor", [](const std::string& t) { auto v = fract_vector(t); return v && v->x == v->y && v->y == v->z; },
         "c scaled unevenly"},
        {"fractal_position", vector(0.0), "a moved fractal"},
        {"fractal_rotation", vector(0.0), "a rotated fractal"},
        {"repeat", vector(0.0), "repetition of space"},
        {"interior_mode", text("false"), "the interior mode"},
        {"box_folding", text("false"), "a box fold before every formula"},
        {"spherical_folding", text("false"), "a sphere fold before every formula"},
        {"limit_outer_bounding", number(100.0), "a nearer outer bound"},
        {"minN", number(1.0), "a least iteration count"},
    };
    for (int i = 1; i <= kSlots; ++i) {
        out.push_back({fmt::format("formula_position_{}", i), vector(0.0), "a moved formula"});
        out.push_back({fmt::format("formula_rotation_{}", i), vector(0.0), "a rotated formula"});
        out.push_back({fmt::format("formula_repeat_{}", i), vector(0.0), "a repeated formula"});
        out.push_back({fmt::format("formula_scale_{}", i), number(1.0), "a scaled formula"});
        out.push_back({fmt::format("formula_weight_{}", i), number(1.0), "a weighted formula"});
    }
    return out;
}

// Main settings read below; everything else of [main_parameters] is the look (or bookkeeping).
const std::set<std::string>& read_settings() {
    static const std::set<std::string> keys = [] {
        std::set<std::string> k{"camera", "target", "camera_top", "fov", "N", "bailout", "use_default_bailout", "DE_factor",
                                "detail_level", "julia_mode", "julia_c", "hybrid_fractal_enable", "repeat_from",
                                "legacy_coordinate_system", "fractal_constant_factor", "limits_enabled", "limit_min",
                                "limit_max", "view_distance_max", "linear_DE_offset", "initial_waxis", "iteration_threshold_mode", "perspective_type",
                                "all_primitives_position", "all_primitives_rotation",
                                // Derived from camera and target, or the image's own size.
                                "camera_rotation", "camera_distance_to_target", "image_width", "image_height"};
        for (int i = 1; i <= kSlots; ++i)
            for (const char* base : {"formula_", "formula_iterations_", "fractal_enable_", "dont_add_c_constant_",
                                     "formula_start_iteration_", "formula_stop_iteration_", "check_for_bailout_"})
                k.insert(fmt::format("{}{}", base, i));
        return k;
    }();
    return keys;
}

class Importer {
public:
    Importer(const FractSettings& s, Diagnostics& diag) : s_(s), diag_(diag) {}

    // A value of [main_parameters] read by `parse`, or the fallback when it is absent; an error
    // naming the line when it is not `kind`.
    template <typename T>
    T read(const std::string& key, T fallback, std::optional<T> (*parse)(const std::string&), const char* kind) {
        const FractValue* v = s_.find(key);
        if (!v) return fallback;
        if (auto x = parse(v->text)) return *x;
        error(*v, key, fmt::format("'{}' is not {}", v->text, kind));
        return fallback;
    }
    double number(const std::string& key, double fallback) { return read(key, fallback, fract_number, "a number"); }
    glm::dvec3 vector(const std::string& key, glm::dvec3 fallback) { return read(key, fallback, fract_vector, "three numbers"); }
    bool flag(const std::string& key, bool fallback) { return read(key, fallback, fract_bool, "true or false"); }
    void error(const FractValue& v, const std::string& key, const std::string& why) {
        diag_.error(fmt::format("line {}: {}: {}", v.line, key, why));
    }

    std::optional<json> run(const std::string& name) {
        for (const auto& setting : shape_settings())
            if (const FractValue* v = s_.find(setting.key); v && !setting.neutral(v->text))
                error(*v, setting.key, fmt::format("{} is not imported ({})", v->text, setting.what));
        json formula = formula_body();
        json scene = camera();
        const int iterations = static_cast<int>(std::lround(number("N", 250.0)));
        json inputs{{"iterations", std::clamp(iterations, 1, 256)}, {"bailout", bailout_}, {"bias", 1.0}};
        if (flag("julia_mode", false)) {
            const json c = to_graph(world(vector("julia_c", glm::dvec3(0.0))));
            inputs["c"] = json::array({c[0], c[1], c[2], 0.0});
            formula["julia"] = true;
        }
        if (four_d_ && number("initial_waxis", 0.0) != 0.0) inputs["w"] = number("initial_waxis", 0.0);
        const double step = number("DE_factor", 1.0), detail = number("detail_level", 1.0);
        scene["max_distance"] = std::clamp(number("view_distance_max", 50.0), 1e-6, 1e9);
        // Mandelbulber bounds every fractal by a sphere of radius 100 about the origin
        // (limit_outer_bounding); the graph's default of 4 would cut a scale-2 Mandelbox.
        scene["bounds"] = {{"center", {0.0, 0.0, 0.0}}, {"radius", 100.0}};
        if (diag_.has_errors()) return std::nullopt;
        warn_looks();
        if (iterations > 256) diag_.warning(fmt::format("N {}: imported as 256 iterations, the formula node's most", iterations));
        // Mandelbulber's DE_factor shortens its steps only: the scene's step_fraction does the same
        // (step_factor would also scale the distance the hit test reads, and fatten the surface).
        if (step < 1.0) scene["step_fraction"] = std::max(step, 0.01);
        if (step < 0.01)
            diag_.warning(fmt::format("DE_factor {:g}: imported as a step fraction of 0.01, the least a graph takes", step));
        if (step > 1.0)
            diag_.warning(fmt::format("DE_factor {:g}: not imported; a step longer than the estimate would skip surfaces, "
                                      "so the graph steps the whole estimate (fgc calibrate makes that safe)", step));
        // A panorama is how fgplay renders, not part of the scene.
        if (const FractValue* v = s_.find("perspective_type"); v && is_equirectangular(v->text))
            diag_.warning(fmt::format("line {}: perspective_type {}: render the panorama with fgplay render --path PATH "
                                      "--projection equirect (the graph's camera is a perspective one)", v->line, v->text));
        if (detail != 1.0)
            diag_.warning(fmt::format("detail_level {:g}: the hit threshold is the renderer's; render with fgplay --detail {:g}", detail, detail));
        json nodes = json::array({
            {{"id", "fractal"}, {"type", "fractal.formula"}, {"inputs", inputs}, {"formula", formula}},
            {{"id", "trap"}, {"type", "math.split4"}, {"inputs", {{"v", "fractal.trap"}}}},
            {{"id", "tone"}, {"type", "math.scale"}, {"inputs", {{"v", "trap.w"}, {"s", 0.5}}}},
            {{"id", "palette"}, {"type", "palette.cosine"}, {"inputs", {{"t", "tone"}, {"a", {0.55, 0.5, 0.45}}, {"b", {0.35, 0.3, 0.25}},
                                                                        {"c", {1.0, 1.0, 1.0}}, {"d", {0.0, 0.1, 0.2}}}}},
            {{"id", "light"}, {"type", "light.fake_diffuse"}, {"inputs", json::object()}},
            {{"id", "occlusion"}, {"type", "light.fake_ao"}, {"inputs", json::object()}}});
        if (native_) {
            // The formula runs in Mandelbulber's axes: it takes the point turned into them.
            nodes.push_back({{"id", "z_up"}, {"type", "xform.rotate"}, {"inputs", {{"axis", {1.0, 0.0, 0.0}}, {"angle_deg", -90.0}}}});
            nodes[0]["inputs"]["p"] = "z_up.p";
        }
        std::string distance = "fractal.distance";
        if (flag("limits_enabled", false)) {
            // Cut by the box of limit_min and limit_max: the intersection with it.
            const glm::dvec3 lo = world(vector("limit_min", glm::dvec3(-10.0))), hi = world(vector("limit_max", glm::dvec3(10.0)));
            const json centre = to_graph(0.5 * (lo + hi)), half = to_graph(0.5 * glm::abs(hi - lo));
            nodes.push_back({{"id", "limits_at"}, {"type", "xform.translate"}, {"inputs", {{"offset", centre}}}});
            nodes.push_back({{"id", "limits"}, {"type", "prim.box"},
                             {"inputs", {{"p", "limits_at.p"}, {"size", {std::abs(half[0].get<double>()), std::abs(half[1].get<double>()),
                                                                        std::abs(half[2].get<double>())}}}}});
            nodes.push_back({{"id", "cut"}, {"type", "op.intersect"}, {"inputs", {{"a", "fractal.distance"}, {"b", "limits.distance"}}}});
            distance = "cut.distance";
        }
        distance = import_primitives(s_, nodes, distance, diag_);
        if (diag_.has_errors()) return std::nullopt;
        return json{
            {"format", "fractograph-graph"},
            {"version", 1},
            {"name", name},
            {"description", fmt::format("Imported from a Mandelbulber settings file: {}.", description_)},
            {"nodes", nodes},
            {"outputs", {{"distance", distance}, {"albedo", "palette.color"}, {"diffuse", "light.diffuse"}, {"ao", "occlusion.ao"}}},
            {"scene", scene}};
    }

private:
    // The formula, or the hybrid: every enabled slot in order, each for its iteration count, over
    // and over.
    // One slot of the sequence: its group, how many iterations in a row, and the iterations it
    // may act on (Mandelbulber skips it outside them: the iteration leaves z as it is).
    struct Slot {
        std::string group;
        int count = 1, start = 0, stop = 0;
    };

    json formula_body() {
        const bool hybrid = flag("hybrid_fractal_enable", false);
        const int iterations = static_cast<int>(std::lround(number("N", 250.0)));
        json groups = json::array();
        std::vector<std::string> names;
        std::vector<Slot> slots;
        for (int slot = 1; slot <= (hybrid ? kSlots : 1); ++slot) {
            const int number = static_cast<int>(std::lround(this->number(fmt::format("formula_{}", slot), slot == 1 ? 2.0 : 0.0)));
            if (number == 0 || !flag(fmt::format("fractal_enable_{}", slot), true)) continue;
            const AddC c{flag(fmt::format("dont_add_c_constant_{}", slot), false), vector("fractal_constant_factor", glm::dvec3(1.0)).x};
            auto f = import_formula(number, slot, c, s_, diag_);
            if (!f) continue;
            const std::string group = fmt::format("slot{}_{}", slot, f->name);
            groups.push_back({{"name", group}, {"nodes", f->nodes}});
            auto integer = [&](const char* base, double fallback) {
                return static_cast<int>(std::lround(this->number(fmt::format("{}{}", base, slot), fallback)));
            };
            slots.push_back({group, hybrid ? std::max(integer("formula_iterations_", 1.0), 1) : 1,
                             integer("formula_start_iteration_", 0.0), integer("formula_stop_iteration_", 250.0)});
            names.push_back(slots.back().count > 1 ? fmt::format("{} x{}", f->name, slots.back().count) : f->name);
            bailout_ = std::max(bailout_, f->bailout);
            (f->four_d ? four_d_ : three_d_) = true;
            (f->native_axes ? native_ : graph_axes_) = true;
            if (f->sheet_radius > 0.0) sheet_radius_ = f->sheet_radius;
            bound_radius_ = f->bound_radius;
            // A power map's logarithmic estimate wins in a hybrid; else the first formula's.
            if (estimate_.empty() || f->estimate == "log") estimate_ = f->estimate;
            if (names.size() == 1) linear_radius_ = f->linear_radius;
        }
        if (!flag("use_default_bailout", true)) bailout_ = number("bailout", 100.0);
        if (hybrid) {
            // A single formula always tests the bailout; in a hybrid a slot may skip the test after it.
            for (int slot = 1; slot <= kSlots; ++slot)
                if (const FractValue* v = s_.find(fmt::format("check_for_bailout_{}", slot)); v && v->text != "true")
                    error(*v, fmt::format("check_for_bailout_{}", slot), fmt::format("{} is not imported (a formula that skips the bailout test)", v->text));
            if (const FractValue* v = s_.find("repeat_from"); v && fract_number(v->text) != 1.0)
                error(*v, "repeat_from", fmt::format("{} is not imported (the hybrid repeats from its first formula)", v->text));
            description_ = "the hybrid " + fmt::format("{}", fmt::join(names, ", then ")) + ", repeated";
        } else if (!names.empty()) {
            description_ = "the " + names.front();
        }
        if (groups.empty() && !diag_.has_errors()) diag_.error("no formula enabled in any slot");
        if (four_d_ && three_d_) diag_.error("a hybrid of 3D and four-dimensional formulas is not imported (one orbit is 3D or 4D)");
        if (native_ && graph_axes_) diag_.error("a pseudo-Kleinian in a hybrid with other formulas is not imported");
        if (const FractValue* v = s_.find("initial_waxis"); v && !four_d_ && fract_number(v->text) != 0.0)
            error(*v, "initial_waxis", fmt::format("{} is not imported (a four-dimensional start of a 3D formula)", v->text));
        // A hybrid's linear estimate is (|z| - linear_DE_offset) / dr, whatever its formulas'.
        if (hybrid) linear_radius_ = number("linear_DE_offset", 0.0);
        json body{{"groups", groups}, {"estimate", estimate_}};
        if (estimate_ == "linear" && linear_radius_ != 0.0) body["linear_radius"] = linear_radius_;
        if (estimate_ == "sheet") body["sheet_radius"] = sheet_radius_;
        // Far away the logarithmic estimate overshoots the set; a lone power map's ball caps it.
        if (!hybrid && slots.size() == 1 && bound_radius_ > 0.0) body["bound_radius"] = bound_radius_;
        // The ray stops where the orbit stays within the bailout for all N iterations.
        if (flag("iteration_threshold_mode", false)) body["filled"] = true;
        const bool windows = std::any_of(slots.begin(), slots.end(), [&](const Slot& s) { return s.start > 0 || s.stop < iterations - 1; });
        if (windows && !slots.empty()) {
            body["schedule"] = windowed_schedule(slots, iterations);
        } else if (hybrid) {
            json schedule = json::array();
            for (const auto& slot : slots) schedule.push_back({{"group", slot.group}, {"count", slot.count}});
            body["schedule"] = schedule;
            body["repeat"] = true;
        }
        return body;
    }

    // The sequence written out iteration by iteration, each slot kept only inside its window, as
    // runs of one group; the last run takes every iteration left.
    json windowed_schedule(const std::vector<Slot>& slots, int iterations) {
        std::vector<const Slot*> sequence;
        for (const auto& slot : slots) sequence.insert(sequence.end(), static_cast<std::size_t>(slot.count), &slot);
        json runs = json::array();
        const Slot* last = nullptr;
        int last_used = -1;
        for (int i = 0; i < iterations; ++i) {
            const Slot* slot = sequence[static_cast<std::size_t>(i) % sequence.size()];
            if (i < slot->start || i > slot->stop) continue;
            last_used = i;
            if (slot == last) {
                runs.back()["count"] = runs.back()["count"].get<int>() + 1;
            } else {
                runs.push_back({{"group", slot->group}, {"count", 1}});
                last = slot;
            }
        }
        if (runs.empty()) {
            diag_.error("formula_start_iteration and formula_stop_iteration leave no iteration to any formula");
            return runs;
        }
        constexpr std::size_t kMaxRuns = 16;
        if (runs.size() > kMaxRuns) {
            diag_.error(fmt::format("formula_start_iteration and formula_stop_iteration make the sequence {} runs of one formula; "
                                    "at most {} are imported", runs.size(), kMaxRuns));
            return runs;
        }
        // A last run that reaches the last iteration takes every iteration left (the node's
        // iteration knob may give more or fewer than N).
        if (last_used == iterations - 1) runs.back()["count"] = 0;
        return runs;
    }

    glm::dvec3 world(glm::dvec3 v) { return flag("legacy_coordinate_system", false) ? mirror_y(v) : v; }

    json camera() {
        const glm::dvec3 position = world(vector("camera", {3.0, -6.0, 2.0})), target = world(vector("target", glm::dvec3(0.0)));
        glm::dvec3 top = world(vector("camera_top", {-0.1277753, 0.2555506, 0.958314}));
        if (flag("legacy_coordinate_system", false)) top = -top;
        const double fov = number("fov", 1.0);
        const double degrees = 2.0 * std::atan(0.5 * fov) * 180.0 / 3.14159265358979323846;
        if (degrees < 10.0 || degrees > 170.0)
            if (const FractValue* v = s_.find("fov")) error(*v, "fov", fmt::format("{} is a view of {:.1f} degrees; 10 to 170 are imported", v->text, degrees));
        return json{{"camera", {{"position", to_graph(position)}, {"target", to_graph(target)}, {"up", to_graph(top)},
                                {"fov_deg", std::clamp(degrees, 10.0, 170.0)}}}};
    }

    void warn_looks() {
        std::vector<std::string> looks;
        std::set<std::string> shape;
        for (const auto& setting : shape_settings()) shape.insert(setting.key);
        for (const auto& [key, value] : *s_.section("main_parameters"))
            if (!read_settings().count(key) && !shape.count(key) && !key.starts_with("primitive_")) looks.push_back(key);
        if (!looks.empty())
            diag_.warning(fmt::format("{} settings of the look are not imported (the graph gets a palette by orbit trap, "
                                      "fake diffuse light and ambient occlusion): {}", looks.size(), fmt::join(looks, ", ")));
    }

    const FractSettings& s_;
    Diagnostics& diag_;
    double bailout_ = 0.0, linear_radius_ = 0.0;
    bool four_d_ = false, three_d_ = false, native_ = false, graph_axes_ = false;
    double sheet_radius_ = 1.0, bound_radius_ = 0.0;
    std::string description_, estimate_;
};

}  // namespace

std::optional<nlohmann::ordered_json> import_mandelbulber(const FractSettings& settings, const std::string& name, Diagnostics& diag) {
    return Importer(settings, diag).run(name);
}

}  // namespace fg
