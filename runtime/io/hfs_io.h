/*
 * hfs_io.h — file formats of hfshade: height fields in, environment maps in,
 * PFM/PNG images out.  Library `hfshade_io`, separate from the renderer core
 * (which links only libc/libm/EGL/GLES); it uses libpng, stb_image (Radiance
 * .hdr) and OpenEXRCore (.exr).
 *
 * Conventions (../../shared/SPEC.md is the authority):
 *   - A height field is H[j][i], i = column (x), j = row (y), stored row-major
 *     with row j = 0 first.  In every format the FIRST ROW STORED IN THE FILE
 *     is j = 0: the top row of a PNG/PGM, the first row of a PFM (this is the
 *     SPEC's rule and differs from the usual bottom-to-top PFM convention),
 *     the first data row of an ESRI .asc grid (its north row, so +y points
 *     south in map terms), the first W floats of a raw file.
 *   - Heights are the stored values, unscaled: an 8/16-bit PNG or PGM sample
 *     v gives height v (0..65535), not v/maxval.  Scale with the scene's
 *     zscale.
 *   - Holes (nodata): NaN, +Inf, -Inf and, when declared, one nodata value
 *     (from the options, and for .asc also the file's NODATA_value) are holes.
 *     A grey+alpha PNG texel with alpha 0 is a hole too.  Holes are filled
 *     (method below) before the loader returns; out->holes says how many.
 *
 * Hole filling: push-pull (Gortler et al., "The Lumigraph", 1996).  Push:
 * build a pyramid by 2x2 averaging of the valid texels only (a coarse texel is
 * valid if any of its up-to-four children is).  Pull: from the coarsest level
 * down, every hole takes the bilinear interpolation of the already complete
 * next-coarser level.  Valid texels are never changed; the result is
 * deterministic, O(W*H) time and 4/3 W*H extra floats, and every hole gets a
 * finite value that is a convex combination of valid heights (so it never
 * leaves their range).  A single hole inside a constant region gets exactly
 * that constant.  A field with no valid texel is an error.
 *
 * Errors: every function returns 0 (HFS_OK) or a negative hfs_status and fills
 * the optional hfs_error with one line "PATH: problem".  Malformed, truncated
 * or absurd files are rejected (HFS_E_FORMAT), unreadable ones give HFS_E_IO,
 * valid but unsupported variants HFS_E_UNSUPPORTED, sizes over the guard
 * HFS_E_INVALID.  On failure the output struct is left zeroed.  Nothing here
 * prints, and there is no global state: calls on different objects may run
 * on different threads at once.
 *
 * Writers are atomic: they write "PATH.tmp-XXXXXX" in the same directory and
 * rename it over PATH only when everything succeeded, so no partial file is
 * ever left behind (PATH with symbolic links resolved: a link keeps pointing
 * at the new file).  An existing PATH that is not a regular file (a
 * character device, a FIFO with a reader) is written in place with every
 * error reported (ENOSPC from /dev/full), never replaced; a directory, a
 * dangling link or a FIFO with no reader is an error.  They refuse images
 * that hold NaN or Inf (SPEC: no non-finite value reaches an output).
 * Reader functions open regular files only, without blocking (a FIFO named
 * as an input is a one-line error, not a hang).
 */
#ifndef HFS_IO_H
#define HFS_IO_H

#include "hfshade.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- height fields --------------------------------------------------------- */

/* Default size guard of hfs_height_load (also the largest GLES texture side
 * we plan for).  16384 * 16384 = 2^28 texels = 1 GiB of float heights. */
#define HFS_HEIGHT_MAX_DIM 16384
#define HFS_HEIGHT_MAX_TEXELS (1LL << 28)

