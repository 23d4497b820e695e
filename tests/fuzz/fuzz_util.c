/*
 * fuzz_util.c — the temporary file and the result checks shared by every
 * fuzz target (see fuzz.h).
 */
#include "fuzz.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void fuzz_fail(const char *what, const char *detail)
{
    fprintf(stderr, "fuzz contract broken: %s (%s)\n", what, detail ? detail : "");
    abort();
}

static const char *tmp_dir(void)
{
    const char *d = getenv("TMPDIR");
    if (d && *d)
        return d;
    return access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
}

const char *fuzz_write(const char *name, const void *data, size_t size)
{
    static char path[512];
    const char *p = data;
    int fd;

    snprintf(path, sizeof path, "%s/hfs_fuzz_%ld_%s", tmp_dir(), (long)getpid(), name);
    fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd < 0)
        return NULL;
    while (size > 0) {
        ssize_t n = write(fd, p, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            close(fd);
            unlink(path);
            return NULL;
        }
        p += n;
        size -= (size_t)n;
    }
    if (close(fd) != 0) {
        unlink(path);
        return NULL;
    }
    return path;
}

void fuzz_remove(const char *path)
{
    if (path)
        unlink(path);
}

void fuzz_check_error(const char *path, int rc, const hfs_error *err)
{
    size_t n = strlen(path);

    if (rc >= 0)
        fuzz_fail("failure without a negative status", err->msg);
    if (strncmp(err->msg, path, n) != 0 || err->msg[n] != ':' || strlen(err->msg) < n + 3)
        fuzz_fail("message does not start with \"PATH: \" and say something", err->msg);
    if (strchr(err->msg, '\n') || strchr(err->msg, '\r'))
        fuzz_fail("message is not one line", err->msg);
}

void fuzz_check_failure(const char *path, int rc, const hfs_error *err, int zeroed)
{
    fuzz_check_error(path, rc, err);
    if (!zeroed)
        fuzz_fail("output not zeroed after a failure", err->msg);
}

void fuzz_check_size(const char *path, int width, int height, int min_side, int max_side,
                     const void *data)
{
    if (width < min_side || height < min_side || width > max_side || height > max_side || !data)
        fuzz_fail("loaded image of an impossible size", path);
}
