#include "identifiers.h"


#include <cctype>

namespace fg {

namespace {
// GLSL 4.60 keywords and reserved words, C++ keywords, and GLSL built-in function names that a
// parameter would shadow.
constexpr std::string_view kReserved[] = {
    "attribute", "const", "uniform", "varying", "buffer", "shared", "coherent", "volatile", "restrict",
    "readonly", "writeonly", "layout", "centroid", "flat", "smooth", "noperspective", "patch", "sample",
    "break", "continue", "do", "for", "while", "switch", "case", "default", "if", "else", "subroutine",
    "in", "out", "inout", "float", "double", "int", "void", "bool", "true", "false", "invariant",
    "precise", "discard", "return", "mat2", "mat3", "mat4", "vec2", "vec3", "vec4", "ivec2", "ivec3",
    "ivec4", "bvec2", "bvec3", "bvec4", "uint", "uvec2", "uvec3", "uvec4", "lowp", "mediump", "highp",
    "precision", "struct", "common", "partition", "active", "asm", "class", "union", "enum", "typedef",
    "template", "this", "resource", "goto", "inline", "noinline", "public", "static", "extern",
    "external", "interface", "long", "short", "half", "fixed", "unsigned", "superp", "input", "output",
    "filter", "sizeof", "cast", "namespace", "using", "auto", "char", "delete", "new", "operator",
    "private", "protected", "friend", "virtual", "register", "signed", "try", "catch", "throw",
    "and", "or", "not", "xor", "main", "length", "dot", "cross", "min", "max", "mix", "clamp", "abs"};
}  // namespace

bool is_reserved_word(std::string_view s) {
    for (auto r : kReserved)
        if (r == s) return true;
    return s.rfind("fg_", 0) == 0 || s.rfind("gl_", 0) == 0 || s.find("__") != std::string_view::npos;
}

bool is_valid_identifier(std::string_view s) {
    if (s.empty() || s.size() > 64) return false;
    if (!(std::islower(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    for (char c : s)
        if (!(std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_'))
            return false;
    return !is_reserved_word(s);
}

bool is_valid_node_id(std::string_view s) {
    if (s.empty() || s.size() > 64) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
    return true;
}

}  // namespace fg
