/*
 * gl_api.h — the OpenGL ES 3.0 entry points the renderer uses, as a table of
 * function pointers loaded from a context (kmscube/glmark2 style).
 *
 * Why a table: a process may hold an EGL (libglvnd) context and an OSMesa one,
 * and OSMesa is not behind libGLESv2's dispatch, so glFoo() linked from
 * libGLESv2 could reach the wrong driver.  Nothing here links a GL library;
 * <GLES3/gl3.h> is used with GL_GLES_PROTOTYPES 0 for its types only.
 *
 * Usage (runtime/gl/gl_context.h):
 *   hfs_gl gl;
 *   if (hfs_gl_load(&gl, hfs_gl_context_loader, ctx, err)) ...
 *   gl.Viewport(0, 0, w, h);
 * The pointers dispatch to the context current on the calling thread, so the
 * context they were loaded from must be current when they are called.
 *
 * The same code runs on ES 3.x and on desktop GL >= 3.3 core with
 * GL_ARB_ES3_compatibility (osmesa); the capability fields below say what
 * differs.  Stick to the ES 3.0 subset: e.g. always bind a vertex array
 * (core profile draws nothing without one), no GL_LUMINANCE/ALPHA formats,
 * no client-side vertex arrays, and enable GL_PRIMITIVE_RESTART_FIXED_INDEX
 * before relying on restart (always on in ES, off by default on desktop).
 */
#ifndef HFS_GL_API_H
#define HFS_GL_API_H

#ifndef GL_GLES_PROTOTYPES
#define GL_GLES_PROTOTYPES 0
#endif
#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>

