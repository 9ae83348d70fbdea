# cmake -DSHADER=<GLSL source> -DOUTPUT=<header> -P CheckShaderOutput.cmake, after glslangValidator,
# which exits 0 when it cannot write its output ("ERROR: Failed to open file"): without this check
# the build would go on to a C++ error about a missing header. The custom command removes OUTPUT
# before glslangValidator, so a header left by an earlier build does not pass either.
if(NOT EXISTS "${OUTPUT}")
  # The line that names the files starts with a space: CMake prints it as is, unwrapped.
  message(FATAL_ERROR "glslangValidator did not write a shader's header:\n"
    " ${SHADER}: wrote no ${OUTPUT}\n"
    "(it exits 0 when it cannot write its output: is that folder there and writable?)")
endif()
