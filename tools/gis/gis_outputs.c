/*
 * gis_outputs.c — see gis_outputs.h.  The sets do the writing, the checks
 * against the input and within a set; this adds the checks across sets
 * and the undo across sets.
 */
#define _XOPEN_SOURCE 700 /* realpath: XSI in glibc's headers */

#include "gis_outputs.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define SET_SIZE 8 /* hfs_outputs' own limit (runtime/io/io_output.c) */

struct gis_outputs {
    const char *input;
    int max, n;
    const char **path;
    char **target;           /* path resolved; NULL when it cannot be */
    unsigned char *existed;  /* the file was there before the run     */
    hfs_outputs **set;       /* max / SET_SIZE rounded up             */
};

/* path with its links and its folder resolved (malloc'ed), so two names of
 * one file compare equal; NULL when its folder does not exist (the writer
 * will say so). */
static char *resolve(const char *path)
{
    char *r = realpath(path, NULL);
    if (r || errno != ENOENT)
        return r;
    const char *slash = strrchr(path, '/');
    char *dir = slash ? strndup(path, slash == path ? 1 : (size_t)(slash - path)) : NULL;
    if (slash && !dir)
        return NULL;
    char *rdir = realpath(dir ? dir : ".", NULL);
    const char *base = slash ? slash + 1 : path;
    const size_t n = rdir ? strlen(rdir) + strlen(base) + 2 : 0;
    char *out = n ? malloc(n) : NULL;
    if (out)
        snprintf(out, n, "%s/%s", rdir, base);
    free(dir);
    free(rdir);
    return out;
}

int gis_outputs_create(gis_outputs **out, const char *input, int n, hfs_error *err)
{
    gis_outputs *g = calloc(1, sizeof *g);
    const int sets = (n + SET_SIZE - 1) / SET_SIZE;
    if (g) {
        g->input = input, g->max = n;
        g->path = calloc((size_t)n, sizeof *g->path);
        g->target = calloc((size_t)n, sizeof *g->target);
        g->existed = calloc((size_t)n, 1);
        g->set = calloc((size_t)sets, sizeof *g->set);
    }
    *out = g;
    if (!g || !g->path || !g->target || !g->existed || !g->set)
        return hfs_fail(err, HFS_E_NOMEM, "outputs: out of memory for %d files", n);
    return HFS_OK;
}

int gis_outputs_add(gis_outputs *g, const char *path, hfs_error *err)
{
    if (g->n == g->max)
        return hfs_fail(err, HFS_E_INVALID, "%s: more than %d outputs", path, g->max);
    hfs_outputs **set = &g->set[g->n / SET_SIZE];
    int rc = HFS_OK;
    if (!*set && !(rc = hfs_outputs_create(set, err)))
        rc = hfs_outputs_input(*set, g->input, err);
    if (rc || (rc = hfs_outputs_add(*set, path, err)))
        return rc;
    char *target = resolve(path);
    for (int k = 0; target && k < g->n; ++k)
        if (g->target[k] && !strcmp(target, g->target[k])) {
            free(target);
            return hfs_fail(err, HFS_E_INVALID, "%s: output is the same file as the output %s",
                            path, g->path[k]);
        }
    struct stat st;
    g->existed[g->n] = stat(path, &st) == 0;
    g->target[g->n] = target;
    g->path[g->n++] = path;
    return HFS_OK;
}

hfs_outputs *gis_outputs_set(gis_outputs *g, const char *path)
{
    for (int k = 0; k < g->n; ++k)
        if (!strcmp(g->path[k], path))
            return g->set[k / SET_SIZE];
    return NULL;
}

int gis_outputs_commit(gis_outputs *g, hfs_error *err)
{
    const int sets = (g->n + SET_SIZE - 1) / SET_SIZE;
    for (int s = 0; s < sets; ++s) {
        const int rc = hfs_outputs_commit(g->set[s], err);
        if (!rc)
            continue;
        /* The earlier sets' new files go again (the failed set undid its own). */
        for (int k = 0; k < s * SET_SIZE; ++k)
            if (!g->existed[k])
                unlink(g->target[k] ? g->target[k] : g->path[k]);
        return rc;
    }
    return HFS_OK;
}

void gis_outputs_destroy(gis_outputs *g)
{
    if (!g)
        return;
    const int sets = (g->max + SET_SIZE - 1) / SET_SIZE;
    for (int s = 0; g->set && s < sets; ++s)
        hfs_outputs_destroy(g->set[s]);
    for (int k = 0; g->target && k < g->n; ++k)
        free(g->target[k]);
    free(g->target);
    free(g->path);
    free(g->existed);
    free(g->set);
    free(g);
}