typedef enum hfs_height_format {
    HFS_HEIGHT_AUTO = 0,  /* not a format: "unknown" in outputs            */
    HFS_HEIGHT_PNG,       /* 1/2/4/8/16-bit grey or grey+alpha PNG          */
    HFS_HEIGHT_PGM,       /* P5 (binary) or P2 (ASCII), maxval 1..65535     */
    HFS_HEIGHT_PFM,       /* "Pf" greyscale float32                         */
    HFS_HEIGHT_ASC,       /* ESRI ASCII grid                                */
    HFS_HEIGHT_RAW_F32,   /* little-endian float32, size from the options   */
    HFS_HEIGHT_EXTERNAL   /* read by the extra loader (hfs_height_set_extra_loader) */
} hfs_height_format;

/* Zero means default for every field; a NULL opts pointer is all defaults. */
typedef struct hfs_height_load_opts {
    int has_nodata;       /* non-zero: `nodata` marks holes                 */
    float nodata;         /* compared after conversion to float             */
    int raw_width;        /* raw float32 only (--size WxH); both or neither */
    int raw_height;
    int max_width;        /* guard; 0 = HFS_HEIGHT_MAX_DIM                  */
    int max_height;       /* guard; 0 = HFS_HEIGHT_MAX_DIM                  */
    long long max_texels; /* guard; 0 = HFS_HEIGHT_MAX_TEXELS               */
} hfs_height_load_opts;

/* A loaded height field.  The caller owns z and frees it with
 * hfs_heightmap_free(). */
typedef struct hfs_heightmap {
    int width, height;    /* >= 2 each                                      */
    float *z;             /* width*height finite heights, row j = 0 first   */
    long holes;           /* texels that were nodata and have been filled   */
    double cellsize;      /* .asc cellsize (suggested dx); 0 = not given    */
    hfs_height_format format;
    char note[200];       /* what a loader changed, for the log ("" none)   */
    /* Where the grid lies, when its file said (the tools' GDAL loader):
     * GDAL's geotransform of the grid as loaded (north-up, row 0 the north
     * edge, after any resampling: x = g[0] + (i + 0.5) g[1] at texel i's
     * centre, y = g[3] + (j + 0.5) g[5]) and its CRS as WKT ("" unknown;
     * longer ones than the buffer are dropped, said in note).  Outputs
     * written through GDAL keep them (hfshade render --geotiff). */
    int has_georef;
    double geotransform[6];
    char crs_wkt[4096];
} hfs_heightmap;

/* A loader for formats this library does not read itself (the tools' GDAL
 * module, tools/gdal/height_gdal.h): hfs_height_load calls it for a file
 * whose content matches none of its signatures, before the raw float32
 * fallback; it returns HFS_E_UNSUPPORTED when it cannot read the file
 * either (the usual "unrecognised format" error follows), else its own
 * result with *out filled as hfs_height_load fills it (holes filled).
 * NULL (default): none.  Set once at start-up, before loading. */
typedef int (*hfs_height_loader_fn)(const char *path, const hfs_height_load_opts *opts,
                                    hfs_heightmap *out, hfs_error *err);
HFS_API void hfs_height_set_extra_loader(hfs_height_loader_fn fn);

/*
 * Loads a height field.  The format comes from the file name's extension
 * (.png .pgm .pfm .asc .raw .f32 .r32 .bin, case-insensitive) and is checked
 * against the content's signature; with any other extension it comes from the
 * content alone, and a file whose content matches no signature is read as raw
 * float32 when opts gives raw_width/raw_height.  Raw sizes given for a file
 * that is not raw are an error (HFS_E_INVALID), so a wrong --size never goes
 * unnoticed.
 *
 * Format details and limits:
 *   PNG  grey 1..16 bit (16-bit big-endian per PNG), or grey+alpha where
 *        alpha = 0 marks a hole and other alpha is ignored.  Palette and RGB
 *        PNGs are rejected (convert to greyscale first).  tRNS, gAMA, sBIT
 *        are ignored (ancillary chunks are skipped unparsed).  The file must
 *        be complete up to IEND, and big enough for its claimed size at
 *        deflate's maximum ratio (checked before anything is allocated).
 *   PGM  P5 (8-bit if maxval < 256, else 16-bit big-endian) or P2 (ASCII);
 *        maxval 1..65535; samples above maxval are errors; one image per file
 *        (no bytes after a P5 image; only whitespace after a P2 image).
 *   PFM  "Pf" only (colour "PF" is rejected: a height field has one
 *        channel); the scale's sign gives the byte order (negative = little
 *        endian), its magnitude is ignored; the file size must match exactly.
 *   ASC  keys ncols, nrows, xllcorner|xllcenter, yllcorner|yllcenter,
 *        cellsize (all required, any order, case-insensitive, each once) and
 *        optional NODATA_value; then exactly nrows*ncols decimal numbers
 *        (no "nan"/"inf" tokens; values beyond float range are errors).
 *        Non-square cells (dx/dy keys) are rejected.
 *   RAW  width*height little-endian IEEE float32, file size exactly
 *        4*width*height bytes.
 *
 * On success returns 0 and fills *out; on failure returns < 0, fills err and
 * leaves *out zeroed.
 */
