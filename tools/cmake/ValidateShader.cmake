# Runs glslangValidator on one flattened shader. On failure prints its message with each
# source-string number ("ERROR: N:L:") replaced by the shader file it stands for.
execute_process(COMMAND ${VALIDATOR} ${SHADER} RESULT_VARIABLE result OUTPUT_VARIABLE output
                ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  file(STRINGS ${SHADER}.files names)
  set(index 0)
  foreach(name ${names})
    string(REGEX REPLACE "(ERROR|WARNING): ${index}:" "\\1: shaders/${name}:" output "${output}")
    math(EXPR index "${index} + 1")
  endforeach()
  message(FATAL_ERROR "glslangValidator rejected ${SHADER}:\n${output}")
endif()
file(TOUCH ${STAMP})
