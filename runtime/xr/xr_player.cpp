#include "xr/xr_player.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <thread>

#include <fmt/format.h>

#include "frame/frame_executor.h"
#include "frame/gpu_uniforms.h"
#include "frame/pipeline_store.h"
#include "frame/image_output.h"
#include "graph/scene_settings.h"
#include "locomotion/collision_witness.h"
#include "locomotion/viewer_step.h"
#include "pack/pack_reader.h"
#include "vk/pipeline_cache_file.h"
#include "vk/vulkan_error.h"
#include "xr/controller_actions.h"
#include "xr/depth_layer.h"
#include "xr/eye_swapchain.h"
#include "xr/swapchain_colour.h"
#include "frame/display_period.h"
#include "frame/frame_governor.h"
#include "frame/trade_off_ladder.h"
#include "xr/frame_time_log.h"
#include "xr/visibility_mask.h"
#include "xr/session_lifecycle.h"
#include "xr/vulkan_binding.h"
#include "xr/xr_error.h"
#include "xr/xr_instance.h"

namespace fg::xr {

namespace {

glm::dvec3 to_glm(const XrVector3f& v) { return {v.x, v.y, v.z}; }
glm::dquat to_glm(const XrQuaternionf& q) { return glm::dquat(q.w, q.x, q.y, q.z); }

struct PlayStats {
    int frames = 0;
    int dark_frames = 0;   // black (a snap turn's middle, the head in the surface): nothing rendered, no layer
    int inside_frames = 0;     // faded because the tracked head is at or in the surface
    int inside_black_frames = 0;   // of those, black: no layer, as at a snap turn's middle
    double darkest_inside = 1.0;
    double gpu_ms_sum = 0.0;
    double depth_ms_sum = 0.0;   // wall time of both eyes' depth layer: conversion pass, copy, wait
    std::map<std::string, double> pass_ms_sum;
};

// One session: spaces, swapchains, the frame graph, and the frame loop.
class XrPlayer {
public:
    XrPlayer(const OpenXrInstance& instance, const vk::Context& ctx, const Pack& pack, const XrPlayOptions& o)
        : instance_(instance), ctx_(ctx), pack_(pack), options_(o) {
        scene_ = pack.manifest.scene;
        origin_ = look_at(scene_.camera.position, scene_.camera.target, scene_.camera.up);

        XrGraphicsBindingVulkan2KHR binding = graphics_binding(ctx);
        XrSessionCreateInfo si{XR_TYPE_SESSION_CREATE_INFO};
        si.next = &binding;
        si.systemId = instance.system();
        check(xrCreateSession(instance.handle(), &si, &session_), "xrCreateSession");

        XrReferenceSpaceCreateInfo space{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
        space.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
        space.poseInReferenceSpace.orientation.w = 1.0f;
        check(xrCreateReferenceSpace(session_, &space, &space_), "xrCreateReferenceSpace");
        if (instance.has_refresh_rate())
            refresh_rate_ = instance.function<PFN_xrGetDisplayRefreshRateFB>("xrGetDisplayRefreshRateFB");
        if (o.controllers) {
            actions_ = std::make_unique<ControllerActions>(instance.handle(), session_);
            fmt::print("controller bindings accepted for: {}\n", fmt::join(actions_->accepted_profiles(), ", "));
        }

        std::uint32_t count = 0;
        check(xrEnumerateViewConfigurationViews(instance.handle(), instance.system(), XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO,
                                                0, &count, nullptr),
              "xrEnumerateViewConfigurationViews");
        std::vector<XrViewConfigurationView> views(count, {XR_TYPE_VIEW_CONFIGURATION_VIEW});
        check(xrEnumerateViewConfigurationViews(instance.handle(), instance.system(), XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO,
                                                count, &count, views.data()),
              "xrEnumerateViewConfigurationViews");
        if (count != 2) throw XrError(XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED, "the headset's stereo view has no two eyes");

        check(xrEnumerateSwapchainFormats(session_, 0, &count, nullptr), "xrEnumerateSwapchainFormats");
        std::vector<std::int64_t> formats(count);
        check(xrEnumerateSwapchainFormats(session_, count, &count, formats.data()), "xrEnumerateSwapchainFormats");
        format_ = choose_eye_swapchain_format(ctx, formats);
        // Each eye's swapchains at its own recommended size (a runtime may recommend different
        // ones); the frame graph renders both eyes at the larger, and each is scaled into its own.
        for (int eye = 0; eye < 2; ++eye)
            swapchains_[eye] = std::make_unique<EyeSwapchain>(session_, format_, views[eye].recommendedImageRectWidth,
                                                              views[eye].recommendedImageRectHeight);
        make_depth_swapchains(formats, views);
        base_width_ = o.width ? o.width : std::max(views[0].recommendedImageRectWidth, views[1].recommendedImageRectWidth);
        base_height_ = o.height ? o.height : std::max(views[0].recommendedImageRectHeight, views[1].recommendedImageRectHeight);
        frame_.width = base_width_;
        frame_.height = base_height_;
        GovernorSettings governing;
        governing.dynamic_resolution = o.dynamic_resolution;
        governor_ = std::make_unique<FrameGovernor>(o.ladder.empty() ? governor_ladder(pack.manifest) : o.ladder, governing);
        frame_.stereo = o.stereo;
        frame_.headset_lens = instance_.has_visibility_mask();   // update_lens_masks puts it into the frames
        frame_.cone_levels = o.cone_levels;
        frame_.knobs = o.knobs;
        frame_.taa = o.taa;
        frame_.taa_sharpen = o.taa_sharpen;
        // The swapchain's pixels are the output's: a render size of its own marches finer or coarser
        // rays that still hit by them.
        base_detail_scale_ = frame_.detail_scale =
            static_cast<double>(base_width_) / std::max(views[0].recommendedImageRectWidth, views[1].recommendedImageRectWidth);
        if (o.governor) apply(governor_->current());
        else set_taa_upscale(frame_, frame_.taa ? o.taa_upscale : 1.0);
        set_marched_size(stereo_, frame_);
        stereo_.world_scale = scene_.world_scale;
        step_ = std::make_unique<ViewerStep>(ctx, pack, origin_, o.wrap);
        if (o.check_collisions) witness_ = std::make_unique<CollisionWitness>(pack);
    }

    ~XrPlayer() {
        step_.reset();
        executor_ = nullptr;
        executors_.clear();
        for (auto& s : swapchains_) s.reset();
        actions_.reset();
        for (auto& s : depth_) s.reset();
        if (space_) xrDestroySpace(space_);
        if (session_) xrDestroySession(session_);
    }

    int run() {
        bool exit_requested = false;
        while (true) {
            SessionAction action = poll_events();
            if (action == SessionAction::Exit) break;
            if (action == SessionAction::Lost) {
                fmt::print(stderr, "fgplay xr: the OpenXR session was lost (the headset was disconnected or the runtime "
                                   "stopped); states: {}\n", fmt::join(lifecycle_.history(), " -> "));
                return 2;
            }
            if (!lifecycle_.running()) {
                std::this_thread::sleep_for(std::chrono::milliseconds(2));
                continue;
            }
            frame();
            if (options_.frames > 0 && stats_.frames + stats_.dark_frames >= options_.frames && !exit_requested) {
                check(xrRequestExitSession(session_), "xrRequestExitSession");
                exit_requested = true;
            }
        }
        return 0;
    }

    const PlayStats& stats() const { return stats_; }
    const FrameTimeLog& frame_times() const { return frame_times_; }
    // The budget the frames are held to (or would be, without the governor); 0 when none is known.
    double frame_budget_ms() { return choose_budget().ms.value_or(0.0); }
    const SessionLifecycle& lifecycle() const { return lifecycle_; }
    const FrameSettings& frame_settings() const { return frame_; }
    VkFormat format() const { return format_; }
    const EyeSwapchain& swapchain(int eye) const { return *swapchains_[eye]; }
    const VisibilityMask& visibility_mask(int eye) const { return masks_[eye]; }
    const LensEllipse& lens(int eye) const { return lenses_[eye]; }
    const CollisionWitness* witness() const { return witness_.get(); }
    const FrameGovernor& governor() const { return *governor_; }
    // Changes of level or dynamic scale, and those that continued the TAA history of the one before.
    int level_changes() const { return level_changes_; }
    int histories_taken() const { return histories_taken_; }
    bool has_depth_layer() const { return depth_[0] != nullptr; }

    // What the controls did over the session, for the log.
    std::string locomotion_summary() const {
        std::string out = fmt::format("snap turns: {} ({} frames black)\n", step_->snap().turns(),
                                      stats_.dark_frames - stats_.inside_black_frames);
        out += fmt::format("head in the surface: {} frames faded (darkest {:.2f}), {} black\n", stats_.inside_frames,
                           stats_.darkest_inside, stats_.inside_black_frames);
        out += fmt::format("world scale: {:.4g} -> {:.4g} (eye separation {:.4g} -> {:.4g} scene units), largest change per "
                           "frame {:.2f} %{}\n",
                           scale_first_, step_->play_space().world_scale(), ipd_first_, ipd_last_,
                           100.0 * step_->largest_scale_change(),
                           *step_->scale_limit() ? fmt::format(", held by the {}", step_->scale_limit()) : std::string());
        const glm::dvec3 axes = glm::inverse(origin_.orientation) * step_->flown();
        out += fmt::format("flight: {:.3f} {:.3f} {:.3f} scene units along the scene camera's right, up, back; the head's "
                           "largest coordinate {:.3g}\n",
                           axes.x, axes.y, axes.z, step_->head_extent());
        if (const auto& period = step_->period())
            out += fmt::format("looping scene: period {:g} x {:g} x {:g}, {} wraps{}\n", period->x, period->y, period->z, step_->wraps(),
                               options_.wrap ? "" : " (wrapping off)");
        return out;
    }

private:
    struct LevelExecutor {
        std::unique_ptr<FrameExecutor> executor;
        std::uint32_t width = 0, height = 0;   // the centre view it was built for
        std::uint64_t last_used = 0;           // select_executor's count when it last took it
    };
    // Executors of dynamic scales kept besides each level's own: each holds a frame graph's images
    // (with TAA a full-size history), and rebuilding one compiles nothing (prepare_levels).
    static constexpr int kKeptScales = 4;

    SessionAction poll_events() {
        while (true) {
            XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
            XrResult r = check(xrPollEvent(instance_.handle(), &event), "xrPollEvent");
            if (r == XR_EVENT_UNAVAILABLE) return SessionAction::None;
            if (event.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) return lifecycle_.on_instance_loss();
            if (event.type == XR_TYPE_EVENT_DATA_VISIBILITY_MASK_CHANGED_KHR) masks_dirty_ = true;
            if (event.type == XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED && actions_) {
                fmt::print("controllers: {}\n", actions_->current_profiles());
                std::fflush(stdout);
            }
            if (event.type != XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) continue;
            const auto& changed = reinterpret_cast<const XrEventDataSessionStateChanged&>(event);
            switch (lifecycle_.on_state(changed.state)) {
                case SessionAction::Begin: {
                    XrSessionBeginInfo bi{XR_TYPE_SESSION_BEGIN_INFO};
                    bi.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
                    check(xrBeginSession(session_, &bi), "xrBeginSession");
                    break;
                }
                case SessionAction::End: check(xrEndSession(session_), "xrEndSession"); break;
                case SessionAction::Exit: return SessionAction::Exit;
                case SessionAction::Lost: return SessionAction::Lost;
                default: break;
            }
        }
    }

    void frame() {
        XrFrameWaitInfo wi{XR_TYPE_FRAME_WAIT_INFO};
        XrFrameState fs{XR_TYPE_FRAME_STATE};
        check(xrWaitFrame(session_, &wi, &fs), "xrWaitFrame");
        display_period_.observe(static_cast<double>(fs.predictedDisplayPeriod) * 1e-6);
        const auto begin = std::chrono::steady_clock::now();
        XrFrameBeginInfo bi{XR_TYPE_FRAME_BEGIN_INFO};
        check(xrBeginFrame(session_, &bi), "xrBeginFrame");
        last_gpu_ms_ = 0.0;

        XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
        XrCompositionLayerProjectionView projection[2] = {{XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW},
                                                          {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW}};
        std::vector<const XrCompositionLayerBaseHeader*> layers;
        if (fs.shouldRender && render(fs.predictedDisplayTime, projection)) {
            layer.space = space_;
            layer.viewCount = 2;
            layer.views = projection;
            layers.push_back(reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer));
        }
        XrFrameEndInfo ei{XR_TYPE_FRAME_END_INFO};
        ei.displayTime = fs.predictedDisplayTime;
        ei.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
        ei.layerCount = static_cast<std::uint32_t>(layers.size());
        ei.layers = layers.data();
        check(xrEndFrame(session_, &ei), "xrEndFrame");
        FrameTimeRow row;
        row.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
        row.period_ms = static_cast<double>(fs.predictedDisplayPeriod) * 1e-6;
        row.gpu_ms = last_gpu_ms_;
        if (governor_) {
            row.level = governor_->level();
            row.render_scale = governor_->effective().render_scale;
        }
        frame_times_.add(row);
    }

