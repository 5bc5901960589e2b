#pragma once
// The benchmarks' plotting scripts travel inside the binary (bench/fg_bench.cmake), so an installed
// fgplay plots without a source tree: a script runs from a temporary copy on a results folder.
#include <string>
#include <string_view>

namespace fg::bench {

// `script`: its file name in bench/ ("plot_bench.py"). False when it is not embedded or python3
// (with matplotlib) fails.
bool run_plot_script(std::string_view script, const std::string& folder);

}  // namespace fg::bench
