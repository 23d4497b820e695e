# Fuzzing (label "io"): one libFuzzer target per input kind, sources in
# tests/fuzz/ (README.md there).  Each fuzz/fuzz_<target>.c is built twice:
#   - always: ctest fuzz_replay_<target> links it with fuzz/fuzz_replay.c (a
#     plain main) and replays every seed (fuzz/corpus/<target>) and every
#     former crash (fuzz/regressions/<target>) through the same entry point,
#     so the normal, Release and ASan/UBSan builds all check them;
#   - with -DHFS_FUZZ=ON (clang only): fuzz_<target> linked with libFuzzer,
#     and the libraries under test instrumented for coverage, ASan and UBSan.
#     tools/fuzz.sh configures build-fuzz/ that way, builds target hfs_fuzz
#     and runs every target for a bounded time.
set(HFS_FUZZ_DIR ${CMAKE_CURRENT_LIST_DIR}/fuzz)
set(HFS_FUZZ_IO_TARGETS height_png height_pgm height_pfm height_asc height_raw
    env_hdr env_exr pfm_image)
# A new regressions/<target> folder must reach the test's arguments.
file(GLOB HFS_FUZZ_REGRESSION_DIRS LIST_DIRECTORIES true CONFIGURE_DEPENDS
     ${HFS_FUZZ_DIR}/regressions/*)

if(HFS_FUZZ)
  if(NOT CMAKE_C_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "HFS_FUZZ=ON needs clang (CC=clang); tools/fuzz.sh sets it up")
  endif()
  set(HFS_FUZZ_SAN -fsanitize=address,undefined -fno-sanitize-recover=all
      -fno-omit-frame-pointer)
  # Coverage feedback and sanitizers inside the code under test; whatever
  # links these libraries links the sanitizer runtimes too.
  foreach(lib hfs_core hfshade_io hfshade_scene)
    if(TARGET ${lib})
      target_compile_options(${lib} PRIVATE -fsanitize=fuzzer-no-link ${HFS_FUZZ_SAN})
      target_link_options(${lib} INTERFACE -fsanitize=address,undefined)
    endif()
  endforeach()
  add_custom_target(hfs_fuzz)
endif()

function(hfs_fuzz_target name lib)
  set(src ${HFS_FUZZ_DIR}/fuzz_${name}.c ${HFS_FUZZ_DIR}/fuzz_util.c ${ARGN})
  set(inputs ${HFS_FUZZ_DIR}/corpus/${name})
  if(EXISTS ${HFS_FUZZ_DIR}/regressions/${name})
    list(APPEND inputs ${HFS_FUZZ_DIR}/regressions/${name})
  endif()
  hfs_add_test(fuzz_replay_${name} LABEL io TIMEOUT 300
               SOURCES ${src} ${HFS_FUZZ_DIR}/fuzz_replay.c LIBS ${lib} m ARGS ${inputs})
  target_include_directories(fuzz_replay_${name} PRIVATE ${HFS_FUZZ_DIR})
  # The replay's allocation limit (fuzz_replay.c): the sanitizer's own
  # where one is linked, else a malloc that checks.
  if(HFS_SANITIZE OR HFS_FUZZ)
    set_tests_properties(fuzz_replay_${name} PROPERTIES
                         ENVIRONMENT "ASAN_OPTIONS=max_allocation_size_mb=512")
  else()
    target_compile_definitions(fuzz_replay_${name} PRIVATE HFS_REPLAY_MALLOC_LIMIT)
  endif()
  if(HFS_FUZZ)
    add_executable(fuzz_${name} ${src})
    target_include_directories(fuzz_${name} PRIVATE ${HFS_FUZZ_DIR})
    target_compile_options(fuzz_${name} PRIVATE -fsanitize=fuzzer ${HFS_FUZZ_SAN})
    target_link_options(fuzz_${name} PRIVATE -fsanitize=fuzzer,address,undefined)
    target_link_libraries(fuzz_${name} PRIVATE ${lib} m)
    add_dependencies(hfs_fuzz fuzz_${name})
  endif()
endfunction()

if(TARGET hfshade_io)
  foreach(t ${HFS_FUZZ_IO_TARGETS})
    hfs_fuzz_target(${t} hfshade_io ${HFS_FUZZ_DIR}/fuzz_io.c)
  endforeach()
endif()
if(TARGET hfshade_scene)
  hfs_fuzz_target(scene hfshade_scene)
endif()
