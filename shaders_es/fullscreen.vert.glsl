/*
 * fullscreen.vert - one triangle that covers the viewport, from gl_VertexID
 * alone: draw with glDrawArrays(GL_TRIANGLES, 0, 3) and an empty vertex array
 * bound (no attributes, no buffers).
 *
 * Vertices (clip space): (-1,-1), (3,-1), (-1,3); the part outside [-1,1]^2
 * is clipped away, so every pixel is covered once and there is no diagonal
 * seam.  v_uv is 0..1 across the viewport (pixel centres at (i+0.5)/W).
 */
out highp vec2 v_uv;

void main()
{
    vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0,
                  float((gl_VertexID & 2) << 1) - 1.0);
    v_uv = p * 0.5 + 0.5;
    gl_Position = vec4(p, 0.0, 1.0);
}
