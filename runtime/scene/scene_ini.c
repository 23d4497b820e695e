/*
 * scene_ini.c — scene files, parsed by libinih (Debian's libinih-dev), and
 * hfs_scene_set: the setter of scene.c plus the objects key's file, read
 * here so that the setter never calls back into the reader.
 *
 * Debian builds inih without per-key line numbers, but ini_parse_string()
 * returns the line of the first error; the handler therefore keeps the first
 * message and the caller prefixes it with "FILE:LINE:".  Files are read whole
 * (size-guarded) and lines longer than inih's buffer are rejected up front,
 * because inih would silently split them.
 */
#include "file_input.h"
#include "scene.h"
#include "scene_keys.h"

#include <ini.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define SCENE_FILE_MAX (1 << 20)
#define SCENE_LINE_MAX 190 /* inih's INI_MAX_LINE is 200 including newline */

typedef struct ini_ctx {
    hfs_scene *scene;
    const char *path;
    const char *base_dir;
    int objects_only;             /* an objects file: pin, box, point only */
    int failed;
    hfs_error first;
} ini_ctx;

static int on_key(void *user, const char *section, const char *name, const char *value)
{
    ini_ctx *c = user;
    if (c->failed)
        return 0;
    if (section && *section) {
        c->failed = 1;
        hfs_fail(&c->first, HFS_E_INVALID, "%s: sections are not used ([%s])", c->path, section);
        return 0;
    }
    const int k = hfs_scene_key_find(name);
    if (c->objects_only && k != HFS_SK_PIN && k != HFS_SK_BOX && k != HFS_SK_POINT) {
        c->failed = 1;
        hfs_fail(&c->first, HFS_E_INVALID, "%s: '%s' is not an object (pin, box or point)",
                 c->path, name);
        return 0;
    }
    if (hfs_scene_set(c->scene, HFS_SOURCE_FILE, name, value, c->path, c->base_dir, &c->first)) {
        c->failed = 1;
        return 0;
    }
    return 1;
}

static int load_ini(hfs_scene *s, const char *path, int objects_only, hfs_error *err)
{
    char *text;
    int rc = hfs_read_text_file(path, objects_only ? "objects file" : "scene file",
                                SCENE_FILE_MAX, &text, NULL, err);
    if (rc)
        return rc;
    int line = 1;
    for (const char *p = text, *start = text; ; ++p) {
        if (*p == '\n' || *p == '\0') {
            if (p - start > SCENE_LINE_MAX) {
                free(text);
                return hfs_fail(err, HFS_E_FORMAT, "%s:%d: line longer than %d characters", path,
                                line, SCENE_LINE_MAX);
            }
            if (!*p)
                break;
            start = p + 1;
            ++line;
        }
    }

    char base_dir[HFS_PATH_MAX];
    snprintf(base_dir, sizeof base_dir, "%s", path);
    char *slash = strrchr(base_dir, '/');
    if (slash)
        *slash = '\0';
    else
        snprintf(base_dir, sizeof base_dir, ".");

    ini_ctx c = {.scene = s, .path = path, .base_dir = base_dir, .objects_only = objects_only};
    const int bad_line = ini_parse_string(text, on_key, &c);
    free(text);
    if (bad_line == 0)
        return HFS_OK;
    if (bad_line < 0)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory while parsing", path);
    if (!c.failed)
        return hfs_fail(err, HFS_E_INVALID, "%s:%d: syntax error (expected key = value)", path, bad_line);
    /* The setter wrote "PATH: ..."; make it "PATH:LINE: ...". */
    const size_t plen = strlen(path);
    const char *rest = c.first.msg;
    if (strncmp(rest, path, plen) == 0 && rest[plen] == ':')
        rest += plen + 1;
    return hfs_fail(err, HFS_E_INVALID, "%s:%d:%s", path, bad_line, rest);
}

int hfs_scene_set(hfs_scene *s, hfs_scene_source src, const char *key,
                  const char *value, const char *where, const char *base_dir,
                  hfs_error *err)
{
    char objects_file[HFS_PATH_MAX];
    const int rc = hfs_scene_apply_key(s, src, key, value, where, base_dir, objects_file, err);
    if (rc || !objects_file[0])
        return rc;
    return load_ini(s, objects_file, 1, err);
}

int hfs_scene_load_file(hfs_scene *s, const char *path, hfs_error *err)
{
    return load_ini(s, path, 0, err);
}

int hfs_scene_load_objects(hfs_scene *s, const char *path, hfs_error *err)
{
    return load_ini(s, path, 1, err);
}