HFS_API int hfs_height_load(const char *path, const hfs_height_load_opts *opts,
                            hfs_heightmap *out, hfs_error *err);

/* Frees out->z and zeroes *out.  NULL-safe. */
HFS_API void hfs_heightmap_free(hfs_heightmap *hm);

/*
 * Fills holes in place by push-pull (see the top of this file).  Holes are
 * NaN, +-Inf and, if has_nodata, texels equal to nodata.  *holes (optional)
 * receives the count.  Errors: sizes < 1 (HFS_E_INVALID), no valid texel
 * (HFS_E_FORMAT, message "no valid heights ..." without a path: callers with
 * a file name prefix it), out of memory.  z is unchanged on error.
 */
HFS_API int hfs_height_fill_holes(float *z, int width, int height,
                                  int has_nodata, float nodata, long *holes,
                                  hfs_error *err);

/* ---- environment maps ------------------------------------------------------- */

/* Size guard of hfs_envmap_load: 16384 per side and 2^27 texels (1.5 GiB of
 * float RGB, e.g. 16384 x 8192). */
#define HFS_ENVMAP_MAX_DIM 16384
#define HFS_ENVMAP_MAX_TEXELS (1LL << 27)

/* An equirectangular environment map (SPEC: column u -> phi = 2 pi u, top
 * row = zenith), linear RGB.  The caller frees it with hfs_envmap_free(). */
typedef struct hfs_envmap {
    int width, height;
    float *rgb;           /* width*height*3 finite floats, top row first    */
} hfs_envmap;

/*
 * Loads an environment map, chosen by content (".hdr"/".exr" extensions are
 * checked against it):
 *   Radiance .hdr  "#?RADIANCE" or "#?RGBE", FORMAT=32-bit_rle_rgbe,
 *                  resolution "-Y H +X W" (the standard orientation; others
 *                  are rejected), flat or RLE scanlines, decoded by stb_image.
 *                  A file that ends before the last pixel is an error, and
 *                  so is a NUL byte in the header.
 *   OpenEXR        first part only, scanline or tiled (level 0 of mip/rip
 *                  maps), any compression OpenEXRCore decodes; channels R,G,B
 *                  (any of half/float/uint; others such as A are ignored) or,
 *                  failing those, a single Y channel used as grey.  Deep
 *                  parts, sub-sampled channels, cube-face envmaps and partial
 *                  RGB sets are rejected.  The data window is the image.
 *                  A chunk claiming more decoded bytes than its stored bytes
 *                  can expand to is corrupt (checked for every chunk before
 *                  the image is allocated).
 *   PFM            "PF" (RGB) or "Pf" (grey: R = G = B), either byte order;
 *                  as every PFM of this project (SPEC "File row order") the
 *                  first row stored is the top row, the zenith (row v = 0),
 *                  NOT the customary bottom-up PFM; a ".pfm" name must hold
 *                  PFM content.
 * Non-finite pixels (NaN/Inf, possible only in EXR) are an error, not
 * clamped: a sun stored as +Inf has no meaningful finite stand-in.  Negative
 * values are kept.  Maps must be at least 1x1 and within the guard above.
 */
