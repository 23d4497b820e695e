#!/usr/bin/env bash
# bench_gpu.sh — the real-GPU checks and frame table (BENCHMARKS.md
# "On a real GPU"): run on a machine with the GPU, from the repository
# root, with a build of the product.
#
#   tools/bench_gpu.sh BUILD [ROUNDS]      (default 2 rounds)
#
# Prints, in order: tests/test_glsl_numerics_gpu (the driver's sine, half
# rounding, LINEAR filter and the shaders' blend), the full hfstress, the
# cold frames at 256^2..2048^2 with the shaders' blend of pairs forced on
# and off (HFS_GL_PAIR_FETCH=1|0: runtime/gl/gl_probe.h; alternating, ROUNDS
# rounds), each against the CPU reference at 256^2 (fp16 and fp32), the
# 1024^2 frame timed by glFinish + clock, a warm 1024^2 frame, and the
# planner's knobs at 512^2.  Needs EGL with a GLES 3 driver (an NVIDIA
# machine: glvnd's libEGL and the vendor's EGL ICD); nothing here is a
# ctest, nothing asserts: the numbers are for the reader.
set -u
B=${1:?usage: tools/bench_gpu.sh BUILD [ROUNDS]}
R=${2:-2}
run() { echo "### $*"; timeout "${T:-300}" "$@" 2>&1; echo "rc $?"; }
run "$B/tests/test_glsl_numerics_gpu"
run "$B/tools/hfstress"
for r in $(seq "$R"); do
  for s in 256 512 1024 2048; do
    for e in 1 0; do
      run env HFS_GL_PAIR_FETCH=$e "$B/tests/gles_bench" --size "$s" --path slice --lights both \
        --cold --frames 5
    done
  done
done
for e in 1 0; do
  for p in fp16 fp32; do
    run env HFS_GL_PAIR_FETCH=$e "$B/tests/gles_bench" --size 256 --path slice --lights both \
      --frames 1 --compare --precision "$p"
  done
done
run "$B/tests/gles_bench" --size 1024 --path slice --lights both --cold --frames 5 --finish
run "$B/tests/gles_bench" --size 1024 --path slice --lights both --frames 30
run "$B/tests/bench_plan" --frames 10 --size 512 --visibility slice --env-map data/courtyard.exr
