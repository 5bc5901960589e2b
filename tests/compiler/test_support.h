#pragma once
// Helpers for compiler tests: a small valid graph to start from, and matchers for diagnostics.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/diagnostics.h"
#include "compiler.h"

namespace fg::test {

// A sphere with a palette: valid, small, and every part a test may want to break.
inline nlohmann::json minimal_graph() {
    return nlohmann::json::parse(R"({
      "format": "fractograph-graph",
      "version": 1,
      "name": "test",
      "params": {"radius": {"type": "float", "default": 1.0, "min": 0.1, "max": 2.0}},
      "nodes": [
        {"id": "ball", "type": "prim.sphere", "inputs": {"radius": "$radius"}},
        {"id": "tone", "type": "palette.cosine", "inputs": {"t": 0.3}}
      ],
      "outputs": {"distance": "ball.distance", "albedo": "tone.color"}
    })");
}

// The minimal graph with its first node a fractal.formula "f" of body `formula`, whose distance it shows.
inline nlohmann::json formula_graph(const nlohmann::json& formula) {
    nlohmann::json g = minimal_graph();
    g["nodes"][0] = {{"id", "f"}, {"type", "fractal.formula"}, {"formula", formula}};
    g["outputs"]["distance"] = "f.distance";
    return g;
}

// The graphs (.json) in a folder of the source tree, sorted.
inline std::vector<std::string> graph_files(const std::string& folder) {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(std::string(FG_SOURCE_DIR) + "/" + folder))
        if (e.path().extension() == ".json") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

inline std::string read_source_file(const std::string& relative) {
    std::ifstream in(std::string(FG_SOURCE_DIR) + "/" + relative, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The gallery Mandelbulb with another value of the literal that scales its orbit trap: a change
// to the colour alone, which only the shade pass evaluates.
inline std::string mandelbulb_with_tone(double scale) {
    auto graph = nlohmann::json::parse(read_source_file("graphs/gallery/mandelbulb.json"));
    for (auto& node : graph["nodes"])
        if (node["id"] == "tone") node["inputs"]["s"] = scale;
    return graph.dump();
}

// Runs the front end (load, IR, folding) and returns the diagnostics.
inline Diagnostics check_front(const std::string& text) {
    Diagnostics diag;
    load_and_lower(text, NodeLibrary::builtin(), diag);
    return diag;
}
inline Diagnostics check_front(const nlohmann::json& j) { return check_front(j.dump()); }

// The whole compiler, GLSL and SPIR-V included; `folder` is where the graph's files (an
// environment image) are read from, a source folder ("graphs/gallery").
inline std::optional<CompileResult> compile_text(const std::string& text, Diagnostics& diag,
                                                 const std::string& folder = {}) {
    CompileOptions options;
    if (!folder.empty()) options.folder = std::string(FG_SOURCE_DIR) + "/" + folder;
    return compile_graph(text, NodeLibrary::builtin(), options, diag);
}

// True if some error's pointer and node match and its message contains `text`.
inline ::testing::AssertionResult has_error(const Diagnostics& diag, const std::string& pointer,
                                            const std::string& node, const std::string& text) {
    for (const auto& d : diag.items())
        if (d.severity == Severity::Error && d.pointer == pointer && d.node_id == node &&
            d.message.find(text) != std::string::npos)
            return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "no error at '" << pointer << "' (node '" << node << "') containing '"
                                         << text << "'; got:\n"
                                         << diag.format();
}

}  // namespace fg::test
