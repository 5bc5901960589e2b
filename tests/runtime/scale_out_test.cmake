# The Slurm job-array script (scripts/scale-out/slurm-render.sh), run as the two tasks of an
# array without Slurm, writes exactly the files one whole-range `fgplay render --path` writes; a
# task run again renders nothing (--resume), and a deleted frame is rendered again.
# Inputs: FGC, FGPLAY, SOURCE, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/../support/work_dir.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${FGC} compile ${SOURCE}/tests/runtime/data/panorama_room.json -o ${WORK}/room.fgpack
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "fgc failed: ${err}")
endif()
set(settings PACK=${WORK}/room.fgpack CAMERA=${SOURCE}/tests/runtime/data/short_path.json PROJECTION=ods SIZE=64x32
             SUPERSAMPLE=2 FGPLAY=${FGPLAY} TMPDIR=${WORK} SLURM_JOB_ID=test SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_MAX=1)

function(array_task index out_var)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${settings} SLURM_ARRAY_TASK_ID=${index} OUT=${WORK}/shards
                          bash ${SOURCE}/scripts/scale-out/slurm-render.sh
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc)
    message(FATAL_ERROR "array task ${index} failed (${rc}):\n${out}\n${err}")
  endif()
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()

array_task(1 out)
array_task(0 out)
execute_process(COMMAND ${CMAKE_COMMAND} -E env MESA_SHADER_CACHE_DIR=${WORK}/cache
                        ${FGPLAY} render ${WORK}/room.fgpack --path ${SOURCE}/tests/runtime/data/short_path.json
                        --projection ods --size 64x32 --supersample 2 --out ${WORK}/whole --no-progress
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "whole-range render failed:\n${out}\n${err}")
endif()

file(GLOB whole RELATIVE ${WORK}/whole ${WORK}/whole/frame_*)
file(GLOB shards RELATIVE ${WORK}/shards ${WORK}/shards/frame_*)
list(LENGTH whole n)
if(NOT n EQUAL 8 OR NOT "${whole}" STREQUAL "${shards}")
  message(FATAL_ERROR "expected 4 frames and 4 records in both folders:\nwhole: ${whole}\nshards: ${shards}")
endif()
foreach(f ${whole})
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/whole/${f} ${WORK}/shards/${f} RESULT_VARIABLE differ)
  if(differ)
    message(FATAL_ERROR "${f} differs between the whole range and the shards")
  endif()
endforeach()

array_task(0 out)
if(NOT out MATCHES "rendered 0 frames, skipped 2 already done")
  message(FATAL_ERROR "re-running a task should render nothing:\n${out}")
endif()
file(REMOVE ${WORK}/shards/frame_000003.png)
array_task(1 out)
if(NOT out MATCHES "rendered 1 frames, skipped 1 already done")
  message(FATAL_ERROR "re-running a task should render only the deleted frame:\n${out}")
endif()
fg_test_passed()