HFS_API int hfs_envmap_load(const char *path, hfs_envmap *out, hfs_error *err);

/* Frees m->rgb and zeroes *m.  NULL-safe. */
HFS_API void hfs_envmap_free(hfs_envmap *m);

/* ---- albedo maps ------------------------------------------------------------- */

/*
 * Loads an albedo map for a width x height field (hfs_lighting albedo_map)
 * into *rgb (width*height*3 linear floats, row j = 0 first like the
 * heights; the caller frees it with free()), chosen by content:
 *   PNG   any colour type and bit depth through libpng's simplified API:
 *         16-bit files are linear; 8-bit files sRGB-encoded (libpng
 *         converts one whose gAMA/sRGB/iCCP chunks say otherwise) and
 *         decoded by the exact sRGB curve, as hfs_png_write encodes; grey
 *         is R = G = B; alpha is ignored;
 *   PFM   "PF" or "Pf" (R = G = B), linear, first row = row j = 0;
 *   .exr / .hdr  linear, as hfs_envmap_load reads them (first row = j = 0).
 * Errors (one line naming the file): a size other than the field's
 * ("PATH: albedo map is 64x64, the heights are 128x128"), a value outside
 * [0, 1] or not finite ("PATH: albedo texel (3, 7) G is 1.5, outside
 * [0, 1]"), and every error of the readers.  *rgb is NULL on failure.
 */
HFS_API int hfs_albedo_load(const char *path, int width, int height, float **rgb,
                            hfs_error *err);

/* ---- writers ------------------------------------------------------------------ */

/*
 * Output sets: the files one run writes, checked and committed together.
 *   hfs_outputs_input(o, PATH)  for every file the run reads (missing ones
 *                               are ignored: their loader will say so);
 *   hfs_outputs_add(o, PATH)    for every file it will write: a PATH that is
 *                               the same file as an input or an earlier
 *                               output (device and inode, through symbolic
 *                               and hard links; for files not there yet the
 *                               path with its directory resolved) is an
 *                               error (HFS_E_INVALID) before anything is
 *                               written;
 *   hfs_pfm_write_to / hfs_png_write_to(o, PATH, ...)  write complete
 *                               temporaries;
 *   hfs_outputs_commit(o)       renames them all over their targets; if a
 *                               rename fails, the files this run created are
 *                               removed again (a file that existed before and
 *                               was already replaced stays replaced);
 *   hfs_outputs_destroy(o)      removes every temporary not committed.
 * At most 16 inputs and 8 outputs.
 */
typedef struct hfs_outputs hfs_outputs;
HFS_API int hfs_outputs_create(hfs_outputs **out, hfs_error *err);
HFS_API int hfs_outputs_input(hfs_outputs *o, const char *path, hfs_error *err);
HFS_API int hfs_outputs_add(hfs_outputs *o, const char *path, hfs_error *err);
HFS_API int hfs_outputs_commit(hfs_outputs *o, hfs_error *err);
HFS_API void hfs_outputs_destroy(hfs_outputs *o);

/*
 * PFM, little-endian (scale -1.0), first row written = row j = 0 (SPEC).
 * grey != 0 writes "Pf" with the Rec. 709 luminance 0.2126 R + 0.7152 G +
 * 0.0722 B computed in double (exactly R when R = G = B); grey == 0 writes
 * "PF" RGB.
 */
HFS_API int hfs_pfm_write(const char *path, const hfs_image *img, int grey,
                          hfs_error *err);
/* The same into an output set (committed by hfs_outputs_commit). */
HFS_API int hfs_pfm_write_to(hfs_outputs *o, const char *path, const hfs_image *img, int grey,
                             hfs_error *err);

/* "Pf" from a single-channel width*height array (e.g. a height field). */
HFS_API int hfs_pfm_write_grey(const char *path, int width, int height,
                               const float *v, hfs_error *err);

