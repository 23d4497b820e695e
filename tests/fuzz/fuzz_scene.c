/*
 * fuzz_scene.c — fuzzes the scene-file parser: the input is a scene file
 * (INI) read by hfs_scene_load_file() (libinih, then hfs_scene_set() for every
 * key; runtime/scene/), followed by hfs_scene_validate() and, for a valid
 * scene, the conversion to the library's lighting and quality.
 *
 *   tools/fuzz.sh [SECONDS]        every target, bounded (build-fuzz/)
 *   build-fuzz/tests/fuzz_scene -max_len=4096 \
 *       -dict=tests/fuzz/dict/scene.dict CORPUS_COPY tests/fuzz/corpus/scene
 */
#include "fuzz.h"
#include "scene.h"

#include <math.h>
#include <string.h>

static void check_one_line(const hfs_error *err)
{
    if (!err->msg[0] || strchr(err->msg, '\n') || strchr(err->msg, '\r'))
        fuzz_fail("scene message empty or not one line", err->msg);
}

static void check_lighting(const hfs_scene *s)
{
    hfs_lighting l;
    hfs_quality q;

    if (s->n_key < 0 || s->n_key > HFS_MAX_KEY_LIGHTS || s->n_local < 0 ||
        s->n_local > HFS_MAX_LOCAL_LIGHTS)
        fuzz_fail("light count out of range", NULL);
    if (memchr(s->height, '\0', sizeof s->height) == NULL ||
        memchr(s->env_map, '\0', sizeof s->env_map) == NULL ||
        memchr(s->context, '\0', sizeof s->context) == NULL)
        fuzz_fail("unterminated string in the scene", NULL);
    hfs_scene_lighting(s, NULL, &l);
    hfs_scene_quality(s, &q);
    for (int i = 0; i < l.n_key; ++i)
        if (!isfinite(l.key[i].phi) || !isfinite(l.key[i].elev) || !(l.key[i].alpha > 0.0) ||
            !isfinite(l.key[i].radiance[0]))
            fuzz_fail("key light not finite or radius not positive", NULL);
    for (int i = 0; i < l.n_local; ++i)
        if (!isfinite(l.local[i].pos[0]) || !isfinite(l.local[i].pos[1]) ||
            !isfinite(l.local[i].pos[2]) || !(l.local[i].radius >= 0.0) ||
            !isfinite(l.local[i].radiance[0]))
            fuzz_fail("local light not finite", NULL);
    if (!(l.albedo >= 0.0 && l.albedo <= 1.0) || !isfinite(l.env_rotate))
        fuzz_fail("albedo or rotation out of range", NULL);
    if (q.k < 1 || q.nphi_env < 3 || q.nphi_key < 1 || q.nphi_local < 3 ||
        (q.subsample != 1 && q.subsample != 2 && q.subsample != 4))
        fuzz_fail("quality setting out of range", NULL);
    if (s->raw_width && (s->raw_width < 2 || s->raw_height < 2))
        fuzz_fail("raw size out of range", NULL);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write("s.ini", data, size);
    static hfs_scene s; /* 9 KB of paths: not on the stack */
    hfs_error err;
    int rc;

    if (!path)
        return 0;
    hfs_scene_init(&s);
    err.msg[0] = '\0';
    rc = hfs_scene_load_file(&s, path, &err);
    if (rc) {
        fuzz_check_error(path, rc, &err);
    } else {
        rc = hfs_scene_validate(&s, &err);
        if (rc) {
            if (rc >= 0)
                fuzz_fail("invalid scene without a negative status", err.msg);
            check_one_line(&err);
        }
        check_lighting(&s);
    }
    fuzz_remove(path);
    return 0;
}
