# fg_embed(TARGET_VAR out_cpp SYMBOL name BASE dir FILES f1 f2 ...)
# Generates a C++ file that defines `std::span<const fg::EmbeddedFile> name()` holding each file's
# path (relative to BASE) and text, so the tools carry the node library and pass templates inside
# them and never look for a source tree at run time.
set(FG_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/EmbedFiles.cmake)
function(fg_embed out_var)
  cmake_parse_arguments(E "" "SYMBOL;BASE;OUTPUT" "FILES" ${ARGN})
  add_custom_command(
    OUTPUT ${E_OUTPUT}
    COMMAND ${CMAKE_COMMAND} -DSYMBOL=${E_SYMBOL} -DBASE=${E_BASE} -DOUTPUT=${E_OUTPUT}
            "-DFILES=${E_FILES}" -P ${FG_EMBED_SCRIPT}
    DEPENDS ${E_FILES} ${FG_EMBED_SCRIPT}
    COMMENT "Embedding ${E_SYMBOL}"
    VERBATIM)
  set(${out_var} ${E_OUTPUT} PARENT_SCOPE)
endfunction()
