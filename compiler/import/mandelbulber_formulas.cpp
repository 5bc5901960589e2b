#include "mandelbulber_formulas.h"

#include <fmt/format.h>
#include <functional>
#include <map>

namespace fg {

namespace {

using json = nlohmann::ordered_json;

// The settings of one formula's slot: its values with their defaults, and the settings whose
// non-default values change the shape in ways no stage here draws.
class SlotReader {
public:
    SlotReader(int number, std::string formula, int slot, const FractSettings& s, Diagnostics& diag)
        : number_(number), formula_(std::move(formula)), section_(fmt::format("fractal_{}", slot)), settings_(s), diag_(diag) {}

    double number(const std::string& key, double fallback) {
        const FractValue* v = settings_.find(key, section_);
        if (!v) return fallback;
        if (auto x = fract_number(v->text)) return *x;
        fail(*v, key, fmt::format("'{}' is not a number", v->text));
        return fallback;
    }

    // A setting this formula reads but that is imported only at its default.
    void only_default(const std::string& key, const std::function<bool(const std::string&)>& is_default, const std::string& what) {
        const FractValue* v = settings_.find(key, section_);
        if (v && !is_default(v->text)) fail(*v, key, fmt::format("{} {} is not imported ({})", key, v->text, what));
    }

    bool ok() const { return ok_; }

private:
    void fail(const FractValue& v, const std::string& key, const std::string& why) {
        diag_.error(fmt::format("line {}: [{}] {}: formula {} ({}): {}", v.line, section_, key, number_, formula_, why));
        ok_ = false;
    }

