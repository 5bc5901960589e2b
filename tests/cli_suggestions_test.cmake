# A mistyped command or option is named, with the nearest one it could have meant, in both tools.
include(${CMAKE_CURRENT_LIST_DIR}/support/work_dir.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/scene.json "{}")
file(WRITE ${WORK}/scene.fgpack "not read: the command line is refused first")

function(expect_suggestion pattern)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${ARGN}: exited 0")
  endif()
  if(NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "${ARGN}: expected a message matching '${pattern}', got: ${out}${err}")
  endif()
  message("${ARGN}: ${err}")
endfunction()

expect_suggestion("^fgc: unknown command \"compil\"; did you mean \"compile\"\\?" ${FGC} compil ${WORK}/scene.json)
expect_suggestion("^fgc compile: unknown option \"--emit-glls\"; did you mean \"--emit-glsl\"\\?"
                  ${FGC} compile ${WORK}/scene.json --emit-glls ${WORK}/glsl)
expect_suggestion("^fgc: unknown command \"frobnicate\" \\(the commands: check, compile, info, nodes, probe, import, calibrate, export\\)"
                  ${FGC} frobnicate)
expect_suggestion("^fgplay: unknown command \"rendr\"; did you mean \"render\"\\?" ${FGPLAY} rendr ${WORK}/scene.fgpack)
expect_suggestion("^fgplay render: unknown option \"--franes\"; did you mean \"--frames\"\\?"
                  ${FGPLAY} render ${WORK}/scene.fgpack --franes 3)
expect_suggestion("^fgplay xr: unknown option \"--validaton\"; did you mean \"--validation\"\\?"
                  ${FGPLAY} xr ${WORK}/scene.fgpack --validaton)
expect_suggestion("^fgplay render: unknown option \"--zzz\" \\(fgplay render --help lists the options\\)"
                  ${FGPLAY} render ${WORK}/scene.fgpack --zzz)
fg_test_passed()
