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
};

in vec3 v_rgb;

layout(location = 0) out vec4 o_color;

void main()
{
    o_color = vec4(clamp(v_rgb, vec3(0.0), vec3(65504.0)), 1.0);
}
