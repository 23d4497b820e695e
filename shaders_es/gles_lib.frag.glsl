/*
 * gles_lib.frag - functions shared by the GLES renderer's passes.  At
 * program creation (runtime/gles/programs.c) every pass is compiled as
 *     "#version 300 es" + variant defines + gles_pairs.frag + gles_lib.frag
 *     + gles_ray.frag + gles_view.frag + sh_product.glsl.inc (generated)
 *     + the pass shader,
 * with #line markers so driver messages name the right part (source string
 * 5 = gles_pairs.frag (the (hi, lo) pairs), 1 = this file, 3 =
 * gles_ray.frag (the gap search), 4 = gles_view.frag, 2 = the SH product,
 * 0 = the pass).  Passes declare the
 * prototypes they use, so each file also compiles alone (build-time check).
 *
 * Precision (DESIGN.md "GLES path"): everything here is highp.  Heights are
 * differenced as hi+lo pairs, angles and SH sums need fp32; nothing in this
 * renderer is safe at fp16 arithmetic except colour output.
 *
 * Variant defines: HFS_FP32 (textures are 32F: heights stored as (v, 0)).
 * The (hi, lo) pairs' functions, and the heights' reads and normals
 * (hfs_height_at, hfs_normal_at), are gles_pairs.frag's, composed before.
 */
precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

#define HFS_PI 3.14159265358979
#define HFS_HALF_PI 1.5707963267948966

float hfs_hdiff(vec2 a, vec2 b);                          /* gles_pairs.frag */
vec4 hfs_pair_tex4_layer_at(highp sampler2DArray t, vec3 uvl, ivec2 size, vec2 p);

/* Texture coordinate of full-resolution texel p on the visibility grid
 * (vsize receivers, one every sub texels, the last at W-1/H-1): between
 * receivers a = p / sub and a + 1 (at min((a+1) sub, size-1)), so a LINEAR
 * fetch interpolates exactly between the two receivers around p. */
vec2 hfs_grid_uv(ivec2 p, int sub, ivec2 size, ivec2 vsize)
{
    ivec2 a = p / sub;
    ivec2 x0 = a * sub;
    ivec2 x1 = min(x0 + sub, size - 1);
    vec2 t = vec2(p - x0) / vec2(max(x1 - x0, ivec2(1)));
    return (vec2(a) + t + 0.5) / vec2(vsize);
}

/* The place t between the receivers (hfs_grid_rise's, which moves it off
 * a receiver across a wall) in the grid's texels, and as a texture
 * coordinate.  The far atlas takes the texels: a coordinate divided by
 * the tile's size and multiplied back lands a rounding error off a
 * receiver's centre, where the sampler's quantized weights then give the
 * neighbour a share (test_metamorphic_turn). */
vec2 hfs_grid_pix_at(ivec2 p, int sub, vec2 t)
{
    return vec2(p / sub) + t + 0.5;
}

vec2 hfs_grid_uv_at(ivec2 p, int sub, vec2 t, ivec2 vsize)
{
    return hfs_grid_pix_at(p, sub, t) / vec2(vsize);
}

/* Split horizons' far atlas (env_horizons.frag HFS_FAR_ATLAS; runtime/
 * split_horizon.h): where tile i (sub-directions 2i, 2i + 1; cols tiles a
 * row, each fsize texels, the atlas atlas texels) holds the place fpix of
 * a tile, in float arithmetic (an integer division by a uniform would run
 * lane by lane). */
vec2 hfs_far_tile_uv(vec2 fpix, float i, int cols, ivec2 fsize, vec2 atlas)
{
    float row = floor((i + 0.5) / float(cols));
    return (fpix + vec2(i - row * float(cols), row) * vec2(fsize)) / atlas;
}

/* The unit of the occluder heights the grids store, texels: 1 up to 2^14
 * texels of relief, a power of two beyond (runtime/core/split_horizon.h
 * hfs_split_h_unit), so that fp16 holds them at any relief. */
uniform float u_hunit;

/* An occluder's height over its receiver, h texels, as a grid stores it:
 * in u_hunit texels, within fp16 (runtime/cpu/cpu_far_grid.c far_row). */
float hfs_pair_h(float h)
{
    return clamp(h / u_hunit, -3e4, 3e4);
}

