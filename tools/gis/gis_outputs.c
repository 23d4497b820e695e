/*
 * gis_outputs.c — see gis_outputs.h.  The sets do the writing, the checks
 * against the input and within a set; this adds the checks across sets,
 * the undo across sets, and the temporaries of files written by name.
 */
#define _XOPEN_SOURCE 700 /* realpath: XSI in glibc's headers */

#include "gis_outputs.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define SET_SIZE 8 /* hfs_outputs' own limit (runtime/io/io_output.c) */

struct gis_outputs {
    const char *input;
    int max, n;
    const char **path;
    char **target;           /* path resolved; NULL when it cannot be */
    unsigned char *existed;  /* the file was there before the run     */
    char **tmp;              /* written by name: its temporary, or NULL */
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
        g->tmp = calloc((size_t)n, sizeof *g->tmp);
        g->set = calloc((size_t)sets, sizeof *g->set);
    }
    *out = g;
    if (!g || !g->path || !g->target || !g->existed || !g->tmp || !g->set)
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

static uint64_t splitmix64(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

/* "target.tmp-XXXXXX", created with O_EXCL (a collision is a retry), as
 * io_output.c's create_temporary names the sets' (mode 0666 less the
 * umask, as any new output). */
static char *create_temporary(const char *target, int *e)
{
    static const char alphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    const size_t n = strlen(target);
    char *tmp = malloc(n + sizeof ".tmp-XXXXXX");
    struct timespec ts;
    clock_gettime(CLOCK_REALTIME, &ts);
    *e = ENOMEM;
    for (unsigned attempt = 0; tmp && attempt < 100; ++attempt) {
        uint64_t r = splitmix64((uint64_t)ts.tv_nsec ^ ((uint64_t)ts.tv_sec << 30) ^
                                ((uint64_t)getpid() << 40) ^ (uint64_t)(uintptr_t)tmp ^
                                ((uint64_t)attempt << 20));
        memcpy(tmp, target, n);
        memcpy(tmp + n, ".tmp-", 5);
        for (int k = 0; k < 6; ++k, r /= 62)
            tmp[n + 5 + k] = alphabet[r % 62];
        tmp[n + 11] = '\0';
        const int fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            close(fd);
            return tmp;
        }
        if ((*e = errno) != EEXIST)
            break;
    }
    free(tmp);
    return NULL;
}

int gis_outputs_temporary(gis_outputs *g, const char *path, const char **tmp, hfs_error *err)
{
    int k = 0;
    while (k < g->n && strcmp(g->path[k], path))
        ++k;
    if (k == g->n || g->tmp[k])
        return hfs_fail(err, HFS_E_INVALID, "%s: not an output of this run (or twice)", path);
    struct stat st;
    if (lstat(path, &st) == 0 && stat(path, &st) != 0)
        return hfs_fail(err, HFS_E_IO, "%s: the symbolic link does not lead to a file", path);
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode))
        return hfs_fail(err, HFS_E_IO, "%s: not a regular file (an output written window by "
                        "window is a temporary renamed over it; --tile 0 writes in place)",
                        path);
    int e = 0;
    if (!(g->tmp[k] = create_temporary(g->target[k] ? g->target[k] : path, &e)))
        return hfs_fail(err, HFS_E_IO, "%s: cannot create a temporary file next to it: %s",
                        path, strerror(e));
    *tmp = g->tmp[k];
    return HFS_OK;
}

/* The temporary of output k synced (a crash after the rename must not
 * expose an empty file) and renamed over its target. */
static int rename_temporary(gis_outputs *g, int k, hfs_error *err)
{
    const char *target = g->target[k] ? g->target[k] : g->path[k];
    const int fd = open(g->tmp[k], O_RDONLY | O_CLOEXEC);
    const char *step = fd < 0 ? "cannot open its temporary" : NULL;
    if (!step && fsync(fd) != 0)
        step = "cannot sync";
    if (!step && rename(g->tmp[k], target) != 0)
        step = "cannot replace the file";
    const int e = errno;
    if (fd >= 0)
        close(fd);
    if (step)
        return hfs_fail(err, HFS_E_IO, "%s: %s: %s", g->path[k], step, strerror(e));
    free(g->tmp[k]);
    g->tmp[k] = NULL;
    return HFS_OK;
}

int gis_outputs_commit(gis_outputs *g, hfs_error *err)
{
    const int sets = (g->n + SET_SIZE - 1) / SET_SIZE;
    unsigned char *placed = calloc(g->n ? (size_t)g->n : 1, 1); /* renamed into place */
    if (!placed)
        return hfs_fail(err, HFS_E_NOMEM, "outputs: out of memory");
    int rc = HFS_OK;
    for (int s = 0; s < sets && !rc; ++s)
        if (!(rc = hfs_outputs_commit(g->set[s], err)))
            for (int k = s * SET_SIZE; k < g->n && k < (s + 1) * SET_SIZE; ++k)
                placed[k] = !g->tmp[k];
    for (int k = 0; k < g->n && !rc; ++k)
        if (g->tmp[k] && !(rc = rename_temporary(g, k, err)))
            placed[k] = 1;
    /* On failure the new files in place go again (a failed set undid its
     * own; a file that was there before stays replaced, as in one set). */
    for (int k = 0; rc && k < g->n; ++k)
        if (placed[k] && !g->existed[k])
            unlink(g->target[k] ? g->target[k] : g->path[k]);
    free(placed);
    return rc;
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
    for (int k = 0; g->tmp && k < g->n; ++k)
        if (g->tmp[k]) { /* not renamed: the run failed */
            unlink(g->tmp[k]);
            free(g->tmp[k]);
        }
    free(g->tmp);
    free(g->target);
    free(g->path);
    free(g->existed);
    free(g->set);
    free(g);
}
