/*
 * kiosk_harness.c — see kiosk_harness.h.  Processes through posix_spawn
 * (no fork of a process that may hold GL threads); waits are polled every
 * 10 ms with a deadline, so a hung kiosk fails the test instead of ctest's
 * timeout.
 */
#define _GNU_SOURCE /* mkdtemp */
#include "kiosk_harness.h"

#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <png.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "frame_image.h"
#include "scene_load.h"
#include "gl_test.h"

extern char **environ;

static char tmpdir[256];

const char *kh_tmpdir(const char *tag)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/%s_XXXXXX", tag);
    return mkdtemp(tmpdir);
}

const char *kh_path(const char *name)
{
    static char buf[8][512];
    static int next;
    char *b = buf[next++ % 8];
    snprintf(b, sizeof buf[0], "%s/%s", tmpdir, name);
    return b;
}

void kh_rm_tmpdir(void)
{
    DIR *d = opendir(tmpdir);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            unlink(kh_path(e->d_name));
    closedir(d);
    rmdir(tmpdir);
}

void kh_write(const char *path, const char *text)
{
    char tmp[600];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *f = fopen(tmp, "w");
    if (!f || fputs(text, f) < 0 || fclose(f) != 0 || rename(tmp, path) != 0) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(1);
    }
}

char *kh_read(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 4096, n = 0;
    char *s = malloc(cap);
    size_t got;
    while (s && (got = fread(s + n, 1, cap - n - 1, f)) > 0) {
        n += got;
        if (cap - n - 1 == 0) {
            char *t = realloc(s, cap * 2);
            if (!t) {
                free(s);
                s = NULL;
                break;
            }
            s = t;
            cap *= 2;
        }
    }
    fclose(f);
    if (s)
        s[n] = '\0';
    return s;
}

int kh_count_lines(const char *path, const char *prefix)
{
    char *s = kh_read(path);
    if (!s)
        return 0;
    int n = 0;
    const size_t len = strlen(prefix);
    for (char *line = s; line && *line;) {
        if (!strncmp(line, prefix, len))
            ++n;
        line = strchr(line, '\n');
        if (line)
            ++line;
    }
    free(s);
    return n;
}

pid_t kh_spawn(char *const argv[], const char *err_path)
{
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 2, err_path, O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&fa, 2, 1);
    pid_t pid;
    const int rc = posix_spawn(&pid, argv[0], &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc) {
        fprintf(stderr, "cannot start %s: %s\n", argv[0], strerror(rc));
        return -1;
    }
    return pid;
}

void kh_sleep(double s)
{
    struct timespec ts = {(time_t)s, (long)((s - floor(s)) * 1e9)};
    nanosleep(&ts, NULL);
}

int kh_wait(pid_t pid, double timeout_s)
{
    for (double t = 0; t < timeout_s; t += 0.01) {
        int st;
        if (waitpid(pid, &st, WNOHANG) == pid)
            return st;
        kh_sleep(0.01);
    }
    fprintf(stderr, "pid %d: no exit after %.0f s, killed\n", (int)pid, timeout_s);
    kill(pid, SIGKILL);
    waitpid(pid, NULL, 0);
    return -1;
}

int kh_wait_lines(pid_t pid, const char *path, const char *prefix, int n, double timeout_s)
{
    for (double t = 0; t < timeout_s; t += 0.01) {
        if (kh_count_lines(path, prefix) >= n)
            return 1;
        if (kill(pid, 0) != 0 || waitpid(pid, NULL, WNOHANG) == pid)
            return kh_count_lines(path, prefix) >= n;
        kh_sleep(0.01);
    }
    return 0;
}

uint8_t *kh_png_rgba(const char *path, int *w, int *h)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path))
        return NULL;
    img.format = PNG_FORMAT_RGBA;
    uint8_t *px = malloc(PNG_IMAGE_SIZE(img));
    if (!px || !png_image_finish_read(&img, NULL, px, 0, NULL)) {
        free(px);
        png_image_free(&img);
        return NULL;
    }
    *w = (int)img.width;
    *h = (int)img.height;
    return px;
}

void kh_require_gl(void)
{
    hfs_renderer_destroy(gl_test_renderer(&(hfs_renderer_desc){0}));
}

/* The frame (view NULL: the grid dump) the library renders for the scene
 * with key 0 at (key_phi, key_elev) unless NaN, as sRGB bytes. */
static uint8_t *direct(const char *scene_path, double key_phi, double key_elev,
                       const hfs_view *view, double zoom, int *w, int *h, int *no_gl)
{
    *no_gl = 0;
    hfs_error err = {{0}};
    hfs_scene s;
    hfs_scene_inputs in;
    memset(&in, 0, sizeof in);
    hfs_renderer *r = NULL;
    hfs_image img = {0};
    uint8_t *px = NULL;
    hfs_scene_init(&s);
    if (hfs_scene_load_file(&s, scene_path, &err))
        goto out;
    if (!isnan(key_phi)) {
        s.key[0].phi = key_phi;
        s.key[0].elev = key_elev;
    }
    if (hfs_scene_inputs_load(&s, &in, &err))
        goto out;
    int rc = hfs_renderer_create(&(hfs_renderer_desc){0}, &r, &err);
    if (rc) {
        *no_gl = rc == HFS_E_CONTEXT;
        goto out;
    }
    hfs_view v = {0};
    if (view) {
        hfs_view_defaults(&v, &in.field);
        v.mode = HFS_VIEW_PERSPECTIVE;
        v.azimuth = view->azimuth, v.elevation = view->elevation, v.fov = view->fov;
        v.width = view->width, v.height = view->height;
        hfs_view_frame(&v, &in.field);
        v.distance *= zoom;
        v.background = view->background, v.haze = view->haze; /* the kiosk's look */
    }
    if (hfs_image_alloc(&img, view ? v.width : in.field.width,
                        view ? v.height : in.field.height, &err) ||
        (view ? hfs_renderer_render_view(r, &in.field, &in.lighting, &in.quality, &v, NULL, &img,
                                         &err)
              : hfs_renderer_render(r, &in.field, &in.lighting, &in.quality, &img, NULL, NULL,
                                    &err)))
        goto out;
    px = malloc((size_t)img.width * (size_t)img.height * 4);
    if (px && hfs_frame_to_rgba8(&img, &KH_PICTURE, px, &err)) {
        free(px);
        px = NULL;
    }
    *w = img.width;
    *h = img.height;
out:
    if (!px)
        fprintf(stderr, "direct render of %s: %s\n", scene_path, err.msg);
    hfs_image_free(&img);
    hfs_renderer_destroy(r);
    hfs_scene_inputs_free(&in);
    return px;
}

uint8_t *kh_direct_frame(const char *scene_path, double key_phi, double key_elev, int *w,
                         int *h, int *no_gl)
{
    return direct(scene_path, key_phi, key_elev, NULL, 1.0, w, h, no_gl);
}

uint8_t *kh_direct_view(const char *scene_path, double az, double el, double zoom, int vw,
                        int vh, int *no_gl)
{
    const double deg = 3.14159265358979323846 / 180.0;
    /* A terrain scene: the kiosk's view shows it against its sky through
     * the automatic haze (kiosk_view_camera). */
    const hfs_view v = {.azimuth = az * deg, .elevation = el * deg, .fov = 40.0 * deg,
                        .width = vw, .height = vh, .background = HFS_BACKGROUND_SKY,
                        .haze = HFS_HAZE_AUTO};
    int w, h;
    return direct(scene_path, NAN, NAN, &v, zoom, &w, &h, no_gl);
}
