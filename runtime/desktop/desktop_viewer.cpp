#include "desktop/desktop_viewer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include "desktop/fly_camera.h"
#include "desktop/pack_source.h"
#include "desktop/window_presenter.h"
#include "frame/frame_governor.h"
#include "frame/sample_jitter.h"
#include "frame/trade_off_ladder.h"
#include "locomotion/collision_witness.h"
#include "locomotion/viewer_step.h"
#include "graph/scene_settings.h"
#include "image_output.h"
#include "vk/pipeline_cache_file.h"
#include "vk/vulkan_error.h"

namespace fg::desktop {

namespace {

struct Input {
    double scroll = 0.0;
    bool toggle_stereo = false;
};

void on_scroll(GLFWwindow* w, double, double dy) { static_cast<Input*>(glfwGetWindowUserPointer(w))->scroll += dy; }

void on_key(GLFWwindow* w, int key, int, int action, int) {
    if (action != GLFW_PRESS) return;
    if (key == GLFW_KEY_B) static_cast<Input*>(glfwGetWindowUserPointer(w))->toggle_stereo = true;
    if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
}

// Whether a scripted key ("right@3-5") is held at `frame` (1-based).
bool scripted(const std::vector<std::string>& press, const std::string& key, int frame) {
    for (const auto& p : press) {
        int first = 0, last = 0;
        auto at = p.find('@');
        if (at == std::string::npos || p.substr(0, at) != key) continue;
        if (std::sscanf(p.c_str() + at + 1, "%d-%d", &first, &last) == 2 && frame >= first && frame <= last) return true;
        if (std::sscanf(p.c_str() + at + 1, "%d", &first) == 1 && last == 0 && frame == first) return true;
    }
    return false;
}

std::string pass_times(const FrameStats& s) {
    std::string out;
    for (const auto& [pass, ms] : s.gpu_ms)
        if (pass != "frame") out += fmt::format("{}{} {:.1f}", out.empty() ? "" : ", ", pass, ms);
    auto f = s.gpu_ms.find("frame");
    return f == s.gpu_ms.end() ? "no GPU timestamps" : fmt::format("GPU {:.1f} ms ({})", f->second, out);
}

}  // namespace

int view(const ViewOptions& o) {
    try {
        // Room for both eyes side by side; one eye is shown centred.
        WindowPresenter presenter(2 * o.width, o.height, "fgplay view");
        vk::ContextOptions co;
        co.validation = o.validation;
        co.device = o.device;
        co.require_timestamps = false;
        co.shader_float64 = true;   // where supported: packs of precision "double" need it
        co.hooks = WindowPresenter::context_hooks();
        co.pipeline_cache_file = vk::user_pipeline_cache_file();
        vk::Context ctx(co);
        struct Detach {
            WindowPresenter& p;
            ~Detach() { p.detach(); }
        } detach_before_context_ends{presenter};
        presenter.attach(ctx);

        FrameSettings frame;
        frame.width = o.width;
        frame.height = o.height;
        frame.stereo = o.stereo;
        frame.taa = o.taa;
        StereoSettings stereo;
        stereo.width = o.width;
        stereo.height = o.height;
        auto fov_of = [&](const SceneSettings& s) { return Fov::symmetric(s.camera.fov_deg, double(o.width) / o.height); };
        // Executors follow `frame` and `stereo` as they are when built: the governor's level too. A
        // graph saved again (--watch) reuses the pipelines of the passes it did not change.
        PipelineStore pipelines;
        auto build_executor = [&](const Pack& p) {
            const SceneSettings& s = p.manifest.scene;
            StereoSettings st = stereo;
            st.world_scale = s.world_scale;
            StereoViews v = make_stereo_views(HeadPose{}, fov_of(s), fov_of(s), st);
            return std::make_unique<FrameExecutor>(ctx, p, FrameGraph::build(p.manifest, frame, v.centre.width, v.centre.height),
                                                   &pipelines);
        };
        PackSource source(o.path, o.watch, build_executor);
        LoadedPack playing = source.load_now();
        // --budget-ms: the governor of `fgplay xr`, stepping along the same ladder.
        const FrameSettings full_accuracy = frame;
        std::unique_ptr<FrameGovernor> governor;
        if (o.budget_ms > 0.0) {
            std::vector<GovernorLevel> ladder;
            if (!o.trade_offs.empty()) {
                ladder = trade_off_ladder(playing.pack->manifest, read_trade_offs(o.trade_offs));
                fmt::print("governor: {} levels from the Pareto front measured in {}\n", ladder.size(), o.trade_offs);
            } else {
                ladder = governor_ladder(playing.pack->manifest);
                fmt::print("governor: the fixed ladder (no --trade-offs), {} levels\n", ladder.size());
            }
            governor = std::make_unique<FrameGovernor>(std::move(ladder));
        }
        SceneSettings scene = playing.pack->manifest.scene;
        fmt::print("fgplay view: {} on {} ({:.0f} ms to load, {:.0f} ms for pipelines)\n", o.path, ctx.device_name(),
                   playing.compile_ms, playing.pipelines_ms);
        // The mouse turns the head; the play space (viewer_step.h) sits at the head's position
        // without turning it, so the keys fly in the scene's own up and level.
        FlyCamera camera(look_at(scene.camera.position, scene.camera.target, scene.camera.up));
        auto make_step = [&](const glm::dvec3& at) {
            return std::make_unique<ViewerStep>(ctx, *playing.pack, HeadPose{at, glm::dquat(1.0, 0.0, 0.0, 0.0)}, true);
        };
        std::unique_ptr<ViewerStep> step = make_step(scene.camera.position);
        HeadPose head = camera.pose();
        std::unique_ptr<CollisionWitness> witness;
        if (o.check_collisions) witness = std::make_unique<CollisionWitness>(*playing.pack);

        Input input;
        glfwSetWindowUserPointer(presenter.window(), &input);
        glfwSetScrollCallback(presenter.window(), on_scroll);
        glfwSetKeyCallback(presenter.window(), on_key);
        bool side_by_side = o.side_by_side;
        double scale_first = scene.world_scale;
        double throttle = 1.0;   // the scroll wheel's share of the distance-proportional speed
        double last_x = 0.0, last_y = 0.0;
        glfwGetCursorPos(presenter.window(), &last_x, &last_y);
        auto last = std::chrono::steady_clock::now();
        std::string status;
        int frames = 0;
        FrameStats stats;
        bool was_converged = false;
        while (!presenter.should_close() && (o.frames == 0 || frames < o.frames)) {
            glfwPollEvents();
            auto now = std::chrono::steady_clock::now();
            double dt = std::min(0.1, std::chrono::duration<double>(now - last).count());
            last = now;

            double x = 0.0, y = 0.0;
            glfwGetCursorPos(presenter.window(), &x, &y);
            const glm::dvec3 forward_before = camera.forward();
            if (glfwGetMouseButton(presenter.window(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) camera.look(x - last_x, y - last_y);
            const double turn = dt > 0.0 ? std::acos(std::clamp(glm::dot(forward_before, camera.forward()), -1.0, 1.0)) / dt : 0.0;
            last_x = x;
            last_y = y;
            throttle = std::clamp(throttle * std::pow(1.25, input.scroll), 0.01, 100.0);
            input.scroll = 0.0;
            if (input.toggle_stereo) side_by_side = !side_by_side;
            input.toggle_stereo = false;
            auto key = [&](int k) { return glfwGetKey(presenter.window(), k) == GLFW_PRESS ? 1.0 : 0.0; };
            double fwd = key(GLFW_KEY_W) - key(GLFW_KEY_S), right = key(GLFW_KEY_D) - key(GLFW_KEY_A), up = key(GLFW_KEY_E) - key(GLFW_KEY_Q);
            glm::dmat3 basis = glm::mat3_cast(camera.pose().orientation);
            glm::dvec3 dir = fwd * -basis[2] + right * basis[0] + up * glm::dvec3(0.0, 1.0, 0.0);
            ViewerControls controls;
            // Tests fly at a fixed 90 Hz so that runs repeat; people fly in real time.
            controls.dt = o.frames > 0 ? 1.0 / 90.0 : dt;
            controls.tracked_orientation = camera.pose().orientation;
            controls.ipd_m = stereo.ipd_m;
            controls.throttle = glm::length(dir) > 0.0 ? throttle : 0.0;
            if (o.autopilot > 0.0) {
                dir = -basis[2];
                controls.throttle = o.autopilot;
            }
            controls.fly_direction = glm::length(dir) > 0.0 ? glm::normalize(dir) : dir;
            // Arrow keys snap-turn (faded, about the head); -/= shrink or grow the viewer.
            auto held = [&](int k, const char* name) { return key(k) > 0.0 || scripted(o.press, name, frames + 1); };
            controls.turn_stick = (held(GLFW_KEY_RIGHT, "right") ? 1.0 : 0.0) - (held(GLFW_KEY_LEFT, "left") ? 1.0 : 0.0);
            controls.scale_stick = (held(GLFW_KEY_EQUAL, "grow") ? 1.0 : 0.0) - (held(GLFW_KEY_MINUS, "shrink") ? 1.0 : 0.0);
            controls.look_rate = turn;
            const ViewerFrame viewer = step->step(controls);
            head = viewer.head;
            if (witness) witness->observe(head.position);

            std::string error;
            if (auto fresh = source.poll(error)) {
                ctx.wait_idle();
                playing = std::move(*fresh);
                scene = playing.pack->manifest.scene;
                // The new pack's flight starts where the viewer is, looking where it looks.
                camera = FlyCamera(head);
                step = make_step(head.position);
                status = fmt::format("reloaded {} in {:.0f} ms + {:.0f} ms pipelines", playing.pack->manifest.name, playing.compile_ms,
                                     playing.pipelines_ms);
                fmt::print("fgplay view: {}\n", status);
                std::fflush(stdout);
            } else if (!error.empty()) {
                status = "compile error, the previous pack keeps playing";
                fmt::print(stderr, "fgplay view: compile error (the previous pack keeps playing):\n{}\n", error);
            }

            stereo.world_scale = viewer.world_scale;
            const bool taa = playing.executor->graph().taa;
            stereo.jitter = playing.executor->taa_jitter();
            StereoViews views = make_stereo_views(head, fov_of(scene), fov_of(scene), stereo);
            // The frame graph's settings: the viewer's with what the pack decides filled in (a double
            // pack's relative origins, the scene's foveation where the viewer says "as the scene says").
            playing.executor->set_frame(make_gpu_frame(views, playing.executor->graph().settings, frames / 60.0, viewer.world_scale,
                                                       static_cast<std::uint32_t>(frames)));
            playing.executor->set_scene(viewer.scene);
            // A still view that has refined to 16 samples per pixel is shown as it is: no frame runs.
            const bool converged = taa && playing.executor->frame().still_frames >= playing.executor->refined_frames();
            if (!converged) stats = playing.executor->run();
            if (converged && !was_converged) {
                fmt::print("fgplay view: still, refined to {} samples per pixel; idle until the view moves\n", kRefinedFrames);
                std::fflush(stdout);
            }
            was_converged = converged;
            ++frames;
            if (governor && !converged) {
                auto gpu = stats.gpu_ms.find("frame");
                if (gpu != stats.gpu_ms.end() && governor->observe(gpu->second, o.budget_ms)) {
                    // A new level takes effect from the next frame: new sizes and pipelines.
                    frame = settings_at_level(full_accuracy, governor->current(), o.width, o.height);
                    set_marched_size(stereo, frame);
                    ctx.wait_idle();
                    auto next = build_executor(*playing.pack);
                    next->take_history(*playing.executor);   // with TAA, the picture converged so far
                    playing.executor = std::move(next);
                }
                if (!governor->message().empty()) {
                    fmt::print("governor: {}\n", governor->message());
                    std::fflush(stdout);
                }
            }
            const bool last_frame = o.frames > 0 && frames == o.frames;
            Rgba8Image shot;
            presenter.present(playing.executor->image("final.left"),
                              side_by_side ? &playing.executor->image("final.right") : nullptr,
                              last_frame && !o.screenshot.empty() ? &shot : nullptr);
            std::string title = fmt::format("fgplay view - {} - {} - {} - clearance {:.3g}{}{}{}", playing.pack->manifest.name,
                                            side_by_side ? "side by side" : "left eye", pass_times(stats),
                                            step->locomotion().guaranteed_clearance(head.position),
                                            governor ? fmt::format(" - governor level {}/{} ({})", governor->level(),
                                                                   governor->levels() - 1, governor->current().describe())
                                                     : std::string(),
                                            source.compiling() ? " - compiling" : "", status.empty() ? "" : " - " + status);
            presenter.set_title(title);
            if (frames == 1 || last_frame) {
                fmt::print("frame {}: {}\n", frames, title);
                std::fflush(stdout);   // a watcher reads the log while the preview runs
            }
            if (!shot.pixels.empty()) {
                write_png(o.screenshot, shot);
                fmt::print("screenshot: {} ({}x{})\n", o.screenshot, shot.width, shot.height);
            }
        }
        const int snap_turns = step->snap().turns();
        const double scale_last = step->play_space().world_scale(), scale_step_max = step->largest_scale_change();
        step.reset();
        ctx.wait_idle();
        fmt::print("snap turns: {}; world scale: {:.4g} -> {:.4g}, largest change per frame {:.2f} %\n", snap_turns, scale_first,
                   scale_last, 100.0 * scale_step_max);
        if (witness) fmt::print("{}\n", witness->summary());
        // Once per pack read (and per compile with --watch), never per frame: the tests hold it to that.
        fmt::print("scene settings decoded: {}\n", scene_settings_parse_count());
        if (ctx.validation_enabled()) {
            fmt::print("Vulkan validation: {} errors\n", ctx.validation_errors());
            if (ctx.validation_errors() > 0) return 1;
        }
        return 0;
    } catch (const vk::VulkanError& e) {
        fmt::print(stderr, "fgplay view: Vulkan: {}\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        fmt::print(stderr, "fgplay view: {}\n", e.what());
        return 1;
    }
}

}  // namespace fg::desktop
