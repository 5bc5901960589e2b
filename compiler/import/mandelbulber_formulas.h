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
    std::string estimate;     // its distance estimate: "log", "linear" (|z| / dr) or "box" (the cube's)
};

// How the slot adds c: its weight (Mandelbulber's fractal_constant_factor when uniform), or not at
// all (dont_add_c_constant).
struct AddC {
    bool enabled = true;
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
