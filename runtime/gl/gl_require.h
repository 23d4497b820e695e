/*
 * gl_require.h — when may a GL consumer call a failure "no device"?
 *
 * The one rule of the test suite (and of hfstress): a GL test may skip only
 * when no GLES context of ANY kind can be made on this machine.  Every other
 * failure — a renderer that cannot be created although a context can, a
 * profile check that goes wrong, a shader that does not compile — is a broken
 * product and must fail.  CI also sets HFS_REQUIRE_GL=1, under which even "no
 * context" fails: the CI machine has Mesa, so a missing context there means
 * the set-up (or the context code) is broken.
 *
 * Call hfs_gl_missing_device() only after something GL failed; it makes (and
 * destroys) a probe context, so the caller's context state is not to be
 * trusted afterwards.
 */
#ifndef HFS_GL_REQUIRE_H
#define HFS_GL_REQUIRE_H

#include "hfshade.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 1 when HFS_REQUIRE_GL is set to 1 in the environment. */
int hfs_gl_required(void);

/* 1 when the failure may be reported as a skip: no GLES context of any kind
 * ("auto": surfaceless, then osmesa) can be made here and HFS_REQUIRE_GL is
 * not 1.  0 otherwise.  why receives one line saying which case it is:
 *   "no GLES context of any kind here: context auto: surfaceless: ...; osmesa: ..."
 *   "a GLES context can be made here (surfaceless: OpenGL ES 3.2 Mesa ...)"
 *   "HFS_REQUIRE_GL=1 and no GLES context can be made: ..." */
int hfs_gl_missing_device(hfs_error *why);

#ifdef __cplusplus
}
#endif

#endif /* HFS_GL_REQUIRE_H */
