# fg_bench: the accuracy-versus-time benchmark behind `fgplay bench` (included from runtime/).
add_library(fg_bench STATIC
  ${PROJECT_SOURCE_DIR}/bench/bench_views.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_settings.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_report.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_runner.cpp
  ${PROJECT_SOURCE_DIR}/bench/frame_measures.cpp
  ${PROJECT_SOURCE_DIR}/bench/head_trace.cpp
  ${PROJECT_SOURCE_DIR}/bench/sequence_settings.cpp
  ${PROJECT_SOURCE_DIR}/bench/sequence_report.cpp
  ${PROJECT_SOURCE_DIR}/bench/sequence_runner.cpp)
target_include_directories(fg_bench PUBLIC ${PROJECT_SOURCE_DIR}/bench)
target_link_libraries(fg_bench PUBLIC fg_runtime fg_locomotion)
target_compile_definitions(fg_bench PRIVATE FG_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
target_compile_options(fg_bench PRIVATE ${FG_WARNINGS})