/* A blended far occluder (height h over its receivers in u_hunit texels,
 * distance d in texels) seen from a texel dz texels below the receivers
 * (a grid of step 1 / inv_step): its slope, -1e30 where there is none
 * (runtime/core/split_horizon.h hfs_split_far_slope). */
float hfs_far_slope(float h, float d, float dz, float inv_step)
{
    if (!(d > 0.0))
        return -1e30;
    return (h * u_hunit + dz * min(d * inv_step, 1.0)) / d;
}

/* An occluder's distance d (0: none) read at a place `shift` texels
 * behind the texel along its direction (hfs_grid_rise's off, dotted);
 * runtime/core/split_horizon.h hfs_split_far_d. */
float hfs_far_d(float d, float shift)
{
    return d > 0.0 ? d + shift : d;
}

/* Occluder k (0 or 1) of a texel of pairs v (height, distance; two a
 * texel) read `shift` texels behind the texel and seen dz below the
 * receivers: hfs_far_slope(h, hfs_far_d(d, shift), ...), the grids'
 * occluders' one read (env_slices.frag, bounce_gather.frag). */
float hfs_far_pair_slope(vec4 v, int k, float shift, float dz, float inv_step)
{
    return hfs_far_slope(v[2 * k], hfs_far_d(v[2 * k + 1], shift), dz, inv_step);
}

/* ---- sample offsets (DESIGN.md "Horizons", float-sized snapping) --------- */

/* Snaps each component within a float tolerance of an integer to it
 * (runtime/gles/uniform_blocks.h: HFS_GLES_SNAP_REL, HFS_GLES_SNAP_ABS). */
vec2 hfs_snap(vec2 o)
{
    vec2 r = floor(o + 0.5);
    vec2 tol = abs(o) * 4.8e-7 + 1e-9;
    return mix(o, r, lessThanEqual(abs(o - r), tol));
}

/* ---- Legendre (NS09 section 4) ---------------------------------------------- */

/* Occlusion vector of the step "blocked below elevation sigma"
 * (runtime/sh/sh_legendre.c hfs_nlp_occlusion). */
vec4 hfs_nlp_occ(float sigma)
{
    sigma = clamp(sigma, -HFS_HALF_PI, HFS_HALF_PI);
    float s = sin(sigma), c = cos(sigma), c2 = c * c;
    return vec4((s + 1.0) * 0.7071067811865476,
                -3.0 * c2 * 0.20412414523193154,
                -5.0 * s * c2 * 0.15811388300841897,
                7.0 * c2 * (5.0 * c2 - 4.0) * 0.03340765523905305);
}

/* hfs_nlp_occ of the angle atan(t), from t alone: sin = t / sqrt(1 + t^2),
 * cos^2 = 1 / (1 + t^2) (t clamped to +-1e18 so that t^2 stays finite). */
vec4 hfs_nlp_occ_tan(float t)
{
    t = clamp(t, -1e18, 1e18);
    float r = inversesqrt(1.0 + t * t);
    float s = t * r, c2 = r * r;
    return vec4((s + 1.0) * 0.7071067811865476,
                -3.0 * c2 * 0.20412414523193154,
                -5.0 * s * c2 * 0.15811388300841897,
                7.0 * c2 * (5.0 * c2 - 4.0) * 0.03340765523905305);
}

/* NLP vector of the visible band (max(omega, win.x), win.y]; occ_top is
 * hfs_nlp_occ(win.y) (visibility.c visible_nlp). */
vec4 hfs_visible(float omega, vec4 win, vec4 occ_top)
{
    float o = max(omega, win.x);
    return o >= win.y ? vec4(0.0) : occ_top - hfs_nlp_occ(o);
}

/* ---- SH: coefficient k lives in v[k / 4][k % 4] ---------------------------- */

/* The 16 basis functions y_k(d) of unit d (SPEC's real SH, no
 * Condon-Shortley phase).  A zonal function rotated to d is its band
 * factors times these; hfs_sh_cosine and hfs_sh_hemisphere below spell
 * them out instead because they run per texel and have a zero band whose
 * products the compiler may not drop (0 * x is not 0 for NaN and -0). */
