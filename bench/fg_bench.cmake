# fg_bench: the accuracy-versus-time benchmark behind `fgplay bench` (included from runtime/).
add_library(fg_bench STATIC
  ${PROJECT_SOURCE_DIR}/bench/bench_views.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_settings.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_report.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_runner.cpp)
target_include_directories(fg_bench PUBLIC ${PROJECT_SOURCE_DIR}/bench)
target_link_libraries(fg_bench PUBLIC fg_runtime)
target_compile_definitions(fg_bench PRIVATE FG_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
target_compile_options(fg_bench PRIVATE ${FG_WARNINGS})
