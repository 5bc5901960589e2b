# `fgplay bench --sequence --timing back-to-back` (a GPU's default: timed frames first, then errors and
# counts from each setting's counting renderer) measures the same frames as `--timing interleaved`
# (each timed frame read back and compared): every frame's errors, PSNR and evaluations are equal,
# the reusing settings' and the snap turn's dark frame included, and the report says how it timed.
include(${CMAKE_CURRENT_LIST_DIR}/../support/work_dir.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(ENV{MESA_SHADER_CACHE_DISABLE} true)

# Every column of sequence_frames.csv but the times: frame_ms (6th) and sm_clock_mhz (last).
function(measured_frames mode out)
  execute_process(COMMAND ${FGPLAY} bench --sequence --quick --no-plots --timing ${mode} --trace snap_turn
                          --out ${WORK}/${mode}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "fgplay bench --sequence --timing ${mode} failed: ${log}${err}")
  endif()
  file(STRINGS ${WORK}/${mode}/sequence_frames.csv lines)
  set(kept "")
  foreach(line ${lines})
    string(REGEX REPLACE "^([^,]*,[^,]*,[^,]*,[^,]*,[^,]*,)[^,]*,(.*),[^,]*$" "\\1\\2" line "${line}")
    list(APPEND kept "${line}")
  endforeach()
  set(${out} "${kept}" PARENT_SCOPE)
endfunction()

measured_frames(back-to-back apart)
measured_frames(interleaved together)
list(LENGTH apart n)
if(n LESS 60)
  message(FATAL_ERROR "back-to-back: only ${n} lines in sequence_frames.csv")
endif()
foreach(i RANGE 1 ${n})
  math(EXPR at "${i} - 1")
  list(GET apart ${at} a)
  list(GET together ${at} b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "the frames differ between the timings:\n  back-to-back: ${a}\n  interleaved:  ${b}")
  endif()
endforeach()
file(READ ${WORK}/back-to-back/sequence.md md)
if(NOT md MATCHES "timed frames ran back to back")
  message(FATAL_ERROR "sequence.md does not say the frames were timed back to back")
endif()
file(READ ${WORK}/interleaved/sequence.md md)
if(md MATCHES "timed frames ran back to back")
  message(FATAL_ERROR "the interleaved run's sequence.md says its frames were timed back to back")
endif()
fg_test_passed()