void hfs_sh_basis(vec3 d, out vec4 y[4])
{
    float x = d.x, yy = d.y, z = d.z;
    y[0] = vec4(0.28209479177387814, 0.4886025119029199 * yy, 0.4886025119029199 * z,
                0.4886025119029199 * x);
    y[1] = vec4(1.0925484305920792 * x * yy, 1.0925484305920792 * yy * z,
                0.31539156525252005 * (3.0 * z * z - 1.0), 1.0925484305920792 * x * z);
    y[2] = vec4(0.5462742152960396 * (x * x - yy * yy),
                0.5900435899266435 * yy * (3.0 * x * x - yy * yy), 2.890611442640554 * x * yy * z,
                0.4570457994644658 * yy * (5.0 * z * z - 1.0));
    y[3] = vec4(0.3731763325901154 * z * (5.0 * z * z - 3.0),
                0.4570457994644658 * x * (5.0 * z * z - 1.0),
                1.445305721320277 * z * (x * x - yy * yy),
                0.5900435899266435 * x * (x * x - 3.0 * yy * yy));
}

/* The clamped cosine about unit n as SH (hfs_sh_rotate_zonal of
 * hfs_zh_clamped_cosine): band factors sqrt(4pi/(2l+1)) zh_l = pi, 2pi/3,
 * pi/4, 0 times y_k(n). */
void hfs_sh_cosine(vec3 n, out vec4 h[4])
{
    float x = n.x, y = n.y, z = n.z;
    float a0 = 3.14159265358979 * 0.28209479177387814;
    float a1 = 2.0943951023931953 * 0.4886025119029199;
    float a2 = 0.7853981633974483;
    h[0] = vec4(a0, a1 * y, a1 * z, a1 * x);
    h[1] = vec4(a2 * 1.0925484305920792 * x * y, a2 * 1.0925484305920792 * y * z,
                a2 * 0.31539156525252005 * (3.0 * z * z - 1.0),
                a2 * 1.0925484305920792 * x * z);
    h[2] = vec4(a2 * 0.5462742152960396 * (x * x - y * y), 0.0, 0.0, 0.0);
    h[3] = vec4(0.0);
}

/* The hemisphere above the plane of unit normal n as SH (hfs_sh_rotate_zonal
 * of hfs_zh_cap(pi/2)): band factors 2pi, pi, 0, -pi/4 times y_k(n).  The
 * visibility grid stores V_env minus this at each receiver and the shading
 * pass adds it back at each texel's own normal (DESIGN.md "GLES path"). */
void hfs_sh_hemisphere(vec3 n, out vec4 h[4])
{
    float x = n.x, y = n.y, z = n.z;
    float b1 = 3.14159265358979 * 0.4886025119029199;
    float b3 = -0.7853981633974483;
    h[0] = vec4(6.283185307179586 * 0.28209479177387814, b1 * y, b1 * z, b1 * x);
    h[1] = vec4(0.0);
    h[2] = vec4(0.0, b3 * 0.5900435899266435 * y * (3.0 * x * x - y * y),
                b3 * 2.890611442640554 * x * y * z,
                b3 * 0.4570457994644658 * y * (5.0 * z * z - 1.0));
    h[3] = vec4(b3 * 0.3731763325901154 * z * (5.0 * z * z - 3.0),
                b3 * 0.4570457994644658 * x * (5.0 * z * z - 1.0),
                b3 * 1.445305721320277 * z * (x * x - y * y),
                b3 * 0.5900435899266435 * x * (x * x - 3.0 * y * y));
}

float hfs_sh_dot(vec4 a[4], vec4 b[4])
{
    return dot(a[0], b[0]) + dot(a[1], b[1]) + dot(a[2], b[2]) + dot(a[3], b[3]);
}

/* The environment's occluded light per channel, T_occ . L_c (l holding 4
 * vec4 a channel), as two targets store it exactly: a = (hi_r, hi_g, hi_b,
 * lo_r), b = (lo_g, lo_b), hi each value's nearest fp16 and lo the rest
 * rounded to fp16 (HFS_FP32: the values, lo 0); hfs_env_occ_sum adds them
 * back (~2^-22 of each value: the shading's own rounding of T_occ, fp16 a
 * coefficient, stays what limits it).  env_slices.frag HFS_ENV_DOT stores
 * it (the sky occlusion) and shade.frag computes it from a kept T_occ: the
 * same function of the same fp16 coefficients, so the two give the same
 * bits. */
