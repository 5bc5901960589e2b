# fg_bench: the accuracy-versus-time benchmark behind `fgplay bench` (included from the top level,
# after runtime/: the benchmark sits above the runtime, fgplay/ above both).
# The plotting script travels inside the binary, so an installed fgplay plots without a source tree.
fg_embed(FG_EMBEDDED_BENCH_SCRIPTS SYMBOL embedded_bench_scripts BASE ${PROJECT_SOURCE_DIR}/bench
         OUTPUT ${CMAKE_BINARY_DIR}/embedded_bench_scripts.cpp
         FILES ${PROJECT_SOURCE_DIR}/bench/plot_bench.py ${PROJECT_SOURCE_DIR}/bench/plot_sequence.py)
# The scenes `fgplay bench --sequence` flies unless given others: three gallery graphs, carried the same way.
fg_embed(FG_EMBEDDED_SEQUENCE_SCENES SYMBOL embedded_sequence_scenes BASE ${PROJECT_SOURCE_DIR}/graphs/gallery
         OUTPUT ${CMAKE_BINARY_DIR}/embedded_sequence_scenes.cpp
         FILES ${PROJECT_SOURCE_DIR}/graphs/gallery/mandelbulb.json ${PROJECT_SOURCE_DIR}/graphs/gallery/mandelbox.json
               ${PROJECT_SOURCE_DIR}/graphs/gallery/kleinian.json)
add_library(fg_bench STATIC
  ${PROJECT_SOURCE_DIR}/bench/bench_views.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_settings.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_report.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_runner.cpp
  ${PROJECT_SOURCE_DIR}/bench/bench_command.cpp
  ${PROJECT_SOURCE_DIR}/bench/plot_script.cpp
  ${PROJECT_SOURCE_DIR}/bench/frame_measures.cpp
  ${PROJECT_SOURCE_DIR}/bench/head_trace.cpp
  ${PROJECT_SOURCE_DIR}/bench/sequence_settings.cpp
  ${PROJECT_SOURCE_DIR}/bench/sequence_report.cpp
  ${PROJECT_SOURCE_DIR}/bench/equal_picture.cpp
  ${PROJECT_SOURCE_DIR}/bench/sequence_trade_offs.cpp
  ${PROJECT_SOURCE_DIR}/bench/sequence_runner.cpp
  ${PROJECT_SOURCE_DIR}/bench/gpu_clock.cpp
  ${FG_EMBEDDED_BENCH_SCRIPTS}
  ${FG_EMBEDDED_SEQUENCE_SCENES})
target_include_directories(fg_bench PUBLIC ${PROJECT_SOURCE_DIR}/bench)
target_link_libraries(fg_bench PUBLIC fg_runtime fg_locomotion CLI11::CLI11 ${CMAKE_DL_LIBS})
target_compile_options(fg_bench PRIVATE ${FG_WARNINGS})
