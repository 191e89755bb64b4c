# Every shader stage in shaders/ is flattened (#include resolved, as the runtime does it) and checked
# by glslangValidator; a broken shader fails the build with the validator's message. All files in
# shaders/ are then embedded into the binary, so an installed tstyles needs no source tree.

add_executable(shader_flatten tools/shader_flatten.cpp src/gl/shader_preprocessor.cpp)
target_include_directories(shader_flatten PRIVATE include)
target_compile_options(shader_flatten PRIVATE ${TSTYLES_WARNINGS})

file(GLOB TSTYLES_SHADER_FILES CONFIGURE_DEPENDS
     ${CMAKE_SOURCE_DIR}/shaders/*.glsl ${CMAKE_SOURCE_DIR}/shaders/*.vert
     ${CMAKE_SOURCE_DIR}/shaders/*.frag ${CMAKE_SOURCE_DIR}/shaders/*.geom
     ${CMAKE_SOURCE_DIR}/shaders/*.comp)

set(TSTYLES_SHADER_STAMPS "")
foreach(shader ${TSTYLES_SHADER_FILES})
  get_filename_component(name ${shader} NAME)
  get_filename_component(extension ${shader} LAST_EXT)
  if(extension STREQUAL ".glsl")
    continue()  # include files are checked inside every stage that includes them
  endif()
  if(name STREQUAL "raycast.frag")
    continue()  # a template: every variant of it is checked below
  endif()
  set(flat ${CMAKE_BINARY_DIR}/shaders_flat/${name})
  set(stamp ${CMAKE_BINARY_DIR}/shaders_flat/${name}.validated)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/shaders_flat
    COMMAND shader_flatten ${CMAKE_SOURCE_DIR}/shaders ${name} ${flat}
    COMMAND ${CMAKE_COMMAND} -DVALIDATOR=${GLSLANG_VALIDATOR} -DSHADER=${flat} -DSTAMP=${stamp}
            -P ${CMAKE_SOURCE_DIR}/tools/cmake/ValidateShader.cmake
    DEPENDS ${TSTYLES_SHADER_FILES} shader_flatten ${CMAKE_SOURCE_DIR}/tools/cmake/ValidateShader.cmake
    COMMENT "Validating shaders/${name} with glslangValidator"
    VERBATIM)
  list(APPEND TSTYLES_SHADER_STAMPS ${stamp})
endforeach()
# The raycasting template in every variant a frame can request (RaycastVariant).
add_executable(validate_raycast_variants tools/validate_raycast_variants.cpp src/render/raycast_variant.cpp
               src/gl/shader_preprocessor.cpp)
target_include_directories(validate_raycast_variants PRIVATE include shaders)
target_link_libraries(validate_raycast_variants PRIVATE tstyles_model)
target_compile_options(validate_raycast_variants PRIVATE ${TSTYLES_WARNINGS})
set(variants_stamp ${CMAKE_BINARY_DIR}/shaders_flat/raycast_variants.validated)
add_custom_command(
  OUTPUT ${variants_stamp}
  COMMAND validate_raycast_variants ${CMAKE_SOURCE_DIR}/shaders ${GLSLANG_VALIDATOR}
          ${CMAKE_BINARY_DIR}/shaders_flat/raycast_variants ${variants_stamp}
  DEPENDS ${TSTYLES_SHADER_FILES} validate_raycast_variants
  COMMENT "Validating every raycasting variant with glslangValidator"
  VERBATIM)
list(APPEND TSTYLES_SHADER_STAMPS ${variants_stamp})

add_custom_target(tstyles_shaders_validated ALL DEPENDS ${TSTYLES_SHADER_STAMPS})

set(TSTYLES_EMBEDDED_SHADERS_CPP ${CMAKE_BINARY_DIR}/generated/embedded_shaders.cpp)
add_custom_command(
  OUTPUT ${TSTYLES_EMBEDDED_SHADERS_CPP}
  COMMAND ${CMAKE_COMMAND} -DOUTPUT=${TSTYLES_EMBEDDED_SHADERS_CPP}
          -DSHADER_DIR=${CMAKE_SOURCE_DIR}/shaders -P ${CMAKE_SOURCE_DIR}/tools/cmake/EmbedShaders.cmake
  DEPENDS ${TSTYLES_SHADER_FILES} ${CMAKE_SOURCE_DIR}/tools/cmake/EmbedShaders.cmake
  COMMENT "Embedding shaders/ into the binary"
  VERBATIM)
