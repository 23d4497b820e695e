/*
 * bounce_light.frag - exit radiance at full resolution from the shading
 * pass's output and the bounces gathered on the grid (pass_bounce.c):
 *   v = u_direct * (hi + lo) + rho(x) * sum_{l in [u_first, u_first +
 *       u_count)} E_l(x),
 * E_l read bilinearly from the grid like the local lights' ratios
 * (hfs_grid_uv) and rho(x) = the albedo times the texel's albedo map
 * (HFS_ALBEDO_MAP).  HFS_SLICE (the bands stop at the direct horizon):
 * E_l times this texel's own occluded part of the hemisphere over the
 * receivers' (W_l in the alpha, interpolated like E), the occluded part
 * being the cosine-weighted solid angle below the direct horizons over pi
 * (here -2 / sqrt(pi) T_occ,0: the constant coefficient of the slices'
 * occluded transfer, env_slices.frag).  Between receivers the terrain a
 * texel sees follows its own normal and horizons, not only its
 * neighbours' (on rough relief: the indirect part's error at subsample 2
 * 3.6% -> 2.4% of its largest value on the DEM, BENCHMARKS.md); at a
 * receiver itself the ratio is 1 up to fp16.  Where W_l < 1e-3 (almost no
 * terrain seen; fp16 keeps W's digits above that) E_l is taken as it is.  Drawn twice over: as the radiance the next bounce
 * gathers (the direct light alone, or rho E of the last bounce; one
 * target) and as the frame's result (direct + every bounce, an fp16 hi +
 * lo pair like the shading pass's).  Radiances carry the frame's output
 * scale (pass_shade.c).
 * HFS_NEAR (a sub-sampled bounce grid, bounce_gather.frag "The near
 * part"): E_l = E_near,l(x) + E_l * (W_occ - W_near,l(x)) / W_l, the
 * texel's own near part (u_en, layer l: (E_near, W_near)) plus the grid's
 * rest scaled to the texel's own occluded part beyond it.
 * HFS_GLOSSY: a glossy receiver's lobe of each bounce, G_l (layer 2 l + 1;
 * E_l is then at 2 l), read and scaled like E_l, is added after the
 * albedo (not the albedo map's, as the direct lobe).
 */
// hfs-variant: HFS_ALBEDO_MAP 1
// hfs-variant: HFS_SLICE 1
// hfs-variant: HFS_FP32 1
// hfs-variant: HFS_SLICE 1, HFS_GLOSSY 1
// hfs-variant: HFS_SLICE 1, HFS_NEAR 1
// hfs-variant: HFS_SLICE 1, HFS_NEAR 1, HFS_FP32 1

#ifndef HFS_PI
#define HFS_PI 3.14159265358979
#endif

precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

vec2 hfs_split(float v);
vec2 hfs_grid_uv(ivec2 p, int sub, ivec2 size, ivec2 vsize);

uniform highp sampler2D u_hi;            /* the shading pass's output, hi */
uniform highp sampler2D u_lo;            /* and lo */
uniform highp sampler2DArray u_e;        /* (E_b, W_b) on the grid, a layer a bounce, LINEAR */
#ifdef HFS_SLICE
uniform highp sampler2D u_t0;            /* the slices' occluded transfer, coefficients 0-3 */
#endif
#ifdef HFS_NEAR
uniform highp sampler2DArray u_en;       /* (E_near, W_near) a bounce, full resolution */
#endif
#ifdef HFS_ALBEDO_MAP
uniform highp sampler2D u_albedo;        /* albedo map (RGB in [0, 1]), full resolution */
#endif
uniform ivec2 u_size;                    /* W, H */
uniform ivec2 u_vsize;                   /* the bounce grid's size */
uniform int u_sub;                       /* and step */
uniform float u_direct;                  /* 1: the direct light is part of v */
uniform float u_rho;                     /* the uniform albedo */
uniform int u_first;                     /* the bounces summed: layers [first, first + count) */
uniform int u_count;

layout(location = 0) out vec4 o_hi;
layout(location = 1) out vec4 o_lo;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 v = u_direct * (texelFetch(u_hi, p, 0).rgb + texelFetch(u_lo, p, 0).rgb);
    vec3 rho = vec3(u_rho);
#ifdef HFS_ALBEDO_MAP
    rho *= texelFetch(u_albedo, p, 0).rgb;
#endif
    vec2 uv = hfs_grid_uv(p, u_sub, u_size, u_vsize);
#ifdef HFS_SLICE
    float w_occ = -texelFetch(u_t0, p, 0).x * (2.0 / sqrt(HFS_PI)); /* over pi */
#endif
    vec3 e = vec3(0.0), gs = vec3(0.0);
    for (int l = 0; l < u_count; ++l) {
#ifdef HFS_GLOSSY
        vec4 eb = texture(u_e, vec3(uv, float(2 * (u_first + l))));
        vec3 gb = texture(u_e, vec3(uv, float(2 * (u_first + l) + 1))).rgb;
#else
        vec4 eb = texture(u_e, vec3(uv, float(u_first + l)));
        vec3 gb = vec3(0.0);
#endif
#ifdef HFS_NEAR
        vec4 en = texelFetch(u_en, ivec3(p, u_first + l), 0);
        if (eb.a >= 1e-3)
            eb.rgb *= max(w_occ - en.a, 0.0) / eb.a;
        eb.rgb += en.rgb;
#elif defined(HFS_SLICE)
        if (eb.a >= 1e-3) {
            float ratio = max(w_occ, 0.0) / eb.a;
            eb.rgb *= ratio;
            gb *= ratio;
        }
#endif
        e += eb.rgb;
        gs += gb;
    }
    v += rho * e + gs;
    v = clamp(v, vec3(-65504.0), vec3(65504.0));
    v = mix(vec3(0.0), v, equal(v, v));
    vec2 r = hfs_split(v.r), g = hfs_split(v.g), b = hfs_split(v.b);
    o_hi = vec4(r.x, g.x, b.x, 1.0);
    o_lo = vec4(r.y, g.y, b.y, 0.0);
}
