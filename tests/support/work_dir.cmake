# For cmake-script tests: each runs in its own folder, ${WORK} (made empty at its start), and
# removes it when it passes; a failing test leaves it to look at. FG_KEEP_TEST_FILES=1 keeps it
# always (to make the docs' pictures from a test's dumps).
macro(fg_test_passed)
  if(NOT "$ENV{FG_KEEP_TEST_FILES}" STREQUAL "1")
    file(REMOVE_RECURSE ${WORK})
  endif()
endmacro()
