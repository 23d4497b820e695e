/*
 * png_same_picture.c — exits 0 when two PNGs show the same picture (same
 * size, same RGB in every pixel, alpha ignored: one may be RGB, the other
 * RGBA), 1 when they differ (printing the first difference and whether B
 * is A upside down), 2 when one cannot be read.  With --asymmetric A, exits
 * 0 only when A differs from itself flipped north-south (so that a test of
 * orientation cannot pass on a symmetric picture).
 */
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct picture {
    png_uint_32 w, h;
    unsigned char *rgba; /* w * h * 4, top row first */
} picture;

static int load(const char *path, picture *p)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path)) {
        fprintf(stderr, "%s: %s\n", path, img.message);
        return -1;
    }
    img.format = PNG_FORMAT_RGBA;
    p->w = img.width;
    p->h = img.height;
    p->rgba = malloc(PNG_IMAGE_SIZE(img));
    if (!p->rgba || !png_image_finish_read(&img, NULL, p->rgba, 0, NULL)) {
        fprintf(stderr, "%s: %s\n", path, p->rgba ? img.message : "out of memory");
        png_image_free(&img);
        free(p->rgba);
        return -1;
    }
    return 0;
}

/* 1 when a and b have the same RGB, b's rows optionally reversed. */
static int same(const picture *a, const picture *b, int flipped, long *first)
{
    if (a->w != b->w || a->h != b->h)
        return 0;
    for (png_uint_32 j = 0; j < a->h; ++j)
        for (png_uint_32 i = 0; i < a->w; ++i) {
            const png_uint_32 jb = flipped ? a->h - 1 - j : j;
            const unsigned char *pa = a->rgba + ((size_t)j * a->w + i) * 4;
            const unsigned char *pb = b->rgba + ((size_t)jb * b->w + i) * 4;
            if (memcmp(pa, pb, 3)) {
                if (first)
                    *first = (long)j * (long)a->w + (long)i;
                return 0;
            }
        }
    return 1;
}

int main(int argc, char **argv)
{
    picture a = {0}, b = {0};
    if (argc == 3 && !strcmp(argv[1], "--asymmetric")) {
        if (load(argv[2], &a))
            return 2;
        const int sym = same(&a, &a, 1, NULL);
        printf("%s: %ux%u, %s north-south\n", argv[2], a.w, a.h, sym ? "SYMMETRIC" : "asymmetric");
        free(a.rgba);
        return sym ? 1 : 0;
    }
    if (argc != 3) {
        fprintf(stderr, "usage: png_same_picture A.png B.png | --asymmetric A.png\n");
        return 2;
    }
    if (load(argv[1], &a) || load(argv[2], &b)) {
        free(a.rgba);
        return 2;
    }
    long first = -1;
    int rc = 0;
    if (same(&a, &b, 0, &first)) {
        printf("same picture (%ux%u)\n", a.w, a.h);
    } else {
        rc = 1;
        if (a.w != b.w || a.h != b.h)
            printf("sizes differ: %ux%u vs %ux%u\n", a.w, a.h, b.w, b.h);
        else
            printf("pictures differ first at pixel (%ld, %ld)%s\n", first % (long)a.w,
                   first / (long)a.w, same(&a, &b, 1, NULL) ? "; B is A upside down" : "");
    }
    free(a.rgba);
    free(b.rgba);
    return rc;
}
