# CPack's pre-build script (tools/cmake/Packaging.cmake): strips every ELF file staged for the
# package as Debian's dh_strip does, symbols, the compiler's .comment and the .note sections.
# CPACK_TEMPORARY_INSTALL_DIRECTORY is the staging folder CPack sets.
file(GLOB_RECURSE staged LIST_DIRECTORIES false "${CPACK_TEMPORARY_INSTALL_DIRECTORY}/*")
find_program(strip_program NAMES strip REQUIRED)
foreach(file IN LISTS staged)
  if(IS_SYMLINK "${file}")
    continue()
  endif()
  file(READ "${file}" magic LIMIT 4 HEX)
  if(NOT magic STREQUAL "7f454c46")  # "\x7fELF"
    continue()
  endif()
  execute_process(COMMAND ${strip_program} --strip-unneeded --remove-section=.comment --remove-section=.note
                          "${file}"
                  RESULT_VARIABLE status ERROR_VARIABLE message)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "strip failed on ${file}: ${message}")
  endif()
endforeach()
