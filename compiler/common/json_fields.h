#pragma once
// Reading a JSON document field by field: the type, range and unknown-key checks shared by every
// reader of Fractograph's JSON (graphs, scene settings, node definitions, pack manifests, camera
// paths), so that they all report a problem the same way: the JSON pointer of the value, what was
// expected and what was found ("/scene/fog/density: expected a number, got a string").
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "diagnostics.h"
#include "value_type.h"

namespace fg {

// The numbers a field accepts. `lo_open` leaves out `lo` itself: NumberRange::positive() is (0, inf).
struct NumberRange {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool lo_open = false;

    static NumberRange positive(double hi = std::numeric_limits<double>::infinity()) { return {0.0, hi, true}; }
    bool contains(double x) const { return (lo_open ? x > lo : x >= lo) && x <= hi; }
    std::string text() const;   // "[2, 16]", "(0, inf]"
};

// The strings a field accepts: Choices{"float", "double"}.
using Choices = std::initializer_list<std::string_view>;

// What a JSON value is, for messages: "a number", "a string", "an array", "an object", "a boolean", "null".
std::string json_kind(const nlohmann::json& v);

class JsonFieldReader {
public:
    using Report = std::function<void(const std::string& message, const std::string& pointer)>;
    explicit JsonFieldReader(Diagnostics& diag);
    explicit JsonFieldReader(Report report);

    // A value at `pointer`: true and `out` set when it is what was asked for; otherwise the problem is
    // reported and `out` keeps its value. Numbers are finite.
    bool read(const nlohmann::json& v, const std::string& pointer, double& out, NumberRange range = {});
    bool read(const nlohmann::json& v, const std::string& pointer, std::int64_t& out, NumberRange range = {});
    bool read(const nlohmann::json& v, const std::string& pointer, std::uint32_t& out, NumberRange range = {});
    bool read(const nlohmann::json& v, const std::string& pointer, bool& out);
    bool read(const nlohmann::json& v, const std::string& pointer, std::string& out);
    bool read(const nlohmann::json& v, const std::string& pointer, glm::dvec3& out, NumberRange range = {});
    // An array of exactly out.size() numbers (a vector, a quaternion).
    bool read_numbers(const nlohmann::json& v, const std::string& pointer, std::span<double> out, NumberRange range = {});
    // A type name: float, int, bool, vec2, vec3 or vec4.
    bool read(const nlohmann::json& v, const std::string& pointer, ValueType& out);
    // A string that is one of `choices`: "expected \"float\" or \"double\", got \"single\"".
    bool read(const nlohmann::json& v, const std::string& pointer, std::string& out, Choices choices);
    bool is_object(const nlohmann::json& v, const std::string& pointer);
    bool is_array(const nlohmann::json& v, const std::string& pointer);

    // The field `key` of the object at `pointer`. Left out, an optional field leaves `out` as it was
    // and a required one is reported missing (at `pointer`); present, it is read as above.
    template <class T, class... Extra>
    bool optional(const nlohmann::json& object, std::string_view key, const std::string& pointer, T& out,
                  Extra&&... extra) {
        const nlohmann::json* v = find(object, key);
        return v && read(*v, field_pointer(pointer, key), out, std::forward<Extra>(extra)...);
    }
    template <class T, class... Extra>
    bool required(const nlohmann::json& object, std::string_view key, const std::string& pointer, T& out,
                  Extra&&... extra) {
        const nlohmann::json* v = require(object, key, pointer);
        return v && read(*v, field_pointer(pointer, key), out, std::forward<Extra>(extra)...);
    }
    // The field itself: nullptr when left out (`require` reports that).
    static const nlohmann::json* find(const nlohmann::json& object, std::string_view key);
    const nlohmann::json* require(const nlohmann::json& object, std::string_view key, const std::string& pointer);
    // A field that holds an object or an array: nullptr when left out or of another kind (reported).
    const nlohmann::json* object_field(const nlohmann::json& object, std::string_view key, const std::string& pointer,
                                       bool needed = false);
    const nlohmann::json* array_field(const nlohmann::json& object, std::string_view key, const std::string& pointer,
                                      bool needed = false);

    // Reports every key of the object at `pointer` that is not in `known`: `unknown <what> "max_sped";
    // did you mean "max_speed"?`, at the key's own pointer.
    void unknown_keys(const nlohmann::json& object, const std::string& pointer,
                      std::initializer_list<std::string_view> known, std::string_view what = "field");

    // A reader's own, more specific checks go through here too, so they reach the same place.
    void error(const std::string& message, const std::string& pointer);
    std::size_t errors() const { return errors_; }

    static std::string field_pointer(const std::string& pointer, std::string_view key);

private:
    bool number(const nlohmann::json& v, const std::string& pointer, double& out, NumberRange range,
                std::string_view expected);
    bool mismatch(const nlohmann::json& v, const std::string& pointer, std::string_view expected);
    bool wrong_number(const nlohmann::json& v, const std::string& pointer, std::string_view expected);

    Report report_;
    std::size_t errors_ = 0;
};

}  // namespace fg
