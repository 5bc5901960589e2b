# `fgplay bench --sequence --timing back-to-back` (a GPU's default: timed frames first, then errors and
# counts from each setting's counting renderer) measures the same frames as `--timing interleaved`
# (each timed frame read back and compared): every frame's errors, PSNR and evaluations are equal,
# the reusing settings' and the snap turn's dark frame included, and the report says how it timed;
# with --compare-every 3 the same figures on the frames it compares, blanks on the others.
include(${CMAKE_CURRENT_LIST_DIR}/../support/work_dir.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(ENV{MESA_SHADER_CACHE_DISABLE} true)

# Every column of sequence_frames.csv but the times: frame_ms (6th) and sm_clock_mhz (last).
function(measured_frames mode out)
  execute_process(COMMAND ${FGPLAY} bench --sequence --quick --no-plots --timing ${mode} --trace snap_turn
                          --out ${WORK}/${mode} ${ARGN}
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

# `measured` against `expected` (an every-frame run) line by line, the header included; where only
# one frame in `every` was compared, the others' error cells (the last six) blank, and flicker (the
# last, which needs the frame before compared too) blank on every frame.
function(expect_frames label measured expected every)
  list(LENGTH measured n_measured)
  list(LENGTH expected n)
  if(NOT n_measured EQUAL n OR n LESS 60)
    message(FATAL_ERROR "${label}: ${n_measured} lines in sequence_frames.csv, against ${n}")
  endif()
  foreach(i RANGE 1 ${n})
    math(EXPR at "${i} - 1")
    list(GET measured ${at} a)
    list(GET expected ${at} b)
    string(REPLACE "," ";" fields "${b}")
    list(GET fields 3 frame)
    if(frame MATCHES "^[0-9]+$")
      math(EXPR left_over "${frame} % ${every}")
      if(NOT left_over EQUAL 0)
        string(REGEX REPLACE "^([^,]*,[^,]*,[^,]*,[^,]*,[^,]*,[^,]*,)[^,]*,[^,]*,[^,]*,[^,]*,[^,]*,[^,]*$" "\\1,,,,," b "${b}")
      elseif(every GREATER 1)
        string(REGEX REPLACE ",[^,]*$" "," b "${b}")
      endif()
    endif()
    if(NOT a STREQUAL b)
      message(FATAL_ERROR "${label}, frame ${frame}:\n  measured: ${a}\n  expected: ${b}")
    endif()
  endforeach()
endfunction()

measured_frames(back-to-back apart)
measured_frames(interleaved together)
expect_frames("back-to-back against interleaved" "${apart}" "${together}" 1)
# --compare-every 3: the same frames, timed and counted, compared on frames 0, 3, 6 ... only, and
# the report says so.
file(REMOVE_RECURSE ${WORK}/back-to-back)
measured_frames(back-to-back sparse --compare-every 3)
expect_frames("--compare-every 3" "${sparse}" "${together}" 3)
file(READ ${WORK}/back-to-back/sequence.md md)
if(NOT md MATCHES "one frame in 3")
  message(FATAL_ERROR "sequence.md does not say errors were compared on one frame in 3")
endif()
file(READ ${WORK}/back-to-back/sequence.md md)
if(NOT md MATCHES "timed frames ran back to back")
  message(FATAL_ERROR "sequence.md does not say the frames were timed back to back")
endif()
file(READ ${WORK}/interleaved/sequence.md md)
if(md MATCHES "timed frames ran back to back")
  message(FATAL_ERROR "the interleaved run's sequence.md says its frames were timed back to back")
endif()
fg_test_passed()
