#include "sequence_settings.h"

namespace fg::bench {

std::string SequenceSetting::name() const { return pixels == kAllPixels ? method : method + " with " + pixels; }

std::vector<SequenceSetting> make_sequence_settings(std::uint32_t size, bool quick) {
    FrameSettings all;
    all.width = all.height = size;
    all.stereo = StereoMode::PerEye;
    all.cone_levels = 5;
    all.foveation = 0.0;   // not the scene's: every setting says what it skips
    auto method = [](StereoMode stereo, bool persistent_lanes, FrameSettings f) {
        f.stereo = stereo;
        if (persistent_lanes) f.knobs["persistent_lanes"] = 1;
        return f;
    };
    std::vector<SequenceSetting> out;
    auto add_methods = [&](const char* pixels, const FrameSettings& f) {
        out.push_back({"naive", pixels, method(StereoMode::Naive, false, f), SequenceBaseline::Naive});
        out.push_back({"naive + persistent lanes", pixels, method(StereoMode::Naive, true, f),
                       SequenceBaseline::NaivePersistent});
        out.push_back({"per-eye", pixels, method(StereoMode::PerEye, false, f)});
        out.push_back({"per-eye + persistent lanes", pixels, method(StereoMode::PerEye, true, f)});
        FrameSettings reuse = method(StereoMode::PerEye, false, f);
        reuse.knobs["reuse"] = 1;
        out.push_back({"per-eye + reuse", pixels, reuse});
        FrameSettings history = method(StereoMode::PerEye, false, f);
        history.knobs["shade_history"] = 0.5;
        out.push_back({"per-eye + shading history", pixels, history});
    };
    add_methods(kAllPixels, all);
    if (!quick) {
        FrameSettings masked = all;
        masked.lens_mask = true;
        masked.foveation = 0.5;
        add_methods(kMaskedPixels, masked);
    }
    return out;
}

}  // namespace fg::bench