vec2 hfs_split(float v);
float hfs_f16(float v);
void hfs_env_occ(vec4 t[4], vec4 l[12], out vec4 a, out vec2 b)
{
    vec4 r[4], g[4], bl[4];
    for (int k = 0; k < 4; ++k) {
        r[k] = l[k];
        g[k] = l[4 + k];
        bl[k] = l[8 + k];
    }
    vec2 pr = hfs_split(hfs_sh_dot(t, r)), pg = hfs_split(hfs_sh_dot(t, g));
    vec2 pb = hfs_split(hfs_sh_dot(t, bl));
    a = vec4(pr.x, pg.x, pb.x, hfs_f16(pr.y));
    b = vec2(hfs_f16(pg.y), hfs_f16(pb.y));
}

vec3 hfs_env_occ_sum(vec4 a, vec2 b)
{
    return a.rgb + vec3(a.a, b);
}

/* Rotation about +z by angle a given (cos ma), (sin ma), m = 1..3
 * (runtime/sh/sh.h hfs_sh_rotate_z): per band l and m > 0,
 *   out[l(l+1)+m] = c in[l(l+1)+m] - s in[l(l+1)-m]
 *   out[l(l+1)-m] = s in[l(l+1)+m] + c in[l(l+1)-m]. */
void hfs_sh_rotz(inout vec4 t[4], vec3 c, vec3 s)
{
    float p, q;
    p = t[0].w; q = t[0].y;            /* l=1, m=1: k 3, 1 */
    t[0].w = c.x * p - s.x * q; t[0].y = s.x * p + c.x * q;
    p = t[1].w; q = t[1].y;            /* l=2, m=1: k 7, 5 */
    t[1].w = c.x * p - s.x * q; t[1].y = s.x * p + c.x * q;
    p = t[2].x; q = t[1].x;            /* l=2, m=2: k 8, 4 */
    t[2].x = c.y * p - s.y * q; t[1].x = s.y * p + c.y * q;
    p = t[3].y; q = t[2].w;            /* l=3, m=1: k 13, 11 */
    t[3].y = c.x * p - s.x * q; t[2].w = s.x * p + c.x * q;
    p = t[3].z; q = t[2].z;            /* l=3, m=2: k 14, 10 */
    t[3].z = c.y * p - s.y * q; t[2].z = s.y * p + c.y * q;
    p = t[3].w; q = t[2].y;            /* l=3, m=3: k 15, 9 */
    t[3].w = c.z * p - s.z * q; t[2].y = s.z * p + c.z * q;
}

/* Reflection y -> -y: negates the m < 0 coefficients (k 1, 4, 5, 9, 10, 11). */
void hfs_sh_mirror_y(inout vec4 t[4])
{
    t[0].y = -t[0].y;
    t[1].x = -t[1].x;
    t[1].y = -t[1].y;
    t[2].yzw = -t[2].yzw;
}

/* Texture coordinate of horizon omega in a wedge table of n entries over
 * [-pi/2, pi/2] (runtime/sh/sh_wedge_table.c table_cell). */
float hfs_table_coord(float omega, float n)
{
    float u = clamp((omega + HFS_HALF_PI) * ((n - 1.0) / HFS_PI), 0.0, n - 1.0);
    return (u + 0.5) / n;
}

/* V += one wedge's table placed in the sky: the four layers layer0..+3 of
 * `tab` at uv (the wedge's horizon pair, hfs_table_coord), mirrored in y
 * when `mirror` (a start boundary wedge), rotated about z by (cos ma),
 * (sin ma) (runtime/core/visibility.c table_placement).  Shared by the
 * environment, key and local passes' wedge-table paths. */
void hfs_table_add(highp sampler2DArray tab, vec2 uv, float layer0, bool mirror, vec3 c,
                   vec3 s, inout vec4 V[4])
{
    vec4 t[4];
    for (int g = 0; g < 4; ++g)
        t[g] = texture(tab, vec3(uv, layer0 + float(g)));
    if (mirror)
        hfs_sh_mirror_y(t);
    hfs_sh_rotz(t, c, s);
    for (int g = 0; g < 4; ++g)
        V[g] += t[g];
}

