/*
 * test_io_corpus.c — every file in the broken-input corpus (argv[1] =
 * tests/data/broken, subdirectories height/ and env/, the layout the CLI's
 * own end-to-end test walks too) is fed to BOTH loaders (a broken height field is no
 * valid environment map either, and vice versa) and must give: a negative
 * status, a non-empty one-line message that starts with the path, and a
 * zeroed output.  Crashes and out-of-bounds reads are caught by running the
 * same test under ASan/UBSan (HFS_SANITIZE=ON).
 *
 * Conventions of the corpus: a name like "x.4x4.raw" carries the raw size to
 * pass; README.md must document every file (checked here), and the corpus
 * stays under 200 KB (checked here).  A nonexistent path and a directory are
 * added by the test itself (height/ also holds a directory, dir.png).
 */
#include "hfs_io.h"
#include "test_util.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int is_tool_file(const char *name)
{
    return name[0] == '.';
}

static int good_message(const char *path, const hfs_error *err)
{
    return err->msg[0] && strncmp(err->msg, path, strlen(path)) == 0 &&
           strlen(err->msg) > strlen(path) + 2 && !strchr(err->msg, '\n') &&
           !strchr(err->msg, '\r');
}

static void try_both(const char *path, const char *name, const char *readme)
{
    hfs_height_load_opts o;
    hfs_heightmap hm;
    hfs_envmap em;
    hfs_error err;
    int w = 0, h = 0, rc;
    const char *dot;

    memset(&o, 0, sizeof o);
    /* "name.WxH.raw": the size a user would give with --size. */
    dot = strrchr(name, '.');
    if (dot && !strcmp(dot, ".raw")) {
        const char *p = dot;
        while (p > name && p[-1] != '.')
            --p;
        if (p > name && sscanf(p, "%dx%d.raw", &w, &h) == 2) {
            o.raw_width = w;
            o.raw_height = h;
        }
    }

    memset(&hm, 0x5a, sizeof hm);
    memset(&err, 0, sizeof err);
    rc = hfs_height_load(path, &o, &hm, &err);
    printf("height %-32s -> %-11s %s\n", name, hfs_status_name(rc), err.msg);
    if (rc == 0) {
        fprintf(stderr, "  %s loaded as a height field!\n", name);
        hfs_heightmap_free(&hm);
    }
    CHECK(rc < 0);
    CHECK(good_message(path, &err));
    CHECK(hm.z == NULL && hm.width == 0 && hm.height == 0 && hm.holes == 0);

    memset(&em, 0x5a, sizeof em);
    memset(&err, 0, sizeof err);
    rc = hfs_envmap_load(path, &em, &err);
    printf("envmap %-32s -> %-11s %s\n", name, hfs_status_name(rc), err.msg);
    /* Broken only as height fields: a colour PFM (2x2) and a 1x1 PFM are
     * valid environment maps (hfs_envmap_load reads PFM, issue 17), all
     * 1.0 (grey: R = G = B). */
    const int pf = !strcmp(name, "pfm_colour_PF.pfm"), one = !strcmp(name, "pfm_1x1.pfm");
    if (pf || one) {
        CHECK(rc == 0 && em.width == (pf ? 2 : 1) && em.height == em.width &&
              em.rgb[0] == 1.0f && em.rgb[em.width * em.height * 3 - 1] == 1.0f);
        if (rc == 0)
            hfs_envmap_free(&em);
        return;
    }
    if (rc == 0) {
        fprintf(stderr, "  %s loaded as an environment map!\n", name);
        hfs_envmap_free(&em);
    }
    CHECK(rc < 0);
    CHECK(good_message(path, &err));
    CHECK(em.rgb == NULL && em.width == 0 && em.height == 0);

    if (readme) {
        char quoted[300];
        snprintf(quoted, sizeof quoted, "`%s`", name);
        if (!strstr(readme, quoted)) {
            fprintf(stderr, "  %s is not documented in README.md\n", name);
            CHECK(0);
        }
    }
}

static int cmp_names(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

int main(int argc, char **argv)
{
    char path[4096], *readme = NULL;
    char *names[512];
    int count = 0;
    long long total = 0;
    DIR *d;
    struct dirent *e;
    FILE *f;

    if (argc != 2) {
        fprintf(stderr, "usage: %s CORPUS_DIR\n", argv[0]);
        return 2;
    }
    snprintf(path, sizeof path, "%s/README.md", argv[1]);
    f = fopen(path, "rb");
    if (f) {
        long n;
        fseek(f, 0, SEEK_END);
        n = ftell(f);
        fseek(f, 0, SEEK_SET);
        readme = calloc((size_t)n + 1, 1);
        if (readme && fread(readme, 1, (size_t)n, f) != (size_t)n)
            readme[0] = '\0';
        fclose(f);
    }
    CHECK(readme != NULL);

    for (int sub = 0; sub < 2; ++sub) {
        static const char *const subdirs[2] = {"height", "env"};
        char dir[2048];
        int first = count;
        snprintf(dir, sizeof dir, "%s/%s", argv[1], subdirs[sub]);
        d = opendir(dir);
        if (!d) {
            perror(dir);
            return 1;
        }
        while ((e = readdir(d)) && count < 512)
            if (!is_tool_file(e->d_name))
                names[count++] = strdup(e->d_name);
        closedir(d);
        qsort(names + first, (size_t)(count - first), sizeof names[0], cmp_names);
        for (int k = first; k < count; ++k) {
            struct stat st;
            snprintf(path, sizeof path, "%s/%s", dir, names[k]);
            if (stat(path, &st) == 0 && S_ISREG(st.st_mode))
                total += st.st_size;
            try_both(path, names[k], readme);
            free(names[k]);
        }
    }
    CHECK(count >= 40);
    CHECK(total < 200 * 1024);
    printf("corpus: %d entries, %lld bytes\n", count, total);

    /* Inputs no file can hold. */
    snprintf(path, sizeof path, "%s/no-such-file.png", argv[1]);
    try_both(path, "no-such-file.png", NULL);
    try_both(argv[1], "(the corpus directory)", NULL);

    free(readme);
    return finish_checks("test_io_corpus");
}
