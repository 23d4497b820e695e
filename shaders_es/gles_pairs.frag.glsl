/*
 * gles_pairs.frag - the (hi, lo) pairs of the GLES renderer's shader
 * library: heights, normals and light ratios stored as two halves whose
 * sum keeps ~22 bits (hfs_split), read back (hfs_h, hfs_hdiff), rounded to
 * halves in integer arithmetic (hfs_half_nearest), blended as texture()
 * blends them (hfs_pair_tex), and the heights read from the level array's
 * layer u_hlayer with the normals made from them (hfs_height_at,
 * hfs_normal_at, hfs_normal_sides), and where a texel reads a grid's
 * receivers from their heights (hfs_grid_snap, hfs_grid_rise).  Every
 * pass is compiled as
 *     "#version 300 es" + variant defines + gles_pairs.frag + gles_lib.frag
 *     + gles_ray.frag + gles_view.frag + [sh_product.glsl.inc] + the pass
 * (runtime/gles/programs.c; source string 5 in driver messages).  Kept
 * apart from gles_lib.frag so that each library file stays one job.
 *
 * Variant defines: HFS_FP32 (textures are 32F: heights stored as (v, 0));
 * HFS_PAIR_FETCH (the driver's LINEAR is inexact: hfs_pair_tex).
 */
// hfs-variant: HFS_PAIR_FETCH 1
// hfs-variant: HFS_PAIR_FETCH 1, HFS_FP32 1
// hfs-variant: HFS_FP32 1
precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

/* ---- heights: normalized v stored as (hi, lo), v = hi + lo -------------- */

float hfs_h(vec2 t)
{
    return t.x + t.y;
}

/* a - b, differencing the halves first (exact for equal his). */
float hfs_hdiff(vec2 a, vec2 b)
{
    return (a.x - b.x) + (a.y - b.y);
}

/* lerp of two hi+lo values in difference form: exact for a == b. */
float hfs_hlerp(vec2 a, vec2 b, float t)
{
    return hfs_h(a) + t * hfs_hdiff(b, a);
}

/* The half nearest to v (ties to even), in integer arithmetic on v's bits.
 * Not unpackHalf2x16(packHalf2x16(v)): a compiler may fold that pair to v
 * (NVIDIA's does, seen on an H200: every hi+lo pair then stored lo = 0, and
 * the heights, normals and lighting kept fp16's 11 bits; BENCHMARKS.md
 * "On a real GPU"), and packHalf2x16's own rounding is implementation-
 * defined.  Halves below 2^-14 are multiples of 2^-24; from 65520 up there
 * is no half, and v is returned for the target to convert. */
float hfs_half_nearest(float v)
{
    float a = abs(v);
    if (a < 6.103515625e-05)
        return roundEven(v * 16777216.0) * 5.9604644775390625e-08;
    if (!(a < 65520.0))
        return v;
    uint u = floatBitsToUint(v);
    u += 0x0FFFu + ((u >> 13) & 1u); /* half-way minus one, plus the kept lsb */
    return uintBitsToFloat(u & 0xFFFFE000u);
}

/* The fp16 value nearest to v (HFS_FP32: v itself).  Render targets may
 * convert float to half by truncation (llvmpipe does: a bias of half an
 * ulp, 2^-12 relative, in every stored value): the value written is
 * exactly representable and stored unchanged. */
float hfs_f16(float v)
{
#ifdef HFS_FP32
    return v;
#else
    return hfs_half_nearest(v);
#endif
}

vec4 hfs_f16v(vec4 v)
{
    return vec4(hfs_f16(v.x), hfs_f16(v.y), hfs_f16(v.z), hfs_f16(v.w));
}

/* v -> (hi, lo) with hi exactly representable in fp16, so that storing the
 * pair in an RG16F target keeps v to ~2^-21 relative (|v| < 65520): lo's
 * own rounding in the target (truncation on llvmpipe) costs at most an ulp
 * of lo, 2^-22 of v. */
vec2 hfs_split(float v)
{
#ifdef HFS_FP32
    return vec2(v, 0.0);
#else
    float hi = hfs_half_nearest(v);
    return vec2(hi, v - hi);
#endif
}

/* ---- (hi, lo) pairs blended as texture() blends them --------------------- */

/* texture() of a pair texture (one pair in xy, or two in xy and zw; at
 * fp32 (v, 0)).  Where the driver's LINEAR is inexact (HFS_PAIR_FETCH:
 * runtime/gl/gl_probe.h; NVIDIA's keeps 8 bits of the position and rounds
 * a 16F blend to a half, so hi's blend keeps 11 bits whatever lo holds),
 * the four texels are fetched and their sums blended in float at the
 * exact position, in difference form (exact where they are equal), and
 * each pair comes back as (v, 0).  Four fetches for one: only there. */
