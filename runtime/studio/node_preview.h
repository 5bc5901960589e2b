#pragma once
// The small picture on a node whose output is a distance, as Blender and the MaterialX editor show
// node previews: the subgraph that feeds that output becomes a scene of its own (same parameters,
// same scene settings), compiled once and kept while it does not change, and rendered small from
// the scene's camera with the page's parameter values.
#include <cstdint>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "graph/node_library.h"
#include "spirv/pass_cache.h"
#include "spirv/pass_cache_file.h"
#include "studio/preview_renderer.h"

namespace fg::studio {

// The graph whose `distance` is output `port` of node `node_id`: that node and every node it reads
// from, nothing else. Nullopt (with `error`) when the graph has no such node.
std::optional<nlohmann::ordered_json> distance_subgraph(const nlohmann::ordered_json& graph, const std::string& node_id,
                                                        const std::string& port, std::string& error);

class NodePreviews {
public:
    NodePreviews(const vk::Context& ctx, const NodeLibrary& library, std::uint32_t size = 96);

    // PNG of the subgraph's distance; nullopt with `error` when it does not compile.
    std::optional<std::vector<std::uint8_t>> render(const std::string& graph_text, const std::string& node_id,
                                                    const std::string& port, const std::map<std::string, Constant>& params,
                                                    std::string& error);
    std::uint64_t compiles() const;

private:
    static constexpr std::size_t kKept = 24;
    const vk::Context& ctx_;
    const NodeLibrary& library_;
    std::uint32_t size_;
    mutable std::mutex mutex_;
    // Subgraphs compiled lately, newest first, by their text's hash: a slider move re-renders them.
    std::list<std::pair<std::string, std::unique_ptr<PreviewScene>>> kept_;
    std::uint64_t compiles_ = 0;
    // Subgraphs share most passes' code with each other and with earlier sessions.
    PassCache pass_cache_{64, user_pass_cache_folder()};
};

}  // namespace fg::studio
