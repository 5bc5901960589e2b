#include "mandelbulber_formulas.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <map>

#include "mandelbulber_axes.h"

namespace fg {

namespace {

using json = nlohmann::ordered_json;

// The settings of one formula's slot: its values with their defaults, and the settings whose
// non-default values change the shape in ways no stage here draws.
class SlotReader {
public:
    SlotReader(int number, std::string formula, int slot, const FractSettings& s, Diagnostics& diag)
        : number_(number), formula_(std::move(formula)), section_(fmt::format("fractal_{}", slot)), settings_(s), diag_(diag) {}

    double number(const std::string& key, double fallback) { return read(key, fallback, fract_number, "a number"); }
    glm::dvec3 vector(const std::string& key, glm::dvec3 fallback) { return read(key, fallback, fract_vector, "three numbers"); }
    bool flag(const std::string& key, bool fallback) { return read(key, fallback, fract_bool, "true or false"); }
    // A value this formula cannot draw, named with its line.
    void refuse(const std::string& key, const std::string& why) {
        if (const FractValue* v = settings_.find(key, section_)) fail(*v, key, why);
    }

    // A setting this formula reads but that is imported only at its default.
    void only_default(const std::string& key, const std::function<bool(const std::string&)>& is_default, const std::string& what) {
        const FractValue* v = settings_.find(key, section_);
        if (v && !is_default(v->text)) fail(*v, key, fmt::format("{} {} is not imported ({})", key, v->text, what));
    }

