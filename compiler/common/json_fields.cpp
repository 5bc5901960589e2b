#include "json_fields.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <vector>

#include "edit_distance.h"

namespace fg {

using nlohmann::json;

std::string NumberRange::text() const {
    return fmt::format("{}{}, {}]", lo_open ? "(" : "[", lo, hi);
}

std::string json_kind(const json& v) {
    switch (v.type()) {
        case json::value_t::null: return "null";
        case json::value_t::boolean: return "a boolean";
        case json::value_t::string: return "a string";
        case json::value_t::array: return "an array";
        case json::value_t::object: return "an object";
        case json::value_t::binary: return "binary data";
        case json::value_t::discarded: return "nothing";
        default: return "a number";
    }
}

JsonFieldReader::JsonFieldReader(Diagnostics& diag)
    : report_([&diag](const std::string& message, const std::string& pointer) { diag.error(message, pointer); }) {}

JsonFieldReader::JsonFieldReader(Report report) : report_(std::move(report)) {}

void JsonFieldReader::error(const std::string& message, const std::string& pointer) {
    ++errors_;
    report_(message, pointer);
}

bool JsonFieldReader::mismatch(const json& v, const std::string& pointer, std::string_view expected) {
    error(fmt::format("expected {}, got {}", expected, json_kind(v)), pointer);
    return false;
}

bool JsonFieldReader::wrong_number(const json& v, const std::string& pointer, std::string_view expected) {
    // A number of the wrong sort says which number it is: "expected an integer, got 7.5".
    if (!v.is_number()) return mismatch(v, pointer, expected);
    error(fmt::format("expected {}, got {}", expected, v.dump()), pointer);
    return false;
}

std::string JsonFieldReader::field_pointer(const std::string& pointer, std::string_view key) {
    std::string p = pointer + "/";
    for (char c : key) {
        if (c == '~') p += "~0";
        else if (c == '/') p += "~1";
        else p += c;
    }
    return p;
}

bool JsonFieldReader::number(const json& v, const std::string& pointer, double& out, NumberRange range,
                             std::string_view expected) {
    if (!v.is_number()) return mismatch(v, pointer, expected);
    const double x = v.get<double>();
    if (!std::isfinite(x)) return wrong_number(v, pointer, "a finite number");
    if (!range.contains(x)) {
        error(fmt::format("{} is out of range {}", x, range.text()), pointer);
        return false;
    }
    out = x;
    return true;
}

bool JsonFieldReader::read(const json& v, const std::string& pointer, double& out, NumberRange range) {
    return number(v, pointer, out, range, "a number");
}

bool JsonFieldReader::read(const json& v, const std::string& pointer, std::int64_t& out, NumberRange range) {
    if (!v.is_number_integer()) return wrong_number(v, pointer, "an integer");
    double x = 0.0;
    if (!number(v, pointer, x, range, "an integer")) return false;
    out = v.get<std::int64_t>();
    return true;
}

bool JsonFieldReader::read(const json& v, const std::string& pointer, std::uint32_t& out, NumberRange range) {
    // A non-negative integer held signed (JSON built in memory rather than parsed) counts too.
    const bool fits = v.is_number_unsigned() ? v.get<std::uint64_t>() <= 0xffffffffull
                                             : v.is_number_integer() && v.get<std::int64_t>() >= 0 &&
                                                   v.get<std::int64_t>() <= 0xffffffffll;
    if (!fits) return wrong_number(v, pointer, "an unsigned 32-bit integer");
    double x = 0.0;
    if (!number(v, pointer, x, range, "an unsigned 32-bit integer")) return false;
    out = v.get<std::uint32_t>();
    return true;
}

bool JsonFieldReader::read(const json& v, const std::string& pointer, bool& out) {
    if (!v.is_boolean()) return mismatch(v, pointer, "true or false");
    out = v.get<bool>();
    return true;
}

bool JsonFieldReader::read(const json& v, const std::string& pointer, std::string& out) {
    if (!v.is_string()) return mismatch(v, pointer, "a string");
    out = v.get<std::string>();
    return true;
}

bool JsonFieldReader::read_numbers(const json& v, const std::string& pointer, std::span<double> out, NumberRange range) {
    const std::string expected = fmt::format("an array of {} numbers", out.size());
    if (!v.is_array()) return mismatch(v, pointer, expected);
    if (v.size() != out.size()) {
        error(fmt::format("expected {}, got an array of {}", expected, v.size()), pointer);
        return false;
    }
    std::vector<double> r(out.size());
    for (std::size_t i = 0; i < r.size(); ++i)
        if (!read(v[i], fmt::format("{}/{}", pointer, i), r[i], range)) return false;
    std::copy(r.begin(), r.end(), out.begin());
    return true;
}

bool JsonFieldReader::read(const json& v, const std::string& pointer, glm::dvec3& out, NumberRange range) {
    std::array<double, 3> xyz{};
    if (!read_numbers(v, pointer, xyz, range)) return false;
    out = {xyz[0], xyz[1], xyz[2]};
    return true;
}

bool JsonFieldReader::read(const json& v, const std::string& pointer, ValueType& out) {
    std::string name;
    if (!read(v, pointer, name, Choices{"float", "int", "bool", "vec2", "vec3", "vec4"})) return false;
    out = *parse_type(name);
    return true;
}

bool JsonFieldReader::read(const json& v, const std::string& pointer, std::string& out, Choices choices) {
    std::string expected;
    std::size_t i = 0;
    for (auto c : choices) {
        expected += fmt::format("{}\"{}\"", i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ", c);
        ++i;
    }
    if (!v.is_string()) return mismatch(v, pointer, expected);
    const std::string s = v.get<std::string>();
    for (auto c : choices)
        if (s == c) {
            out = s;
            return true;
        }
    error(fmt::format("expected {}, got \"{}\"", expected, s), pointer);
    return false;
}

bool JsonFieldReader::is_object(const json& v, const std::string& pointer) {
    return v.is_object() || mismatch(v, pointer, "an object");
}

bool JsonFieldReader::is_array(const json& v, const std::string& pointer) {
    return v.is_array() || mismatch(v, pointer, "an array");
}

const json* JsonFieldReader::find(const json& object, std::string_view key) {
    if (!object.is_object()) return nullptr;
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

const json* JsonFieldReader::require(const json& object, std::string_view key, const std::string& pointer) {
    const json* v = find(object, key);
    if (!v) error(fmt::format("missing \"{}\"", key), pointer);
    return v;
}

const json* JsonFieldReader::object_field(const json& object, std::string_view key, const std::string& pointer,
                                          bool needed) {
    const json* v = needed ? require(object, key, pointer) : find(object, key);
    return v && is_object(*v, field_pointer(pointer, key)) ? v : nullptr;
}

const json* JsonFieldReader::array_field(const json& object, std::string_view key, const std::string& pointer,
                                         bool needed) {
    const json* v = needed ? require(object, key, pointer) : find(object, key);
    return v && is_array(*v, field_pointer(pointer, key)) ? v : nullptr;
}

void JsonFieldReader::unknown_keys(const json& object, const std::string& pointer,
                                   std::initializer_list<std::string_view> known, std::string_view what) {
    if (!object.is_object()) return;
    for (auto it = object.begin(); it != object.end(); ++it) {
        const std::string& key = it.key();
        std::string_view nearest;
        std::size_t best = 3;   // more edits than this is another word, not a typo
        bool listed = false;
        for (auto k : known) {
            listed |= k == key;
            std::size_t d = edit_distance(key, k);
            if (d < best) {
                best = d;
                nearest = k;
            }
        }
        if (listed) continue;
        error(fmt::format("unknown {} \"{}\"{}", what, key,
                          nearest.empty() ? std::string() : fmt::format("; did you mean \"{}\"?", nearest)),
              field_pointer(pointer, key));
    }
}

}  // namespace fg