#ifdef HFS_PAIR_FETCH
vec4 hfs_pair_blend(vec4 t00, vec4 t10, vec4 t01, vec4 t11, vec2 f)
{
    vec2 s00 = t00.xz + t00.yw, s10 = t10.xz + t10.yw;
    vec2 s01 = t01.xz + t01.yw, s11 = t11.xz + t11.yw;
    vec2 top = s00 + f.x * (s10 - s00), bot = s01 + f.x * (s11 - s01);
    vec2 v = top + f.y * (bot - top);
    return vec4(v.x, 0.0, v.y, 0.0);
}

/* The texels about p (texel units: texel i's centre at p = i), clamped to
 * the edge as CLAMP_TO_EDGE does; f the fractions. */
void hfs_pair_taps(ivec2 size, vec2 p, out ivec2 a, out ivec2 b, out vec2 f)
{
    vec2 i = floor(p);
    f = p - i;
    a = clamp(ivec2(i), ivec2(0), size - 1);
    b = clamp(ivec2(i) + 1, ivec2(0), size - 1);
}
#endif

/* At uv; where the caller knows the texel position p = uv size - 1/2 of a
 * size-texel texture (the horizon searches: an integer receiver plus an
 * offset), the _at forms take it as well and spare the shaders' blend
 * the texture's size and the conversion back (texture() still gets uv). */
vec4 hfs_pair_tex4_at(highp sampler2D t, vec2 uv, ivec2 size, vec2 p)
{
#ifdef HFS_PAIR_FETCH
    ivec2 a, b;
    vec2 f;
    hfs_pair_taps(size, p, a, b, f);
    return hfs_pair_blend(texelFetch(t, a, 0), texelFetch(t, ivec2(b.x, a.y), 0),
                          texelFetch(t, ivec2(a.x, b.y), 0), texelFetch(t, b, 0), f);
#else
    return texture(t, uv);
#endif
}

vec4 hfs_pair_tex4(highp sampler2D t, vec2 uv)
{
#ifdef HFS_PAIR_FETCH
    ivec2 size = textureSize(t, 0);
    return hfs_pair_tex4_at(t, uv, size, uv * vec2(size) - 0.5);
#else
    return texture(t, uv);
#endif
}

vec2 hfs_pair_tex(highp sampler2D t, vec2 uv)
{
    return hfs_pair_tex4(t, uv).xy;
}

/* The same on layer round(uvl.z) of an array. */
vec4 hfs_pair_tex4_layer_at(highp sampler2DArray t, vec3 uvl, ivec2 size, vec2 p)
{
#ifdef HFS_PAIR_FETCH
    ivec2 a, b;
    vec2 f;
    hfs_pair_taps(size, p, a, b, f);
    int l = int(floor(uvl.z + 0.5));
    return hfs_pair_blend(texelFetch(t, ivec3(a, l), 0), texelFetch(t, ivec3(b.x, a.y, l), 0),
                          texelFetch(t, ivec3(a.x, b.y, l), 0), texelFetch(t, ivec3(b, l), 0), f);
#else
    return texture(t, uvl);
#endif
}

vec4 hfs_pair_tex4_layer(highp sampler2DArray t, vec3 uvl)
{
#ifdef HFS_PAIR_FETCH
    ivec2 size = textureSize(t, 0).xy;
    return hfs_pair_tex4_layer_at(t, uvl, size, uvl.xy * vec2(size) - 0.5);
#else
    return texture(t, uvl);
#endif
}

/* ---- the heights' layer: reads and normals ------------------------------ */

/* The heights' layer of the level array (its last: the finest level, R_{N-1};
 * DESIGN.md "Heights"), set with the array wherever a pass reads heights as
 * u_height (pass_common.c hfs_gles_bind_ray, hfs_gles_bind_normals; 0 for
 * the GIS horizons' own one-layer array). */
uniform highp int u_hlayer;

/* The normalized height (hi, lo) at texel p. */
vec2 hfs_height_at(highp sampler2DArray h, ivec2 p)
{
    return texelFetch(h, ivec3(p, u_hlayer), 0).xy;
}