#include "hfshade.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Required entry points: X(PFN type, member); the GL name is "gl" member. */
#define HFS_GL_FUNCTIONS(X)                                                  \
    /* state, queries, errors */                                             \
    X(PFNGLGETERRORPROC, GetError)                                           \
    X(PFNGLGETSTRINGPROC, GetString)                                         \
    X(PFNGLGETSTRINGIPROC, GetStringi)                                       \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                     \
    X(PFNGLGETFLOATVPROC, GetFloatv)                                         \
    X(PFNGLGETINTERNALFORMATIVPROC, GetInternalformativ)                     \
    X(PFNGLENABLEPROC, Enable)                                               \
    X(PFNGLDISABLEPROC, Disable)                                             \
    X(PFNGLISENABLEDPROC, IsEnabled)                                         \
    X(PFNGLFINISHPROC, Finish)                                               \
    X(PFNGLFLUSHPROC, Flush)                                                 \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                                     \
    X(PFNGLVIEWPORTPROC, Viewport)                                           \
    X(PFNGLSCISSORPROC, Scissor)                                             \
    X(PFNGLCOLORMASKPROC, ColorMask)                                         \
    X(PFNGLDEPTHMASKPROC, DepthMask)                                         \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                         \
    X(PFNGLBLENDFUNCPROC, BlendFunc)                                         \
    X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                         \
    X(PFNGLBLENDEQUATIONPROC, BlendEquation)                                 \
    X(PFNGLCLEARCOLORPROC, ClearColor)                                       \
    X(PFNGLCLEARPROC, Clear)                                                 \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                                 \
    X(PFNGLCLEARBUFFERIVPROC, ClearBufferiv)                                 \
    X(PFNGLCLEARBUFFERUIVPROC, ClearBufferuiv)                               \
    /* shaders and programs */                                               \
    X(PFNGLCREATESHADERPROC, CreateShader)                                   \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                   \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                                 \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                     \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                           \
    X(PFNGLDELETESHADERPROC, DeleteShader)                                   \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                 \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                   \
    X(PFNGLDETACHSHADERPROC, DetachShader)                                   \
    X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation)                       \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                     \
    X(PFNGLVALIDATEPROGRAMPROC, ValidateProgram)                             \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                   \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                         \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                       \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                 \
    X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation)                         \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                       \
    X(PFNGLGETACTIVEUNIFORMPROC, GetActiveUniform)                           \
    X(PFNGLGETUNIFORMBLOCKINDEXPROC, GetUniformBlockIndex)                   \
    X(PFNGLUNIFORMBLOCKBINDINGPROC, UniformBlockBinding)                     \
    /* uniforms (the *v forms set arrays: count elements from location) */   \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                                         \
    X(PFNGLUNIFORM2IPROC, Uniform2i)                                         \
    X(PFNGLUNIFORM1IVPROC, Uniform1iv)                                       \
    X(PFNGLUNIFORM2IVPROC, Uniform2iv)                                       \
    X(PFNGLUNIFORM4IVPROC, Uniform4iv)                                       \
    X(PFNGLUNIFORM1UIPROC, Uniform1ui)                                       \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                                         \
    X(PFNGLUNIFORM2FPROC, Uniform2f)                                         \
    X(PFNGLUNIFORM3FPROC, Uniform3f)                                         \
    X(PFNGLUNIFORM4FPROC, Uniform4f)                                         \
    X(PFNGLUNIFORM1FVPROC, Uniform1fv)                                       \
    X(PFNGLUNIFORM2FVPROC, Uniform2fv)                                       \
    X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                       \
    X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                       \
    X(PFNGLUNIFORMMATRIX2FVPROC, UniformMatrix2fv)                           \
    X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                           \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                           \
    /* textures (2D, 2D array) and samplers */                               \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                 \
    X(PFNGLGENTEXTURESPROC, GenTextures)                                     \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                               \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                                     \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                 \
    X(PFNGLTEXPARAMETERFPROC, TexParameterf)                                 \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                       \
    X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                                 \
    X(PFNGLTEXIMAGE3DPROC, TexImage3D)                                       \
    X(PFNGLTEXSUBIMAGE3DPROC, TexSubImage3D)                                 \
    X(PFNGLTEXSTORAGE2DPROC, TexStorage2D)                                   \
    X(PFNGLTEXSTORAGE3DPROC, TexStorage3D)                                   \
    X(PFNGLCOPYTEXSUBIMAGE2DPROC, CopyTexSubImage2D)                         \
    X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)                               \
    X(PFNGLGENSAMPLERSPROC, GenSamplers)                                     \
    X(PFNGLDELETESAMPLERSPROC, DeleteSamplers)                               \
    X(PFNGLBINDSAMPLERPROC, BindSampler)                                     \
    X(PFNGLSAMPLERPARAMETERIPROC, SamplerParameteri)                         \
    /* framebuffers and renderbuffers */                                     \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                             \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                       \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                             \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                   \
    X(PFNGLFRAMEBUFFERTEXTURELAYERPROC, FramebufferTextureLayer)             \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)             \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)               \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                     \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                                       \
    X(PFNGLREADPIXELSPROC, ReadPixels)                                       \
    X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                             \
    X(PFNGLINVALIDATEFRAMEBUFFERPROC, InvalidateFramebuffer)                 \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                           \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                     \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                           \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                     \
    X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample) \
    /* buffers, vertex arrays, drawing */                                    \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                                       \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                 \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                       \
    X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                               \
    X(PFNGLBINDBUFFERRANGEPROC, BindBufferRange)                             \
    X(PFNGLBUFFERDATAPROC, BufferData)                                       \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                                 \
    X(PFNGLMAPBUFFERRANGEPROC, MapBufferRange)                               \
    X(PFNGLUNMAPBUFFERPROC, UnmapBuffer)                                     \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                             \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                       \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                             \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)             \
    X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray)           \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                     \
    X(PFNGLVERTEXATTRIBIPOINTERPROC, VertexAttribIPointer)                   \
    X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor)                     \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                                       \
    X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)                     \
    X(PFNGLDRAWELEMENTSPROC, DrawElements)                                   \
    /* queries (occlusion / transform feedback in ES 3.0; timing below) */   \
    X(PFNGLGENQUERIESPROC, GenQueries)                                       \
    X(PFNGLDELETEQUERIESPROC, DeleteQueries)                                 \
    X(PFNGLBEGINQUERYPROC, BeginQuery)                                       \
    X(PFNGLENDQUERYPROC, EndQuery)                                           \
    X(PFNGLGETQUERYIVPROC, GetQueryiv)                                       \
    X(PFNGLGETQUERYOBJECTUIVPROC, GetQueryObjectuiv)                         \
    /* sync */                                                               \
    X(PFNGLFENCESYNCPROC, FenceSync)                                         \
    X(PFNGLCLIENTWAITSYNCPROC, ClientWaitSync)                               \
    X(PFNGLWAITSYNCPROC, WaitSync)                                           \
    X(PFNGLDELETESYNCPROC, DeleteSync)

