/*
 * view_sky.frag - the 3-D view's background (runtime/gles/pass_view.c),
 * drawn first, under the mesh: the camera's background in the direction
 * of the pixel centre's ray (the truth's miss, truth_view.c; view_look.h):
 * the environment map itself (u_sky, times its scale), else the
 * environment's SH (zero without an environment: u_env then holds zeros),
 * a studio grey gradient, or a colour.  Perspective: forward + x right +
 * y up with the pixel's normalized device coordinates (u_right, u_up carry
 * the half extents at unit depth); ortho: every ray is forward.
 */
precision highp float;
precision highp int;

void hfs_sh_basis(vec3 d, out vec4 y[4]);
vec3 hfs_sky_map(highp sampler2D tex, vec3 d, float rot);
float hfs_studio(vec3 d);

uniform highp sampler2D u_sky;          /* the environment map (view_sky.c), or none */

layout(std140) uniform HfsView {
    mat4 u_mvp;
    vec4 u_eye;
    vec4 u_zmap;
    vec4 u_sizes;
    vec4 u_fwd;                         /* forward, the side walls' bottom z */
    vec4 u_right;
    vec4 u_up;
    vec4 u_env[12];
    vec4 u_bg;                          /* (mode, map scale, env_rotate, 0): view_sky.c */
    vec4 u_bg_rgb;                      /* studio level or colour, times the scale */
    vec4 u_haze;                        /* (sigma, z0, scale height, 0); 0: no haze */
    vec4 u_haze_in;                     /* in-scattered radiance, times the scale */
};

layout(location = 0) out vec4 o_color;

void main()
{
    vec2 ndc = gl_FragCoord.xy / u_sizes.zw * 2.0 - 1.0;
    vec3 d = u_fwd.xyz;
    if (u_eye.w < 0.5)
        d += ndc.x * u_right.xyz + ndc.y * u_up.xyz;
    vec3 n = normalize(d);
    vec3 rgb;
    if (u_bg.x > 2.5) {
        rgb = u_bg_rgb.rgb;
    } else if (u_bg.x > 1.5) {
        rgb = u_bg_rgb.rgb * hfs_studio(n);
    } else if (u_bg.x > 0.5) {
        rgb = hfs_sky_map(u_sky, n, u_bg.z) * u_bg.y;
    } else {
        vec4 y[4];
        hfs_sh_basis(n, y);
        for (int c = 0; c < 3; ++c)
            rgb[c] = dot(y[0], u_env[4 * c]) + dot(y[1], u_env[4 * c + 1]) +
                     dot(y[2], u_env[4 * c + 2]) + dot(y[3], u_env[4 * c + 3]);
    }
    o_color = vec4(rgb, 1.0);
}