/* ... read bilinearly at uv, texel position p (hfs_pair_tex4_layer_at). */
vec2 hfs_height_bilinear(highp sampler2DArray h, vec2 uv, ivec2 size, vec2 p)
{
    return hfs_pair_tex4_layer_at(h, vec3(uv, float(u_hlayer)), size, p).xy;
}

/* The normal from the heights already read at (lo.x, p.y), (hi.x, p.y),
 * (p.x, lo.y), (p.x, hi.y), span = hi - lo (hfs_normal_sides, and
 * env_slices.frag's 3 x 3 reads). */
vec3 hfs_normal_from(vec2 hx0, vec2 hx1, vec2 hy0, vec2 hy1, ivec2 span_i, float zf)
{
    vec2 span = vec2(max(span_i, ivec2(1)));
    float gx = hfs_hdiff(hx1, hx0) * zf / span.x;
    float gy = hfs_hdiff(hy1, hy0) * zf / span.y;
    float m = max(1.0, max(abs(gx), abs(gy)));
    return normalize(vec3(-gx / m, -gy / m, 1.0 / m));
}

/* Texel p's normal (hfs_normal_at) and, from the same 4
 * reads, its height differences (hfs_hdiff) over zp to the neighbours at
 * (+x, -x, +y, -y), with which of them lie on the field (off it the read
 * is p's own): a pass that needs its own cell's one-sided slopes as well
 * reads the neighbours once (key_visibility.frag, bounce_gather.frag). */
vec3 hfs_normal_sides(highp sampler2DArray h, ivec2 p, ivec2 size, float zf, vec2 zp,
                      out vec4 d, out bvec4 on)
{
    ivec2 lo = max(p - 1, ivec2(0)), hi = min(p + 1, size - 1);
    vec2 x1 = hfs_height_at(h, ivec2(hi.x, p.y)), x0 = hfs_height_at(h, ivec2(lo.x, p.y));
    vec2 y1 = hfs_height_at(h, ivec2(p.x, hi.y)), y0 = hfs_height_at(h, ivec2(p.x, lo.y));
    d = vec4(hfs_hdiff(x1, zp), hfs_hdiff(x0, zp), hfs_hdiff(y1, zp), hfs_hdiff(y0, zp));
    on = bvec4(hi.x > p.x, lo.x < p.x, hi.y > p.y, lo.y < p.y);
    return hfs_normal_from(x0, x1, y0, y1, hi - lo, zf);
}

/* The unit normal at texel p of the heights h (RG hi+lo, size W x H):
 * SPEC's central differences of world z, one-sided at the border, as
 * runtime/core/field_geom.c hfs_field_normal, its overflow-safe scaling
 * included (zf = hscale zscale / dx, clamped to 1e30).  Computed where it
 * is read, from 4 fetches, instead of a full-resolution texture of normals
 * (2 MiB at 512^2; DESIGN.md "Normals where they are read").  N is
 * proportional to (-gx, -gy, 1) scaled by 1 / max(1, |gx|, |gy|): every
 * component in [-1, 1], N_z > 0 even on a wall of slope 1e30. */
vec3 hfs_normal_at(highp sampler2DArray h, ivec2 p, ivec2 size, float zf)
{
    vec4 d; /* unused: the compiler drops its arithmetic */
    bvec4 on;
    return hfs_normal_sides(h, p, size, zf, vec2(0.0), d, on);
}

/* ---- the grids: where a texel reads its receivers ------------------------ */

/* runtime/core/split_horizon.h HFS_SPLIT_STEEP, which runtime/gles/
 * programs.c defines for every program; this default serves the build's
 * checks of the files alone. */
#ifndef HFS_FAR_STEEP
#define HFS_FAR_STEEP 6
#endif

/* Where texel p reads a grid of occluders (runtime/core/split_horizon.h
 * hfs_split_far_snap: the same rule): f, its bilinear place between the
 * receivers (0 = x0, 1 = (x1.x, x0.y), 2 = (x0.x, x1.y), 3 = x1), kept
 * where no receiver that weighs rises above p steeper than HFS_FAR_STEEP
 * (r: the receivers' heights above p, texels, over their distances);
 * else moved to the heavier edge whose two receivers pass (two as heavy:
 * the receiver they share), else to the one receiver that passes and
 * weighs most (none passing: the least steep; a tie: f itself).  A receiver on a roof sees over the building across the street
 * that hides the sky from a texel at the wall's foot: its occluders are
 * not the texel's at any blend. */
