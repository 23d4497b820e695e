/*
 * shm_double.frag - one doubling pass of a shadow height map
 * (runtime/core/shm.h, runtime/gles/shm_query.c):
 *     S_{j+1}(x) = max(S_j(x), S_j(x + u_off) - u_drop),
 * S_j read bilinearly between the four grid points around x + u_off
 * (weighted in highp here, as shm.c hfs_shm_sample), nothing added where
 * x + u_off leaves the grid.  S is the field's normalized height (v = (z -
 * base) / hscale, in [-1, 1]: S never leaves the heights' range) as an
 * fp16-exact hi and its rest lo, like the heights themselves.
 */
// hfs-variant: HFS_FP32 1

precision highp float;
precision highp int;
precision highp sampler2D;

vec2 hfs_split(float v);

uniform highp sampler2D u_src;           /* S_j: (hi, lo), W x H */
uniform ivec2 u_size;                    /* W, H */
uniform vec2 u_off;                      /* 2^j texels towards the light */
uniform float u_drop;                    /* the ray's rise over them, normalized */

layout(location = 0) out vec4 o_s;

float s_at(ivec2 p)
{
    vec2 t = texelFetch(u_src, p, 0).xy;
    return t.x + t.y;
}

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    float v = s_at(p);
    vec2 last = vec2(u_size - 1);
    vec2 g = vec2(p) + u_off;
    float slack = 1e-5 * (1.0 + abs(u_off.x) + abs(u_off.y));
    if (all(greaterThanEqual(g, vec2(-slack))) && all(lessThanEqual(g, last + slack))) {
        g = clamp(g, vec2(0.0), last);
        ivec2 c = min(ivec2(g), ivec2(last) - 1);
        vec2 f = g - vec2(c);
        float a = s_at(c) + f.x * (s_at(c + ivec2(1, 0)) - s_at(c));
        float b = s_at(c + ivec2(0, 1)) + f.x * (s_at(c + ivec2(1, 1)) - s_at(c + ivec2(0, 1)));
        v = max(v, a + f.y * (b - a) - u_drop);
    }
#ifdef HFS_FP32
    o_s = vec4(v, 0.0, 0.0, 1.0);
#else
    vec2 r = hfs_split(v);
    o_s = vec4(r.x, r.y, 0.0, 1.0);
#endif
}
