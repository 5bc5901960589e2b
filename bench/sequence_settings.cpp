#include "sequence_settings.h"

#include <fmt/format.h>

#include "frame/frame_arguments.h"

namespace fg::bench {

std::string SequenceSetting::name() const { return pixels == kAllPixels ? method : method + " with " + pixels; }

std::string SequenceVariant::method() const {
    // No commas: the name is a CSV cell.
    std::string out = "per-eye +";
    for (const auto& [knob, value] : knobs) out += fmt::format(" {}={:g}", knob, value);
    return out;
}

bool parse_sequence_variant(const std::string& text, SequenceVariant& out, std::string& error) {
    std::vector<std::string> parts;
    for (std::size_t at = 0; at <= text.size();) {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        parts.push_back(text.substr(at, comma - at));
        at = comma + 1;
    }
    out.knobs.clear();
    if (!parse_knobs(parts, out.knobs, error)) {
        error = fmt::format("--variant takes knob=value[,knob=value], not '{}'", text);
        return false;
    }
    return true;
}

std::vector<SequenceSetting> make_sequence_settings(std::uint32_t size, bool quick,
                                                    const std::vector<SequenceVariant>& variants) {
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
        for (const auto& v : variants) {
            FrameSettings changed = method(StereoMode::PerEye, false, f);
            for (const auto& [knob, value] : v.knobs) changed.knobs[knob] = value;
            out.push_back({v.method(), pixels, changed});
        }
        FrameSettings reuse = method(StereoMode::PerEye, false, f);
        reuse.knobs["reuse"] = 1;
        out.push_back({"per-eye + reuse", pixels, reuse});
        FrameSettings history = method(StereoMode::PerEye, false, f);
        history.knobs["shade_history"] = 0.5;
        out.push_back({"per-eye + shading history", pixels, history});
        FrameSettings taa = method(StereoMode::PerEye, false, f);
        taa.taa = true;
        out.push_back({"per-eye + TAA", pixels, taa});
        for (double upscale : {1.5, 2.0}) {
            FrameSettings taau = taa;
            set_taa_upscale(taau, upscale);
            out.push_back({fmt::format("per-eye + TAAU {:g}", upscale), pixels, taau});
        }
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
