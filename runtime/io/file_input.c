/*
 * file_input.c — non-blocking, regular-file-only opens (file_input.h).
 */
#include "file_input.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

const char *hfs_file_kind(unsigned mode)
{
    return S_ISDIR(mode)    ? "a directory"
           : S_ISFIFO(mode) ? "a FIFO"
           : S_ISSOCK(mode) ? "a socket"
           : S_ISCHR(mode)  ? "a character device"
           : S_ISBLK(mode)  ? "a block device"
           : S_ISLNK(mode)  ? "a symbolic link"
                            : "not a regular file";
}

int hfs_open_regular(const char *path, const char *what, int *fd_out, long long *size_out,
                     hfs_error *err)
{
    *fd_out = -1;
    if (!path || !*path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): empty path for the %s", what);
    /* O_NONBLOCK: a FIFO without a writer (or a device that waits for a
     * carrier) returns at once instead of blocking in open(2). */
    const int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        char why[128];
        if (strerror_r(errno, why, sizeof why) != 0)
            snprintf(why, sizeof why, "error %d", errno);
        return hfs_fail(err, HFS_E_IO, "%s: cannot open %s: %s", path, what, why);
    }
    struct stat st;
    if (fstat(fd, &st) != 0) {
        close(fd);
        return hfs_fail(err, HFS_E_IO, "%s: cannot stat the %s", path, what);
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return hfs_fail(err, HFS_E_IO, "%s: the %s is %s, not a regular file", path, what,
                        hfs_file_kind((unsigned)st.st_mode));
    }
    const int fl = fcntl(fd, F_GETFL);
    if (fl < 0 || fcntl(fd, F_SETFL, fl & ~O_NONBLOCK) != 0) {
        close(fd);
        return hfs_fail(err, HFS_E_IO, "%s: cannot switch the %s to blocking reads", path, what);
    }
    if (size_out)
        *size_out = (long long)st.st_size;
    *fd_out = fd;
    return HFS_OK;
}

int hfs_fopen_regular(const char *path, const char *what, FILE **f, long long *size_out,
                      hfs_error *err)
{
    int fd;
    *f = NULL;
    const int rc = hfs_open_regular(path, what, &fd, size_out, err);
    if (rc)
        return rc;
    *f = fdopen(fd, "rb");
    if (!*f) {
        close(fd);
        return hfs_fail(err, HFS_E_NOMEM, "%s: cannot open the %s as a stream", path, what);
    }
    return HFS_OK;
}

int hfs_read_text_file(const char *path, const char *what, long long max_bytes, char **text,
                       size_t *len, hfs_error *err)
{
    long long size = 0;
    FILE *f;
    *text = NULL;
    const int rc = hfs_fopen_regular(path, what, &f, &size, err);
    if (rc)
        return rc;
    if (size > max_bytes) {
        fclose(f);
        return hfs_fail(err, HFS_E_FORMAT, "%s: %s larger than %lld bytes", path, what, max_bytes);
    }
    /* One byte more than fstat said: a file that grew while we read it is
     * refused rather than read in part (the buffer is the file's size, not
     * max_bytes: scene files are read at every reload and every fuzz run). */
    const size_t want = (size_t)size + 1;
    char *buf = malloc(want + 1);
    if (!buf) {
        fclose(f);
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
    }
    const size_t n = fread(buf, 1, want, f);
    const int bad = ferror(f);
    fclose(f);
    if (bad) {
        free(buf);
        return hfs_fail(err, HFS_E_IO, "%s: read error in the %s", path, what);
    }
    if (n == want) {
        free(buf);
        return hfs_fail(err, HFS_E_IO, "%s: the %s changed while it was read", path, what);
    }
    buf[n] = '\0';
    if (memchr(buf, '\0', n)) {
        free(buf);
        return hfs_fail(err, HFS_E_FORMAT, "%s: binary data (a NUL byte) in the %s", path, what);
    }
    *text = buf;
    if (len)
        *len = n;
    return HFS_OK;
}
