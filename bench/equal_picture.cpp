#include "equal_picture.h"

#include <fmt/format.h>

namespace fg::bench {

std::vector<EqualPicture> cheapest_at_naive_picture(const std::vector<SequenceRow>& rows) {
    std::vector<EqualPicture> out;
    for (const auto& naive : rows) {
        if (naive.setting.method != "naive" || !naive.error.empty() || naive.rendered == 0) continue;
        EqualPicture e{naive.scene, naive.trace, naive.setting.pixels, &naive, nullptr, &naive};
        for (const auto& r : rows) {
            if (&r == &naive || r.scene != naive.scene || r.trace != naive.trace ||
                r.setting.pixels != naive.setting.pixels || !r.error.empty() || r.rendered == 0)
                continue;
            if (r.picture_psnr_median > e.best->picture_psnr_median) e.best = &r;
            if (r.picture_psnr_median >= naive.picture_psnr_median && r.median_ms < naive.median_ms &&
                (!e.cheapest || r.median_ms < e.cheapest->median_ms))
                e.cheapest = &r;
        }
        out.push_back(e);
    }
    return out;
}

std::string equal_picture_markdown(const std::vector<EqualPicture>& entries) {
    std::string md =
        "\n## Time at naive's picture\n\nFor each trace, the cheapest setting whose picture (median PSNR against "
        "the ground truth, over the pixels the headset shows) is at least naive 1 spp's, and its median GPU "
        "time against naive's; the best picture of any setting beside it.\n\n"
        "| scene | trace | pixels | naive 1 spp | cheapest at its picture | × faster | best picture |\n"
        "|---|---|---|---|---|---:|---|\n";
    for (const auto& e : entries) {
        const auto cell = [](const SequenceRow* r) {
            return fmt::format("{}: {:.1f} ms, {:.1f} dB", r->setting.method, r->median_ms, r->picture_psnr_median);
        };
        md += fmt::format("| {} | {} | {} | {:.1f} ms, {:.1f} dB | {} | {} | {} |\n", e.scene, e.trace, e.pixels,
                          e.naive->median_ms, e.naive->picture_psnr_median,
                          e.cheapest ? cell(e.cheapest) : std::string("none"),
                          e.cheapest ? fmt::format("{:.2f}", e.naive->median_ms / e.cheapest->median_ms) : "",
                          cell(e.best));
    }
    return md;
}

}  // namespace fg::bench
