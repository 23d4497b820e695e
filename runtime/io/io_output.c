/*
 * io_output.c — writing outputs without ever touching an input, a device
 * node or a file the run did not mean to replace (issue 13).
 *
 * - hfs_io_atomic: the file is written to "TARGET.tmp-XXXXXX" next to its
 *   target and renamed over it only when complete.  TARGET is the path with
 *   symbolic links resolved (a link to a file keeps pointing at the new
 *   file instead of being replaced by it).  A target that exists and is not
 *   a regular file (a character device such as /dev/null or /dev/full, a
 *   FIFO with a reader) is written IN PLACE, never replaced: renaming over
 *   a device node would turn it into a file.  A directory or a dangling
 *   link is an error.
 * - hfs_outputs: the files of one run, checked against its inputs and each
 *   other before anything is written, then committed together.
 */
#define _XOPEN_SOURCE 700 /* realpath */

#include "io_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* ---- atomic output --------------------------------------------------------- */

static uint64_t splitmix64(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

static int fail_errno(hfs_error *err, int e, const char *path, const char *step)
{
    char why[128];
    hfs_io_strerror(e, why, sizeof why);
    return hfs_fail(err, HFS_E_IO, "%s: %s: %s", path, step, why);
}

/* An existing non-regular target: open it for writing without creating,
 * truncating or blocking (a FIFO without a reader is ENXIO, not a hang). */
static int open_in_place(hfs_io_atomic *a, const char *path, hfs_error *err)
{
    const int fd = open(path, O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0)
        return fail_errno(err, errno, path, errno == ENXIO ? "cannot write (a FIFO with no reader)"
                                                           : "cannot open for writing");
    const int fl = fcntl(fd, F_GETFL);
    if (fl < 0 || fcntl(fd, F_SETFL, fl & ~O_NONBLOCK) != 0 || !(a->f = fdopen(fd, "wb"))) {
        const int e = errno;
        close(fd);
        return fail_errno(err, e, path, "cannot open for writing");
    }
    a->path = path;
    a->in_place = 1;
    return HFS_OK;
}

/* Creates "target.tmp-XXXXXX" with O_EXCL and our own random suffix rather
 * than mkstemp(): mkstemp creates mode 0600, and reading the umask to fix
 * that is process-global and racy.  O_EXCL makes a collision a retry. */
static int create_temporary(hfs_io_atomic *a, hfs_error *err)
{
    static const char alphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    const size_t n = strlen(a->target);
    struct timespec ts;
    int fd = -1;
    a->tmp = malloc(n + sizeof ".tmp-XXXXXX");
    if (!a->tmp)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", a->path);
    clock_gettime(CLOCK_REALTIME, &ts);
    for (unsigned attempt = 0; attempt < 100; ++attempt) {
        uint64_t r = splitmix64((uint64_t)ts.tv_nsec ^ ((uint64_t)ts.tv_sec << 30) ^
                                ((uint64_t)getpid() << 40) ^ (uint64_t)(uintptr_t)a ^
                                ((uint64_t)attempt << 20));
        memcpy(a->tmp, a->target, n);
        memcpy(a->tmp + n, ".tmp-", 5);
        for (int k = 0; k < 6; ++k) {
            a->tmp[n + 5 + k] = alphabet[r % 62];
            r /= 62;
        }
        a->tmp[n + 11] = '\0';
        fd = open(a->tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST)
            break;
    }
    if (fd < 0) {
        const int e = errno;
        free(a->tmp);
        a->tmp = NULL;
        return fail_errno(err, e, a->path, "cannot create a temporary file next to it");
    }
    a->f = fdopen(fd, "wb");
    if (!a->f) {
        const int e = errno;
        close(fd);
        unlink(a->tmp);
        free(a->tmp);
        a->tmp = NULL;
        return fail_errno(err, e, a->path, "cannot open for writing");
    }
    return HFS_OK;
}

int hfs_io_atomic_open(hfs_io_atomic *a, const char *path, hfs_error *err)
{
    struct stat lst, st;
    memset(a, 0, sizeof *a);
    if (!path || !*path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): empty output path");
    a->path = path;
    if (lstat(path, &lst) == 0) {
        if (stat(path, &st) != 0)
            return fail_errno(err, errno, path, "the symbolic link does not lead to a file");
        if (S_ISDIR(st.st_mode))
            return hfs_fail(err, HFS_E_IO, "%s: is a directory, not an output file", path);
        if (!S_ISREG(st.st_mode))
            return open_in_place(a, path, err);
        a->target = S_ISLNK(lst.st_mode) ? realpath(path, NULL) : strdup(path);
    } else {
        a->target = strdup(path);
        a->created = 1;
    }
    if (!a->target)
        return fail_errno(err, errno, path, "cannot resolve the output path");
    const int rc = create_temporary(a, err);
    if (rc) {
        free(a->target);
        memset(a, 0, sizeof *a);
    }
    return rc;
}

int hfs_io_atomic_write(hfs_io_atomic *a, const void *data, size_t n, hfs_error *err)
{
    if (n && fwrite(data, 1, n, a->f) != n)
        return fail_errno(err, errno ? errno : EIO, a->path, "write error");
    return HFS_OK;
}

void hfs_io_atomic_abort(hfs_io_atomic *a)
{
    if (!a)
        return;
    if (a->f)
        fclose(a->f);
    if (a->tmp) {
        unlink(a->tmp);
        free(a->tmp);
    }
    free(a->target);
    memset(a, 0, sizeof *a);
}

int hfs_io_atomic_finish(hfs_io_atomic *a, hfs_error *err)
{
    const char *step = NULL;
    int e = 0;
    if (fflush(a->f) != 0 || ferror(a->f)) {
        step = "write error";
        e = errno ? errno : EIO;
    } else if (fsync(fileno(a->f)) != 0 && !(a->in_place && (errno == EINVAL || errno == EROFS))) {
        /* Without this a crash after rename could expose an empty file.  A
         * device written in place may not support fsync (EINVAL). */
        step = "cannot sync";
        e = errno;
    }
    if (fclose(a->f) != 0 && !step) {
        step = "write error";
        e = errno ? errno : EIO;
    }
    a->f = NULL;
    if (step) {
        const int rc = fail_errno(err, e, a->path, step);
        hfs_io_atomic_abort(a);
        return rc;
    }
    return HFS_OK;
}

int hfs_io_atomic_rename(hfs_io_atomic *a, hfs_error *err)
{
    if (!a->in_place && rename(a->tmp, a->target) != 0) {
        const int rc = fail_errno(err, errno, a->path, "cannot replace the file");
        hfs_io_atomic_abort(a);
        return rc;
    }
    free(a->tmp);
    free(a->target);
    memset(a, 0, sizeof *a);
    return HFS_OK;
}

int hfs_io_atomic_commit(hfs_io_atomic *a, hfs_error *err)
{
    const int rc = hfs_io_atomic_finish(a, err);
    return rc ? rc : hfs_io_atomic_rename(a, err);
}

/* ---- output sets ----------------------------------------------------------- */

#define OUTPUTS_MAX_IN 16
#define OUTPUTS_MAX_OUT 8

/* Which file a path names: device and inode when it exists; the path with
 * its directory resolved otherwise (two new outputs can still clash). */
typedef struct file_id {
    int exists;
    dev_t dev;
    ino_t ino;
    char *resolved; /* owned; NULL when it cannot be resolved */
    const char *path;
} file_id;

struct hfs_outputs {
    file_id in[OUTPUTS_MAX_IN], out[OUTPUTS_MAX_OUT];
    int n_in, n_out, n_pending;
    hfs_io_atomic pending[OUTPUTS_MAX_OUT];
};

static void file_id_of(const char *path, file_id *id)
{
    struct stat st;
    memset(id, 0, sizeof *id);
    id->path = path;
    if (stat(path, &st) == 0) {
        id->exists = 1;
        id->dev = st.st_dev;
        id->ino = st.st_ino;
        id->resolved = realpath(path, NULL);
        return;
    }
    const char *slash = strrchr(path, '/');
    char dir[PATH_MAX];
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else if (slash == path)
        snprintf(dir, sizeof dir, "/");
    else
        snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
    char *rdir = realpath(dir, NULL);
    if (!rdir)
        return;
    const char *base = slash ? slash + 1 : path;
    const size_t n = strlen(rdir) + strlen(base) + 2;
    id->resolved = malloc(n);
    if (id->resolved)
        snprintf(id->resolved, n, "%s/%s", rdir, base);
    free(rdir);
}

static int same_file(const file_id *a, const file_id *b)
{
    if (a->exists && b->exists)
        return a->dev == b->dev && a->ino == b->ino;
    return a->resolved && b->resolved && !strcmp(a->resolved, b->resolved);
}

int hfs_outputs_create(hfs_outputs **out, hfs_error *err)
{
    *out = calloc(1, sizeof **out);
    return *out ? HFS_OK : hfs_fail(err, HFS_E_NOMEM, "outputs: out of memory");
}

int hfs_outputs_input(hfs_outputs *o, const char *path, hfs_error *err)
{
    if (!path || !*path)
        return HFS_OK;
    if (o->n_in == OUTPUTS_MAX_IN)
        return hfs_fail(err, HFS_E_INVALID, "%s: more than %d inputs", path, OUTPUTS_MAX_IN);
    file_id_of(path, &o->in[o->n_in++]);
    return HFS_OK;
}

int hfs_outputs_add(hfs_outputs *o, const char *path, hfs_error *err)
{
    if (!path || !*path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): empty output path");
    if (o->n_out == OUTPUTS_MAX_OUT)
        return hfs_fail(err, HFS_E_INVALID, "%s: more than %d outputs", path, OUTPUTS_MAX_OUT);
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return hfs_fail(err, HFS_E_INVALID, "%s: is a directory, not an output file", path);
    file_id id;
    file_id_of(path, &id);
    for (int i = 0; i < o->n_in; ++i)
        if (same_file(&id, &o->in[i])) {
            free(id.resolved);
            return hfs_fail(err, HFS_E_INVALID, "%s: output is the same file as the input %s", path,
                            o->in[i].path);
        }
    for (int i = 0; i < o->n_out; ++i)
        if (same_file(&id, &o->out[i])) {
            free(id.resolved);
            return hfs_fail(err, HFS_E_INVALID, "%s: output is the same file as the output %s",
                            path, o->out[i].path);
        }
    o->out[o->n_out++] = id;
    return HFS_OK;
}

int hfs_io_outputs_adopt(hfs_outputs *o, hfs_io_atomic *a, hfs_error *err)
{
    int known = 0;
    for (int i = 0; i < o->n_out; ++i)
        known |= !strcmp(o->out[i].path, a->path);
    if (!known || o->n_pending == OUTPUTS_MAX_OUT) {
        const int rc = hfs_fail(err, HFS_E_INVALID, "%s: not an output of this set (hfs_outputs_add)",
                                a->path);
        hfs_io_atomic_abort(a);
        return rc;
    }
    const int rc = hfs_io_atomic_finish(a, err);
    if (rc)
        return rc;
    o->pending[o->n_pending++] = *a;
    memset(a, 0, sizeof *a);
    return HFS_OK;
}

int hfs_outputs_commit(hfs_outputs *o, hfs_error *err)
{
    int rc = HFS_OK, done = 0;
    for (; done < o->n_pending; ++done) {
        const hfs_io_atomic *a = &o->pending[done];
        if (!a->in_place && rename(a->tmp, a->target) != 0) {
            rc = fail_errno(err, errno, a->path, "cannot replace the file");
            break;
        }
    }
    /* On failure undo what can be undone: files this run created go again;
     * a file that existed before was replaced and stays replaced. */
    for (int j = 0; rc && j < done; ++j)
        if (o->pending[j].created)
            unlink(o->pending[j].target);
    for (int j = 0; j < o->n_pending; ++j) {
        if (j < done) { /* renamed: no temporary left to remove */
            free(o->pending[j].tmp);
            o->pending[j].tmp = NULL;
        }
        hfs_io_atomic_abort(&o->pending[j]);
    }
    o->n_pending = 0;
    return rc;
}

void hfs_outputs_destroy(hfs_outputs *o)
{
    if (!o)
        return;
    for (int k = 0; k < o->n_pending; ++k)
        hfs_io_atomic_abort(&o->pending[k]);
    for (int i = 0; i < o->n_in; ++i)
        free(o->in[i].resolved);
    for (int i = 0; i < o->n_out; ++i)
        free(o->out[i].resolved);
    free(o);
}
