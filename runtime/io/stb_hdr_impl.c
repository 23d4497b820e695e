/*
 * stb_hdr_impl.c — the stb_image implementation, Radiance .hdr only, for
 * systems whose stb is header-only (io.cmake compiles this file only when
 * pkg-config finds no libstb).  Thread-local failure strings keep stb free of
 * process-wide mutable state.
 */
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_HDR
#include <stb_image.h>
