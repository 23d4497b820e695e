/*
 * view_objects.vert - the objects of the 3-D view (runtime/gles/pass_view.c,
 * runtime/core/objects.h): their lit faces as triangles from a vertex buffer,
 * a position (the view's world: z times the exaggeration) and an exit
 * radiance already times the view's scale per vertex; positions taken
 * relative to the eye before the projection, as the mesh's (view.vert).
 */
precision highp float;

layout(std140) uniform HfsView {
    mat4 u_mvp;                         /* eye-relative world -> clip */
    vec4 u_eye;                         /* eye (world), ortho flag */
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

layout(location = 0) in vec3 a_pos;     /* relative to the eye */
layout(location = 1) in vec3 a_rgb;

out vec3 v_rgb;
out highp vec3 v_rel;                   /* relative to the eye (the haze) */

void main()
{
    v_rgb = a_rgb;
    v_rel = a_pos;
    gl_Position = u_mvp * vec4(a_pos, 1.0);
}
