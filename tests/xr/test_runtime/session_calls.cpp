// The test runtime's session-level calls: lifecycle, spaces, swapchains backed by images on
// fgplay's VkDevice, the frame loop with scripted poses, the visibility mask, and the frame checks
// in xrEndFrame.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "depth_layer_check.h"
#include "swapchain_colour.h"
#include "runtime_objects.h"

namespace fgxrt {

namespace {

// Depth formats for XR_KHR_composition_layer_depth; FG_XR_TEST_DEPTH_FORMAT=D16_UNORM offers only that one.
std::vector<VkFormat> depth_formats() {
    const char* only = std::getenv("FG_XR_TEST_DEPTH_FORMAT");
    if (only && std::string(only) == "D16_UNORM") return {VK_FORMAT_D16_UNORM};
    return {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D16_UNORM};
}

template <typename T, typename Fill>
XrResult two_call(std::uint32_t capacity, std::uint32_t* count, T* out, std::size_t size, Fill fill) {
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = static_cast<std::uint32_t>(size);
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < size) return XR_ERROR_SIZE_INSUFFICIENT;
    for (std::size_t i = 0; i < size; ++i) fill(out[i], i);
    return XR_SUCCESS;
}

double seconds(const Session& s, XrTime t) { return session_seconds(s, t); }

bool pose_close(const XrPosef& a, const XrPosef& b) {
    auto d = [](float x, float y) { return std::abs(x - y); };
    float dq = std::min(d(a.orientation.x, b.orientation.x) + d(a.orientation.y, b.orientation.y) +
                            d(a.orientation.z, b.orientation.z) + d(a.orientation.w, b.orientation.w),
                        d(a.orientation.x, -b.orientation.x) + d(a.orientation.y, -b.orientation.y) +
                            d(a.orientation.z, -b.orientation.z) + d(a.orientation.w, -b.orientation.w));
    float dp = d(a.position.x, b.position.x) + d(a.position.y, b.position.y) + d(a.position.z, b.position.z);
    return dq < 1e-4f && dp < 1e-4f;
}

void destroy_swapchain_images(Swapchain& sc) {
    VkDevice device = sc.session->device;
    vkDeviceWaitIdle(device);
    for (VkImage i : sc.images) vkDestroyImage(device, i, nullptr);
    for (VkDeviceMemory m : sc.memory) vkFreeMemory(device, m, nullptr);
    sc.images.clear();
    sc.memory.clear();
}

// Down to STOPPING the way the specification's state diagram goes: FOCUSED, VISIBLE,
// SYNCHRONIZED, STOPPING, each an event of its own.
void walk_down_to_stopping(Session& s) {
    if (s.state == XR_SESSION_STATE_STOPPING) return;
    if (s.state == XR_SESSION_STATE_FOCUSED) push_state(s, XR_SESSION_STATE_VISIBLE);
    if (s.state == XR_SESSION_STATE_VISIBLE) push_state(s, XR_SESSION_STATE_SYNCHRONIZED);
    push_state(s, XR_SESSION_STATE_STOPPING);
}

XRAPI_ATTR XrResult XRAPI_CALL CreateSession(XrInstance handle, const XrSessionCreateInfo* info, XrSession* out) {
    Instance* inst = instance(handle);
    if (!inst) return XR_ERROR_HANDLE_INVALID;
    if (info->systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (!inst->requirements_queried) return XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING;
    const XrGraphicsBindingVulkan2KHR* binding = nullptr;
    for (auto* p = static_cast<const XrBaseInStructure*>(info->next); p; p = p->next)
        if (p->type == XR_TYPE_GRAPHICS_BINDING_VULKAN2_KHR) binding = reinterpret_cast<const XrGraphicsBindingVulkan2KHR*>(p);
    if (!binding || !binding->device || !binding->physicalDevice) return XR_ERROR_GRAPHICS_DEVICE_INVALID;
    if (!inst->sessions.empty()) return XR_ERROR_LIMIT_REACHED;
    auto s = std::make_unique<Session>();
    s->vk_instance = binding->instance;
    s->physical = binding->physicalDevice;
    s->device = binding->device;
    s->queue_family = binding->queueFamilyIndex;
    s->queue_index = binding->queueIndex;
    try {
        s->inspector = std::make_unique<FrameInspector>(s->physical, s->device, s->queue_family, s->queue_index);
    } catch (const std::exception& e) {
        inst->report.fail(0, e.what());
        return XR_ERROR_RUNTIME_FAILURE;
    }
    Session& ref = *s;
    inst->sessions.push_back(std::move(s));
    push_state(ref, XR_SESSION_STATE_IDLE);
    push_state(ref, XR_SESSION_STATE_READY);
    *out = reinterpret_cast<XrSession>(&ref);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroySession(XrSession handle) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    Instance* inst = live_instance();
    for (auto& sc : s->swapchains) destroy_swapchain_images(*sc);
    s->swapchains.clear();
    s->inspector.reset();
    std::erase_if(inst->spaces, [s](const auto& sp) { return sp->session == s; });
    std::erase_if(inst->events, [s](const XrEventDataBuffer& e) {
        return e.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED &&
               reinterpret_cast<const XrEventDataSessionStateChanged&>(e).session == reinterpret_cast<XrSession>(s);
    });
    std::erase_if(inst->sessions, [s](const auto& p) { return p.get() == s; });
    inst->report.session_destroyed = true;
    inst->report.write();
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL BeginSession(XrSession handle, const XrSessionBeginInfo* info) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    if (s->lost) return XR_ERROR_SESSION_LOST;
    if (s->running) return XR_ERROR_SESSION_RUNNING;
    if (s->state != XR_SESSION_STATE_READY) return XR_ERROR_SESSION_NOT_READY;
    if (info->primaryViewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
        return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    Instance* inst = live_instance();
    s->running = true;
    s->begin_time = inst->clock;
    s->next_display_time = inst->clock + 2 * kPeriodNs;
    push_state(*s, XR_SESSION_STATE_SYNCHRONIZED);
    // stop@0: the user quits while the application starts; the session never becomes visible.
    if (inst->script.stop_at == 0) walk_down_to_stopping(*s);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EndSession(XrSession handle) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    if (!s->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (s->state != XR_SESSION_STATE_STOPPING) return XR_ERROR_SESSION_NOT_STOPPING;
    s->running = false;
    Instance* inst = live_instance();
    inst->report.session_ended = true;
    push_state(*s, XR_SESSION_STATE_IDLE);
    // Whether fgplay asked to leave or the user quit from the headset, the session is over.
    push_state(*s, XR_SESSION_STATE_EXITING);
    inst->report.write();
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL RequestExitSession(XrSession handle) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    if (!s->running) return XR_ERROR_SESSION_NOT_RUNNING;
    s->exit_requested = true;
    live_instance()->report.exit_requested = true;
    walk_down_to_stopping(*s);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EnumerateReferenceSpaces(XrSession handle, std::uint32_t capacity, std::uint32_t* count,
                                                        XrReferenceSpaceType* types) {
    if (!session(handle)) return XR_ERROR_HANDLE_INVALID;
    static const XrReferenceSpaceType kTypes[] = {XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL,
                                                  XR_REFERENCE_SPACE_TYPE_STAGE};
    return two_call(capacity, count, types, 3, [](XrReferenceSpaceType& t, std::size_t i) { t = kTypes[i]; });
}

XRAPI_ATTR XrResult XRAPI_CALL CreateReferenceSpace(XrSession handle, const XrReferenceSpaceCreateInfo* info, XrSpace* out) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    if (info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_VIEW && info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_LOCAL &&
        info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_STAGE)
        return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
    auto sp = std::make_unique<Space>();
    sp->session = s;
    sp->type = info->referenceSpaceType;
    sp->pose = info->poseInReferenceSpace;
    *out = reinterpret_cast<XrSpace>(sp.get());
    live_instance()->spaces.push_back(std::move(sp));
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroySpace(XrSpace handle) {
    Space* sp = space(handle);
    if (!sp) return XR_ERROR_HANDLE_INVALID;
    std::erase_if(live_instance()->spaces, [sp](const auto& p) { return p.get() == sp; });
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EnumerateSwapchainFormats(XrSession handle, std::uint32_t capacity, std::uint32_t* count,
                                                         std::int64_t* formats) {
    if (!session(handle)) return XR_ERROR_HANDLE_INVALID;
    std::vector<VkFormat> all = offered_colour_formats();
    for (VkFormat f : depth_formats()) all.push_back(f);
    return two_call(capacity, count, formats, all.size(), [&](std::int64_t& f, std::size_t i) { f = all[i]; });
}

XRAPI_ATTR XrResult XRAPI_CALL CreateSwapchain(XrSession handle, const XrSwapchainCreateInfo* info, XrSwapchain* out) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    bool known = false;
    for (VkFormat f : offered_colour_formats()) known = known || f == info->format;
    const bool depth = is_depth_format(static_cast<VkFormat>(info->format));
    for (VkFormat f : depth_formats()) known = known || f == info->format;
    if (!known) return XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED;
    if (depth != ((info->usageFlags & XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT) != 0)) return XR_ERROR_VALIDATION_FAILURE;
    if (info->width == 0 || info->height == 0 || info->width > 4096 || info->height > 4096 || info->faceCount != 1 ||
        info->arraySize != 1 || info->mipCount != 1 || info->sampleCount != 1)
        return XR_ERROR_VALIDATION_FAILURE;
    auto sc = std::make_unique<Swapchain>();
    sc->session = s;
    sc->format = static_cast<VkFormat>(info->format);
    sc->width = info->width;
    sc->height = info->height;
    // The compositor reads the images, so they are always transfer sources.
    VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                              (depth ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT) usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_SAMPLED_BIT) usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_UNORDERED_ACCESS_BIT) usage |= VK_IMAGE_USAGE_STORAGE_BIT;
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(s->physical, &props);
    for (int i = 0; i < 3; ++i) {
        VkImageCreateInfo ii{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        ii.imageType = VK_IMAGE_TYPE_2D;
        ii.format = sc->format;
        ii.extent = {sc->width, sc->height, 1};
        ii.mipLevels = 1;
        ii.arrayLayers = 1;
        ii.samples = VK_SAMPLE_COUNT_1_BIT;
        ii.tiling = VK_IMAGE_TILING_OPTIMAL;
        ii.usage = usage;
        ii.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        VkImage image = VK_NULL_HANDLE;
        if (vkCreateImage(s->device, &ii, nullptr, &image) != VK_SUCCESS) return XR_ERROR_RUNTIME_FAILURE;
        sc->images.push_back(image);
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(s->device, image, &req);
        std::uint32_t type = UINT32_MAX;
        for (std::uint32_t t = 0; t < props.memoryTypeCount && type == UINT32_MAX; ++t)
            if ((req.memoryTypeBits & (1u << t)) &&
                (props.memoryTypes[t].propertyFlags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT))
                type = t;
        if (type == UINT32_MAX) return XR_ERROR_RUNTIME_FAILURE;
        VkMemoryAllocateInfo mi{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        mi.allocationSize = req.size;
        mi.memoryTypeIndex = type;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        if (vkAllocateMemory(s->device, &mi, nullptr, &memory) != VK_SUCCESS) return XR_ERROR_RUNTIME_FAILURE;
        sc->memory.push_back(memory);
        vkBindImageMemory(s->device, image, memory, 0);
        if (depth) s->inspector->prepare_depth(image);
        else s->inspector->prepare(image);
    }
    live_instance()->report.swapchains.push_back(std::string(depth ? depth_format_name(sc->format) : colour_format_name(sc->format)) + " " + std::to_string(sc->width) +
                                                 "x" + std::to_string(sc->height));
    *out = reinterpret_cast<XrSwapchain>(sc.get());
    s->swapchains.push_back(std::move(sc));
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroySwapchain(XrSwapchain handle) {
    Swapchain* sc = swapchain(handle);
    if (!sc) return XR_ERROR_HANDLE_INVALID;
    destroy_swapchain_images(*sc);
    std::erase_if(sc->session->swapchains, [sc](const auto& p) { return p.get() == sc; });
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EnumerateSwapchainImages(XrSwapchain handle, std::uint32_t capacity, std::uint32_t* count,
                                                        XrSwapchainImageBaseHeader* images) {
    Swapchain* sc = swapchain(handle);
    if (!sc) return XR_ERROR_HANDLE_INVALID;
    if (capacity > 0 && images[0].type != XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR) return XR_ERROR_VALIDATION_FAILURE;
    auto* out = reinterpret_cast<XrSwapchainImageVulkan2KHR*>(images);
    return two_call(capacity, count, out, sc->images.size(),
                    [sc](XrSwapchainImageVulkan2KHR& img, std::size_t i) { img.image = sc->images[i]; });
}

XRAPI_ATTR XrResult XRAPI_CALL AcquireSwapchainImage(XrSwapchain handle, const XrSwapchainImageAcquireInfo*,
                                                     std::uint32_t* index) {
    Swapchain* sc = swapchain(handle);
    if (!sc) return XR_ERROR_HANDLE_INVALID;
    if (sc->acquired >= 0) return XR_ERROR_CALL_ORDER_INVALID;   // one image at a time is all fgplay needs
    sc->acquired = static_cast<std::int32_t>(sc->next);
    *index = sc->next;
    sc->next = (sc->next + 1) % static_cast<std::uint32_t>(sc->images.size());
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL WaitSwapchainImage(XrSwapchain handle, const XrSwapchainImageWaitInfo*) {
    Swapchain* sc = swapchain(handle);
    if (!sc) return XR_ERROR_HANDLE_INVALID;
    if (sc->acquired < 0 || sc->waited >= 0) return XR_ERROR_CALL_ORDER_INVALID;
    sc->waited = sc->acquired;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL ReleaseSwapchainImage(XrSwapchain handle, const XrSwapchainImageReleaseInfo*) {
    Swapchain* sc = swapchain(handle);
    if (!sc) return XR_ERROR_HANDLE_INVALID;
    if (sc->waited < 0) return XR_ERROR_CALL_ORDER_INVALID;
    sc->last_released = sc->waited;
    sc->acquired = sc->waited = -1;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL WaitFrame(XrSession handle, const XrFrameWaitInfo*, XrFrameState* state) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    if (s->lost) return XR_ERROR_SESSION_LOST;
    if (!s->running) return XR_ERROR_SESSION_NOT_RUNNING;
    Instance* inst = live_instance();
    if (s->state == XR_SESSION_STATE_SYNCHRONIZED) {
        push_state(*s, XR_SESSION_STATE_VISIBLE);
        push_state(*s, XR_SESSION_STATE_FOCUSED);
    }
    // No real display: time advances one period per frame, so every run is the same.
    XrDuration period = inst->script.period_ns(inst->report.frames_waited);
    const auto now = std::chrono::steady_clock::now();
    if (inst->stretch && inst->report.frames_waited > 0) {
        // Whole display periods that cover the time since the last wait (Monado's pacing).
        const auto since = std::chrono::duration_cast<std::chrono::nanoseconds>(now - inst->last_wait).count();
        period *= std::max<XrDuration>(1, (since + period - 1) / period);
    }
    inst->last_wait = now;
    if (inst->report.frames_waited == 0 && inst->first_period_ms > 0.0)
        period = static_cast<XrDuration>(inst->first_period_ms * 1e6);
    inst->report.longest_period_ms = std::max(inst->report.longest_period_ms, static_cast<double>(period) * 1e-6);
    s->waited_display_time = s->next_display_time;
    s->next_display_time += period;
    inst->clock += period;
    s->frame_waited = true;
    ++inst->report.frames_waited;
    state->predictedDisplayTime = s->waited_display_time;
    state->predictedDisplayPeriod = period;
    state->shouldRender = s->state == XR_SESSION_STATE_VISIBLE || s->state == XR_SESSION_STATE_FOCUSED;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL BeginFrame(XrSession handle, const XrFrameBeginInfo*) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    if (!s->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (!s->frame_waited) return XR_ERROR_CALL_ORDER_INVALID;
    s->frame_waited = false;
    s->frame_begun = true;
    s->begun = std::chrono::steady_clock::now();
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL LocateViews(XrSession handle, const XrViewLocateInfo* info, XrViewState* view_state,
                                           std::uint32_t capacity, std::uint32_t* count, XrView* views) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    Space* sp = space(info->space);
    if (!sp) return XR_ERROR_HANDLE_INVALID;
    if (info->viewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
        return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    const PoseScript& poses = live_instance()->poses;
    double t = seconds(*s, info->displayTime);
    view_state->viewStateFlags = XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT |
                                 XR_VIEW_STATE_ORIENTATION_TRACKED_BIT | XR_VIEW_STATE_POSITION_TRACKED_BIT;
    return two_call(capacity, count, views, 2, [&](XrView& v, std::size_t eye) {
        v.pose = poses.eye(t, static_cast<int>(eye));
        if (sp->type == XR_REFERENCE_SPACE_TYPE_VIEW) {
            v.pose = XrPosef{{0, 0, 0, 1}, {eye == 0 ? -0.032f : 0.032f, 0, 0}};
        }
        v.fov = poses.fov(static_cast<int>(eye));
    });
}

// Each eye, decoded as the spec says for its swapchain's format, against the PNG fgplay wrote for
// the same frame (fgplay xr --record: the layer's index among frames with a layer).
template <typename Fail>
void check_colour(const EyeImage (&eyes)[2], const std::string& folder, int layer_frame, Fail& fail) {
    RuntimeReport& report = live_instance()->report;
    char number[16];
    std::snprintf(number, sizeof number, "%06d", layer_frame);
    for (int eye = 0; eye < 2; ++eye) {
        const std::string name = eye ? "right" : "left";
        const ColourComparison c = compare_colour_with_png(eyes[eye], folder + "/" + name + "_" + number + ".png", 2.0);
        if (!c.compared) {
            fail(name + " eye: no PNG of this frame to compare its colour with (" + folder + "/" + name + "_" + number + ".png)");
            continue;
        }
        ++report.colour.eyes_compared;
        report.colour.steps = c.steps;
        report.colour.worst = std::max(report.colour.worst, c.worst);
        if (c.off > 0)
            fail(name + " eye: " + std::to_string(c.off) + " pixels differ from the PNG of the same frame by more than 2 " +
                 c.steps + " (at most " + std::to_string(c.worst) + ") once decoded as " + colour_format_name(eyes[eye].format) +
                 " says");
    }
}

void inspect(Session& s, const XrFrameEndInfo& info) {
    Instance* inst = live_instance();
    RuntimeReport& report = inst->report;
    int frame = report.frames_ended;
    if (info.displayTime != s.waited_display_time) report.fail(frame, "displayTime is not the predicted display time");
    const XrCompositionLayerProjection* projection = nullptr;
    for (std::uint32_t i = 0; i < info.layerCount; ++i)
        if (info.layers[i] && info.layers[i]->type == XR_TYPE_COMPOSITION_LAYER_PROJECTION)
            projection = reinterpret_cast<const XrCompositionLayerProjection*>(info.layers[i]);
    if (!projection) {
        report.frame_luma.push_back(-1.0);   // nothing to show: the compositor shows black
        return;
    }
    ++report.frames_with_layers;
    ++report.frames_checked;
    std::size_t failures_before = report.failures.size();
    bool bad = false;
    auto fail = [&](const std::string& what) {
        bad = true;
        report.fail(frame, what);
    };
    if (projection->viewCount != 2) return fail("the projection layer has " + std::to_string(projection->viewCount) + " views");
    if (!space(projection->space)) fail("the projection layer's space is not valid");
    EyeImage eyes[2];
    for (int eye = 0; eye < 2; ++eye) {
        const XrCompositionLayerProjectionView& v = projection->views[eye];
        const char* name = eye == 0 ? "left" : "right";
        Swapchain* sc = swapchain(v.subImage.swapchain);
        if (!sc) return fail(std::string(name) + " eye: no valid swapchain");
        if (sc->last_released < 0) return fail(std::string(name) + " eye: no swapchain image was released");
        const XrRect2Di& r = v.subImage.imageRect;
        if (r.offset.x != 0 || r.offset.y != 0 || r.extent.width != static_cast<std::int32_t>(sc->width) ||
            r.extent.height != static_cast<std::int32_t>(sc->height))
            fail(std::string(name) + " eye: the image rectangle does not cover the swapchain image");
        if (sc->width != inst->recommended_width[eye] || sc->height != inst->recommended_height[eye])
            fail(std::string(name) + " eye: the swapchain is not the recommended size");
        if (!is_colour_format(sc->format)) fail(std::string(name) + " eye: unexpected format");
        Space* sp = space(projection->space);
        if (sp && sp->type != XR_REFERENCE_SPACE_TYPE_VIEW &&
            !pose_close(v.pose, inst->poses.eye(seconds(s, info.displayTime), eye)))
            fail(std::string(name) + " eye: the layer's pose is not the pose predicted for its display time");
        try {
            eyes[eye] = s.inspector->read(sc->images[static_cast<std::size_t>(sc->last_released)], sc->format, sc->width,
                                          sc->height);
        } catch (const std::exception& e) {
            return fail(e.what());
        }
    }
    check_depth_layer(s, *projection, frame, fail);
    FrameVerdict verdict = judge_stereo_pair(eyes[0], eyes[1]);
    for (const auto& p : verdict.problems) fail(p);
    report.mean_luma_left = verdict.mean_luma[0];
    report.mean_luma_right = verdict.mean_luma[1];
    report.eyes_differ_fraction = verdict.eyes_differ_fraction;
    report.frame_luma.push_back(verdict.mean_luma[0]);
    if (const char* pngs = std::getenv("FG_XR_TEST_COLOUR_PNGS")) check_colour(eyes, pngs, report.frames_with_layers - 1, fail);
    if (const char* reference = std::getenv("FG_XR_TEST_REFERENCE")) {
        ImageDifference d = compare_with_png(eyes[0], reference);
        report.reference_compared = d.compared;
        report.reference_differ_fraction = d.differ_fraction;
        report.reference_max_diff = d.max_diff;
    }
    if (!bad && report.failures.size() == failures_before) ++report.frames_good;
    if (const char* dump = std::getenv("FG_XR_TEST_DUMP")) {
        write_eye_png(std::string(dump) + "/xr_left.png", eyes[0]);
        write_eye_png(std::string(dump) + "/xr_right.png", eyes[1]);
    }
}

XRAPI_ATTR XrResult XRAPI_CALL EndFrame(XrSession handle, const XrFrameEndInfo* info) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    if (!s->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (!s->frame_begun) return XR_ERROR_CALL_ORDER_INVALID;
    if (info->environmentBlendMode != XR_ENVIRONMENT_BLEND_MODE_OPAQUE) return XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED;
    s->frame_begun = false;
    Instance* inst = live_instance();
    inst->report.frame_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - s->begun).count());
    inspect(*s, *info);
    int ended = ++inst->report.frames_ended;
    if (ended == inst->script.stop_at) walk_down_to_stopping(*s);
    if (ended == inst->script.loss_at) {
        s->lost = true;
        push_state(*s, XR_SESSION_STATE_LOSS_PENDING);
    }
    return XR_SUCCESS;
}

// XR_FB_display_refresh_rate: the display's own rate, the scripted period's (never stretched).
XRAPI_ATTR XrResult XRAPI_CALL GetDisplayRefreshRateFB(XrSession handle, float* rate) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    Instance* inst = live_instance();
    if (!inst->refresh_rate) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (!rate) return XR_ERROR_VALIDATION_FAILURE;
    *rate = static_cast<float>(1e9 / static_cast<double>(inst->script.period_ns(std::max(0, inst->report.frames_waited - 1))));
    ++inst->report.refresh_rate_calls;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetVisibilityMaskKHR(XrSession handle, XrViewConfigurationType type, std::uint32_t view,
                                                    XrVisibilityMaskTypeKHR mask_type, XrVisibilityMaskKHR* mask) {
    Session* s = session(handle);
    if (!s) return XR_ERROR_HANDLE_INVALID;
    Instance* inst = live_instance();
    if (!inst->visibility_mask) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (view > 1) return XR_ERROR_VALIDATION_FAILURE;
    ++inst->report.visibility_mask_calls;
    std::vector<XrVector2f> vertices;
    std::vector<std::uint32_t> indices;
    if (mask_type == XR_VISIBILITY_MASK_TYPE_HIDDEN_TRIANGLE_MESH_KHR) {
        // The four corners of the view, each a right triangle with legs of 30 % of the side: the
        // lens shows an octagon.
        XrFovf f = inst->poses.fov(static_cast<int>(view));
        float l = std::tan(f.angleLeft), r = std::tan(f.angleRight), d = std::tan(f.angleDown), u = std::tan(f.angleUp);
        float cx = 0.3f * (r - l), cy = 0.3f * (u - d);
        const XrVector2f corners[4][3] = {{{l, u}, {l + cx, u}, {l, u - cy}},
                                          {{r, u}, {r, u - cy}, {r - cx, u}},
                                          {{r, d}, {r - cx, d}, {r, d + cy}},
                                          {{l, d}, {l, d + cy}, {l + cx, d}}};
        for (const auto& tri : corners)
            for (const auto& v : tri) {
                indices.push_back(static_cast<std::uint32_t>(vertices.size()));
                vertices.push_back(v);
            }
    }
    mask->vertexCountOutput = static_cast<std::uint32_t>(vertices.size());
    mask->indexCountOutput = static_cast<std::uint32_t>(indices.size());
    if (mask->vertexCapacityInput == 0 && mask->indexCapacityInput == 0) return XR_SUCCESS;
    if (mask->vertexCapacityInput < vertices.size() || mask->indexCapacityInput < indices.size())
        return XR_ERROR_SIZE_INSUFFICIENT;
    std::copy(vertices.begin(), vertices.end(), mask->vertices);
    std::copy(indices.begin(), indices.end(), mask->indices);
    return XR_SUCCESS;
}

#define FG_FN(name) {"xr" #name, reinterpret_cast<PFN_xrVoidFunction>(&name)}

}  // namespace

double session_seconds(const Session& s, XrTime t) { return static_cast<double>(t - s.begin_time) * 1e-9; }

Session* session(XrSession handle) {
    Instance* inst = live_instance();
    if (!inst) return nullptr;
    for (auto& s : inst->sessions)
        if (reinterpret_cast<XrSession>(s.get()) == handle) return s.get();
    return nullptr;
}

Swapchain* swapchain(XrSwapchain handle) {
    Instance* inst = live_instance();
    if (!inst) return nullptr;
    for (auto& s : inst->sessions)
        for (auto& sc : s->swapchains)
            if (reinterpret_cast<XrSwapchain>(sc.get()) == handle) return sc.get();
    return nullptr;
}

Space* space(XrSpace handle) {
    Instance* inst = live_instance();
    if (!inst) return nullptr;
    for (auto& sp : inst->spaces)
        if (reinterpret_cast<XrSpace>(sp.get()) == handle) return sp.get();
    return nullptr;
}

const std::vector<NamedFunction> kSessionFunctions = {
    FG_FN(CreateSession),
    FG_FN(DestroySession),
    FG_FN(BeginSession),
    FG_FN(EndSession),
    FG_FN(RequestExitSession),
    FG_FN(EnumerateReferenceSpaces),
    FG_FN(CreateReferenceSpace),
    FG_FN(DestroySpace),
    FG_FN(EnumerateSwapchainFormats),
    FG_FN(CreateSwapchain),
    FG_FN(DestroySwapchain),
    FG_FN(EnumerateSwapchainImages),
    FG_FN(AcquireSwapchainImage),
    FG_FN(WaitSwapchainImage),
    FG_FN(ReleaseSwapchainImage),
    FG_FN(WaitFrame),
    FG_FN(BeginFrame),
    FG_FN(LocateViews),
    FG_FN(EndFrame),
    FG_FN(GetVisibilityMaskKHR),
    FG_FN(GetDisplayRefreshRateFB),
};

}  // namespace fgxrt
