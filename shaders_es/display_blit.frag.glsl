/*
 * display_blit.frag - shows a display-encoded RGBA8 picture (board/display_gl.c)
 * in the viewport, which the caller set to the fitted rectangle; drawn with
 * fullscreen.vert.
 *
 * The texture holds the picture's row 0 (its top) at t = 0, as uploaded;
 * v_uv.y = 0 is the BOTTOM of the viewport, hence the flip.  The sampler's
 * filter (NEAREST at integer scales, LINEAR otherwise) is set by the caller;
 * at 1:1 every fragment samples its own texel centre, so bytes pass
 * unchanged (RGBA8 texture to an 8-bit window: no conversion, no sRGB
 * decode, the data is already sRGB).  Alpha is written as 1: the screen is
 * opaque.
 */
precision highp float;

uniform highp sampler2D u_image;

in highp vec2 v_uv;
layout(location = 0) out vec4 o_color;

void main()
{
    o_color = vec4(texture(u_image, vec2(v_uv.x, 1.0 - v_uv.y)).rgb, 1.0);
}
