#include "literal.h"

#include <cmath>
#include <fmt/format.h>

namespace fg {

namespace {
std::string json_kind(const nlohmann::json& j) {
    if (j.is_string()) return fmt::format("the string \"{}\"", j.get<std::string>());
    if (j.is_array()) return fmt::format("an array of {}", j.size());
    return j.type_name();
}
}  // namespace

std::optional<Constant> read_literal(const nlohmann::json& j, const LiteralSite& site, Diagnostics& diag) {
    if (j.is_boolean()) return Constant::scalar(ValueType::Bool, j.get<bool>() ? 1.0 : 0.0);
    if (j.is_number()) {
        double x = j.get<double>();
        if (!std::isfinite(x)) {
            diag.error("literal is NaN or infinite", site.pointer, site.node_id);
            return std::nullopt;
        }
        return Constant::scalar(ValueType::Float, x);
    }
    if (j.is_array()) {
        if (j.size() < 2 || j.size() > 4) {
            diag.error(fmt::format("a vector literal has 2, 3 or 4 numbers, not {}", j.size()), site.pointer, site.node_id);
            return std::nullopt;
        }
        std::array<double, 4> xs{0, 0, 0, 0};
        for (std::size_t i = 0; i < j.size(); ++i) {
            if (!j[i].is_number()) {
                diag.error(fmt::format("vector component {} is {}, expected a number", i, json_kind(j[i])),
                           site.pointer + fmt::format("/{}", i), site.node_id);
                return std::nullopt;
            }
            xs[i] = j[i].get<double>();
            if (!std::isfinite(xs[i])) {
                diag.error("literal is NaN or infinite", site.pointer + fmt::format("/{}", i), site.node_id);
                return std::nullopt;
            }
        }
        return Constant::vector(float_vector(static_cast<int>(j.size())), xs);
    }
    diag.error(fmt::format("expected a literal (number, bool or array of numbers), got {}", json_kind(j)), site.pointer,
               site.node_id);
    return std::nullopt;
}

std::optional<Constant> coerce_literal(const Constant& c, ValueType want, const LiteralSite& site, Diagnostics& diag) {
    if (c.type == want) return c;
    auto mismatch = [&] {
        diag.error(fmt::format("expected {}, got {} {}", type_name(want), type_name(c.type), c.text()), site.pointer,
                   site.node_id);
        return std::nullopt;
    };
    if (c.type == ValueType::Float) {
        if (want == ValueType::Int) {
            if (std::floor(c.v[0]) != c.v[0] || std::abs(c.v[0]) > 2147483647.0) return mismatch();
            return Constant::scalar(ValueType::Int, c.v[0]);
        }
        if (is_vector(want)) return Constant::scalar(want, c.v[0]);
    }
    return mismatch();
}

bool check_range(const Constant& c, std::optional<double> min, std::optional<double> max, const LiteralSite& site,
                 Diagnostics& diag) {
    for (int i = 0; i < component_count(c.type); ++i) {
        double x = c.v[static_cast<std::size_t>(i)];
        if ((min && x < *min) || (max && x > *max)) {
            diag.error(fmt::format("{} is out of range [{}, {}]", c.text(), min ? fmt::format("{}", *min) : "-inf",
                                   max ? fmt::format("{}", *max) : "inf"),
                       site.pointer, site.node_id);
            return false;
        }
    }
    return true;
}

}  // namespace fg