/*
 * Reads a PFM dump back into an RGB image (the inverse of hfs_pfm_write, for
 * comparisons against references): "PF" as is, "Pf" with R = G = B; either
 * byte order; first row in the file = row j = 0 (SPEC).  Values are returned
 * AS STORED, NaN and Inf included, because a result under test may hold them
 * and hfs_compare_images() must count them.  At least 1x1, at most
 * HFS_HEIGHT_MAX_DIM per side and HFS_HEIGHT_MAX_TEXELS texels.  The caller
 * frees out with hfs_image_free(); out is zeroed on failure.
 */
HFS_API int hfs_pfm_read_image(const char *path, hfs_image *out, hfs_error *err);

/*
 * Display mapping: how linear radiance becomes an 8-bit picture (the PNG
 * writer, the kiosk's frames and its GPU-encoded texture: the same bytes).
 * Per pixel: x = exposure * rgb -> tonemap(x) -> sRGB OETF per channel
 * (12.92 y below 0.0031308, else 1.055 y^(1/2.4) - 0.055) -> round(255 y).
 * The OETF always comes after the curve.  Only the 8-bit outputs see any
 * of this: PFM and GeoTIFF dumps, and HFS_LIT_RADIANCE textures, stay the
 * untouched linear radiance.
 *
 * The curves:
 *   HFS_TONEMAP_CLAMP     per channel min(max(x, 0), 1).  Zero, so the
 *                         default of a zeroed hfs_png_opts (API as before).
 *                         A bright channel clips alone: a sky blue
 *                         (0.25, 0.5, 1) at 3x shows as cyan (0.75, 1, 1),
 *                         at 8x as white.
 *   HFS_TONEMAP_REINHARD  per channel x / (1 + x) (0 below 0): no clipping,
 *                         but each channel compressed apart, so bright
 *                         colours still drift towards grey and shift hue.
 *   HFS_TONEMAP_HUE       "max-RGB extended Reinhard": one factor for the
 *                         pixel, s = r(n) / n with n = max(R, G, B) of x
 *                         (negatives 0 first) and r the extended Reinhard
 *                         curve (Reinhard et al. 2002, eq. 4) with white
 *                         point W = 16: r(n) = n (1 + n / W^2) / (1 + n),
 *                         1 from n = W on.  All three channels are scaled
 *                         by s, so their ratios -- the hue and the
 *                         saturation -- are exactly those of the radiance
 *                         at every brightness and no channel reaches
 *                         beyond 1: a sky ten stops over the terrain keeps
 *                         its blue, a grey or white highlight rolls off to
 *                         white.  Middle grey 0.18 shows at 0.153 (sRGB
 *                         byte 110).  Chosen over a luminance-based
 *                         Reinhard that desaturates towards white above 1:
 *                         that keeps the hue only while some chroma is
 *                         left, and at ten stops over it leaves a sky blue
 *                         as (254, 254, 255), no hue to keep.  The cost: a
 *                         very bright saturated colour stays saturated (no
 *                         path to white for it).  The default of hfshade
 *                         render's PNG (grid and 3-D view) and of the kiosk.
 */
typedef enum hfs_tonemap {
    HFS_TONEMAP_CLAMP = 0,
    HFS_TONEMAP_REINHARD,
    HFS_TONEMAP_HUE
} hfs_tonemap;

/* The curve alone, on linear values (in: exposure already applied; out:
 * linear display values in [0, 1], before the OETF).  The neutral C form of
 * the mapping; lit_texture.frag.glsl holds the same in GLSL. */
HFS_API void hfs_tonemap_rgb(const double in[3], hfs_tonemap tm, double out[3]);

/* Zero means default; NULL opts is all defaults. */
typedef struct hfs_png_opts {
    double exposure;       /* linear multiplier applied first; 0 = 1, > 0   */
    hfs_tonemap tonemap;   /* 0 = HFS_TONEMAP_CLAMP                        */
} hfs_png_opts;