    // Renders both eyes for the views predicted at `time`; false (no layer) when tracking is lost
    // or a snap turn has the view at black.
    bool render(XrTime time, XrCompositionLayerProjectionView* projection) {
        XrViewLocateInfo li{XR_TYPE_VIEW_LOCATE_INFO};
        li.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
        li.displayTime = time;
        li.space = space_;
        XrViewState vs{XR_TYPE_VIEW_STATE};
        XrView views[2] = {{XR_TYPE_VIEW}, {XR_TYPE_VIEW}};
        std::uint32_t count = 0;
        check(xrLocateViews(session_, &li, &vs, 2, &count, views), "xrLocateViews");
        const XrViewStateFlags needed = XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT;
        if ((vs.viewStateFlags & needed) != needed || count != 2) return false;

        // Tracking space (metres, the LOCAL space) into the scene through the play space: the scene
        // camera is its origin; flight, snap turns, world scale and wrapping move it.
        const glm::dvec3 eye_l = to_glm(views[0].pose.position), eye_r = to_glm(views[1].pose.position);
        const glm::dvec3 tracked_head = 0.5 * (eye_l + eye_r);
        const double dt = last_time_ ? static_cast<double>(time - last_time_) * 1e-9 : 0.0;
        last_time_ = time;
        const ControllerState input = actions_ ? actions_->sync(space_, time) : ControllerState{};

        // Flight: the trigger flies along the controller's aim (the gaze when the aim is not
        // tracked); without it, `--fly` flies along the gaze.
        ViewerControls controls;
        controls.dt = dt;
        controls.tracked_head = tracked_head;
        controls.tracked_orientation = to_glm(views[0].pose.orientation);
        controls.ipd_m = glm::length(eye_r - eye_l);
        controls.turn_stick = input.turn.x;
        controls.scale_stick = input.scale.y;
        controls.throttle = options_.fly;
        if (input.fly > 0.05) {
            controls.throttle = input.fly * options_.controller_speed;
            if (input.aim_valid) controls.fly_direction = input.aim_orientation * glm::dvec3(0.0, 0.0, -1.0);
        }
        const double scale_before = step_->play_space().world_scale();
        const ViewerFrame viewer = step_->step(controls);
        const HeadPose& head = viewer.head;
        if (witness_) witness_->observe(head.position);
        stereo_.ipd_m = controls.ipd_m;
        stereo_.world_scale = viewer.world_scale;
        if (ipd_first_ < 0.0) {
            ipd_first_ = controls.ipd_m * viewer.world_scale;
            scale_first_ = scale_before;
        }
        ipd_last_ = controls.ipd_m * viewer.world_scale;
        if (viewer.inside_brightness < 1.0) {
            ++stats_.inside_frames;
            stats_.darkest_inside = std::min(stats_.darkest_inside, viewer.inside_brightness);
        }
        // Black at the middle of a snap turn, or a head inside the surface: the compositor shows
        // black without a layer.
        if (viewer.brightness <= 0.0) {
            ++stats_.dark_frames;
            if (viewer.snap_brightness > 0.0) ++stats_.inside_black_frames;
            return false;
        }
        auto fov = [](const XrFovf& f) { return Fov::from_angles(f.angleLeft, f.angleRight, f.angleDown, f.angleUp); };
        // Temporal anti-aliasing jitters the rays of every frame; a wrap moves the head by whole
        // periods, where the previous frame's view no longer shows the same points.
        if (executor_ && executor_->graph().taa && step_->wraps() != wraps_seen_) executor_->forget_history();
        stereo_.jitter = executor_ ? executor_->taa_jitter() : glm::dvec2(0.0);
        wraps_seen_ = step_->wraps();
        if (options_.governor && !levels_prepared_) prepare_levels(head, fov(views[0].fov), fov(views[1].fov), viewer);
        StereoViews sv = make_stereo_views(head, fov(views[0].fov), fov(views[1].fov), stereo_);
        select_executor(sv);
        if (masks_dirty_) update_lens_masks(sv);
        if (first_time_ == 0) first_time_ = time;
        // The frame graph's settings are the player's with what the pack decides filled in (a double
        // pack's relative origins, the scene's foveation where the player says "as the scene says").
        GpuFrame gpu = make_gpu_frame(sv, executor_->graph().settings, static_cast<double>(time - first_time_) * 1e-9, viewer.world_scale,
                                      static_cast<std::uint32_t>(stats_.frames));
        put_lenses(gpu);
        executor_->set_frame(gpu);
        executor_->set_scene(viewer.scene);
        FrameStats fs = executor_->run();
        if (options_.governor) govern(fs);
        if (!options_.record.empty()) record_frame();
        swapchains_[0]->present(ctx_, executor_->image("final.left"));
        swapchains_[1]->present(ctx_, executor_->image("final.right"));
        const View* rendered[2] = {&sv.left, &sv.right};
        const auto depth_start = std::chrono::steady_clock::now();
        // Metres follow the viewer's current scale; the far plane stays the march's far limit.
        depth_projection_.far_m = static_cast<float>(scene_.max_distance / stereo_.world_scale);
        for (int eye = 0; eye < 2 && depth_[eye]; ++eye) {
            depth_[eye]->present(ctx_, executor_->image(eye ? "depth.right" : "depth.left"), rendered[eye]->fov, stereo_.world_scale,
                                 depth_projection_);
            depth_[eye]->describe(depth_info_[eye], depth_projection_);
            projection[eye].next = &depth_info_[eye];
        }
        if (depth_[0]) stats_.depth_ms_sum += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - depth_start).count();
        for (int eye = 0; eye < 2; ++eye) {
            projection[eye].pose = views[eye].pose;
            projection[eye].fov = views[eye].fov;
            projection[eye].subImage.swapchain = swapchains_[eye]->handle();
            projection[eye].subImage.imageRect = {{0, 0},
                                                  {static_cast<std::int32_t>(swapchains_[eye]->width()),
                                                   static_cast<std::int32_t>(swapchains_[eye]->height())}};
            projection[eye].subImage.imageArrayIndex = 0;
        }
        ++stats_.frames;
        if (auto it = fs.gpu_ms.find("frame"); it != fs.gpu_ms.end()) {
            stats_.gpu_ms_sum += it->second;
            last_gpu_ms_ = it->second;
        }
        for (const auto& [pass, ms] : fs.gpu_ms) stats_.pass_ms_sum[pass] += ms;
        return true;
    }

