#include "double_lowering.h"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <map>
#include <set>

namespace fg {

namespace {

const std::map<std::string_view, std::string_view>& renames() {
    static const std::map<std::string_view, std::string_view> m = {
        {"float", "double"}, {"vec2", "dvec2"}, {"vec3", "dvec3"}, {"vec4", "dvec4"},
        {"mat2", "dmat2"},   {"mat3", "dmat3"}, {"mat4", "dmat4"},
        {"sin", "fg_d_sin"}, {"cos", "fg_d_cos"}, {"tan", "fg_d_tan"}, {"asin", "fg_d_asin"},
        {"acos", "fg_d_acos"}, {"atan", "fg_d_atan"}, {"pow", "fg_d_pow"}, {"exp", "fg_d_exp"},
        {"log", "fg_d_log"}, {"exp2", "fg_d_exp2"}, {"log2", "fg_d_log2"},
        // Shade-context bodies ask for the distance at absolute (double) points.
        {"fg_scene_distance", "fg_scene_distance_d"},
    };
    return m;
}

// GLSL built-ins without a double overload that double_math.glsl does not provide either.
const std::set<std::string_view>& without_double() {
    static const std::set<std::string_view> s = {
        "floatBitsToInt", "floatBitsToUint", "intBitsToFloat", "uintBitsToFloat", "packHalf2x16", "unpackHalf2x16",
        "packUnorm2x16", "packSnorm2x16", "packUnorm4x8", "packSnorm4x8", "unpackUnorm2x16", "unpackSnorm2x16",
        "unpackUnorm4x8", "unpackSnorm4x8", "dFdx", "dFdy", "fwidth", "dFdxFine", "dFdyFine", "dFdxCoarse",
        "dFdyCoarse", "fwidthFine", "fwidthCoarse", "noise1", "noise2", "noise3", "noise4", "texture",
        "textureLod", "texelFetch", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "radians", "degrees"};
    return s;
}

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// Walks GLSL text token by token, calling `ident` for identifiers and `number` for numeric
// literals; comments and everything else go to `other` unchanged.
template <class Ident, class Number, class Other>
void scan(std::string_view s, Ident ident, Number number, Other other) {
    std::size_t i = 0;
    while (i < s.size()) {
        char c = s[i];
        if (c == '/' && i + 1 < s.size() && (s[i + 1] == '/' || s[i + 1] == '*')) {
            std::size_t end = s[i + 1] == '/' ? s.find('\n', i) : s.find("*/", i + 2);
            end = end == std::string_view::npos ? s.size() : (s[i + 1] == '/' ? end : end + 2);
            other(s.substr(i, end - i));
            i = end;
        } else if (ident_start(c)) {
            std::size_t j = i;
            while (j < s.size() && ident_char(s[j])) ++j;
            ident(s.substr(i, j - i), j);
            i = j;
        } else if (digit(c) || (c == '.' && i + 1 < s.size() && digit(s[i + 1]))) {
            std::size_t j = i;
            if (c == '0' && i + 1 < s.size() && (s[i + 1] == 'x' || s[i + 1] == 'X')) {
                j += 2;
                while (j < s.size() && ident_char(s[j])) ++j;
                other(s.substr(i, j - i));
                i = j;
                continue;
            }
            while (j < s.size() && (digit(s[j]) || s[j] == '.')) ++j;
            if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
                std::size_t k = j + 1;
                if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
                if (k < s.size() && digit(s[k])) {
                    j = k;
                    while (j < s.size() && digit(s[j])) ++j;
                }
            }
            std::size_t suffix_end = j;
            while (suffix_end < s.size() && std::isalpha(static_cast<unsigned char>(s[suffix_end]))) ++suffix_end;
            number(s.substr(i, j - i), s.substr(j, suffix_end - j));
            i = suffix_end;
        } else {
            other(s.substr(i, 1));
            ++i;
        }
    }
}

}  // namespace

std::string lower_to_double(std::string_view glsl) {
    std::string out;
    out.reserve(glsl.size() + glsl.size() / 8);
    scan(
        glsl,
        [&](std::string_view id, std::size_t) {
            auto it = renames().find(id);
            out += it == renames().end() ? id : it->second;
        },
        [&](std::string_view digits, std::string_view suffix) {
            bool is_float = digits.find_first_of(".eE") != std::string_view::npos;
            out += digits;
            if (is_float && (suffix.empty() || suffix == "f" || suffix == "F")) out += "lf";
            else out += suffix;
        },
        [&](std::string_view text) { out += text; });
    return out;
}

std::vector<std::string> functions_without_double(std::string_view glsl) {
    std::vector<std::string> found;
    scan(
        glsl,
        [&](std::string_view id, std::size_t end) {
            std::size_t k = end;
            while (k < glsl.size() && (glsl[k] == ' ' || glsl[k] == '\t')) ++k;
            if (k >= glsl.size() || glsl[k] != '(' || !without_double().count(id)) return;
            if (std::find(found.begin(), found.end(), id) == found.end()) found.emplace_back(id);
        },
        [](std::string_view, std::string_view) {}, [](std::string_view) {});
    return found;
}

std::string double_math_vector_forms() {
    std::string s = "// Componentwise vector forms of the double math functions (generated by fgc).\n";
    const char* unary[] = {"sin", "cos", "tan", "asin", "acos", "atan", "exp", "log", "exp2", "log2"};
    for (int n = 2; n <= 4; ++n) {
        const char* comps[] = {"x", "y", "z", "w"};
        for (const char* f : unary) {
            std::string args;
            for (int c = 0; c < n; ++c) args += fmt::format("{}fg_d_{}(v.{})", c ? ", " : "", f, comps[c]);
            s += fmt::format("dvec{0} fg_d_{1}(dvec{0} v) {{ return dvec{0}({2}); }}\n", n, f, args);
        }
        std::string pow_args, atan_args;
        for (int c = 0; c < n; ++c) {
            pow_args += fmt::format("{}fg_d_pow(x.{}, y.{})", c ? ", " : "", comps[c], comps[c]);
            atan_args += fmt::format("{}fg_d_atan2(y.{}, x.{})", c ? ", " : "", comps[c], comps[c]);
        }
        s += fmt::format("dvec{0} fg_d_pow(dvec{0} x, dvec{0} y) {{ return dvec{0}({1}); }}\n", n, pow_args);
        s += fmt::format("dvec{0} fg_d_atan(dvec{0} y, dvec{0} x) {{ return dvec{0}({1}); }}\n", n, atan_args);
    }
    // GLSL's two-argument atan is atan2.
    s += "double fg_d_atan(double y, double x) { return fg_d_atan2(y, x); }\n";
    return s;
}

std::string double_type_name(ValueType t) {
    switch (t) {
        case ValueType::Float: return "double";
        case ValueType::Vec2: return "dvec2";
        case ValueType::Vec3: return "dvec3";
        case ValueType::Vec4: return "dvec4";
        default: return std::string(type_name(t));
    }
}

}  // namespace fg
