/*
 * resources.c — see resources.h.
 */
#include "resources.h"

#include "gl_util.h"

#include <string.h>

GLuint hfs_gles_tex_new(const hfs_gl *gl, GLenum target, GLenum fmt, int w, int h, int layers,
                        int linear)
{
    GLuint t = 0;
    gl->GenTextures(1, &t);
    gl->BindTexture(target, t);
    if (target == GL_TEXTURE_2D_ARRAY)
        gl->TexStorage3D(target, 1, fmt, w, h, layers);
    else
        gl->TexStorage2D(target, 1, fmt, w, h);
    const GLint f = linear ? GL_LINEAR : GL_NEAREST;
    gl->TexParameteri(target, GL_TEXTURE_MIN_FILTER, f);
    gl->TexParameteri(target, GL_TEXTURE_MAG_FILTER, f);
    gl->TexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->BindTexture(target, 0);
    return t;
}

void hfs_gles_tex_delete(const hfs_gl *gl, GLuint *t)
{
    if (*t)
        gl->DeleteTextures(1, t);
    *t = 0;
}

static void fbo_delete(const hfs_gl *gl, GLuint *f)
{
    if (*f)
        gl->DeleteFramebuffers(1, f);
    *f = 0;
}

/* What an incomplete attachment usually means: a texture the driver did
 * not allocate (llvmpipe: past its memory for one texture). */
static const char *attachment_note(GLenum status)
{
    return status == GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT
               ? ": an attachment the driver could not allocate, too large for its memory"
               : "";
}

int hfs_gles_fbo_new(const hfs_gl *gl, GLuint *fbo, int n, const GLuint *tex, const int *layer,
                     const char *what, hfs_error *err)
{
    gl->GenFramebuffers(1, fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, *fbo);
    GLenum bufs[4];
    for (int i = 0; i < n; ++i) {
        if (layer && layer[i] >= 0)
            gl->FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + (GLenum)i, tex[i],
                                        0, layer[i]);
        else
            gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + (GLenum)i,
                                     GL_TEXTURE_2D, tex[i], 0);
        bufs[i] = GL_COLOR_ATTACHMENT0 + (GLenum)i;
    }
    gl->DrawBuffers(n, bufs);
    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "backend gles: %s framebuffer incomplete "
                        "(0x%x%s)", what, (unsigned)status, attachment_note(status));
    return hfs_gl_check(gl, what, err);
}

int hfs_gles_fbo_layers(const hfs_gl *gl, GLuint fbo, GLuint tex, int layer0, int outs,
                        const char *what, hfs_error *err)
{
    gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
    /* Attachments past 4 exist only where the context has them (the
     * caller's outs come from hfs_gl_caps): touch no more. */
    GLenum bufs[HFS_GLES_MAX_OUTS];
    if (outs > HFS_GLES_MAX_OUTS)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "backend gles: %s: %d targets (at most %d)", what,
                        outs, HFS_GLES_MAX_OUTS);
    for (int o = 0; o < (outs > 4 ? outs : 4); ++o) {
        gl->FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + (GLenum)o,
                                    o < outs ? tex : 0, 0, o < outs ? layer0 + o : 0);
        bufs[o] = GL_COLOR_ATTACHMENT0 + (GLenum)o;
    }
    gl->DrawBuffers(outs, bufs);
    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "backend gles: %s framebuffer incomplete (0x%x%s)",
                        what, (unsigned)status, attachment_note(status));
    return HFS_OK;
}

void hfs_gles_draw(const hfs_gl *gl, GLuint fbo, int w, int h)
{
    gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl->Viewport(0, 0, w, h);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
}

void hfs_gles_ubo_upload(const hfs_gl *gl, GLuint ubo, const void *data, size_t bytes)
{
    gl->BindBuffer(GL_UNIFORM_BUFFER, ubo);
    gl->BufferData(GL_UNIFORM_BUFFER, (GLsizeiptr)(bytes ? bytes : 16), data, GL_DYNAMIC_DRAW);
    gl->BindBuffer(GL_UNIFORM_BUFFER, 0);
}

