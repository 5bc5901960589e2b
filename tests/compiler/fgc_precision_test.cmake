# fgc compile --precision: double is recorded in the pack and shown by fgc info; the option
# overrides the graph's scene.precision either way; anything else is refused before compiling.
include(${CMAKE_CURRENT_LIST_DIR}/../support/work_dir.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${FGC} compile ${SOURCE}/graphs/gallery/mandelbulb.json --precision double -o ${WORK}/double.fgpack
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "precision:  double")
  message(FATAL_ERROR "fgc compile --precision double: ${rc}\n${out}\n${err}")
endif()
execute_process(COMMAND ${FGC} info ${WORK}/double.fgpack --json RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "\"precision\": \"double\"")
  message(FATAL_ERROR "the manifest does not say double: ${out}")
endif()
execute_process(COMMAND ${FGC} compile ${SOURCE}/graphs/hard/deep_zoom.json --precision float -o ${WORK}/float.fgpack
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR out MATCHES "precision:  double")
  message(FATAL_ERROR "--precision float did not override the graph's double: ${out}")
endif()
execute_process(COMMAND ${FGC} compile ${SOURCE}/graphs/gallery/mandelbulb.json --precision quad -o ${WORK}/quad.fgpack
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0 OR EXISTS ${WORK}/quad.fgpack)
  message(FATAL_ERROR "fgc compile accepted --precision quad")
endif()
fg_test_passed()
