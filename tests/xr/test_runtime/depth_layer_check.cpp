#include "depth_layer_check.h"

#include <cmath>
#include <cstdlib>
#include <fstream>

#include <nlohmann/json.hpp>

namespace fgxrt {

bool is_depth_format(VkFormat f) { return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM; }

const char* depth_format_name(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT ? "D32_SFLOAT" : f == VK_FORMAT_D16_UNORM ? "D16_UNORM" : "not a depth format";
}

namespace {

const XrCompositionLayerDepthInfoKHR* chained_depth(const XrCompositionLayerProjectionView& v) {
    for (auto* p = static_cast<const XrBaseInStructure*>(v.next); p; p = p->next)
        if (p->type == XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR) return reinterpret_cast<const XrCompositionLayerDepthInfoKHR*>(p);
    return nullptr;
}

}  // namespace

void check_depth_layer(Session& s, const XrCompositionLayerProjection& layer, int frame,
                       const std::function<void(const std::string&)>& fail) {
    Instance* inst = live_instance();
    RuntimeReport& report = inst->report;
    nlohmann::json dump = nlohmann::json::array();
    std::vector<float> depth[2];
    bool all_sky[2] = {false, false};
    int chained = 0;
    for (int eye = 0; eye < 2; ++eye) {
        const std::string name = eye == 0 ? "left eye: " : "right eye: ";
        const XrCompositionLayerProjectionView& v = layer.views[eye];
        const XrCompositionLayerDepthInfoKHR* info = chained_depth(v);
        if (!inst->depth_layer) {
            if (info) fail(name + "depth info chained although XR_KHR_composition_layer_depth is not enabled");
            continue;
        }
        if (!info) {
            fail(name + "no XrCompositionLayerDepthInfoKHR chained to the projection view");
            continue;
        }
        ++chained;
        Swapchain* sc = swapchain(info->subImage.swapchain);
        Swapchain* colour = swapchain(v.subImage.swapchain);
        if (!sc || !is_depth_format(sc->format)) {
            fail(name + "the depth info's swapchain is not a depth swapchain");
            continue;
        }
        if (sc->last_released < 0) {
            fail(name + "no depth swapchain image was released");
            continue;
        }
        if (colour && (sc->width != colour->width || sc->height != colour->height))
            fail(name + "the depth swapchain is not the colour swapchain's size");
        const XrRect2Di& r = info->subImage.imageRect;
        if (r.offset.x != 0 || r.offset.y != 0 || r.extent.width != static_cast<std::int32_t>(sc->width) ||
            r.extent.height != static_cast<std::int32_t>(sc->height))
            fail(name + "the depth image rectangle does not cover the depth swapchain image");
        if (!(info->minDepth >= 0.0f && info->minDepth < info->maxDepth && info->maxDepth <= 1.0f))
            fail(name + "minDepth and maxDepth are not a range inside [0, 1]");
        if (!(std::isfinite(info->nearZ) && std::isfinite(info->farZ) && info->nearZ > 0.0f && info->farZ > 0.0f &&
              info->nearZ != info->farZ))
            fail(name + "nearZ and farZ are not two different positive distances");
        try {
            depth[eye] = s.inspector->read_depth(sc->images[static_cast<std::size_t>(sc->last_released)], sc->format, sc->width,
                                                 sc->height);
        } catch (const std::exception& e) {
            fail(name + e.what());
            continue;
        }
        std::size_t outside = 0, sky = 0;
        for (float d : depth[eye]) {
            if (!(d >= info->minDepth && d <= info->maxDepth)) ++outside;
            if (d == info->maxDepth) ++sky;
        }
        if (outside) fail(name + std::to_string(outside) + " depth values outside [minDepth, maxDepth]");
        all_sky[eye] = sky == depth[eye].size();
        report.depth_format = depth_format_name(sc->format);
        report.sky_fraction[eye] = static_cast<double>(sky) / static_cast<double>(depth[eye].size());
        dump.push_back({{"width", sc->width},
                        {"height", sc->height},
                        {"format", depth_format_name(sc->format)},
                        {"near_z", info->nearZ},
                        {"far_z", info->farZ},
                        {"min_depth", info->minDepth},
                        {"max_depth", info->maxDepth},
                        {"position", {v.pose.position.x, v.pose.position.y, v.pose.position.z}},
                        {"orientation", {v.pose.orientation.x, v.pose.orientation.y, v.pose.orientation.z, v.pose.orientation.w}},
                        {"fov", {v.fov.angleLeft, v.fov.angleRight, v.fov.angleDown, v.fov.angleUp}},
                        {"depth", std::string("xr_depth_") + (eye ? "right" : "left") + ".f32"}});
    }
    if (chained == 2) ++report.frames_with_depth;
    // Both eyes all sky is a view of empty space (after a snap turn away from the fractal, say);
    // one eye all sky beside hits in the other means nothing was written for it. Whether the sky
    // is right at all is the depth judge's question (it traces the CPU twin).
    if (chained == 2 && all_sky[0] != all_sky[1])
        fail(std::string(all_sky[0] ? "left" : "right") + " eye: the depth is all sky (maxDepth) while the other eye has hits");
    if (chained == 2 && !all_sky[0] && depth[0].size() == depth[1].size() && depth[0] == depth[1])
        fail("both eyes submitted the same depth");
    const char* folder = std::getenv("FG_XR_TEST_DUMP");
    if (!folder || chained != 2 || dump.size() != 2) return;
    for (int eye = 0; eye < 2; ++eye)
        std::ofstream(std::string(folder) + "/xr_depth_" + (eye ? "right" : "left") + ".f32", std::ios::binary)
            .write(reinterpret_cast<const char*>(depth[eye].data()), static_cast<std::streamsize>(depth[eye].size() * 4));
    std::ofstream(std::string(folder) + "/xr_depth.json") << nlohmann::json{{"frame", frame}, {"eyes", dump}}.dump(1) << "\n";
}

}  // namespace fgxrt