/* Deletes n textures and the framebuffer drawing into them. */
static void targets_delete(const hfs_gl *gl, GLuint *tex, int n, GLuint *fbo)
{
    for (int i = 0; i < n; ++i)
        hfs_gles_tex_delete(gl, &tex[i]);
    fbo_delete(gl, fbo);
}

static void grid_free(hfs_gles_resources *r, const hfs_gl *gl)
{
    targets_delete(gl, r->venv, 4, &r->venv_fbo);
    r->venv_bytes = 0;
    hfs_gles_tex_delete(gl, &r->hor);
    r->hor_layers = 0;
    r->hor_bytes = 0;
    hfs_gles_tex_delete(gl, &r->far);
    r->far_layers = r->far_w = r->far_h = 0;
    r->far_bytes = 0;
    hfs_gles_tex_delete(gl, &r->keyhz);
    r->keyhz_layers = 0;
    r->keyhz_bytes = 0;
    hfs_gles_tex_delete(gl, &r->localv);
    r->localv_layers = 0;
    r->localv_bytes = 0;
    r->vw = r->vh = 0;
}

void hfs_gles_resources_free(hfs_gles_resources *r, const hfs_gl *gl)
{
    grid_free(r, gl);
    hfs_gles_tex_delete(gl, &r->bounds);
    hfs_gles_pyramid_build_free(r, gl);
    for (int i = 0; i < HFS_GLES_MAX_LEVELS; ++i) {
        fbo_delete(gl, &r->arr_fbo[i]);
        fbo_delete(gl, &r->arr_mrt_fbo[i]);
    }
    hfs_gles_tex_delete(gl, &r->arr);
    hfs_gles_tex_delete(gl, &r->out[0]);
    hfs_gles_tex_delete(gl, &r->out[1]);
    fbo_delete(gl, &r->out_fbo);
    fbo_delete(gl, &r->out_lo_fbo);
    fbo_delete(gl, &r->hor_fbo);
    fbo_delete(gl, &r->far_fbo);
    fbo_delete(gl, &r->keyhz_fbo);
    fbo_delete(gl, &r->localv_fbo);
    targets_delete(gl, r->transfer, 4, &r->transfer_fbo);
    targets_delete(gl, r->skyocc, 2, &r->skyocc_fbo);
    hfs_gles_tex_delete(gl, &r->kf);
    fbo_delete(gl, &r->kf_fbo);
    const unsigned gen[5] = {r->terrain_gen, r->grid_gen, r->keyhz_gen, r->localv_gen,
                             r->kf_gen};
    memset(r, 0, sizeof *r);
    r->terrain_gen = gen[0] + 1, r->grid_gen = gen[1] + 1, r->keyhz_gen = gen[2] + 1;
    r->localv_gen = gen[3] + 1, r->kf_gen = gen[4] + 1;
}

int hfs_gles_pyramid_build_ensure(hfs_gles_resources *r, const hfs_gl *gl, const hfs_gl_caps *c,
                                  const hfs_gles_layout *L, hfs_error *err)
{
    int rc = HFS_OK;
    for (int l = L->lmin; !rc && l < L->n_levels - 1; ++l) {
        if (r->lev[l])
            continue;
        r->lev[l] = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rg, L->lw[l], L->lh[l], 1, 1);
        r->build_bytes += (size_t)L->lw[l] * L->lh[l] * c->bytes_rg;
        /* The separable reconstruction's intermediate, its own size so
         * that CLAMP_TO_EDGE clamps at the level's last row. */
        r->half[l] = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rg, L->w, L->lh[l], 1, 1);
        r->build_bytes += (size_t)L->w * L->lh[l] * c->bytes_rg;
        if (!(rc = hfs_gles_fbo_new(gl, &r->lev_fbo[l], 1, &r->lev[l], NULL, "level", err)))
            rc = hfs_gles_fbo_new(gl, &r->half_fbo[l], 1, &r->half[l], NULL, "level", err);
    }
    if (rc) /* nothing half made: the next terrain pass makes them again */
        hfs_gles_pyramid_build_free(r, gl);
    return rc;
}

