/*
 * view_sky.frag - the 3-D view's background (runtime/gles/pass_view.c),
 * drawn first, under the mesh: the environment's SH in the direction of
 * the pixel centre's ray (the truth's miss, truth_view.c), zero without an
 * environment (u_env then holds zeros).  Perspective: forward + x right +
 * y up with the pixel's normalized device coordinates (u_right, u_up carry
 * the half extents at unit depth); ortho: every ray is forward.
 */
precision highp float;
precision highp int;

void hfs_sh_basis(vec3 d, out vec4 y[4]);

layout(std140) uniform HfsView {
    mat4 u_mvp;
    vec4 u_eye;
    vec4 u_zmap;
    vec4 u_sizes;
    vec4 u_fwd;                         /* forward, the side walls' bottom z */
    vec4 u_right;
    vec4 u_up;
    vec4 u_env[12];
};

layout(location = 0) out vec4 o_color;

void main()
{
    vec2 ndc = gl_FragCoord.xy / u_sizes.zw * 2.0 - 1.0;
    vec3 d = u_fwd.xyz;
    if (u_eye.w < 0.5)
        d += ndc.x * u_right.xyz + ndc.y * u_up.xyz;
    vec4 y[4];
    hfs_sh_basis(normalize(d), y);
    vec3 rgb;
    for (int c = 0; c < 3; ++c)
        rgb[c] = dot(y[0], u_env[4 * c]) + dot(y[1], u_env[4 * c + 1]) +
                 dot(y[2], u_env[4 * c + 2]) + dot(y[3], u_env[4 * c + 3]);
    o_color = vec4(rgb, 1.0);
}