/* ---- lights ------------------------------------------------------------------ */

/* sin(x) to float's RELATIVE precision.  A GPU may
 * compute sin() to an absolute error near 2^-21 (NVIDIA's hardware sine:
 * tests/test_glsl_numerics_gpu.c), no digit at all for a 1e-8 rad sun, whose
 * irradiance goes as sin^2.  Below |x| = 1/2 the Taylor series to x^9
 * (the next term is under 2^-30 of the sum); above it sin() (in
 * [1/2, pi/2] an absolute error of 2^-21 is under 2^-20 of the value). */
float hfs_sin_acc(float x)
{
    float x2 = x * x;
    if (x2 < 0.25)
        return x * (1.0 - x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0))));
    return sin(x);
}

vec4 hfs_sin_acc4(vec4 x)
{
    vec4 x2 = x * x;
    vec4 ser = x * (1.0 - x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0))));
    return mix(sin(x), ser, lessThan(x2, vec4(0.25)));
}

/* Irradiance of a uniform cap whose half-angle (< pi/2) has sine s and
 * cosine c and whose axis makes angle acos(cos_beta) with the normal
 * (runtime/core/lights.c).  Taking the half-angle by its sine spares a sphere
 * light the atan of its angular radius (r/d is its sine): llvmpipe's atan
 * cost every local light a 4e-5 relative bias.  The cap is above the
 * tangent plane iff cos_beta >= s, below it iff cos_beta <= -s. */
float hfs_cap_irradiance_sc(float cos_beta, float s, float c)
{
    cos_beta = clamp(cos_beta, -1.0, 1.0);
    if (!(s > 0.0))
        return 0.0;
    float s2 = s * s;
    if (cos_beta >= s)
        return HFS_PI * s2 * cos_beta;
    if (cos_beta <= -s)
        return 0.0;
    /* Straddling: runtime/core/lights.c's cancellation-free form for small caps
     * (the textbook (cos_beta acos(y) - x q) s2 + atan(q, x) keeps a
     * 2-degree disk at the horizon 1/500 of float's precision). */
    float sin_beta = sqrt(max(1.0 - cos_beta * cos_beta, 0.0));
    float x = c / s;
    float y = clamp(-x * cos_beta / sin_beta, -1.0, 1.0);
    float q = sin_beta * sqrt(max(1.0 - y * y, 0.0));
    float t = q * s / c;
    float e;
    if (t < 0.25) {
        float u = t * t, sum = 0.0, term = 1.0;
        for (int k = 0; k < 7; ++k) { /* u^7 < 2^-28 */
            sum += (k % 2 == 1 ? -term : term) / float(2 * k + 3);
            term *= u;
        }
        e = -t * u * sum + t * s2 + s2 * cos_beta * acos(y);
    } else {
        e = (cos_beta * acos(y) - x * q) * s2 + atan(q, x);
    }
    return max(e, 0.0);
}

/* The same for a half-angle alpha in (0, pi/2) (key lights). */
float hfs_cap_irradiance(float cos_beta, float alpha)
{
    if (!(alpha > 0.0))
        return 0.0;
    return hfs_cap_irradiance_sc(cos_beta, hfs_sin_acc(alpha), cos(alpha));
}

/* Int_x^{pi/2} (a cos e + b sin e) cos e de: the clamped cosine over a
 * slice's elevations from x up (slice_light.c hfs_slice_cosine). */
float hfs_slice_cosine(float a, float b, float x)
{
    return 0.5 * a * (HFS_HALF_PI - x - 0.5 * sin(2.0 * x)) + 0.25 * b * (1.0 + cos(2.0 * x));
}

/* ---- horizon sampling on the visibility grid (env_horizons, key_horizons, ------ */
/* ---- shade's local lights; DESIGN.md "Horizons") ------------------- */

#ifndef HFS_NLAYERS
#define HFS_NLAYERS 25
#endif

/* This fragment's receiver: grid point min(a * sub, size - 1). */
ivec2 hfs_receiver(ivec2 size, int sub)
{
    return min(ivec2(gl_FragCoord.xy) * sub, size - 1);
}

/* R_L(x) of receiver g at every level (layer l of the R_L array), fetched
 * once: it does not depend on the direction. */