    // The PNGs `fgplay render` would write for this frame's views: what the headset must show.
    void record_frame() const {
        for (const char* eye : {"left", "right"}) {
            const VkExtent2D size = executor_->image(fmt::format("final.{}", eye)).extent();
            const auto path = std::filesystem::path(options_.record) / fmt::format("{}_{:06}.png", eye, stats_.frames);
            if (!write_png(path.string(), rgba8_from_bytes(executor_->download(fmt::format("final.{}", eye)), size.width, size.height)))
                throw std::runtime_error(fmt::format("--record: cannot write {}", path.string()));
        }
    }

    // Reads this frame's GPU time; a new level takes effect from the next frame (new sizes and
    // pipelines), logged with its reason.
    void govern(const FrameStats& fs) {
        auto it = fs.gpu_ms.find("frame");
        const auto budget = budget_ms();
        if (it == fs.gpu_ms.end() || !budget) return;
        bool changed = governor_->observe(it->second, *budget);
        ++governed_frames_;
        if (!governor_->message().empty()) {
            fmt::print("governor: {} (frame {})\n", governor_->message(), governed_frames_);
            std::fflush(stdout);
        }
        if (!changed) return;
        apply(governor_->effective());
        set_marched_size(stereo_, frame_);
    }

    // The executor of the governor's level, or of the fixed settings. Each level keeps its own, so a
    // level change swaps executors and waits for nothing; only a new field of view (a new size)
    // builds one again.
    void select_executor(const StereoViews& sv) {
        LevelExecutor& slot = level_executor(options_.governor ? governor_->setting_key() : 0, sv);
        slot.last_used = ++selections_;
        if (executor_ == slot.executor.get()) return;
        // Its own history is from when its level last ran, another view; with TAA it continues the
        // level before's, which resolves to the same size (settings_at_level).
        if (executor_) {
            ++level_changes_;
            if (slot.executor->take_history(*executor_)) ++histories_taken_;
            else slot.executor->forget_history();
        }
        executor_ = slot.executor.get();
        masks_dirty_ = true;
        drop_unused_scales();
    }

