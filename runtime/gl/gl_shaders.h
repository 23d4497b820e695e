/*
 * gl_shaders.h — GLSL ES 3.00 sources embedded at build time from
 * shaders_es/<stem>.<vert|frag>.glsl (cmake/embed_shaders.cmake).  Nothing
 * is read from disk at run time.
 *
 * The files carry no #version line: hfs_gl_program_create (gl_util.h)
 * prepends "#version 300 es", the variant #defines and "#line 1", so driver
 * messages give the line numbers of the .glsl file.  When glslangValidator
 * was installed at build time every shader was validated as ES 3.00
 * (with each "// hfs-variant: NAME VALUE, ..." line of the file as well,
 * and every "// hfs-base: NAME VALUE" line's defines in each of them:
 * cmake/shader_variants.cmake).
 */
#ifndef HFS_GL_SHADERS_H
#define HFS_GL_SHADERS_H

#ifdef __cplusplus
extern "C" {
#endif

/* Source of the shader named by its file name without ".glsl"
 * ("fullscreen.vert", "pattern.frag"), or NULL.  Static storage. */
const char *hfs_shader_source(const char *name);

/* Number of embedded shaders and the name of shader i (0 <= i < count),
 * sorted by name; NULL out of range.  For tests and tools. */
int hfs_shader_count(void);
const char *hfs_shader_name(int i);

#ifdef __cplusplus
}
#endif
#endif /* HFS_GL_SHADERS_H */