/*
 * 8-bit sRGB RGB PNG for display: each pixel through the display mapping
 * above (hfs_srgb8_encode_rgb).  Carries an sRGB chunk.  Top row = row
 * j = 0.
 */
HFS_API int hfs_png_write(const char *path, const hfs_image *img,
                          const hfs_png_opts *opts, hfs_error *err);
/* The same into an output set (committed by hfs_outputs_commit). */
HFS_API int hfs_png_write_to(hfs_outputs *o, const char *path, const hfs_image *img,
                             const hfs_png_opts *opts, hfs_error *err);

/* n bytes another encoder made (the tools' GeoTIFF writer, through GDAL's
 * in-memory files) as the output `path` of o: a temporary, renamed at
 * hfs_outputs_commit like the others. */
HFS_API int hfs_bytes_write_to(hfs_outputs *o, const char *path, const void *data, size_t n,
                               hfs_error *err);

/*
 * The display mapping of one pixel, for code that displays frames
 * (board/frame_image.h) and must produce the same bytes as the PNG:
 * tonemap(exposure * rgb) -> sRGB OETF -> round(255 * y), into out[3].
 * exposure must be > 0 and finite (not checked here: 0 is NOT "default"
 * in these functions); rgb must be finite.
 */
HFS_API void hfs_srgb8_encode_rgb(const float rgb[3], double exposure, hfs_tonemap tonemap,
                                  unsigned char out[3]);
/* The same for a grey pixel (R = G = B = v): its one byte.  For the
 * per-channel curves (clamp, Reinhard) also each channel's byte of a
 * colour pixel, which is how it was used before HFS_TONEMAP_HUE. */
HFS_API unsigned char hfs_srgb8_encode(float v, double exposure, hfs_tonemap tonemap);

/*
 * Automatic exposure: the linear multiplier that puts the median Rec. 709
 * luminance (0.2126 R + 0.7152 G + 0.0722 B) of img's lit pixels at middle
 * grey, HFS_EXPOSURE_GREY / median.  A percentile, not the mean: a few
 * saturated texels (a glint, a sun disk) cannot move it.  Lit: luminance
 * > 0; pixels in full umbra under no sky meter nothing (else a field half
 * in shadow would have a median of 0).  Metered on a regular subsample of
 * at most HFS_EXPOSURE_SAMPLES pixels.  Give it terrain only: the tools
 * meter the lit grid (also for a 3-D view, whose sky and objects are not
 * terrain), so the grid and the view of one scene get the same exposure.
 * Returns 1 for an empty or all-black image; always within
 * [HFS_EXPOSURE_MIN, HFS_EXPOSURE_MAX].  Exposure in stops (EV) is
 * log2 of the multiplier.
 */
#define HFS_EXPOSURE_GREY 0.18
#define HFS_EXPOSURE_SAMPLES 65536
#define HFS_EXPOSURE_MIN 0x1p-40
#define HFS_EXPOSURE_MAX 0x1p40
HFS_API double hfs_exposure_auto(const hfs_image *img);

/*
 * 8-bit RGBA PNG of pixels that are already display-encoded (sRGB, e.g. a
 * screen capture): width*height*4 bytes, top row first, written unchanged
 * with an sRGB chunk.  At most HFS_HEIGHT_MAX_DIM per side.
 */
HFS_API int hfs_png_write_rgba8(const char *path, int width, int height,
                                const uint8_t *rgba, hfs_error *err);

/*
 * 16-bit grey PNG of a height field (the inverse of the PNG loader): each
 * value is rounded to the nearest integer and must lie in [0, 65535]; values
 * outside, NaN or Inf are an error (HFS_E_INVALID) rather than clamped.
 */
HFS_API int hfs_png16_write_grey(const char *path, int width, int height,
                                 const float *v, hfs_error *err);

#ifdef __cplusplus
}
#endif
#endif /* HFS_IO_H */