void hfs_receiver_heights(highp sampler2DArray levels, ivec2 g, out vec2 hx[HFS_NLAYERS])
{
    for (int l = 0; l < HFS_NLAYERS; ++l)
        hx[l] = texelFetch(levels, ivec3(g, l), 0).xy;
}

/* Floor of direction cs: the elevation of the receiver's tangent plane. */
float hfs_floor(vec3 n, vec2 cs)
{
    return atan(-(n.x * cs.x + n.y * cs.y), n.z);
}

/* Where the ray p + t cs, 0 <= t <= t_max, crosses the box (x0, y0, x1,
 * y1) (the slab test): t.x its entry, t.y its exit; false when it misses.
 * For the edits' tests (runtime/gles/edit_frame.c). */
bool hfs_ray_box(vec2 p, vec2 cs, vec4 box, float t_max, out vec2 t)
{
    t = vec2(0.0, t_max);
    for (int a = 0; a < 2; ++a) {
        float lo = box[a], hi = box[a + 2];
        if (abs(cs[a]) < 1e-12) {
            if (p[a] < lo || p[a] > hi)
                return false;
        } else {
            float ta = (lo - p[a]) / cs[a], tb = (hi - p[a]) / cs[a];
            t.x = max(t.x, min(ta, tb));
            t.y = min(t.y, max(ta, tb));
        }
    }
    return t.x <= t.y;
}

/* Texel offset o = snap(d * cs) of a scale sample from receiver g; false
 * when it falls off the size grid (a fractional offset also needs p + 1). */
bool hfs_scale_offset(ivec2 g, ivec2 size, float d, vec2 cs, out vec2 o)
{
    o = hfs_snap(d * cs);
    vec2 io = floor(o);
    ivec2 p = g + ivec2(io);
    ivec2 lim = size - 1 - ivec2(notEqual(o, io));
    return !(any(lessThan(p, ivec2(0))) || any(greaterThan(p, lim)));
}

/* Slope D = (R_L(g + o) - R_L(g)) * inv_run of scale sc = (d, inv_run,
 * layer, 0), h = R_L(g); the sample is bilinear (the array is LINEAR). */
float hfs_scale_slope(highp sampler2DArray levels, ivec2 g, ivec2 size, vec2 o, vec4 sc, vec2 h)
{
    vec2 inv_size = 1.0 / vec2(size);
    vec2 gc = vec2(g) + 0.5;
    vec2 t = hfs_pair_tex4_layer_at(levels, vec3((gc + o) * inv_size, sc.z), size, vec2(g) + o).xy;
    return hfs_hdiff(t, h) * sc.y;
}

/* ---- horizons refined between scales (cpu_horizon.h hfs_horizon_refined) -- */

/* pyramid_layout.h HFS_HORIZON_TIE: relative slope differences that tie. */
#define HFS_HORIZON_TIE 1e-5

/* Whether slope sl, met going fine to coarse, takes over from the current
 * leading slope ref: it must beat it by more than the tie (relative, plus
 * tie, hfs_horizon_tie_slope), so that near-ties go to the finer scale in
 * float as in the CPU's double. */
bool hfs_scale_takes_over(float sl, float ref, float tie)
{
    return sl > ref + HFS_HORIZON_TIE * abs(ref) + tie;
}

/* The distance factor 2^(u/k), u = -1 + 2 (q + 1) / (n + 1), of refining
 * sample q of n (cpu_horizon.c refine_factor): strictly between a scale's
 * neighbours. */
float hfs_refine_factor(int q, int n, float k)
{
    return exp2((-1.0 + 2.0 * float(q + 1) / float(n + 1)) / k);
}

/* The n refining samples about scale sc = (d, inv_run, layer, 0) of
 * receiver g (height h = R_layer(g)) in direction cs: at d 2^(u/k),
 * u = -1 + 2 (q + 1) / (n + 1), strictly between sc's neighbouring scales,
 * read from sc's level; returns max(best, their slopes), and sets *dist to
 * the distance of a sample that raised it past the relative tie (as
 * cpu_horizon.c refine_about).  Counts its fetches. */
