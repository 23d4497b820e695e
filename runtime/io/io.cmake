# hfshade_io: file formats — height fields (PNG, PGM, PFM, ESRI .asc, raw
# float32), environment maps (Radiance .hdr, OpenEXR) and PFM/PNG output.
# Kept apart from libhfshade so that the renderer core links only
# libc/libm/EGL/GLES; this library brings libpng, stb_image and OpenEXRCore.
#
# Targets made here (global, so tests/ and tools/ can use them):
#   hfshade_io        the static library (public header io/hfs_io.h)
#   hfs_openexrcore   OpenEXRCore's C API only (not the C++ IlmImf stack)

pkg_check_modules(HFS_PNG REQUIRED IMPORTED_TARGET GLOBAL libpng16)
pkg_check_modules(HFS_STB IMPORTED_TARGET GLOBAL stb)
# OpenEXR's .pc file names the whole C++ stack; we want only the C core, so
# take its include directories and find OpenEXRCore ourselves.
pkg_check_modules(HFS_OPENEXR REQUIRED OpenEXR)
find_library(HFS_OPENEXRCORE_LIBRARY NAMES OpenEXRCore OpenEXRCore-3_1
             HINTS ${HFS_OPENEXR_LIBRARY_DIRS} REQUIRED)
if(NOT TARGET hfs_openexrcore)
  add_library(hfs_openexrcore INTERFACE)
  target_include_directories(hfs_openexrcore INTERFACE ${HFS_OPENEXR_INCLUDE_DIRS})
  target_link_libraries(hfs_openexrcore INTERFACE ${HFS_OPENEXRCORE_LIBRARY})
endif()

set(HFS_IO_DIR ${CMAKE_CURRENT_SOURCE_DIR}/io)
add_library(hfshade_io STATIC
  ${HFS_IO_DIR}/io_util.c
  ${HFS_IO_DIR}/io_output.c
  ${HFS_IO_DIR}/height_load.c
  ${HFS_IO_DIR}/height_png.c
  ${HFS_IO_DIR}/height_netpbm.c
  ${HFS_IO_DIR}/height_asc.c
  ${HFS_IO_DIR}/hole_fill.c
  ${HFS_IO_DIR}/envmap.c
  ${HFS_IO_DIR}/envmap_exr.c
  ${HFS_IO_DIR}/albedo_load.c
  ${HFS_IO_DIR}/image_write.c)
target_include_directories(hfshade_io PUBLIC ${HFS_IO_DIR})
target_compile_definitions(hfshade_io PRIVATE HFS_BUILDING_LIBRARY)
target_link_libraries(hfshade_io PUBLIC hfs_base
                      PRIVATE PkgConfig::HFS_PNG hfs_openexrcore m)

# Compiling stb's decoder ourselves also puts it under the sanitizers and the
# fuzzer's coverage, which a prebuilt libstb.so is not (tools/fuzz.sh does;
# tests/fuzz.cmake instruments this library when HFS_FUZZ is on).
option(HFS_IO_STB_HEADER_ONLY
       "Compile stb_image's Radiance decoder into hfshade_io instead of linking libstb" OFF)
if(TARGET PkgConfig::HFS_STB AND NOT HFS_IO_STB_HEADER_ONLY)
  # Debian/Ubuntu ship stb as a shared library (libstb.so).
  target_link_libraries(hfshade_io PRIVATE PkgConfig::HFS_STB)
else()
  # Header-only stb: compile its Radiance decoder, and nothing else, once.
  find_path(HFS_STB_INCLUDE_DIR stb_image.h PATH_SUFFIXES stb REQUIRED)
  target_include_directories(hfshade_io PRIVATE ${HFS_STB_INCLUDE_DIR})
  target_sources(hfshade_io PRIVATE ${HFS_IO_DIR}/stb_hdr_impl.c)
  # Third-party code: our warning set is not its contract.
  set_source_files_properties(${HFS_IO_DIR}/stb_hdr_impl.c PROPERTIES COMPILE_OPTIONS "-w")
endif()

