/*
 * test_scene.c — scene keys from files and flags: parsing, ranges, line
 * numbers in errors, flags overriding the file, repeatable keys.
 */
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int failures;

#define CHECK(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); \
    printf(__VA_ARGS__); printf("\n"); } } while (0)

static char dir[] = "/tmp/hfs_test_scene_XXXXXX";

static const char *write_file(const char *name, const char *text)
{
    static char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    return path;
}

/* Loads text as a scene file; returns status, message in err. */
static int load(hfs_scene *s, const char *text, hfs_error *err)
{
    hfs_scene_init(s);
    memset(err, 0, sizeof *err);
    return hfs_scene_load_file(s, write_file("s.ini", text), err);
}

int main(void)
{
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    hfs_scene s;
    hfs_error err;

    /* A valid file with comments, relative path, repeated key lights. */
    int rc = load(&s, "# demo\nheight = terrain.png\ndx = 30 ; metres\nzscale=2\n"
                      "env-sh = 3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0\n"
                      "key = 135,35,4,3\nkey = 300,60,10,1\nk = 8\noffset = 0\nvisibility = wedge\n",
                  &err);
    CHECK(rc == 0, "valid file rejected: %s", err.msg);
    CHECK(strstr(s.height, "/terrain.png") && strncmp(s.height, dir, strlen(dir)) == 0,
          "relative path not resolved against the file: %s", s.height);
    CHECK(s.dx == 30 && s.zscale == 2 && s.n_key == 2 && s.key[1].elev == 60, "values not stored");
    hfs_quality q;
    hfs_scene_quality(&s, &q);
    hfs_quality dq;
    hfs_quality_defaults(&dq);
    CHECK(q.k == 8 && q.offset == 0 && q.nphi_env == dq.nphi_env && q.visibility == HFS_VIS_WEDGE_TABLE,
          "quality: k=%d offset=%d nphi_env=%d", q.k, q.offset, q.nphi_env);
    hfs_lighting l;
    hfs_scene_lighting(&s, NULL, &l);
    CHECK(l.has_env && l.env_sh[2][0] > 3.5 && l.n_key == 2 && l.albedo == 1.0 &&
          l.key[0].phi > 2.35 && l.key[0].phi < 2.36, "lighting conversion (degrees -> radians)");

    /* azimuth-convention = compass (anywhere in the file): key and
     * view-dir azimuths are clockwise from north, SPEC's = compass - 90. */
    hfs_scene sc;
    rc = load(&sc, "height = t.png\nkey = 135,35,4,3\nview-dir = 180,40\nspecular = 0.2\n"
                   "azimuth-convention = compass\n", &err);
    hfs_lighting lc;
    hfs_scene_lighting(&sc, NULL, &lc);
    const double d2r = 3.14159265358979323846 / 180.0;
    CHECK(rc == 0 && fabs(lc.key[0].phi - 45.0 * d2r) < 1e-12 &&
          fabs(lc.view_dir[0] - cos(90.0 * d2r) * cos(40.0 * d2r)) < 1e-12 &&
          fabs(lc.view_dir[1] - sin(90.0 * d2r) * cos(40.0 * d2r)) < 1e-12,
          "compass azimuths: key %g rad, view (%g, %g)", lc.key[0].phi, lc.view_dir[0],
          lc.view_dir[1]);
    rc = load(&sc, "height = t.png\nazimuth-convention = north\n", &err);
    CHECK(rc != 0 && strstr(err.msg, "azimuth-convention"), "bad convention word: %s", err.msg);

    /* Flags override the file; a flag key replaces the file's key list. */
    rc = hfs_scene_set(&s, HFS_SOURCE_FLAG, "dx", "5", "--dx", NULL, &err);
    CHECK(rc == 0 && s.dx == 5, "flag did not override dx");
    rc = hfs_scene_set(&s, HFS_SOURCE_FLAG, "key", "10,20,3,1", "--key", NULL, &err);
    CHECK(rc == 0 && s.n_key == 1 && s.key[0].phi == 10, "flag --key did not replace the file's keys (n=%d)", s.n_key);
    rc = hfs_scene_set(&s, HFS_SOURCE_FLAG, "key", "11,20,3,1", "--key", NULL, &err);
    CHECK(rc == 0 && s.n_key == 2, "second --key did not append");
    rc = hfs_scene_set(&s, HFS_SOURCE_FLAG, "dx", "6", "--dx", NULL, &err);
    CHECK(rc != 0 && strstr(err.msg, "twice"), "duplicate flag accepted: %s", err.msg);

    /* A key light in colour (PHI,ELEV,ALPHA,R,G,B): le the largest channel,
     * the radiances exact; a negative channel refused like LE. */
    rc = hfs_scene_set(&s, HFS_SOURCE_FLAG, "key", "12,20,3,2,8,4", "--key", NULL, &err);
    hfs_scene_lighting(&s, NULL, &l);
    CHECK(rc == 0 && s.n_key == 3 && s.key[2].le == 8 && l.key[2].radiance[0] == 2.0f &&
              l.key[2].radiance[1] == 8.0f && l.key[2].radiance[2] == 4.0f &&
              l.key[1].radiance[0] == 1.0f && l.key[1].radiance[2] == 1.0f,
          "colour key: %s", err.msg);
    rc = hfs_scene_set(&s, HFS_SOURCE_FLAG, "key", "12,20,3,2,-8,4", "--key", NULL, &err);
    CHECK(rc != 0 && strstr(err.msg, "radiance -8 is out of range"), "colour key: %s", err.msg);
    rc = hfs_scene_set(&s, HFS_SOURCE_FLAG, "key", "12,20,3,0,0,0", "--key", NULL, &err);
    hfs_scene_lighting(&s, NULL, &l);
    CHECK(rc == 0 && l.key[3].radiance[1] == 0.0f, "black colour key: %s", err.msg);
    rc = hfs_scene_set(&s, HFS_SOURCE_FLAG, "key", "12,20,3,2,8", "--key", NULL, &err);
    CHECK(rc != 0, "5 numbers accepted");

    /* The environment in colour: env-sh-r/g/b, all three, alone. */
    {
        hfs_scene c;
        hfs_scene_init(&c);
        static const char *const ch[3] = {"env-sh-r", "env-sh-g", "env-sh-b"};
        static const char *const v[3] = {"1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0",
                                         "2,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0",
                                         "3,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0.5"};
        CHECK(!hfs_scene_set(&c, HFS_SOURCE_FILE, "height", "h.pfm", "s.ini:1", NULL, &err),
              "height");
        for (int i = 0; i < 2; ++i)
            CHECK(!hfs_scene_set(&c, HFS_SOURCE_FILE, ch[i], v[i], "s.ini:2", NULL, &err),
                  "%s: %s", ch[i], err.msg);
        CHECK(hfs_scene_validate(&c, &err) != 0 && strstr(err.msg, "env-sh-b missing"),
              "two channels accepted: %s", err.msg);
        CHECK(!hfs_scene_set(&c, HFS_SOURCE_FILE, ch[2], v[2], "s.ini:3", NULL, &err),
              "env-sh-b: %s", err.msg);
        CHECK(!hfs_scene_validate(&c, &err), "three channels refused: %s", err.msg);
        hfs_scene_lighting(&c, NULL, &l);
        CHECK(l.has_env && l.env_sh[0][0] == 1 && l.env_sh[1][0] == 2 && l.env_sh[2][0] == 3 &&
                  l.env_sh[2][15] == 0.5, "colour environment not stored");
        CHECK(!hfs_scene_set(&c, HFS_SOURCE_FILE, "env-sh", v[0], "s.ini:4", NULL, &err) &&
                  hfs_scene_validate(&c, &err) != 0 && strstr(err.msg, "choose one"),
              "env-sh with env-sh-r/g/b accepted: %s", err.msg);
    }

    /* Errors carry file:line. */
    struct { const char *text; const char *expect; } bad[] = {
        {"height = a.png\nbogus = 1\n", "s.ini:2: unknown key 'bogus'"},
        {"height = a.png\n\nk = 0\n", "s.ini:3: k: 0 is out of range"},
        {"dx = -1\n", "s.ini:1: dx: spacing -1 is out of range"},
        {"dx = 1\ndx = 2\n", "s.ini:2: dx given twice"},
        {"key = 1,2,3\n", "s.ini:1: key: expected 4 comma-separated values"},
        {"key = 1,95,3,1\n", "s.ini:1: key: elevation 95 is out of range"},
        {"subsample = 3\n", "s.ini:1: subsample: 3 is not one of 1, 2, 4"},
        {"[scene]\nk = 4\n", "s.ini:2: sections are not used"},
        {"this line has no equals sign\n", "s.ini:1: syntax error"},
        {"albedo = nan\n", "s.ini:1: albedo: 'nan' is not 1 finite number"},
        {"env-sh = 1,2,3\n", "s.ini:1: env-sh: expected 16 comma-separated values"},
        {"backend = vulkan\n", "s.ini:1: backend: 'vulkan' is not gles, cpu or truth"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        rc = load(&s, bad[i].text, &err);
        CHECK(rc != 0 && strstr(err.msg, bad[i].expect) && !strchr(err.msg, '\n'),
              "case %zu: got rc=%d '%s', want '%s'", i, rc, err.msg, bad[i].expect);
    }
    /* A line longer than inih's buffer is an error, not silently split. */
    char longline[400];
    memset(longline, 'x', sizeof longline);
    memcpy(longline, "height = ", 9);
    longline[sizeof longline - 2] = '\n';
    longline[sizeof longline - 1] = '\0';
    rc = load(&s, longline, &err);
    CHECK(rc != 0 && strstr(err.msg, "s.ini:1: line longer"), "long line: %s", err.msg);
    /* Missing file, directory. */
    hfs_scene_init(&s);
    rc = hfs_scene_load_file(&s, "/nonexistent/scene.ini", &err);
    CHECK(rc != 0 && strstr(err.msg, "/nonexistent/scene.ini"), "missing file: %s", err.msg);
    rc = hfs_scene_load_file(&s, dir, &err);
    CHECK(rc != 0 && strstr(err.msg, "not a regular file"), "directory: %s", err.msg);
    /* Consistency. */
    hfs_scene_init(&s);
    rc = hfs_scene_validate(&s, &err);
    CHECK(rc != 0 && strstr(err.msg, "no height field"), "missing height accepted");

    /* A preset written into a scene that never named one (the kiosk's
     * preset.next knob, board/input_map.c) is honoured, and quality keys
     * the scene gave still override it. */
    {
        hfs_quality pq, want;
        hfs_scene_init(&s);
        rc = hfs_scene_set(&s, HFS_SOURCE_FILE, "k", "3", "s.ini:1", NULL, &err);
        snprintf(s.preset, sizeof s.preset, "panel");
        hfs_scene_quality(&s, &pq);
        hfs_quality_preset(&want, "panel");
        CHECK(rc == 0 && pq.nphi_env == want.nphi_env && pq.offset == want.offset && pq.k == 3,
              "edited preset: nphi_env %d (panel %d), k %d (given 3)", pq.nphi_env,
              want.nphi_env, pq.k);
    }

    unlink(write_file("s.ini", ""));
    rmdir(dir);
    printf("%s: %d failure(s)\n", failures ? "FAIL" : "PASS", failures);
    return failures ? 1 : 0;
}
