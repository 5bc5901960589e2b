# fgplay as a user runs it: a bad pack is refused with the byte it broke at, a good one renders
# both eyes with only the passes asked for, and `fgplay bench --quick` writes its table, CSV and
# plots and ends on the summary line.
include(${CMAKE_CURRENT_LIST_DIR}/../support/work_dir.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(ENV{MESA_SHADER_CACHE_DISABLE} true)

function(expect_failure what pattern)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${what}: exited 0")
  endif()
  if(NOT "${out}${err}" MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: expected a message matching '${pattern}', got: ${out}${err}")
  endif()
endfunction()

expect_failure("a missing pack" "does not exist|not exist" ${FGPLAY} render ${WORK}/missing.fgpack --out ${WORK}/x)
file(WRITE ${WORK}/not_a_pack.fgpack "hello")
expect_failure("a file that is no pack" "byte 0" ${FGPLAY} render ${WORK}/not_a_pack.fgpack --out ${WORK}/x)
expect_failure("a bad size" "--size" ${FGPLAY} render ${WORK}/not_a_pack.fgpack --size 12 --out ${WORK}/x)

execute_process(COMMAND ${FGC} compile ${SOURCE}/graphs/gallery/mandelbulb.json -o ${WORK}/bulb.fgpack RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fgc compile failed on the gallery Mandelbulb")
endif()
# Frames of a still are numbered, and the closing line names the files as written.
execute_process(COMMAND ${FGPLAY} render ${WORK}/bulb.fgpack --size 16x16 --frames 2 --out ${WORK}/frames
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK}/frames/left_0001.png OR EXISTS ${WORK}/frames/left.png)
  message(FATAL_ERROR "fgplay render --frames 2: exit ${rc}, expected frames/left_0000.png and left_0001.png: ${out}${err}")
endif()
if(NOT out MATCHES "left_NNNN.png right_NNNN.png side_by_side_NNNN.png for NNNN from 0000 to 0001")
  message(FATAL_ERROR "fgplay render --frames 2 names files it did not write: ${out}")
endif()
# Counting costs GPU time: only --count does it.
if(out MATCHES "SDF evaluations")
  message(FATAL_ERROR "fgplay render counted evaluations without --count: ${out}")
endif()
expect_failure("an unknown knob" "no_such_knob" ${FGPLAY} render ${WORK}/bulb.fgpack --size 64x64 --knob no_such_knob=1
               --out ${WORK}/x)
expect_failure("an unknown output format" "--format is png, png16 or exr, not 'tiff'" ${FGPLAY} render ${WORK}/bulb.fgpack
               --path ${SOURCE}/docs/mandelbulb_flight.json --format tiff --out ${WORK}/x)
expect_failure("an output format without a path" "go with --path" ${FGPLAY} render ${WORK}/bulb.fgpack --format exr
               --out ${WORK}/x)
expect_failure("no samples" "--samples: Value 0 not in range" ${FGPLAY} render ${WORK}/bulb.fgpack --samples 0
               --out ${WORK}/x)

expect_failure("depth of field without samples" "--aperture blurs by averaging samples through the lens" ${FGPLAY} render
               ${WORK}/bulb.fgpack --size 32x32 --aperture 0.1 --out ${WORK}/x)
expect_failure("temporal upsampling without temporal anti-aliasing" "--taa-upscale resolves through temporal" ${FGPLAY}
               render ${WORK}/bulb.fgpack --size 32x32 --taa-upscale 2 --out ${WORK}/x)
expect_failure("temporal anti-aliasing in shards" "--taa carries history from frame to frame" ${FGPLAY} render
               ${WORK}/bulb.fgpack --path ${SOURCE}/docs/mandelbulb_flight.json --taa --shard 0/2 --out ${WORK}/x)

# Jittered samples of a still: the picture differs from one sample's, and the line says how many.
execute_process(COMMAND ${FGPLAY} render ${WORK}/bulb.fgpack --size 32x32 --samples 4 --out ${WORK}/samples
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
execute_process(COMMAND ${FGPLAY} render ${WORK}/bulb.fgpack --size 32x32 --out ${WORK}/one_sample
                RESULT_VARIABLE rc1 OUTPUT_VARIABLE out1 ERROR_VARIABLE err1)
file(SHA256 ${WORK}/samples/left.png four)
file(SHA256 ${WORK}/one_sample/left.png one)
if(NOT rc EQUAL 0 OR NOT rc1 EQUAL 0 OR NOT out MATCHES "32x32 per eye, 4 samples summed" OR four STREQUAL one)
  message(FATAL_ERROR "fgplay render --samples 4 failed, said no sample count, or wrote the one-sample picture: ${out}${err}")
endif()

# A camera path to OpenEXR (tests/runtime/exr_output_test.cpp reads the files back).
execute_process(COMMAND ${FGPLAY} render ${WORK}/bulb.fgpack --path ${SOURCE}/docs/mandelbulb_flight.json --frames 0:1
                        --size 32x32 --format exr --exr-compression piz --out ${WORK}/exr --no-progress --validation
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK}/exr/frame_000000.exr OR NOT out MATCHES "encoding and writing: [0-9.]+ s per frame")
  message(FATAL_ERROR "fgplay render --format exr failed or wrote no frame_000000.exr: ${out}${err}")
endif()

execute_process(COMMAND ${FGPLAY} render ${WORK}/bulb.fgpack --size 64x64 --out ${WORK}/frame --describe --lens-mask
                        --foveation 0.5 --validation --count
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fgplay render failed: ${out}${err}")
endif()
foreach(expected "fovea.left" "conemarch.right.L0.periphery" "lens mask on" "SDF evaluations per output pixel")
  string(FIND "${out}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "fgplay render printed no '${expected}':\n${out}")
  endif()
endforeach()
foreach(image left.png right.png side_by_side.png)
  if(NOT EXISTS ${WORK}/frame/${image})
    message(FATAL_ERROR "fgplay render wrote no ${image}")
  endif()
endforeach()

# Each dispatch's own time, one line per pass, and no counts (counting is off while timing).
execute_process(COMMAND ${FGPLAY} render ${WORK}/bulb.fgpack --size 48x48 --out ${WORK}/timed --time-passes
                        --lens-mask --foveation 0.5
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "\n  conemarch[.]left[.]L0[.]periphery +[0-9.]+ ms +[0-9.]+ %"
   OR NOT out MATCHES "\n  fovea[.]right +[0-9.]+ ms" OR out MATCHES "SDF evaluations")
  message(FATAL_ERROR "fgplay render --time-passes printed no line per pass, or counted: ${out}${err}")
endif()

execute_process(COMMAND ${FGPLAY} bench --graph ${SOURCE}/graphs/gallery/mandelbulb.json --quick --size 48 --frames 1
                        --compile-gallery ${SOURCE}/graphs/gallery --out ${WORK}/bench
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fgplay bench --quick failed: ${out}${err}")
endif()
foreach(file results.csv results.md results.json time_vs_error.png time_per_pass.png)
  if(NOT EXISTS ${WORK}/bench/${file})
    message(FATAL_ERROR "fgplay bench wrote no ${file}:\n${out}${err}")
  endif()
endforeach()
string(STRIP "${out}" out)
string(REGEX MATCH "[^\n]*$" last "${out}")
if(NOT last MATCHES "^summary: ")
  message(FATAL_ERROR "fgplay bench's last line is no summary: ${last}")
endif()
file(READ ${WORK}/bench/results.md table)
if(NOT table MATCHES "## Compile side")
  message(FATAL_ERROR "fgplay bench reported no compile side:\n${table}")
endif()
file(STRINGS ${WORK}/bench/results.csv rows)
list(LENGTH rows n)
if(n LESS 10)
  message(FATAL_ERROR "fgplay bench wrote ${n} CSV lines")
endif()
fg_test_passed()