    bool ok() const { return ok_; }

private:
    // The slot's value read by `parse`, or the fallback when it is absent; an error naming the line
    // when it is not `kind`.
    template <typename T>
    T read(const std::string& key, T fallback, std::optional<T> (*parse)(const std::string&), const char* kind) {
        const FractValue* v = settings_.find(key, section_);
        if (!v) return fallback;
        if (auto x = parse(v->text)) return *x;
        fail(*v, key, fmt::format("'{}' is not {}", v->text, kind));
        return fallback;
    }
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
json array(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

// A body's stages in order, each taking the last one's z. Vectors and turns are given in
// Mandelbulber's axes and written in the graph's, or, between enter_ and leave_mandelbulber_axes,
// as they are: there z itself is in Mandelbulber's axes, for formulas that are not symmetric
// under the change (an abs of its y is not one of the graph's z).
class Chain {
public:
    void add(const std::string& id, const std::string& type, json inputs = json::object()) {
        if (!last_.empty()) inputs["z"] = last_;
        nodes_.push_back(stage(id, type, std::move(inputs)));
        last_ = id;
    }
    // A quarter turn about x takes the graph's (x, y, z) to Mandelbulber's (x, -z, y); without
    // `turn_z` the formula's point is in Mandelbulber's axes already (ImportedFormula::native_axes).
    void enter_mandelbulber_axes(bool turn_z = true) {
        if (turn_z) add("to_z_up", "stage.rotate", {{"axis", {1.0, 0.0, 0.0}}, {"angle_deg", 90.0}});
        native_ = true;
    }
    void leave_mandelbulber_axes() {
        add("from_z_up", "stage.rotate", {{"axis", {1.0, 0.0, 0.0}}, {"angle_deg", -90.0}});
        native_ = false;
    }
    // A turn given about Mandelbulber's axes (none for the identity).
    void rotate(const std::string& id, const glm::dmat3& rotation) {
        const AxisAngle turn = native_ ? axis_angle(rotation) : graph_axis_angle(rotation);
        if (turn.degrees != 0.0) add(id, "stage.rotate", {{"axis", array(turn.axis)}, {"angle_deg", turn.degrees}});
    }
    // A reflection that keeps the side of Mandelbulber's plane dot(z, normal) >= distance.
    void plane_fold(const std::string& id, const glm::dvec3& normal, double distance) {
        add(id, "stage.plane_fold", {{"normal", array(axes(normal))}, {"distance", distance}});
    }
    void translate(const std::string& id, const glm::dvec3& offset) {
        if (offset != glm::dvec3(0.0)) add(id, "stage.translate", {{"offset", array(axes(offset))}});
    }
    glm::dvec3 axes(const glm::dvec3& v) const { return native_ ? v : to_graph_axes(v); }
    // + c as the slot adds it: by default unless dont_add_c_constant, or the other way round.
    void add_c(const AddC& c, bool by_default = true) {
        if (c.dont_add_c != by_default) add("add", "stage.add_c", {{"weight", c.weight}});
    }
    json nodes() const { return nodes_; }

private:
    json nodes_ = json::array();
    std::string last_;
    bool native_ = false;
};

// Mandelbulber's rotation settings, three angles in degrees: (x, y, z) for the Mandelbox's turns
// (Rz Ry Rx), (alpha, beta, gamma) for the IFS's (Rz(alpha) Ry(beta) Rx(gamma)).
glm::dmat3 mandelbox_rotation(const glm::dvec3& deg) { return rotation_zyx(deg.z, deg.y, deg.x); }
glm::dmat3 ifs_rotation(const glm::dvec3& deg) { return rotation_zyx(deg.x, deg.y, deg.z); }

// The ball a power map z^n + w c (n >= 2, |z^n| = |z|^n) keeps its set in: once |w c| > 2, every
// iterate grows, so no point beyond 2 / |w| belongs to it (beyond 1 without c).
double power_map_bound(const AddC& c) { return c.dont_add_c ? 2.0 : 2.0 / std::min(1.0, std::max(std::abs(c.weight), 1e-6)); }

// Mandelbulber 2's formula 2: z -> z^power with theta the elevation above the xy plane (its z is
// up), each angle first turned by its offset, then + c. Its angle about z is the graph's about y
// the other way round, so alpha turns the graph's phi by -alpha.
std::optional<ImportedFormula> mandelbulb(int slot, const AddC& c, const FractSettings& s, Diagnostics& diag) {
    SlotReader r(2, "mandelbulb", slot, s, diag);
    const double power = r.number("power", 9.0);
    const double alpha = r.number("alpha_angle_offset", 0.0), beta = r.number("beta_angle_offset", 0.0);
    if (!r.ok()) return std::nullopt;
    Chain body;
    body.add("power", "stage.triplex_power_elevation", {{"power", power}, {"theta_offset_deg", beta}, {"phi_offset_deg", -alpha}});
    body.add_c(c);
    ImportedFormula f{"mandelbulb", body.nodes(), 10.0, "log"};
    if (power >= 2.0) f.bound_radius = power_map_bound(c);
    return f;
}

// Formula 11, Xenodreambuie: the power with the colatitude folded into the upper half (its alpha
// offset turns the colatitude, its beta the angle about z), then + c.
std::optional<ImportedFormula> xenodreambuie(int slot, const AddC& c, const FractSettings& s, Diagnostics& diag) {
    SlotReader r(11, "xenodreambuie", slot, s, diag);
    const double power = r.number("power", 9.0);
    const double alpha = r.number("alpha_angle_offset", 0.0), beta = r.number("beta_angle_offset", 0.0);
    if (!r.ok()) return std::nullopt;
    Chain body;
    body.add("power", "stage.xenodreambuie", {{"power", power}, {"theta_offset_deg", alpha}, {"phi_offset_deg", beta}});
    body.add_c(c);
    ImportedFormula f{"xenodreambuie", body.nodes(), 10.0, "log"};
    if (power >= 2.0) f.bound_radius = power_map_bound(c);
    return f;
}

// Formula 3: the power-2 bulb, ((x^2 - y^2)(1 - z^2 / rho^2), 2xy(1 - z^2 / rho^2), -2 z rho) + c with
// rho^2 = x^2 + y^2: the elevation-angle power of 2 with its z mirrored.
void power2_bulb(Chain& body) {
    body.add("power", "stage.triplex_power_elevation", {{"power", 2.0}});
    body.add("mirror", "stage.scale_axes", {{"scale", {1.0, -1.0, 1.0}}});   // Mandelbulber's z is the graph's y
}
std::optional<ImportedFormula> mandelbulb_power2(int, const AddC& c, const FractSettings&, Diagnostics&) {
    Chain body;
    power2_bulb(body);
    body.add_c(c);
    ImportedFormula f{"mandelbulb_power2", body.nodes(), 10.0, "log"};
    f.bound_radius = power_map_bound(c);
    return f;
}

// Formula 16, Box Fold Bulb Pow 2: a box fold at the folding factor, the sphere fold of radii 0.5
// and 1, a scale by 2, the power-2 bulb, and Mandelbulber's z times the z factor; then + c.
std::optional<ImportedFormula> box_fold_bulb_pow2(int slot, const AddC& c, const FractSettings& s, Diagnostics& diag) {
    SlotReader r(16, "box_fold_bulb_pow2", slot, s, diag);
    const double fold = r.number("boxfold_bulbpow2_folding_factor", 2.0), z_factor = r.number("boxfold_bulbpow2_z_factor", 5.0);
    if (!r.ok()) return std::nullopt;
    Chain body;
    body.add("fold", "stage.box_fold", {{"limit", fold}});
    body.add("sphere", "stage.sphere_fold", {{"min_radius", 0.5}, {"fixed_radius", 1.0}});
    body.add("scale", "stage.scale", {{"scale", 2.0}});
    body.add("power", "stage.triplex_power_elevation", {{"power", 2.0}});
    body.add("stretch", "stage.scale_axes", {{"scale", {1.0, -z_factor, 1.0}}});
    body.add_c(c);
    return ImportedFormula{"box_fold_bulb_pow2", body.nodes(), 10.0, "log"};
}

// Formula 8: box fold, sphere fold, the turn of every iteration, scale, + c. With the per-plane
// rotations each axis folds in two turned frames: beyond +limit along the first frame's axis, else
// beyond -limit along the second's.
std::optional<ImportedFormula> mandelbox(int slot, const AddC& c, const FractSettings& s, Diagnostics& diag) {
    SlotReader r(8, "mandelbox", slot, s, diag);
    const double scale = r.number("mandelbox_scale", 2.0);
    const double limit = r.number("mandelbox_folding_limit", 1.0), value = r.number("mandelbox_folding_value", 2.0);
    double min_radius = r.number("mandelbox_folding_min_radius", 0.5);
    const double fixed_radius = r.number("mandelbox_folding_fixed_radius", 1.0);
    const bool rotations = r.flag("mandelbox_rotations_enabled", false), main_rotation = r.flag("mandelbox_main_rotation_enabled", false);
    const glm::dvec3 main_turn = r.vector("mandelbox_rotation_main", glm::dvec3(0.0));
    if (value != 2.0 * limit)
        r.refuse("mandelbox_folding_value", fmt::format("a fold to {:g} - z beyond {:g} is not a reflection (imported: value = 2 x limit)", value, limit));
    r.only_default("mandelbox_offset", is_zero_vector, "the sphere fold about another centre");
    if (!r.ok()) return std::nullopt;
    if (min_radius < 0.01) {
        diag.warning(fmt::format("[fractal_{}] mandelbox_folding_min_radius {:g}: imported as 0.01, the sphere fold's least "
                                 "(it changes the shape only within 0.01 of the fold's centre)", slot, min_radius));
        min_radius = 0.01;
    }
    Chain body;
    if (rotations) {
        const char* axes = "xyz";
        for (int a = 0; a < 3; ++a) {
            // The fold's frame turns z; its axis a read in the frame is row a of the turn.
            const glm::dmat3 upper = mandelbox_rotation(r.vector(fmt::format("mandelbox_rotation_neg_{}", a + 1), glm::dvec3(0.0)));
            const glm::dmat3 lower = mandelbox_rotation(r.vector(fmt::format("mandelbox_rotation_pos_{}", a + 1), glm::dvec3(0.0)));
            const glm::dvec3 up = glm::transpose(upper)[a], down = glm::transpose(lower)[a];
            body.add(fmt::format("fold_{}", axes[a]), "stage.slab_fold",
                     {{"upper", array(to_graph_axes(up))}, {"lower", array(to_graph_axes(down))}, {"limit", limit}});
        }
    } else {
        body.add("fold", "stage.box_fold", {{"limit", limit}});
    }
    body.add("sphere", "stage.sphere_fold", {{"min_radius", min_radius}, {"fixed_radius", fixed_radius}});
    if (main_rotation) body.rotate("turn", mandelbox_rotation(main_turn));
    body.add("scale", "stage.scale", {{"scale", scale}});
    body.add_c(c);
    if (!r.ok()) return std::nullopt;
    return ImportedFormula{"mandelbox", body.nodes(), 100.0, "linear"};
}

// Formula 7: |z|, sort the coordinates, scale by 3 about the corner (1, 1, 1); the distance to the
// unit cube over the running derivative (its render has the cube's sharp corners).
std::optional<ImportedFormula> menger(int, const AddC&, const FractSettings&, Diagnostics&) {
    Chain body;
    body.add("abs", "stage.abs_fold");
    body.add("sort", "stage.menger_fold");
    body.add("scale", "stage.menger_scale", {{"scale", 3.0}, {"offset", {1.0, 1.0, 1.0}}});
    return ImportedFormula{"menger_sponge", body.nodes(), 10.0, "box"};
}

// Formula 5, Quaternion: z^2 + c with z the quaternion (x, y, z, 0), which stays in 3D. Its
// imaginary y and z are symmetric, so the formula reads the same in the graph's axes.
std::optional<ImportedFormula> quaternion(int, const AddC& c, const FractSettings&, Diagnostics&) {
    Chain body;
    body.add("square", "stage.quaternion_square_3d");
    body.add_c(c);
    ImportedFormula f{"quaternion", body.nodes(), 10.0, "log"};
    f.bound_radius = power_map_bound(c);
    return f;
}

// Formula 4, Hypercomplex: z^2 + c in Mandelbulber's commutative hypercomplex numbers, 4D.
std::optional<ImportedFormula> hypercomplex(int, const AddC& c, const FractSettings&, Diagnostics&) {
    Chain body;
    body.add("square", "stage.hypercomplex_square");
    body.add_c(c);
    ImportedFormula f{"hypercomplex", body.nodes(), 10.0, "log"};
    f.four_d = true;
    return f;
}

// A turn of Mandelbulber's transforms, in the iterations [start, stop): imported only when that
// is every iteration; else an error naming the window.
bool turn_in_every_iteration(SlotReader& r, const FractSettings& s, const std::string& start_key, const std::string& stop_key) {
    r.only_default(start_key, is_number(0.0), "a turn in some iterations only");
    const FractValue* n = s.find("N");
    const double iterations = n ? fract_number(n->text).value_or(250.0) : 250.0;
    if (r.number(stop_key, 250.0) < iterations)
        r.refuse(stop_key, fmt::format("the turn stops before the last iteration ({:g}); a turn in some iterations only is not imported", iterations));
    return r.ok();
}

// Formula 61, Menger - Mod 1, in Mandelbulber's axes: |z|, sort, z * scale - 2 (x and y), z.z - 2
// beyond 1; an optional turn; a shift. The estimate is (|z| - 2) / dr; c only when asked.
std::optional<ImportedFormula> menger_mod1(int slot, const AddC& c, const FractSettings& s, Diagnostics& diag) {
    SlotReader r(61, "menger_mod1", slot, s, diag);
    const double scale = r.number("transf_scale_3", 3.0);
    const glm::dvec3 step = 2.0 * r.vector("transf_constant_multiplier_111", glm::dvec3(1.0));
    const glm::dvec3 shift = r.vector("transf_addition_constant", glm::dvec3(0.0));
    const bool turn = r.flag("transf_rotation_enabled", false);
    const glm::dvec3 angles = r.vector("transf_rotation", glm::dvec3(0.0));
    if (step.z != 2.0) r.refuse("transf_constant_multiplier_111", "a z step other than 2 does not keep the edge cubes (imported: z = 1)");
    if (scale <= 1.0) r.refuse("transf_scale_3", fmt::format("a scale of {:g} does not shrink the copies (imported: above 1)", scale));
    r.only_default("transf_function_enabledx_false", is_false, "the box offset");
    r.only_default("transf_function_enabled_false", is_false, "the iteration-picked additions");
    if (turn) turn_in_every_iteration(r, s, "transf_start_iterations", "transf_stop_iterations");
    if (!r.ok()) return std::nullopt;
    Chain body;
    body.enter_mandelbulber_axes();
    body.add("abs", "stage.abs_fold");
    body.add("sort", "stage.menger_fold");
    // z * scale - step: stage.menger_scale's offset o subtracts o (scale - 1), its z beyond o.z (scale - 1) / 2 = 1.
    body.add("scale", "stage.menger_scale", {{"scale", scale}, {"offset", array(step / (scale - 1.0))}});
    if (turn) body.rotate("turn", mandelbox_rotation(angles));
    body.translate("shift", shift);
    body.leave_mandelbulber_axes();
    body.add_c(c, false);
    return ImportedFormula{"menger_mod1", body.nodes(), 10.0, "linear", 2.0};
}

// Formula 103, Pseudo Kleinian, in Mandelbulber's axes: a box fold to the size (clamped per axis),
// an inversion in the sphere of squared radius minR, a turn, a shift; the estimate is Knighty's
// seed disc about z of radius analyticDE_scale_1. c is added only when asked.
std::optional<ImportedFormula> pseudo_kleinian(int slot, const AddC& c, const FractSettings& s, Diagnostics& diag) {
    SlotReader r(103, "pseudo_kleinian", slot, s, diag);
    const glm::dvec3 size = r.vector("transf_addition_constant_0777", glm::dvec3(0.7));
    const glm::dvec3 shift = r.vector("transf_addition_constant", glm::dvec3(0.0));
    const double radius2 = r.number("transf_minimum_radius_05", 0.5), seed = r.number("analyticDE_scale_1", 1.0);
    const bool turn = r.flag("transf_function_enabledR_false", false);
    const glm::dvec3 angles = r.vector("transf_rotation", glm::dvec3(0.0));
    for (const char* key : {"transf_sphere_inversion_enabled_false", "transf_function_enabledP_false",
                            "transf_function_enabledBy_false", "transf_function_enabledBx_false"})
        r.only_default(key, is_false, "an optional step of the pseudo-Kleinian");
    if (turn) turn_in_every_iteration(r, s, "transf_start_iterations_R", "transf_stop_iterations_R");
    if (!r.ok()) return std::nullopt;
    if (const double tweak = r.number("analyticDE_tweak_005", 0.05); tweak != 0.0)
        diag.warning(fmt::format("[fractal_{}] analyticDE_tweak_005 {:g}: not imported; the compiler derives the running derivative "
                                 "of the inversion exactly (the tweak only thickens Mandelbulber's surface)", slot, tweak));
    Chain body;
    body.enter_mandelbulber_axes(false);
    body.add("fold", "stage.box_fold", {{"limit", array(size)}});
    body.add("invert", "stage.inversion", {{"radius2", radius2}});
    if (turn) body.rotate("turn", mandelbox_rotation(angles));
    body.translate("shift", shift);
    body.add_c(c, false);
    ImportedFormula f{"pseudo_kleinian", body.nodes(), 100.0, "sheet"};
    f.native_axes = true;
    f.sheet_radius = seed;
    return f;
}

// Formula 10, Kaleidoscopic IFS, in Mandelbulber's axes: abs of the chosen axes; each enabled plane, after its own turn,
// folds z onto the side its direction points to; the main turn about the offset; the edge folds
// (a coordinate beyond its edge mirrored back); then z * scale - offset * (scale - 1), in Menger
// sponge mode keeping the edge cubes along z (stage.menger_scale). c is added only when asked. The estimate is (|z| - 2) / dr.
std::optional<ImportedFormula> kaleidoscopic_ifs(int slot, const AddC& c, const FractSettings& s, Diagnostics& diag) {
    SlotReader r(10, "kaleidoscopic_ifs", slot, s, diag);
    const double scale = r.number("IFS_scale", 2.0);
    const glm::dvec3 offset = r.vector("IFS_offset", {1.0, 0.0, 0.0}), edge = r.vector("IFS_edge", glm::dvec3(0.0));
    const bool abs_x = r.flag("IFS_abs_x", false), abs_y = r.flag("IFS_abs_y", false), abs_z = r.flag("IFS_abs_z", false);
    // Files of Mandelbulber 2.06 and older always turned the IFS (its first four slots).
    const bool menger_mode = r.flag("IFS_menger_sponge_mode", false);
    const bool main_rotation = r.flag("IFS_rotation_enabled", false) || (s.version() <= 2.06 && slot <= 4);
    const glm::dvec3 main_turn = r.vector("IFS_rotation", glm::dvec3(0.0));
    Chain body;
    body.enter_mandelbulber_axes();
    if (abs_x && abs_y && abs_z) {
        body.add("abs", "stage.abs_fold");
    } else {
        if (abs_x) body.plane_fold("abs_x", {1, 0, 0}, 0.0);
        if (abs_y) body.plane_fold("abs_y", {0, 1, 0}, 0.0);
        if (abs_z) body.plane_fold("abs_z", {0, 0, 1}, 0.0);
    }
    for (int i = 0; i < 9; ++i) {
        if (!r.flag(fmt::format("IFS_enabled_{}", i), false)) continue;
        const glm::dvec3 direction = r.vector(fmt::format("IFS_direction_{}", i), {1.0, 0.0, 0.0});
        const double distance = r.number(fmt::format("IFS_distance_{}", i), 0.0);
        const double intensity = r.number(fmt::format("IFS_intensity_{}", i), 1.0);
        body.rotate(fmt::format("turn_{}", i), ifs_rotation(r.vector(fmt::format("IFS_rotations_{}", i), glm::dvec3(0.0))));
        if (intensity == 0.0) continue;   // the plane moves nothing
        if (intensity != 1.0) {
            r.refuse(fmt::format("IFS_intensity_{}", i), fmt::format("a fold of intensity {:g} is not a reflection (imported: 0 and 1)", intensity));
            continue;
        }
        if (glm::length(direction) == 0.0) {
            r.refuse(fmt::format("IFS_direction_{}", i), "a plane without a direction");
            continue;
        }
        body.plane_fold(fmt::format("plane_{}", i), glm::normalize(direction), distance);
    }
    if (main_rotation) {
        body.translate("to_offset", -offset);
        body.rotate("turn", ifs_rotation(main_turn));
        body.translate("from_offset", offset);
    }
    const char* axes = "xyz";
    for (int a = 0; a < 3; ++a)
        if (edge[a] > 0.0) {
            glm::dvec3 normal(0.0);
            normal[a] = -1.0;
            body.plane_fold(fmt::format("edge_{}", axes[a]), normal, -edge[a]);
        }
    if (menger_mode) {
        body.add("scale", "stage.menger_scale", {{"scale", scale}, {"offset", array(offset)}});
    } else {
        body.add("scale", "stage.scale", {{"scale", scale}});
        body.translate("shift", -offset * (scale - 1.0));
    }
    body.leave_mandelbulber_axes();
    body.add_c(c, false);
    if (!r.ok()) return std::nullopt;
    return ImportedFormula{"kaleidoscopic_ifs", body.nodes(), 100.0, "linear", 2.0};
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
        {2, {"mandelbulb", mandelbulb}},         {3, {"mandelbulb_power2", mandelbulb_power2}},
        {4, {"hypercomplex", hypercomplex}},     {5, {"quaternion", quaternion}},
        {11, {"xenodreambuie", xenodreambuie}},
        {7, {"menger_sponge", menger}},          {8, {"mandelbox", mandelbox}},
        {10, {"kaleidoscopic_ifs", kaleidoscopic_ifs}}, {16, {"box_fold_bulb_pow2", box_fold_bulb_pow2}},
        {61, {"menger_mod1", menger_mod1}},      {103, {"pseudo_kleinian", pseudo_kleinian}}};
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
