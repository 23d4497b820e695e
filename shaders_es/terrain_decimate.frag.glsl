/*
 * terrain_decimate.frag - one pyramid level from the next finer one (DESIGN.md
 * "Height pyramid"): level i samples level i+1 bilinearly at its own texel
 * centres, clamped to the edge (runtime/cpu/cpu_pyramid.c decimate).  The
 * target is the level's own RG texture; heights are normalized hi+lo pairs,
 * and bilinear filtering is linear, so filtering hi and lo separately and
 * adding them filters v.
 *
 * Uniforms: u_src (level i+1, LINEAR, CLAMP_TO_EDGE), u_dsize (level i size).
 * HFS_SRC_LAYERS N: level i+1 is the heights, the last layer of the level
 * array of N layers (the first decimation: the frame keeps one copy of the
 * heights, issue 37).
 */
// hfs-variant: HFS_FP32 1
// hfs-variant: HFS_SRC_LAYERS 3

precision highp float;
precision highp int;
precision highp sampler2D;

vec2 hfs_split(float v);
vec2 hfs_pair_tex(highp sampler2D t, vec2 uv);
vec4 hfs_pair_tex4_layer(highp sampler2DArray t, vec3 uvl);
float hfs_h(vec2 t);

#ifdef HFS_SRC_LAYERS
uniform highp sampler2DArray u_src;
#else
uniform highp sampler2D u_src;
#endif
uniform ivec2 u_dsize;

layout(location = 0) out vec4 o_h;

void main()
{
    /* gl_FragCoord.xy = (t + 0.5, r + 0.5): the level's texel centre in
     * normalized coordinates is the same point of the finer level. */
    vec2 uv = gl_FragCoord.xy / vec2(u_dsize);
#ifdef HFS_SRC_LAYERS
    vec2 t = hfs_pair_tex4_layer(u_src, vec3(uv, float(HFS_SRC_LAYERS - 1))).xy;
#else
    vec2 t = hfs_pair_tex(u_src, uv);
#endif
    o_h = vec4(hfs_split(hfs_h(t)), 0.0, 0.0);
}