vec2 hfs_grid_snap(ivec2 p, ivec2 x0, ivec2 x1, vec2 f, vec4 r)
{
    float steep = float(HFS_FAR_STEEP);
    vec4 w = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
    vec2 d0 = vec2(x0 - p), d1 = vec2(x1 - p);
    vec4 dist = vec4(length(d0), length(vec2(d1.x, d0.y)), length(vec2(d0.x, d1.y)), length(d1));
    vec4 rise = mix(max(r, vec4(0.0)) / max(dist, vec4(1e-30)), vec4(0.0),
                    lessThanEqual(dist, vec4(0.0)));
    vec4 ok = max(vec4(lessThanEqual(w, vec4(0.0))), vec4(lessThanEqual(rise, vec4(steep))));
    if (ok.x * ok.y * ok.z * ok.w > 0.5)
        return f;
    vec4 pass = vec4(ok.x * ok.y, ok.z * ok.w, ok.x * ok.z, ok.y * ok.w);
    vec4 ew = vec4(w.x + w.y, w.z + w.w, w.x + w.z, w.y + w.w);
    int best = -1, tie = -1;
    float bw = 0.0;
    for (int k = 0; k < 4; ++k) {
        if (!(pass[k] > 0.5) || !(ew[k] > 0.0))
            continue;
        if (ew[k] > bw) {
            best = k;
            tie = -1;
            bw = ew[k];
        } else if (ew[k] == bw) {
            tie = k;
        }
    }
    if (best >= 0 && tie < 0)
        return best < 2 ? vec2(f.x, float(best)) : vec2(float(best - 2), f.y);
    if (best >= 0) /* two edges as heavy: the receiver they share */
        return vec2(float(tie - 2), float(best));
    int one = -1;
    bool tied = false;
    for (int k = 0; k < 4; ++k) {
        if (!(w[k] > 0.0))
            continue;
        bool ok_k = ok[k] > 0.5;
        bool same = one >= 0 && ok_k == (ok[max(one, 0)] > 0.5);
        if (one < 0 || (ok_k && !(ok[max(one, 0)] > 0.5)) ||
            (same && (ok_k ? w[k] > w[max(one, 0)] : rise[k] < rise[max(one, 0)]))) {
            one = k;
            tied = false;
        } else if (same && (ok_k ? w[k] == w[max(one, 0)] : rise[k] == rise[max(one, 0)])) {
            tied = true;
        }
    }
    return tied ? f : vec2(float(one % 2), float(one / 2));
}

/* The receivers' heights above texel p (r, texels; x0 and x1 as in
 * hfs_grid_snap) blended at the place t where p reads the grid (its
 * bilinear place, or hfs_grid_snap's off a wall); off, that place less
 * p's (0 but off a wall: an occluder read there lies dot(off, u) farther
 * along its direction u).  hfs_grid_rise's and env_slices.frag's. */
float hfs_grid_blend(ivec2 p, ivec2 x0, ivec2 x1, vec4 r, out vec2 t, out vec2 off)
{
    t = hfs_grid_snap(p, x0, x1, vec2(p - x0) / vec2(max(x1 - x0, ivec2(1))), r);
    off = vec2(x0 - p) + t * vec2(x1 - x0);
    return mix(mix(r.x, r.y, t.x), mix(r.z, r.w, t.x), t.y);
}

/* How far the receivers of the grid of step `step` around texel p stand
 * above it, in texels: their heights (on layer sc.z, scaled by sc.y: the
 * finest scale's (d, inv_run, layer)) blended at p's place t on the grid
 * (its bilinear weights, or hfs_grid_snap's place off a wall), minus p's;
 * 4 fetches (env_slices.frag grid_rise; bounce_gather.frag's far
 * occluders).  t and off: hfs_grid_blend's (t for hfs_grid_uv_at). */
float hfs_grid_rise(highp sampler2DArray levels, ivec2 p, int step, ivec2 size, vec4 sc,
                    out vec2 t, out vec2 off)
{
    ivec2 x0 = (p / step) * step;
    ivec2 x1 = min(x0 + step, size - 1);
    int layer = int(sc.z);
    vec2 h = texelFetch(levels, ivec3(p, layer), 0).xy;
    vec4 r = sc.y * vec4(hfs_hdiff(texelFetch(levels, ivec3(x0, layer), 0).xy, h),
                         hfs_hdiff(texelFetch(levels, ivec3(x1.x, x0.y, layer), 0).xy, h),
                         hfs_hdiff(texelFetch(levels, ivec3(x0.x, x1.y, layer), 0).xy, h),
                         hfs_hdiff(texelFetch(levels, ivec3(x1, layer), 0).xy, h));
    return hfs_grid_blend(p, x0, x1, r, t, off);
}
