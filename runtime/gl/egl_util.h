/*
 * egl_util.h — small EGL helpers shared by the EGL users (the library's
 * surfaceless context and the x11/kms displays).
 */
#ifndef HFS_BOARD_EGL_UTIL_H
#define HFS_BOARD_EGL_UTIL_H

#include <EGL/egl.h>

/* "EGL_BAD_ALLOC" for an eglGetError() code; static string. */
const char *hfs_egl_error_name(EGLint code);

/* 1 if word is a whole word of the space-separated list (an extension
 * string), else 0; a NULL list has no words. */
int hfs_egl_has_word(const char *list, const char *word);

#endif /* HFS_BOARD_EGL_UTIL_H */