float hfs_refine_about(highp sampler2DArray levels, ivec2 g, ivec2 size, vec2 cs, vec4 sc,
                       vec2 h, int n, float k, float best, inout float dist, inout int fetches)
{
    for (int q = 0; q < n; ++q) {
        float f = hfs_refine_factor(q, n, k);
        vec2 o;
        if (!hfs_scale_offset(g, size, sc.x * f, cs, o))
            continue;
        float sl = hfs_scale_slope(levels, g, size, o, sc, h) / f;
        ++fetches;
        if (sl > best) {
            if (hfs_scale_takes_over(sl, best, 0.0)) /* cpu_horizon.c refine_about */
                dist = sc.x * f;
            best = sl;
        }
    }
    return best;
}

/* B-spline max over the scale index on the fly, fed per-scale angles from
 * fine (i = n - 1, n scales) to coarse, indices clamped (runtime/cpu/cpu_horizon.c
 * hfs_horizon_bspline_max, same expressions): after om[i] = a arrives,
 * w = om[i..i+3] and knot i+1 and midpoint i+1 are complete. */
float hfs_bspline_knot(vec4 w)
{
    return w.y + ((w.x - w.y) + (w.z - w.y)) / 6.0;
}
float hfs_bspline_mid(vec4 w)
{
    return w.y + ((w.x - w.y) + 23.0 * (w.z - w.y) + (w.w - w.y)) / 48.0;
}

void hfs_bspline_push(inout float best, inout vec4 w, float a, int i, int n)
{
    if (i == n - 1) {
        w = vec4(a);
        return;
    }
    w = vec4(a, w.xyz);
    best = max(best, hfs_bspline_knot(w));                               /* knot i+1 */
    if (i + 2 < n)
        best = max(best, hfs_bspline_mid(w));
}

/* Knot 0 and midpoint 0 (om[-1] clamps to om[0]), once every scale came in. */
float hfs_bspline_close(float best, vec4 w, int n)
{
    best = max(best, hfs_bspline_knot(w.xxyz));
    if (n > 1)
        best = max(best, hfs_bspline_mid(w.xxyz));
    return best;
}

/* The same max, also keeping where it was reached: bd is dk or dm of the
 * winning knot or midpoint (the caller's tag for knot i+1 and midpoint i+1;
 * at the close, for knot 0 and midpoint 0), unchanged while the seed value
 * wins. */
void hfs_bspline_push_at(inout float best, inout float bd, inout vec4 w, float a, int i,
                         int n, float dk, float dm)
{
    if (i == n - 1) {
        w = vec4(a);
        return;
    }
    w = vec4(a, w.xyz);
    float k = hfs_bspline_knot(w);
    if (k > best) {
        best = k;
        bd = dk;
    }
    if (i + 2 < n) {
        float m = hfs_bspline_mid(w);
        if (m > best) {
            best = m;
            bd = dm;
        }
    }
}

void hfs_bspline_close_at(inout float best, inout float bd, vec4 w, int n, float dk,
                          float dm)
{
    float k = hfs_bspline_knot(w.xxyz);
    if (k > best) {
        best = k;
        bd = dk;
    }
    if (n > 1) {
        float m = hfs_bspline_mid(w.xxyz);
        if (m > best) {
            best = m;
            bd = dm;
        }
    }
}

/* ---- uniform data carried by a texture (runtime/gles/block_texture.h) -- */
/* A block too large for GL_MAX_UNIFORM_BLOCK_SIZE arrives as RGBA16UI
 * texels, each vec4 as two texels holding its floats' bits as (high, low)
 * 16-bit halves: vec4 i of the block, bit for bit the float the block would
 * have held. */
#if defined(HFS_SWATH_TEX) || defined(HFS_KEYS_TEX) || defined(HFS_LOCAL_TEX)
#define HFS_BLOCK_TEX_W 1024
vec4 hfs_block_vec4(highp usampler2D t, int i)
{
    int k = 2 * i;
    ivec2 p = ivec2(k % HFS_BLOCK_TEX_W, k / HFS_BLOCK_TEX_W);
    uvec4 a = texelFetch(t, p, 0);
    uvec4 b = texelFetch(t, p + ivec2(1, 0), 0);
    return vec4(uintBitsToFloat((a.x << 16) | a.y), uintBitsToFloat((a.z << 16) | a.w),
                uintBitsToFloat((b.x << 16) | b.y), uintBitsToFloat((b.z << 16) | b.w));
}
#endif
