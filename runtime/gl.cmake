# gl.cmake — hfs_gl: the GL ES 3.0 function table (gl_api.c), GL helpers
# (gl_util.c) and the shaders of ../shaders_es embedded as C (weston style).
# No GL, EGL or OSMesa library is linked: entry points come from a context
# at run time (runtime/gl/gl_context.h).  Only the Khronos headers are needed.
#
# Shaders: every shaders_es/<stem>.<vert|frag>.glsl becomes the embedded
# source "<stem>.<vert|frag>" (gl_shaders.h).  With glslangValidator
# installed, each one (and each "// hfs-variant:" of it) is validated at build
# time as GLSL ES 3.00 and an invalid shader fails the build; without it the
# step is skipped with a configure-time message.

set(HFS_GL_DIR ${CMAKE_CURRENT_LIST_DIR})
set(HFS_SHADER_DIR ${PROJECT_SOURCE_DIR}/shaders_es)
set(HFS_EMBED_SCRIPT ${PROJECT_SOURCE_DIR}/cmake/embed_shaders.cmake)
set(HFS_SHADER_GEN ${PROJECT_BINARY_DIR}/generated/shaders)
file(MAKE_DIRECTORY ${HFS_SHADER_GEN})

find_path(HFS_GLES3_INCLUDE_DIR GLES3/gl3.h)
if(NOT HFS_GLES3_INCLUDE_DIR)
  message(FATAL_ERROR "hfshade: <GLES3/gl3.h> not found (Debian: libgles-dev)")
endif()

find_program(HFS_GLSLANG_VALIDATOR glslangValidator)
if(HFS_GLSLANG_VALIDATOR)
  message(STATUS "hfshade: shaders validated at build time with ${HFS_GLSLANG_VALIDATOR}")
else()
  message(STATUS "hfshade: glslangValidator not found (glslang-tools): shaders are embedded without validation")
endif()

file(GLOB HFS_SHADERS CONFIGURE_DEPENDS ${HFS_SHADER_DIR}/*.glsl)
list(SORT HFS_SHADERS)
set(HFS_SHADER_STAMPS "")
foreach(shader IN LISTS HFS_SHADERS)
  get_filename_component(shader_file ${shader} NAME)
  if(NOT shader_file MATCHES "^[A-Za-z0-9_]+\\.(vert|frag)\\.glsl$")
    message(FATAL_ERROR "${shader}: shader files are named <stem>.vert.glsl or <stem>.frag.glsl")
  endif()
  set(stage ${CMAKE_MATCH_1})
  if(HFS_GLSLANG_VALIDATOR)
    set(stamp ${HFS_SHADER_GEN}/${shader_file}.ok)
    add_custom_command(
      OUTPUT ${stamp}
      COMMAND ${CMAKE_COMMAND} -DMODE=validate -DVALIDATOR=${HFS_GLSLANG_VALIDATOR}
              -DINPUT=${shader} -DSTAGE=${stage} -DSTAMP=${stamp} -P ${HFS_EMBED_SCRIPT}
      DEPENDS ${shader} ${HFS_EMBED_SCRIPT}
      COMMENT "Validating ${shader_file} (GLSL ES 3.00)"
      VERBATIM)
    list(APPEND HFS_SHADER_STAMPS ${stamp})
  endif()
endforeach()

string(REPLACE ";" "|" hfs_shader_inputs "${HFS_SHADERS}")
add_custom_command(
  OUTPUT ${HFS_SHADER_GEN}/hfs_shaders.c
  COMMAND ${CMAKE_COMMAND} -DMODE=embed -DOUTPUT=${HFS_SHADER_GEN}/hfs_shaders.c
          "-DINPUTS=${hfs_shader_inputs}" -P ${HFS_EMBED_SCRIPT}
  DEPENDS ${HFS_SHADERS} ${HFS_SHADER_STAMPS} ${HFS_EMBED_SCRIPT}
  COMMENT "Embedding shaders_es/*.glsl"
  VERBATIM)

add_library(hfs_gl STATIC
  ${HFS_GL_DIR}/gl_api.c
  ${HFS_GL_DIR}/gl_util.c
  ${HFS_SHADER_GEN}/hfs_shaders.c)
target_include_directories(hfs_gl PUBLIC ${HFS_GL_DIR} ${HFS_GLES3_INCLUDE_DIR})
target_compile_definitions(hfs_gl PRIVATE HFS_BUILDING_LIBRARY
                           PUBLIC GL_GLES_PROTOTYPES=0)
target_link_libraries(hfs_gl PUBLIC hfs_base)

# The GLES renderer backend built on this library (issue 3).
include(${HFS_GL_DIR}/gles/gles.cmake)
