/*
 * view.vert - the 3-D view's mesh (runtime/gles/pass_view.c): the field's
 * grid points as triangle strips, one instance per row of cells, from
 * gl_VertexID and gl_InstanceID alone (no attribute, no buffer): vertex 2i
 * of instance j is grid point (i, j), vertex 2i + 1 is (i, j + 1), so each
 * cell is two triangles split along its (i, j+1)-(i+1, j) diagonal.
 * With u_skirt = 1 it draws the field's four side walls instead (instance
 * = edge: j = 0, j = H-1, i = 0, i = W-1; vertex 2k the edge's k-th grid
 * point, 2k + 1 the same point at the walls' bottom z, u_fwd.w): the
 * truth's rays test the terrain from where they enter the grid, so a ray
 * entering below the surface hits at the edge, and the field looks like a
 * solid block; a wall shows its edge point's radiance all the way down.
 * Heights come from the level array's last layer (u_hlayer; normalized, as an
 * fp16 (hi, lo) pair, or fp32 (v, 0)): world z = zscale exaggeration
 * (base + hscale v), folded into u_zmap.  Positions are taken relative to
 * the eye before the projection, so a large dx loses no float precision
 * to the translation.
 */
precision highp float;
precision highp int;
precision highp sampler2D;

uniform highp sampler2DArray u_height;  /* the level array: normalized heights, W x H */
uniform highp int u_hlayer;             /* its layer of the heights (gles_pairs.frag) */
uniform int u_skirt;                    /* 1: the side walls, 0: the surface */

layout(std140) uniform HfsView {
    mat4 u_mvp;                         /* eye-relative world -> clip */
    vec4 u_eye;                         /* eye (world), ortho flag */
    vec4 u_zmap;                        /* (z per normalized unit, z offset, dx, lit -> view scale) */
    vec4 u_sizes;                       /* (W, H, view w, view h) */
    vec4 u_fwd;                         /* forward, the side walls' bottom z */
    vec4 u_right;                       /* right * tan(fov/2) * aspect */
    vec4 u_up;                          /* up * tan(fov/2) */
    vec4 u_env[12];                     /* the sky's SH times the view scale, 4 vec4 per channel */
    vec4 u_bg;                          /* (mode, map scale, env_rotate, 0): view_sky.c */
    vec4 u_bg_rgb;                      /* studio level or colour, times the scale */
    vec4 u_haze;                        /* (sigma, z0, scale height, 0); 0: no haze */
    vec4 u_haze_in;                     /* in-scattered radiance, times the scale */
};

out highp vec2 v_grid;                  /* grid position (i, j) */
out highp vec3 v_rel;                   /* world position relative to the eye (the haze) */

void main()
{
    ivec2 p = ivec2(gl_VertexID >> 1, gl_InstanceID + (gl_VertexID & 1));
    bool bottom = false;
    if (u_skirt == 1) {
        ivec2 last = ivec2(u_sizes.xy) - 1;
        int k = min(gl_VertexID >> 1, gl_InstanceID < 2 ? last.x : last.y);
        p = gl_InstanceID < 2 ? ivec2(k, gl_InstanceID == 0 ? 0 : last.y)
                              : ivec2(gl_InstanceID == 2 ? 0 : last.x, k);
        bottom = (gl_VertexID & 1) == 1;
    }
    vec2 h = texelFetch(u_height, ivec3(p, u_hlayer), 0).rg;
    float z = bottom ? u_fwd.w : u_zmap.y + u_zmap.x * (h.x + h.y);
    vec3 w = vec3(float(p.x) * u_zmap.z, float(p.y) * u_zmap.z, z);
    v_grid = vec2(p);
    v_rel = w - u_eye.xyz;
    gl_Position = u_mvp * vec4(v_rel, 1.0);
}
