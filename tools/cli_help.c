/*
 * cli_help.c — see cli_help.h.
 */
#include "cli_help.h"

#include "scene.h"

#include <float.h>
#include <string.h>

void hfshade_usage(FILE *f)
{
    fprintf(f,
            "usage: hfshade render  [SCENE.ini] [--KEY VALUE ...] -o OUT.png [--pfm OUT.pfm] "
            "[--geotiff OUT.tif]\n"
            "       hfshade compare [SCENE.ini] [--KEY VALUE ...] RESULT.pfm REFERENCE.pfm\n"
            "       hfshade query   [SCENE.ini] [--KEY VALUE ...] --points FILE  (x y z a line;\n"
            "                       prints each point's visible fraction of every key light)\n"
            "       hfshade keys\n"
            "       hfshade --version\n"
            "       hfshade info [--context surfaceless|osmesa|auto]\n"
            "       hfshade envmap decompose MAP [--max-lights N] [--min-share F]\n"
            "                      [--contrast C] [--picture OUT.png]\n"
            "       hfshade svf DEM -o OUT.tif [...]        (GIS rasters on the DEM's own grid:\n"
            "       hfshade openness DEM -o OUT.tif [...]    sky-view factor, openness, horizon\n"
            "       hfshade horizon DEM -o PREFIX [...]      angles, the sun's beam at an\n"
            "       hfshade sun DEM -o OUT.tif [...]         instant, clear-sky irradiation;\n"
            "       hfshade insolation DEM -o OUT.tif [...]  COMMAND --help, docs/GIS.md)\n"
            "       hfshade tiles plan|run|merge ...         (a DEM's windows as jobs for GNU\n"
            "                                                parallel or Slurm: tiles --help)\n"
            "options: --exposure auto|EV (PNG only; default auto: the lit terrain's median\n"
            "         luminance at middle grey; EV: stops, 0 = radiance x 1, -1 = x 0.5),\n"
            "         --colormap none|terrain (PNG only),\n"
            "         --time N (render N full frames after a warm-up; print per-pass medians),\n"
            "         --check (load, validate and render one frame off screen; write nothing),\n"
            "         --view ortho|perspective (the outputs are the 3-D view, not the grid),\n"
            "         --camera AZ,EL,DIST,FOV[,TX,TY,TZ] (degrees; DIST empty: frame the field),\n"
            "         --exaggeration E, --view-size WxH (default 512x512),\n"
            "         --background sky|studio|#rrggbb|R,G,B (default sky; studio with\n"
            "         preset = panel; R,G,B linear radiance), --haze off|auto|DEPTH (optical\n"
            "         depth across the field's diagonal; default auto, off with preset = panel),\n"
            "         --tile N --job K (with --geotiff OUT.tif only: job K of a DEM's render in\n"
            "         tiles of N texels, the part written as a GeoTIFF; `hfshade tiles`),\n"
            "         --quiet, --help\n"
            "scene keys (also accepted in SCENE.ini as KEY = VALUE): run 'hfshade keys'\n");
}

/* One line a key: its form, help, the range of a single number and the
 * default, all from the table of scene keys. */
void hfshade_print_keys(void)
{
    int n;
    const hfs_scene_key_info *k = hfs_scene_keys(&n);
    for (int i = 0; i < n; ++i) {
        char range[96] = "";
        const hfs_key_number *num = &k[i].num[0];
        if (k[i].n == 1 && !k[i].pow2 && num->range.lo != -DBL_MAX) {
            range[0] = ' ';
            hfs_key_range_text(&num->range, num->unit, range + 1, sizeof range - 1);
            if (*hfs_key_unit_name(num->unit))
                snprintf(range + strlen(range), sizeof range - strlen(range), " %s",
                         hfs_key_unit_name(num->unit));
        }
        printf("  --%-15s %-24s %s%s%s%s\n", k[i].name, k[i].arg, k[i].help, range,
               k[i].def ? "; default " : "", k[i].def ? k[i].def : "");
    }
}
