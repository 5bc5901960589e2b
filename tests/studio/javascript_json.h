#pragma once
// What the page sends back for a graph it did not change: JavaScript has one number type, so its
// JSON writes 8.0 as 8.
#include <cstdint>

#include <nlohmann/json.hpp>

namespace fg::studio::test {

inline void as_javascript_writes_it(nlohmann::ordered_json& v) {
    if (v.is_number_float() && v.get<double>() == static_cast<double>(static_cast<std::int64_t>(v.get<double>())))
        v = static_cast<std::int64_t>(v.get<double>());
    if (v.is_structured())
        for (auto& x : v) as_javascript_writes_it(x);
}

}  // namespace fg::studio::test
