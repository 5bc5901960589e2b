// Compile-time benchmark: graph -> pack for the gallery Mandelbulb, cold (first compile in the
// process: glslang's built-in symbol tables are built then) and warm.
#include <benchmark/benchmark.h>
#include <fstream>
#include <sstream>

#include "compiler.h"

namespace {

std::string gallery_graph() {
    std::ifstream in(std::string(FG_SOURCE_DIR) + "/graphs/gallery/mandelbulb.json");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void compile_once(benchmark::State& state, const std::string& text) {
    fg::Diagnostics diag;
    auto result = fg::compile_graph(text, fg::NodeLibrary::builtin(), {}, diag);
    if (!result) state.SkipWithError(diag.format().c_str());
    auto bytes = fg::pack_bytes(*result);
    benchmark::DoNotOptimize(bytes.data());
    state.counters["pack_bytes"] = static_cast<double>(bytes.size());
    state.counters["glslang_ms"] = result->times.glslang_ms;
    state.counters["spirv_opt_ms"] = result->times.optimize_ms;
}

// Runs first, once: the process's first compile includes glslang's one-time initialisation.
void BM_CompileMandelbulbCold(benchmark::State& state) {
    std::string text = gallery_graph();
    for (auto _ : state) compile_once(state, text);
}
BENCHMARK(BM_CompileMandelbulbCold)->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_CompileMandelbulbWarm(benchmark::State& state) {
    std::string text = gallery_graph();
    for (auto _ : state) compile_once(state, text);
}
BENCHMARK(BM_CompileMandelbulbWarm)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