    // Beyond kKeptScales executors of dynamic scales, the least recently used goes.
    void drop_unused_scales() {
        const int per_level = governor_->most_scale_steps() + 1;
        auto dynamic = [&](int key) { return per_level > 1 && key % per_level != 0; };
        while (std::count_if(executors_.begin(), executors_.end(), [&](const auto& e) { return dynamic(e.first); }) > kKeptScales) {
            auto oldest = executors_.end();
            for (auto it = executors_.begin(); it != executors_.end(); ++it)
                if (dynamic(it->first) && it->second.executor.get() != executor_ &&
                    (oldest == executors_.end() || it->second.last_used < oldest->second.last_used))
                    oldest = it;
            ctx_.wait_idle();   // a present may still read its images
            executors_.erase(oldest);
        }
    }

    // The executor of a setting (FrameGovernor::setting_key) for the current frame settings, built
    // where it has none for these views' size. A dynamic scale's is built again on its next use: it
    // was built, run and presented once before the first frame, so it compiles nothing.
    LevelExecutor& level_executor(int key, const StereoViews& sv) {
        LevelExecutor& slot = executors_[key];
        if (slot.executor && slot.width == sv.centre.width && slot.height == sv.centre.height) return slot;
        if (slot.executor) ctx_.wait_idle();   // a present may still read its images
        if (executor_ == slot.executor.get()) executor_ = nullptr;
        slot.executor = std::make_unique<FrameExecutor>(
            ctx_, pack_, FrameGraph::build(pack_.manifest, frame_, sv.centre.width, sv.centre.height), &pipelines_, &taa_history_);
        slot.width = sv.centre.width;
        slot.height = sv.centre.height;
        return slot;
    }

