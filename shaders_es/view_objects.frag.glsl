/*
 * view_objects.frag - an object's face in the 3-D view: its vertices' lit
 * radiance (runtime/core/objects.h), interpolated across the triangle (the
 * truth's view reads the same vertex grid bilinearly).
 */
precision highp float;

layout(std140) uniform HfsView {
    mat4 u_mvp;
    vec4 u_eye;
    vec4 u_zmap;
    vec4 u_sizes;
    vec4 u_fwd;
    vec4 u_right;
    vec4 u_up;
    vec4 u_env[12];
    vec4 u_bg;                          /* (mode, map scale, env_rotate, 0): view_sky.c */
    vec4 u_bg_rgb;                      /* studio level or colour, times the scale */
    vec4 u_haze;                        /* (sigma, z0, scale height, 0); 0: no haze */
    vec4 u_haze_in;                     /* in-scattered radiance, times the scale */
};

in vec3 v_rgb;
in highp vec3 v_rel;

layout(location = 0) out vec4 o_color;

vec3 hfs_haze(vec3 rgb, vec4 haze, vec3 lin, vec3 rel, vec3 eye, vec3 fwd, bool ortho);

void main()
{
    vec3 rgb = clamp(v_rgb, vec3(0.0), vec3(65504.0));
    if (u_haze.x > 0.0) /* seen through the view's haze, as the terrain */
        rgb = hfs_haze(rgb, u_haze, u_haze_in.rgb, v_rel, u_eye.xyz, u_fwd.xyz, u_eye.w > 0.5);
    o_color = vec4(rgb, 1.0);
}
