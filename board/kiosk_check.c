/*
 * kiosk_check.c — a reload's admission check in a child process (kiosk.h
 * "kiosk_check").  The child is this program with --check, started with
 * posix_spawn (a fresh process: no fork of a process whose GL driver runs
 * threads); its stdout goes to /dev/null, its stderr into a pipe.
 */
#define _GNU_SOURCE /* pipe2 */
#include "kiosk.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

void kiosk_check_init(kiosk_check *c)
{
    memset(c, 0, sizeof *c);
    c->fd = -1;
}

int kiosk_check_start(kiosk_check *c, const kiosk_opts *o, hfs_error *err)
{
    int p[2];
    if (pipe2(p, O_CLOEXEC) != 0)
        return hfs_fail(err, HFS_E_IO, "reload check: pipe: %s", strerror(errno));
    char *argv[6];
    int n = 0;
    argv[n++] = "hfshade-kiosk";
    argv[n++] = (char *)o->scene_path;
    if (o->input_path) {
        argv[n++] = "--input";
        argv[n++] = (char *)o->input_path;
    }
    argv[n++] = "--check";
    argv[n] = NULL;
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&fa, p[1], STDERR_FILENO);
    /* The child starts with SIGHUP/SIGTERM/SIGINT unblocked (the kiosk
     * blocks them for its signalfd), at their default actions. */
    posix_spawnattr_t at;
    posix_spawnattr_init(&at);
    sigset_t none, dfl;
    sigemptyset(&none);
    sigemptyset(&dfl);
    sigaddset(&dfl, SIGHUP);
    sigaddset(&dfl, SIGTERM);
    sigaddset(&dfl, SIGINT);
    posix_spawnattr_setsigmask(&at, &none);
    posix_spawnattr_setsigdefault(&at, &dfl);
    posix_spawnattr_setflags(&at, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    pid_t pid;
    const int rc = posix_spawn(&pid, "/proc/self/exe", &fa, &at, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    posix_spawnattr_destroy(&at);
    close(p[1]);
    if (rc != 0) {
        close(p[0]);
        return hfs_fail(err, HFS_E_IO, "reload check: cannot start /proc/self/exe: %s",
                        strerror(rc));
    }
    fcntl(p[0], F_SETFL, O_NONBLOCK);
    c->pid = pid;
    c->fd = p[0];
    c->len = 0;
    c->out[0] = '\0';
    return HFS_OK;
}

/* The last non-empty line of the child's output, without the program's
 * "hfshade-kiosk: " prefix. */
static void last_line(const kiosk_check *c, char *msg, size_t size)
{
    size_t end = c->len;
    while (end > 0 && (c->out[end - 1] == '\n' || c->out[end - 1] == '\r'))
        --end;
    size_t start = end;
    while (start > 0 && c->out[start - 1] != '\n')
        --start;
    const char *line = c->out + start;
    size_t len = end - start;
    static const char prefix[] = "hfshade-kiosk: ";
    if (len >= sizeof prefix - 1 && !strncmp(line, prefix, sizeof prefix - 1)) {
        line += sizeof prefix - 1;
        len -= sizeof prefix - 1;
    }
    if (len == 0) {
        line = "the check gave no reason";
        len = strlen(line);
    }
    snprintf(msg, size, "%.*s", (int)len, line);
}

int kiosk_check_poll(kiosk_check *c, int *ok, char *msg, size_t size)
{
    for (;;) {
        char buf[512];
        const ssize_t got = read(c->fd, buf, sizeof buf);
        if (got > 0) {
            /* Keep the tail: the reason is the last line. */
            size_t keep = (size_t)got;
            if (c->len + keep >= sizeof c->out) {
                const size_t drop = c->len + keep - (sizeof c->out - 1);
                const size_t from_old = drop < c->len ? drop : c->len;
                memmove(c->out, c->out + from_old, c->len - from_old);
                c->len -= from_old;
                if (keep > sizeof c->out - 1 - c->len)
                    keep = sizeof c->out - 1 - c->len;
            }
            memcpy(c->out + c->len, buf + (size_t)got - keep, keep);
            c->len += keep;
            c->out[c->len] = '\0';
            continue;
        }
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0 && errno == EAGAIN)
            return 0; /* more to come */
        break;        /* end of file (or an error): the child is done */
    }
    int st = 0;
    while (waitpid(c->pid, &st, 0) < 0 && errno == EINTR)
        ;
    close(c->fd);
    c->fd = -1;
    c->pid = 0;
    *ok = WIFEXITED(st) && WEXITSTATUS(st) == 0;
    if (WIFSIGNALED(st))
        snprintf(msg, size, "the check (%s --check) died of %s", "hfshade-kiosk",
                 strsignal(WTERMSIG(st)));
    else if (!*ok)
        last_line(c, msg, size);
    return 1;
}

int kiosk_check_stop(kiosk_check *c)
{
    int killed = 0;
    if (c->pid > 0) {
        kill(c->pid, SIGKILL);
        int st = 0;
        while (waitpid(c->pid, &st, 0) < 0 && errno == EINTR)
            ;
        /* Killed here, not ended by itself: it was still checking. */
        killed = WIFSIGNALED(st) && WTERMSIG(st) == SIGKILL;
    }
    if (c->fd >= 0)
        close(c->fd);
    c->pid = 0;
    c->fd = -1;
    c->again = 0;
    return killed;
}