void hfs_gles_pyramid_build_free(hfs_gles_resources *r, const hfs_gl *gl)
{
    for (int i = 0; i < HFS_GLES_MAX_LEVELS; ++i) {
        targets_delete(gl, &r->lev[i], 1, &r->lev_fbo[i]);
        targets_delete(gl, &r->half[i], 1, &r->half_fbo[i]);
    }
    r->build_bytes = 0;
}

/* The pyramid: bounds, the layer array (the heights its last layer) and its single- and
 * multi-target framebuffers (the build's own targets: hfs_gles_pyramid_build_ensure). */
static int pyramid_alloc(hfs_gles_resources *r, const hfs_gl *gl, const hfs_gl_caps *c,
                         const hfs_gles_layout *L, hfs_error *err)
{
    const int w = L->w, h = L->h;
    int rc;
    r->bounds = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_r, L->rb.aw, L->rb.ah, 1, 0);
    r->bytes += (size_t)L->rb.aw * L->rb.ah * c->bytes_r;
    r->arr = hfs_gles_tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rg, w, h, L->n_layers, 1);
    r->bytes += (size_t)w * h * L->n_layers * c->bytes_rg;
    for (int i = 0; i < L->n_layers - 1; ++i)
        if ((rc = hfs_gles_fbo_new(gl, &r->arr_fbo[i], 1, &r->arr, &i, "level layer", err)))
            return rc;
    for (int i = 0; i < L->n_layers - 1; i += HFS_GLES_RECON_MRT) {
        const int left = L->n_layers - 1 - i;
        const int n = left < HFS_GLES_RECON_MRT ? left : HFS_GLES_RECON_MRT;
        const GLuint att[HFS_GLES_RECON_MRT] = {r->arr, r->arr, r->arr, r->arr};
        const int lay[HFS_GLES_RECON_MRT] = {i, i + 1, i + 2, i + 3};
        if ((rc = hfs_gles_fbo_new(gl, &r->arr_mrt_fbo[i / HFS_GLES_RECON_MRT], n, att, lay,
                                   "level layers", err)))
            return rc;
    }
    return HFS_OK;
}

/* Full-resolution targets: the output (hi, lo); the normals are computed
 * where they are read (hfs_normal_at), not kept. */
static int terrain_alloc(hfs_gles_resources *r, const hfs_gl *gl, const hfs_gl_caps *c,
                         const hfs_gles_layout *L, hfs_error *err)
{
    const int w = L->w, h = L->h;
    int rc;
    r->w = L->w, r->h = L->h, r->n_levels = L->n_levels, r->lmin = L->lmin;
    r->n_layers = L->n_layers, r->fp32 = c->fp32;
    if ((rc = pyramid_alloc(r, gl, c, L, err)))
        return rc;
    r->out[0] = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 0);
    r->out[1] = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 0);
    r->bytes += (size_t)2 * w * h * c->bytes_rgba;
    if ((rc = hfs_gles_fbo_new(gl, &r->out_fbo, 2, r->out, NULL, "output", err)) ||
        (rc = hfs_gles_fbo_new(gl, &r->out_lo_fbo, 1, &r->out[1], NULL, "output", err)))
        return rc;
    gl->GenFramebuffers(1, &r->hor_fbo);
    gl->GenFramebuffers(1, &r->far_fbo);
    gl->GenFramebuffers(1, &r->kf_fbo);
    gl->GenFramebuffers(1, &r->keyhz_fbo);
    gl->GenFramebuffers(1, &r->localv_fbo);
    r->valid = 1;
    return HFS_OK;
}

