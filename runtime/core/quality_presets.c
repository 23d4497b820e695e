/*
 * quality_presets.c — the default quality settings and the presets per use
 * (hfshade.h hfs_quality_preset).  The presets' values are the settings
 * tools/bench_pareto.sh picked from the measured error/time front
 * (docs/bench/pareto-256.csv, column "use"); tests/test_presets.c checks
 * that this table and that CSV agree, so a new measurement that picks
 * another setting fails until the table follows it.
 */
#include "hfshade.h"

#include <string.h>

typedef struct preset {
    const char *use;
    int k, offset, nphi_env, nphi_key, subsample;
    hfs_precision precision;
    hfs_visibility_path visibility;
} preset;

/* The first row is the defaults. */
static const preset presets[] = {
    {"kiosk", 2, 8, 12, 3, 2, HFS_PRECISION_FP16, HFS_VIS_SLICE},
    {"panel", 8, 8, 16, 5, 1, HFS_PRECISION_FP16, HFS_VIS_SLICE},
    {"headless", 2, 8, 12, 3, 4, HFS_PRECISION_FP16, HFS_VIS_SLICE},
};

static void apply(hfs_quality *q, const preset *p)
{
    q->k = p->k;
    q->offset = p->offset;
    q->nphi_env = p->nphi_env;
    q->nphi_key = p->nphi_key;
    q->subsample = p->subsample;
    q->precision = p->precision;
    q->visibility = p->visibility;
}

void hfs_quality_defaults(hfs_quality *q)
{
    memset(q, 0, sizeof *q);
    q->nphi_local = 16;
    q->refine = 4; /* BENCHMARKS.md "... horizons refined between scales" */
    q->split = 1; /* BENCHMARKS.md "Split horizons"; far_* by subsample */
    q->far_from = 0;
    q->far_dirs = 0;
    q->far_step = 0;
    q->nphi_bounce = 12; /* BENCHMARKS.md "Indirect light" */
    q->bounce_refine = 1;
    q->bounce_subsample = 4;
    q->bounce_near = 2; /* BENCHMARKS.md "Bounces, before / after (issue 36)" */
    q->local_full_swath = 0;
    q->threads = 0;
    q->truth_azimuths = 720;
    q->truth_elev_order = 16;
    q->truth_light_samples = 256;
    apply(q, &presets[0]);
}

int hfs_quality_preset(hfs_quality *q, const char *use)
{
    hfs_quality_defaults(q);
    for (size_t i = 0; i < sizeof presets / sizeof presets[0]; ++i)
        if (use && !strcmp(use, presets[i].use)) {
            apply(q, &presets[i]);
            return HFS_OK;
        }
    return HFS_E_INVALID;
}
