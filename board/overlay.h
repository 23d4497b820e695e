/*
 * overlay.h — short text drawn into an RGBA8 picture with a tiny built-in
 * 5x7 bitmap font, for the kiosk's frame-time line ("12.3 ms  7/9 passes").
 *
 * Characters: digits, A-Z, a-z, space and . : % / - + = , ( ) ?; any other
 * byte is drawn as '?'.  Each glyph sits in a 6 x 8 cell (one column and one
 * row of spacing), every font pixel a scale x scale block.  Pictures are
 * row 0 = top (as hfs_display_present takes them).  Drawing is clipped to
 * the picture: any position is safe.  Scales are clamped to 1..64 and text
 * is cut after 1024 characters.  No allocation, no state.
 */
#ifndef HFS_OVERLAY_H
#define HFS_OVERLAY_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define HFS_OVERLAY_GLYPH_W 5
#define HFS_OVERLAY_GLYPH_H 7

/* The 7 rows of c's glyph, top first, bit 4 = leftmost pixel.  Returns 1 if
 * the font has c, 0 if not (rows then hold '?'). */
int hfs_overlay_glyph(char c, uint8_t rows[HFS_OVERLAY_GLYPH_H]);

/* Size in pixels of the box hfs_overlay_text fills: a margin of one font
 * pixel around the text, i.e. ((6 n + 1) * scale) x (9 * scale) for n
 * characters (0 x 0 for an empty string). */
void hfs_overlay_text_size(const char *text, int scale, int *w, int *h);

/* Draws text with the box's top-left corner at (x, y): the box in bg
 * (NULL = no box; bg[3] < 255 blends it over the picture), then the glyphs
 * in fg (opaque).  scale < 1 counts as 1.  rgba is w x h pixels. */
void hfs_overlay_text(uint8_t *rgba, int w, int h, int x, int y, int scale, const char *text,
                      const uint8_t fg[4], const uint8_t *bg);

/* The kiosk's label, readable over any picture (issue 41): the box in
 * black at alpha HFS_OVERLAY_BOX_ALPHA (a white picture under it becomes
 * sRGB byte 95: 6.4:1 against white text, WCAG AA), each glyph ringed by a
 * one-pixel opaque black outline (21:1 right at its edges, so a glyph
 * reads even where the box is blended over a bright patch), then the
 * glyphs in white.  Same box and clipping as hfs_overlay_text. */
#define HFS_OVERLAY_BOX_ALPHA 160
void hfs_overlay_label(uint8_t *rgba, int w, int h, int x, int y, int scale, const char *text);

#ifdef __cplusplus
}
#endif
#endif /* HFS_OVERLAY_H */