    int number_;
    std::string formula_, section_;
    const FractSettings& settings_;
    Diagnostics& diag_;
    bool ok_ = true;
};

bool is_false(const std::string& t) { return t == "false"; }
auto is_number(double x) {
    return [x](const std::string& t) { return fract_number(t) == x; };
}
bool is_zero_vector(const std::string& t) { return fract_vector(t) == glm::dvec3(0.0); }

json stage(const std::string& id, const std::string& type, json inputs = json::object()) {
    return json{{"id", id}, {"type", type}, {"inputs", std::move(inputs)}};
}

// + c as the slot adds it, after the stage `last`.
void add_c(json& nodes, const std::string& last, const AddC& c) {
    if (c.enabled) nodes.push_back(stage("add", "stage.add_c", {{"z", last}, {"weight", c.weight}}));
}

// Mandelbulber 2's formula 2: z -> z^power with theta the elevation above the xy plane (its z is
// up), then + c.
std::optional<ImportedFormula> mandelbulb(int slot, const AddC& c, const FractSettings& s, Diagnostics& diag) {
    SlotReader r(2, "mandelbulb", slot, s, diag);
    const double power = r.number("power", 9.0);
    r.only_default("alpha_angle_offset", is_number(0.0), "an angle offset turns the bulb's lobes");
    r.only_default("beta_angle_offset", is_number(0.0), "an angle offset turns the bulb's lobes");
    if (!r.ok()) return std::nullopt;
    json nodes = json::array({stage("power", "stage.triplex_power_elevation", {{"power", power}})});
    add_c(nodes, "power", c);
    return ImportedFormula{"mandelbulb", nodes, 10.0, "log"};
}

// Formula 3: the power-2 bulb, ((x^2 - y^2)(1 - z^2 / rho^2), 2xy(1 - z^2 / rho^2), 2 z rho) + c with
// rho^2 = x^2 + y^2: the elevation-angle power of 2, written out (the sign of its z term mirrors the
// set in z, under which it is symmetric).
std::optional<ImportedFormula> mandelbulb_power2(int, const AddC& c, const FractSettings&, Diagnostics&) {
    json nodes = json::array({stage("power", "stage.triplex_power_elevation", {{"power", 2.0}})});
    add_c(nodes, "power", c);
    return ImportedFormula{"mandelbulb_power2", nodes, 10.0, "log"};
}

// Formula 8: box fold, sphere fold, scale, + c.
std::optional<ImportedFormula> mandelbox(int slot, const AddC& c, const FractSettings& s, Diagnostics& diag) {
    SlotReader r(8, "mandelbox", slot, s, diag);
    const double scale = r.number("mandelbox_scale", 2.0);
    const double limit = r.number("mandelbox_folding_limit", 1.0);
    double min_radius = r.number("mandelbox_folding_min_radius", 0.5);
    const double fixed_radius = r.number("mandelbox_folding_fixed_radius", 1.0);
    r.only_default("mandelbox_folding_value", is_number(2.0), "the fold reflects about the limit, value 2");
    r.only_default("mandelbox_rotations_enabled", is_false, "the per-plane fold rotations");
    r.only_default("mandelbox_main_rotation_enabled", is_false, "the rotation of every iteration");
    r.only_default("mandelbox_offset", is_zero_vector, "the sphere fold about another centre");
    if (!r.ok()) return std::nullopt;
    if (min_radius < 0.01) {
        diag.warning(fmt::format("[fractal_{}] mandelbox_folding_min_radius {:g}: imported as 0.01, the sphere fold's least "
                                 "(it changes the shape only within 0.01 of the fold's centre)", slot, min_radius));
        min_radius = 0.01;
    }
    json nodes = json::array({stage("fold", "stage.box_fold", {{"limit", limit}}),
                              stage("sphere", "stage.sphere_fold", {{"z", "fold"}, {"min_radius", min_radius}, {"fixed_radius", fixed_radius}}),
                              stage("scale", "stage.scale", {{"z", "sphere"}, {"scale", scale}})});
    add_c(nodes, "scale", c);
    return ImportedFormula{"mandelbox", nodes, 100.0, "linear"};
}

// Formula 7: |z|, sort the coordinates, scale by 3 about the corner (1, 1, 1); the distance to the
// unit cube over the running derivative (its render has the cube's sharp corners).
std::optional<ImportedFormula> menger(int, const AddC&, const FractSettings&, Diagnostics&) {
    return ImportedFormula{"menger_sponge", json::array({stage("abs", "stage.abs_fold"),
                                                        stage("sort", "stage.menger_fold", {{"z", "abs"}}),
                                                        stage("scale", "stage.menger_scale", {{"z", "sort"}, {"scale", 3.0}, {"offset", {1.0, 1.0, 1.0}}})}),
                           10.0, "box"};
}

using Importer = std::optional<ImportedFormula> (*)(int, const AddC&, const FractSettings&, Diagnostics&);

// Node ids are unique over the whole formula, so each slot's carry its prefix.
void prefix_ids(json& nodes, const std::string& prefix) {
    for (auto& n : nodes) {
        n["id"] = prefix + n["id"].get<std::string>();
        for (auto& [name, value] : n["inputs"].items())
            if (name == "z" && value.is_string()) value = prefix + value.get<std::string>();
    }
}
const std::map<int, std::pair<const char*, Importer>>& importers() {
    static const std::map<int, std::pair<const char*, Importer>> table{
        {2, {"mandelbulb", mandelbulb}}, {3, {"mandelbulb_power2", mandelbulb_power2}}, {7, {"menger_sponge", menger}},
        {8, {"mandelbox", mandelbox}}};
    return table;
}

}  // namespace

std::optional<ImportedFormula> import_formula(int number, int slot, const AddC& add_c, const FractSettings& settings,
                                              Diagnostics& diag) {
    auto it = importers().find(number);
    if (it == importers().end()) {
        const FractValue* v = settings.find(fmt::format("formula_{}", slot));
        diag.error(fmt::format("{}formula_{} {}: this formula is not imported (imported: {})",
                               v ? fmt::format("line {}: ", v->line) : "", slot, number, imported_formula_list()));
        return std::nullopt;
    }
    auto f = it->second.second(slot, add_c, settings, diag);
    if (f) prefix_ids(f->nodes, fmt::format("s{}_", slot));
    return f;
}

std::string imported_formula_list() {
    std::string out;
    for (const auto& [number, entry] : importers()) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", number, entry.first);
    return out;
}

}  // namespace fg