/* A layered RGBA texture of w x h x layers (fp16 or fp32 as the frame
 * runs, LINEAR) in place of *tex, and its size in *bytes. */
static void layered_rgba(const hfs_gl *gl, const hfs_gl_caps *c, GLuint *tex, size_t *bytes,
                         int w, int h, int layers)
{
    hfs_gles_tex_delete(gl, tex);
    *tex = hfs_gles_tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rgba, w, h, layers, 1);
    *bytes = (size_t)w * h * layers * c->bytes_rgba;
}

/* Grows the layered textures that follow the light counts and the
 * environment's directions. */
static void layers_ensure(hfs_gles_resources *r, const hfs_gl *gl, const hfs_gl_caps *c,
                          const hfs_gles_layout *L, const hfs_gles_layers *n)
{
    const int key_layers = n->key, local_layers = n->local, n_keys = n->n_keys;
    if (r->hor_layers < n->hor) { /* the environment's visibility: lost with it */
        layered_rgba(gl, c, &r->hor, &r->hor_bytes, L->vw, L->vh, n->hor);
        r->hor_layers = n->hor;
        ++r->grid_gen;
    }
    if (n->far > 0 && (r->far_layers < n->far || r->far_w != n->far_w || r->far_h != n->far_h)) {
        /* split horizons' far grid: part of the environment's visibility */
        layered_rgba(gl, c, &r->far, &r->far_bytes, n->far_w, n->far_h, n->far);
        r->far_layers = n->far, r->far_w = n->far_w, r->far_h = n->far_h;
        ++r->grid_gen;
    }
    if (key_layers > 0 && r->keyhz_layers < key_layers) {
        layered_rgba(gl, c, &r->keyhz, &r->keyhz_bytes, L->vw, L->vh, key_layers);
        r->keyhz_layers = key_layers;
        ++r->keyhz_gen;
    }
    if (n_keys > 0 && r->kf_layers < n_keys) {
        hfs_gles_tex_delete(gl, &r->kf);
        r->kf = hfs_gles_tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rg, L->w, L->h, n_keys, 0);
        r->kf_layers = n_keys;
        ++r->kf_gen;
        r->kf_bytes = (size_t)L->w * L->h * n_keys * c->bytes_rg;
    }
    if (local_layers > 0 && r->localv_layers < local_layers) {
        layered_rgba(gl, c, &r->localv, &r->localv_bytes, L->vw, L->vh, local_layers);
        r->localv_layers = local_layers;
        ++r->localv_gen;
    }
}

int hfs_gles_transfer_ensure(hfs_gles_resources *r, const hfs_gl *gl, const hfs_gl_caps *c,
                             hfs_error *err)
{
    if (r->transfer_fbo)
        return HFS_OK;
    for (int i = 0; i < 4; ++i)
        r->transfer[i] = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, r->w, r->h, 1, 0);
    r->transfer_bytes = (size_t)4 * r->w * r->h * c->bytes_rgba;
    int rc = hfs_gles_fbo_new(gl, &r->transfer_fbo, 4, r->transfer, NULL, "env transfer", err);
    if (rc) { /* nothing half made: the next frame that needs them tries again */
        targets_delete(gl, r->transfer, 4, &r->transfer_fbo);
        r->transfer_bytes = 0;
    }
    return rc;
}

int hfs_gles_skyocc_ensure(hfs_gles_resources *r, const hfs_gl *gl, const hfs_gl_caps *c,
                           hfs_error *err)
{
    if (r->skyocc_fbo)
        return HFS_OK;
    r->skyocc[0] = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, r->w, r->h, 1, 0);
    r->skyocc[1] = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rg, r->w, r->h, 1, 0);
    r->skyocc_bytes = (size_t)r->w * r->h * (c->bytes_rgba + c->bytes_rg);
    int rc = hfs_gles_fbo_new(gl, &r->skyocc_fbo, 2, r->skyocc, NULL, "sky occlusion", err);
    if (rc) { /* nothing half made: the next frame that needs them tries again */
        targets_delete(gl, r->skyocc, 2, &r->skyocc_fbo);
        r->skyocc_bytes = 0;
    }
    return rc;
}

