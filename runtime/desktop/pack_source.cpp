#include "desktop/pack_source.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compiler.h"

namespace fg::desktop {

namespace {
double ms_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}
}  // namespace

PackSource::PackSource(std::string path, bool watch, ExecutorFactory factory)
    : path_(std::move(path)), watch_(watch), factory_(std::move(factory)) {
    is_graph_ = std::filesystem::path(path_).extension() == ".json";
}

PackSource::~PackSource() {
    if (pending_.valid()) pending_.wait();
}

PackSource::Outcome PackSource::build() const {
    Outcome out;
    Diagnostics diag;
    auto start = std::chrono::steady_clock::now();
    LoadedPack loaded;
    if (is_graph_) {
        std::ifstream in(path_, std::ios::binary);
        if (!in) {
            out.error = path_ + ": cannot read the graph";
            return out;
        }
        std::stringstream text;
        text << in.rdbuf();
        CompileOptions options;
        options.cache = pass_cache_.get();
        options.folder = std::filesystem::path(path_).parent_path().string();
        auto result = compile_graph(text.str(), NodeLibrary::builtin(), options, diag);
        if (!result) {
            out.error = diag.format(path_);
            return out;
        }
        auto pack = read_pack(pack_bytes(*result), diag);
        if (!pack) {
            out.error = diag.format(path_);
            return out;
        }
        loaded.pack = std::make_unique<Pack>(std::move(*pack));
    } else {
        auto pack = read_pack_file(path_, diag);
        if (!pack) {
            out.error = diag.format(path_);
            return out;
        }
        loaded.pack = std::make_unique<Pack>(std::move(*pack));
    }
    loaded.compile_ms = ms_since(start);
    start = std::chrono::steady_clock::now();
    try {
        loaded.executor = factory_(*loaded.pack);
    } catch (const std::exception& e) {
        out.error = path_ + ": " + e.what();
        return out;
    }
    loaded.pipelines_ms = ms_since(start);
    out.loaded = std::move(loaded);
    return out;
}

LoadedPack PackSource::load_now() {
    std::error_code ec;
    stamp_ = std::filesystem::last_write_time(path_, ec);
    Outcome o = build();
    if (!o.loaded) throw std::runtime_error(o.error);
    return std::move(*o.loaded);
}

std::optional<LoadedPack> PackSource::poll(std::string& error) {
    error.clear();
    if (pending_.valid()) {
        if (pending_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
        Outcome o = pending_.get();
        if (!o.loaded) {
            error = o.error;
            return std::nullopt;
        }
        return std::move(o.loaded);
    }
    if (!watch_ || ms_since(last_check_) < 200.0) return std::nullopt;
    last_check_ = std::chrono::steady_clock::now();
    std::error_code ec;
    auto stamp = std::filesystem::last_write_time(path_, ec);
    if (ec || stamp == stamp_) return std::nullopt;
    stamp_ = stamp;
    pending_ = std::async(std::launch::async, [this] { return build(); });
    return std::nullopt;
}

}  // namespace fg::desktop
