# fg_bench: the accuracy-versus-time benchmark behind `fgplay bench` (included from the top level,
# after runtime/: the benchmark sits above the runtime, fgplay/ above both).
# The plotting script travels inside the binary, so an installed fgplay plots without a source tree.
fg_embed(FG_EMBEDDED_BENCH_SCRIPTS SYMBOL embedded_bench_scripts BASE ${PROJECT_SOURCE_DIR}/bench
         OUTPUT ${CMAKE_BINARY_DIR}/embedded_bench_scripts.cpp FILES ${PROJECT_SOURCE_DIR}/bench/plot_bench.py)
add_library(fg_bench STATIC
  ${PROJECT_SOURCE_DIR}/bench/bench_views.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_settings.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_report.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_runner.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_command.cpp
  ${FG_EMBEDDED_BENCH_SCRIPTS})
target_include_directories(fg_bench PUBLIC ${PROJECT_SOURCE_DIR}/bench)
target_link_libraries(fg_bench PUBLIC fg_runtime CLI11::CLI11)
target_compile_options(fg_bench PRIVATE ${FG_WARNINGS})
