#pragma once
// Literals in JSON: a number, a bool, or an array of 2-4 numbers.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/diagnostics.h"
#include "common/value_type.h"

namespace fg {

struct LiteralSite {
    std::string pointer;   // where the literal is, for messages
    std::string node_id;   // the node it belongs to, if any
};

// The literal's own type: numbers are float (a scalar), arrays vecN, true/false bool.
// Reports and returns nullopt for anything else, and for NaN or infinite numbers.
std::optional<Constant> read_literal(const nlohmann::json& j, const LiteralSite& site, Diagnostics& diag);

// Convert a literal to the type a port or parameter wants: a scalar broadcasts to a vector, an
// integral float becomes an int; anything else is a type mismatch, reported at the site.
std::optional<Constant> coerce_literal(const Constant& c, ValueType want, const LiteralSite& site, Diagnostics& diag);

// Check each component against [min, max]; reports "out of range".
bool check_range(const Constant& c, std::optional<double> min, std::optional<double> max, const LiteralSite& site,
                 Diagnostics& diag);

}  // namespace fg
