# fgplay view in a real X11 window (Xvfb): a few frames side by side, a screenshot of what the
# window presented, and no Vulkan validation errors.
include(${CMAKE_CURRENT_LIST_DIR}/../support/work_dir.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
# fgplay view PACK ARGS... --validation in a 320x240 Xvfb screen: its output in `out`; a failure or
# a validation error fails the test.
function(run_view)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env MESA_SHADER_CACHE_DIR=${WORK}/mesa_cache
                          ${XVFB_RUN} -a -s "-screen 0 320x240x24" ${FGPLAY} view ${PACK} ${ARGN} --validation
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 240)
  message("${out}${err}")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "Vulkan validation: 0 errors")
    message(FATAL_ERROR "fgplay view ${ARGN} failed (${rc})")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

if(CASE STREQUAL "keys")
  # The right arrow held for two frames, then "-" held: one faded snap turn and a smooth shrink.
  run_view(--frames 30 --size 32x32 --press right@2-3 --press shrink@1-30)
  if(NOT out MATCHES "snap turns: 1; world scale: 1 -> 0\\.[6-8][0-9]*, largest change per frame [01]\\.[0-9]+ %")
    message(FATAL_ERROR "the keys did not snap-turn once and shrink the viewer smoothly")
  endif()
  # The pack is read once and its scene settings decoded then, not again in any of the 30 frames.
  if(NOT out MATCHES "scene settings decoded: 1\n")
    message(FATAL_ERROR "fgplay view decoded the scene settings more than once for one pack")
  endif()
  fg_test_passed()
  return()
endif()
if(CASE STREQUAL "taa")
  # Temporal anti-aliasing with a still view: 16 frames refine it to 16 samples per pixel, then the
  # viewer renders nothing until the view moves.
  run_view(--frames 24 --size 32x32 --taa)
  if(NOT out MATCHES "still, refined to 16 samples per pixel; idle until the view moves")
    message(FATAL_ERROR "a still view with --taa did not refine and idle")
  endif()
  fg_test_passed()
  return()
endif()
if(CASE STREQUAL "governor")
  # A budget no frame can meet: the governor steps down the ladder of the benchmark's measured
  # front to its floor, says so, and the title shows the level.
  run_view(--frames 40 --size 48x48 --budget-ms 0.001 --trade-offs ${TRADE_OFFS})
  if(NOT out MATCHES "governor: ([0-9]+) levels from the Pareto front measured in")
    message(FATAL_ERROR "the governor did not read the benchmark's front")
  endif()
  math(EXPR floor "${CMAKE_MATCH_1} - 1")
  if(NOT out MATCHES "governor: at the floor" OR NOT out MATCHES "frame 40: fgplay view - [^\n]* - governor level ${floor}/${floor} ")
    message(FATAL_ERROR "the governor did not reach its floor (level ${floor}) or the title does not show it")
  endif()
  fg_test_passed()
  return()
endif()
if(CASE STREQUAL "foveated")
  # The pack's scene has a foveation block and the user says nothing: its frames carry the fovea
  # the frame graph was built with (a frame without it would leave the periphery unmarched).
  run_view(--frames 4 --size 48x48)
  fg_test_passed()
  return()
endif()
if(CASE STREQUAL "flight")
  # Autopilot straight ahead at 30 times the normal speed: the probes must stop it at the surface,
  # a head radius (0.05) away.
  run_view(--frames 60 --size 48x48 --autopilot 30 --check-collisions)
  if(NOT out MATCHES "closest head distance 0\\.0[5-9][0-9]* over 60 frames, 0 frames inside a surface")
    message(FATAL_ERROR "the flight entered the fractal or stopped far from it")
  endif()
  fg_test_passed()
  return()
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env MESA_SHADER_CACHE_DIR=${WORK}/mesa_cache
                        ${XVFB_RUN} -a -s "-screen 0 640x480x24"
                        ${FGPLAY} view ${PACK} --frames 4 --size 96x96 --side-by-side --screenshot ${WORK}/window.png --validation
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 240)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fgplay view exited with ${rc}")
endif()
if(NOT out MATCHES "frame 4: fgplay view - Mandelbulb - side by side - GPU" OR NOT out MATCHES "Vulkan validation: 0 errors")
  message(FATAL_ERROR "no frames with GPU times in the title, or validation errors")
endif()
if(NOT out MATCHES "screenshot: .*window.png \\(192x96\\)")
  message(FATAL_ERROR "no screenshot of the two-eye window")
endif()
# A flat image compresses to a few hundred bytes; the fractal does not.
file(SIZE ${WORK}/window.png bytes)
if(bytes LESS 3000)
  message(FATAL_ERROR "the window looks blank (${bytes} bytes of PNG)")
endif()
fg_test_passed()
