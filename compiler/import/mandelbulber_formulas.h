#pragma once
// Mandelbulber's formulas by number, as formula-graph stage groups. Each is written from its
// definition (the Mandelbulb with the elevation angle, the Mandelbox, the Menger sponge), with
// the formula's own parameters read from its [fractal_N] section and its defaults.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/diagnostics.h"
#include "fract_settings.h"

namespace fg {

struct ImportedFormula {
    std::string name;         // "mandelbox"
    nlohmann::ordered_json nodes;   // the group's stage nodes, the last one's z leaving the group
    double bailout = 100.0;   // the formula's default bailout in Mandelbulber
    std::string estimate;     // its distance estimate: "log", "linear" ((|z| - linear_radius) / dr) or "box"
    double linear_radius = 0.0;
    bool four_d = false;      // its orbit is 4D (quaternion-like), starting at (p, initial_waxis)
    // Its stages and estimate are in Mandelbulber's axes, so the whole formula takes the point in
    // them (the estimate of a pseudo-Kleinian singles out its z).
    bool native_axes = false;
    double sheet_radius = 0.0;   // estimate "sheet": the seed disc's radius
    double bound_radius = 0.0;   // alone in a formula, the set lies within this radius (0: not known)
};

// How the slot adds c: its weight (Mandelbulber's fractal_constant_factor when uniform), and the
// slot's dont_add_c_constant. That setting turns c off for formulas that add it by default and
// on for those that do not (Kaleidoscopic IFS).
struct AddC {
    bool dont_add_c = false;
    double weight = 1.0;
};

// The formula numbered `number` in slot `slot` ([fractal_<slot>]), its node ids prefixed with
// "s<slot>_"; nullopt with an error naming the setting when the number or one of its settings is
// not imported.
std::optional<ImportedFormula> import_formula(int number, int slot, const AddC& add_c, const FractSettings& settings,
                                              Diagnostics& diag);

// Every formula number import_formula knows, for messages.
std::string imported_formula_list();

}  // namespace fg