    // The copies of an executor's pictures into the swapchains, made once into images of their own:
    // lavapipe compiles a blit, and a pass again for an image of a size it has not seen.
    void rehearse_presents(FrameExecutor& executor) {
        for (int eye = 0; eye < 2; ++eye) {
            swapchains_[eye]->prepare(ctx_, executor.image(eye ? "final.right" : "final.left"));
            if (depth_[eye])
                depth_[eye]->prepare(ctx_, executor.image(eye ? "depth.right" : "depth.left"), Fov{}, 1.0,
                                     depth_projection_);
        }
    }

    // The headset's own visibility mask, where it gives one, as the frame graph's lens mask: pixels
    // outside it are never marched.
    void put_lenses(GpuFrame& gpu) const {
        for (int eye = 0; eye < 2; ++eye)
            if (lenses_[eye].radius_u > 0.0) {
                gpu.views[eye].lens_centre = {static_cast<float>(lenses_[eye].centre_u), static_cast<float>(lenses_[eye].centre_v)};
                gpu.views[eye].lens_radii = {static_cast<float>(lenses_[eye].radius_u), static_cast<float>(lenses_[eye].radius_v)};
            }
    }

    // Every level's executor, at every dynamic scale, built and run once before the first frame is
    // shown: lavapipe compiles a pipeline at its first dispatch, and again for images of a size it
    // has not run (the first 32^2 frame: 0.9 s under validation), and building one
    // takes a device that waits. Settings that differ only in size share their pipelines
    // (pipelines_); the dynamic scales' executors are then dropped, and rebuilt in milliseconds.
    void prepare_levels(const HeadPose& head, const Fov& left, const Fov& right, const ViewerFrame& viewer) {
        levels_prepared_ = true;
        const auto start = std::chrono::steady_clock::now();
        for (int level = governor_->levels() - 1; level >= 0; --level) {
            for (int steps = governor_->most_scale_steps(); steps >= 0; --steps) {
                apply(governor_->effective(level, steps));
                set_marched_size(stereo_, frame_);
                const StereoViews sv = make_stereo_views(head, left, right, stereo_);
                LevelExecutor& slot = level_executor(governor_->setting_key(level, steps), sv);
                // With the lens mask, so that its tile lists' passes are compiled too.
                update_lens_masks(sv);
                GpuFrame gpu = make_gpu_frame(sv, slot.executor->graph().settings, 0.0, viewer.world_scale, 0);
                put_lenses(gpu);
                slot.executor->set_frame(gpu);
                slot.executor->set_scene(viewer.scene);
                slot.executor->run();
                slot.executor->forget_history();
                rehearse_presents(*slot.executor);
                if (steps > 0) executors_.erase(governor_->setting_key(level, steps));
            }
        }
        apply(governor_->effective());
        set_marched_size(stereo_, frame_);
        fmt::print("governor: {} levels at {} render scales each built and run once in {:.1f} s: a change waits for nothing\n",
                   governor_->levels(), governor_->most_scale_steps() + 1,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        std::fflush(stdout);
    }

    // The frame budget: --budget-ms, else the display's own refresh (XR_FB_display_refresh_rate),
    // else the display period learned from the predicted ones (display_period.h): never the first
    // frame's placeholder, never a period stretched to cover a slow application, which would never
    // ask for a cheaper frame. None yet on the first frame.
    struct Budget {
        std::optional<double> ms;
        std::string source;
    };
    Budget choose_budget() {
        Budget b;
        float hz = 0.0f;
        if (options_.budget_ms > 0.0) {
            b = {options_.budget_ms, "--budget-ms"};
        } else if (refresh_rate_ && refresh_rate_(session_, &hz) == XR_SUCCESS && hz > 0.0f) {
            b = {1000.0 / hz, fmt::format("the display's refresh rate, {:.4g} Hz", hz)};
        } else if ((b.ms = display_period_.ms())) {
            b.source = "the display period learned from the predicted ones, the first left out";
        }
        return b;
    }
    // The budget the governor holds this frame to; says which when it changes.
    std::optional<double> budget_ms() {
        const Budget b = choose_budget();
        if (b.ms && (*b.ms != budget_ms_ || b.source != budget_source_)) {
            fmt::print("governor: budget {:.4g} ms per frame ({})\n", *b.ms, b.source);
            std::fflush(stdout);
            budget_source_ = b.source;
            budget_ms_ = *b.ms;
        }
        return b.ms;
    }

    void apply(const GovernorLevel& level) {
        FrameSettings full = frame_;
        full.stereo = options_.stereo;
        full.cone_levels = options_.cone_levels;
        full.knobs = options_.knobs;
        full.detail_scale = base_detail_scale_;
        full.taa_upscale_factor = options_.taa_upscale;
        frame_ = settings_at_level(full, level, base_width_, base_height_);
    }

    // XR_KHR_composition_layer_depth where the runtime has it, in a depth format it lists.
    void make_depth_swapchains(const std::vector<std::int64_t>& formats, const std::vector<XrViewConfigurationView>& views) {
        if (!instance_.has_depth_layer()) {
            fmt::print("depth layer: the runtime has no XR_KHR_composition_layer_depth; no depth is submitted\n");
            return;
        }
        auto format = choose_depth_format(formats);
        if (!format) {
            fmt::print("depth layer: the runtime lists no D32_SFLOAT or D16_UNORM swapchain format; no depth is submitted\n");
            return;
        }
        // The projection's far plane is the march's far limit: every hit is nearer, the sky is there.
        depth_projection_.far_m = static_cast<float>(scene_.max_distance / scene_.world_scale);
        depth_projection_.near_m = std::min(0.05f, 0.01f * depth_projection_.far_m);
        // The same size as the eye's colour swapchain.
        for (int eye = 0; eye < 2; ++eye)
            depth_[eye] = std::make_unique<DepthSwapchain>(ctx_, session_, *format, views[eye].recommendedImageRectWidth,
                                                           views[eye].recommendedImageRectHeight);
        fmt::print("depth layer: XR_KHR_composition_layer_depth, {} {}x{} and {}x{}, near {:g} m, far {:g} m\n",
                   *format == VK_FORMAT_D32_SFLOAT ? "D32_SFLOAT" : "D16_UNORM", views[0].recommendedImageRectWidth,
                   views[0].recommendedImageRectHeight, views[1].recommendedImageRectWidth, views[1].recommendedImageRectHeight,
                   depth_projection_.near_m, depth_projection_.far_m);
    }

    void update_lens_masks(const StereoViews& sv) {
        masks_dirty_ = false;
        if (!instance_.has_visibility_mask()) return;
        auto get = instance_.function<PFN_xrGetVisibilityMaskKHR>("xrGetVisibilityMaskKHR");
        const View* eyes[2] = {&sv.left, &sv.right};
        for (std::uint32_t eye = 0; eye < 2; ++eye) {
            XrVisibilityMaskKHR mask{XR_TYPE_VISIBILITY_MASK_KHR};
            check(get(session_, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, eye, XR_VISIBILITY_MASK_TYPE_HIDDEN_TRIANGLE_MESH_KHR,
                      &mask),
                  "xrGetVisibilityMaskKHR");
            std::vector<XrVector2f> vertices(mask.vertexCountOutput);
            std::vector<std::uint32_t> indices(mask.indexCountOutput);
            mask.vertexCapacityInput = mask.vertexCountOutput;
            mask.vertices = vertices.data();
            mask.indexCapacityInput = mask.indexCountOutput;
            mask.indices = indices.data();
            check(get(session_, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, eye, XR_VISIBILITY_MASK_TYPE_HIDDEN_TRIANGLE_MESH_KHR,
                      &mask),
                  "xrGetVisibilityMaskKHR");
            std::vector<float> flat;
            for (const auto& v : vertices) flat.insert(flat.end(), {v.x, v.y});
            masks_[eye] = rasterize_hidden_triangles(flat, indices, eyes[eye]->fov, frame_.width, frame_.height);
            lenses_[eye] = enclosing_lens(masks_[eye], lens_ellipse(*eyes[eye]));
        }
    }

    const OpenXrInstance& instance_;
    const vk::Context& ctx_;
    const Pack& pack_;
    XrPlayOptions options_;
    SceneSettings scene_;
    HeadPose origin_;
    XrSession session_ = XR_NULL_HANDLE;
    XrSpace space_ = XR_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    std::unique_ptr<EyeSwapchain> swapchains_[2];
    std::unique_ptr<DepthSwapchain> depth_[2];
    XrCompositionLayerDepthInfoKHR depth_info_[2] = {{XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR}, {XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR}};
    DepthProjection depth_projection_;
    FrameSettings frame_;
    StereoSettings stereo_;
    PipelineStore pipelines_;
    SharedTaaHistory taa_history_;   // with TAA, every level's and scale's executor holds this one history
    std::map<int, LevelExecutor> executors_;   // per governor level (0 without the governor)
    FrameExecutor* executor_ = nullptr;        // the one in use
    bool levels_prepared_ = false;
    int level_changes_ = 0, histories_taken_ = 0;
    std::uint64_t selections_ = 0;
    int governed_frames_ = 0;   // frames whose time the governor judged, for its log
    XrTime first_time_ = 0, last_time_ = 0;
    std::unique_ptr<ControllerActions> actions_;
    double scale_first_ = 1.0, ipd_first_ = -1.0, ipd_last_ = 0.0;
    std::unique_ptr<ViewerStep> step_;
    std::unique_ptr<FrameGovernor> governor_;
    std::uint32_t base_width_ = 0, base_height_ = 0;
    int wraps_seen_ = 0;
    double base_detail_scale_ = 1.0;   // the render size's pixels per swapchain pixel at level 0
    PFN_xrGetDisplayRefreshRateFB refresh_rate_ = nullptr;   // where the runtime has XR_FB_display_refresh_rate
    DisplayPeriod display_period_;
    std::string budget_source_;
    double budget_ms_ = 0.0;
    std::unique_ptr<CollisionWitness> witness_;
    SessionLifecycle lifecycle_;
    VisibilityMask masks_[2];
    LensEllipse lenses_[2];
    bool masks_dirty_ = true;
    PlayStats stats_;
    double last_gpu_ms_ = 0.0;
    FrameTimeLog frame_times_;
};

}  // namespace

int play_xr(const XrPlayOptions& o) {
    Diagnostics diag;
    auto pack = read_pack_file(o.pack, diag);
    if (!pack) {
        fmt::print(stderr, "{}", diag.format(o.pack));
        return 1;
    }
    XrPlayOptions options = o;
    if (o.governor && !o.trade_offs.empty()) {
        try {
            auto front = read_trade_offs(o.trade_offs);
            options.ladder = trade_off_ladder(pack->manifest, front);
            fmt::print("governor: {} levels from the Pareto front measured in {}:\n{}\n", options.ladder.size(), o.trade_offs,
                       describe_trade_off_ladder(front));
        } catch (const TradeOffError& e) {
            fmt::print(stderr, "fgplay xr: --trade-offs {}\n", e.what());
            return 1;
        }
    } else if (o.governor) {
        fmt::print("governor: the fixed ladder (no --trade-offs)\n");
    }
    try {
        if (!o.record.empty()) std::filesystem::create_directories(o.record);
        OpenXrInstance instance;
        fmt::print("OpenXR runtime: {}, system: {}\n", instance.runtime_name(), instance.system_name());
        vk::ContextOptions co;
        co.validation = o.validation;
        co.device = o.device;
        co.require_timestamps = false;
        co.shader_float64 = true;   // where supported: packs of precision "double" need it
        co.hooks = vulkan_creation_hooks(instance);
        co.pipeline_cache_file = vk::user_pipeline_cache_file();
        std::size_t vk_errors = 0;
        int rc = 0;
        // The validation log outlives the context: errors at teardown (objects left when the device
        // is destroyed, under the messenger) count too.
        std::shared_ptr<const vk::ValidationLog> validation;
        {
            vk::Context ctx(co);
            if (ctx.validation_enabled()) validation = ctx.validation_log();
            fmt::print("Vulkan device: {}\n", ctx.device_name());
            {
                XrPlayer player(instance, ctx, *pack, options);
                rc = player.run();
                const auto& s = player.stats();
                const auto& f = player.frame_settings();
                fmt::print("frames: {} ({} stereo, render {}x{} per eye, swapchains {}x{} and {}x{} format {})\n", s.frames,
                           stereo_mode_name(f.stereo), f.width, f.height, player.swapchain(0).width(), player.swapchain(0).height(),
                           player.swapchain(1).width(), player.swapchain(1).height(), colour_format_name(player.format()));
                if (s.frames > 0 && !s.pass_ms_sum.empty()) {
                    std::string passes;
                    for (const auto& [pass, ms] : s.pass_ms_sum) passes += fmt::format(" {} {:.2f} ms,", pass, ms / s.frames);
                    fmt::print("mean GPU time per frame:{}\n", passes.substr(0, passes.size() - 1));
                }
                if (auto line = player.frame_times().summary(player.frame_budget_ms()); !line.empty()) fmt::print("{}\n", line);
                if (!o.frame_times.empty() && !player.frame_times().write_csv(o.frame_times))
                    throw std::runtime_error(fmt::format("--frame-times: cannot write {}", o.frame_times));
                if (player.has_depth_layer() && s.frames > 0)
                    fmt::print("depth layer: {} frames, {:.2f} ms per frame for both eyes (conversion pass, copy, wait)\n", s.frames,
                               s.depth_ms_sum / s.frames);
                fmt::print("session states: {}\n", fmt::join(player.lifecycle().history(), " -> "));
                fmt::print("{}", player.locomotion_summary());
                if (player.witness()) fmt::print("{}\n", player.witness()->summary());
                if (o.governor)
                    fmt::print("governor: ended at level {} of {} ({})\n", player.governor().level(),
                               player.governor().levels() - 1, player.governor().effective().describe());
                if (o.governor && o.taa)
                    fmt::print("governor: {} of {} changes of level or scale continued the TAA history\n", player.histories_taken(),
                               player.level_changes());
                if (instance.has_visibility_mask()) {
                    auto skipped = [&](int eye) {
                        const auto& m = player.visibility_mask(eye);
                        auto v = visible_pixels(player.lens(eye), m.width, m.height);
                        return 100.0 * static_cast<double>(std::count(v.begin(), v.end(), std::uint8_t{0})) / static_cast<double>(v.size());
                    };
                    fmt::print("lens mask (XR_KHR_visibility_mask): {} + {} hidden triangles hide {:.1f} % / {:.1f} % of the "
                               "pixels; the enclosing lens ellipse skips {:.1f} % / {:.1f} %\n",
                               player.visibility_mask(0).triangles, player.visibility_mask(1).triangles,
                               100.0 * player.visibility_mask(0).hidden_fraction(),
                               100.0 * player.visibility_mask(1).hidden_fraction(), skipped(0), skipped(1));
                }
                else
                    fmt::print("lens mask: the runtime has no XR_KHR_visibility_mask\n");
            }
            ctx.wait_idle();
        }
        vk_errors = validation ? validation->errors() : 0;
        if (validation) fmt::print("Vulkan validation: {} errors\n", vk_errors);
        const auto& xr_log = instance.messages();
        fmt::print("OpenXR messages: {} errors, {} warnings\n", xr_log.errors, xr_log.warnings);
        if (rc == 0 && (vk_errors > 0 || xr_log.errors > 0)) rc = 1;
        return rc;
    } catch (const XrError& e) {
        fmt::print(stderr, "fgplay xr: {}\n", e.what());
        return 1;
    } catch (const vk::VulkanError& e) {
        fmt::print(stderr, "fgplay xr: Vulkan: {}\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        fmt::print(stderr, "fgplay xr: {}\n", e.what());
        return 1;
    }
}

}  // namespace fg::xr