int hfs_gles_transfer_free(hfs_gles_resources *r, const hfs_gl *gl)
{
    const int had = r->transfer_fbo != 0;
    targets_delete(gl, r->transfer, 4, &r->transfer_fbo);
    r->transfer_bytes = 0;
    return had;
}

int hfs_gles_skyocc_free(hfs_gles_resources *r, const hfs_gl *gl)
{
    const int had = r->skyocc_fbo != 0;
    targets_delete(gl, r->skyocc, 2, &r->skyocc_fbo);
    r->skyocc_bytes = 0;
    return had;
}

int hfs_gles_resources_ensure(hfs_gles_resources *r, const hfs_gl *gl, const hfs_gl_caps *c,
                              const hfs_gles_layout *L, const hfs_gles_layers *n,
                              hfs_error *err)
{
    int rc;
    if (!(r->valid && r->w == L->w && r->h == L->h && r->n_levels == L->n_levels &&
          r->lmin == L->lmin && r->fp32 == c->fp32)) {
        hfs_gles_resources_free(r, gl);
        if ((rc = hfs_gl_check(gl, "backend gles: pending error", err)) ||
            (rc = terrain_alloc(r, gl, c, L, err)))
            return rc;
    }
    if (r->vw != L->vw || r->vh != L->vh) {
        grid_free(r, gl);
        r->vw = L->vw, r->vh = L->vh;
        ++r->grid_gen, ++r->keyhz_gen, ++r->localv_gen;
    }
    if (n->venv && !r->venv_fbo) { /* the Legendre and table paths' V_env */
        ++r->grid_gen;
        for (int i = 0; i < 4; ++i)
            r->venv[i] = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, L->vw, L->vh, 1, 1);
        r->venv_bytes = (size_t)4 * L->vw * L->vh * c->bytes_rgba;
        if ((rc = hfs_gles_fbo_new(gl, &r->venv_fbo, 4, r->venv, NULL, "visibility", err))) {
            targets_delete(gl, r->venv, 4, &r->venv_fbo); /* tried again next frame */
            r->venv_bytes = 0;
            return rc;
        }
    }
    layers_ensure(r, gl, c, L, n);
    return hfs_gl_check(gl, "backend gles: allocating textures", err);
}

int hfs_gles_grid_horizons_free(hfs_gles_resources *r, const hfs_gl *gl)
{
    const int had = r->hor || r->far;
    hfs_gles_tex_delete(gl, &r->hor);
    hfs_gles_tex_delete(gl, &r->far);
    r->hor_bytes = r->far_bytes = 0;
    return had;
}

int hfs_gles_grid_horizons_freed(const hfs_gles_resources *r)
{
    return (r->hor_layers > 0 && !r->hor) || (r->far_layers > 0 && !r->far);
}

void hfs_gles_grid_horizons_remake(hfs_gles_resources *r, const hfs_gl *gl,
                                   const hfs_gl_caps *c)
{
    if (r->hor_layers > 0 && !r->hor)
        layered_rgba(gl, c, &r->hor, &r->hor_bytes, r->vw, r->vh, r->hor_layers);
    if (r->far_layers > 0 && !r->far)
        layered_rgba(gl, c, &r->far, &r->far_bytes, r->far_w, r->far_h, r->far_layers);
}

size_t hfs_gles_resources_bytes(const hfs_gles_resources *r)
{
    return r->bytes + r->build_bytes + r->transfer_bytes + r->skyocc_bytes + r->venv_bytes +
           r->hor_bytes + r->far_bytes + r->keyhz_bytes + r->localv_bytes + r->kf_bytes;
}