typedef struct hfs_gl {
#define HFS_GL_MEMBER_(type, name) type name;
    HFS_GL_FUNCTIONS(HFS_GL_MEMBER_)
#undef HFS_GL_MEMBER_

    /* Optional: GPU timing.  Non-NULL only when timer_query is set.  On ES
     * they are glQueryCounterEXT / glGetQueryObjectui64vEXT
     * (GL_EXT_disjoint_timer_query: use GL_TIME_ELAPSED_EXT with
     * BeginQuery/EndQuery, and check GL_GPU_DISJOINT_EXT before trusting a
     * result); on desktop the GL 3.3 core functions (no disjoint flag: do not
     * query GL_GPU_DISJOINT_EXT there, it is GL_INVALID_ENUM).  llvmpipe
     * (Mesa 22.3) answers GL_TIME_ELAPSED with a timestamp, not a duration;
     * pairs of QueryCounter(GL_TIMESTAMP_EXT) are right everywhere. */
    PFNGLQUERYCOUNTEREXTPROC QueryCounter;
    PFNGLGETQUERYOBJECTUI64VEXTPROC GetQueryObjectui64v;

    /* What this GL is and can do, read by hfs_gl_load. */
    int is_es;              /* 1: OpenGL ES; 0: desktop core (osmesa)        */
    int major, minor;       /* GL_VERSION                                    */
    int render_half_float;  /* R16F/RG16F/RGBA16F colour-renderable: ES with
                               EXT_color_buffer_half_float or _float, ES 3.2,
                               or desktop                                     */
    int render_float;       /* R32F..RGBA32F colour-renderable               */
    int float_linear;       /* 32F textures filterable (OES_texture_float_linear
                               on ES; 16F always is)                          */
    int timer_query;        /* QueryCounter/GetQueryObjectui64v usable       */
} hfs_gl;

/* Loads every entry point through proc(user, "glName") and reads the version
 * and capabilities.  The context proc belongs to must be current.  Fails with
 * HFS_E_CONTEXT when no context is current or a required function is missing,
 * HFS_E_UNSUPPORTED when the GL is neither ES >= 3.0 nor desktop >= 3.3 with
 * GL_ARB_ES3_compatibility.  On failure *gl is zeroed. */
int hfs_gl_load(hfs_gl *gl, void *(*proc)(void *user, const char *name), void *user,
                hfs_error *err);

/* 1 if the current context lists the extension (GL_NUM_EXTENSIONS /
 * glGetStringi).  Desktop contexts list GL_ARB_* names, not ES ones. */
int hfs_gl_has_extension(const hfs_gl *gl, const char *name);

/* "GL_INVALID_OPERATION", ...; static strings. */
const char *hfs_gl_error_name(GLenum code);

/* Reads glGetError once; on an error returns HFS_E_GL with "WHAT: GL_..." in
 * err and drains the remaining queued errors (they are reported together as
 * "(+N more)"). */
int hfs_gl_check(const hfs_gl *gl, const char *what, hfs_error *err);

#ifdef __cplusplus
}
#endif
#endif /* HFS_GL_API_H */
