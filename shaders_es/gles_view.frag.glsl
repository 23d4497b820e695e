/*
 * gles_view.frag - what the 3-D view shows besides the lit terrain
 * (issue 41): the environment map's background and the aerial
 * perspective, the third part of the GLES renderer's shader library
 * (runtime/gles/programs.c composes every pass as gles_pairs + gles_lib +
 * gles_ray + gles_view + [product] + the pass; source string 4 in driver
 * messages).
 * Each function is the float twin of runtime/core/view_look.c's, which
 * the truth's (and the cpu backend's) view calls per pixel: change both
 * together (test_view_look compares the two paths).
 */
precision highp float;
precision highp int;
precision highp sampler2D;

#define HFS_PI 3.14159265358979
#define HFS_HAZE_SERIES 1e-2    /* view_look.h */
#define HFS_STUDIO_BASE 0.12    /* view_look.h */
#define HFS_STUDIO_SLOPE 0.14

/* hfs_env_map_bilinear: the equirect map in `tex` (row 0 the zenith,
 * pixel centres at (c + 0.5, r + 0.5)) in unit direction d, turned by rot
 * about +z; bilinear between pixel centres, wrapping in azimuth, clamped
 * at the poles.  The four texels are fetched and weighted in highp, as
 * view.frag reads the lit image (a texture unit's weights may be 8-bit). */
vec3 hfs_sky_map(highp sampler2D tex, vec3 d, float rot)
{
    ivec2 n = textureSize(tex, 0);
    float u = (atan(d.y, d.x) - rot) / (2.0 * HFS_PI);
    u = (u - floor(u)) * float(n.x) - 0.5;
    float el = asin(clamp(d.z, -1.0, 1.0));
    float v = clamp((0.5 - el / HFS_PI) * float(n.y) - 0.5, 0.0, float(n.y - 1));
    float fu = floor(u), fv = floor(v);
    float au = u - fu, av = v - fv;
    int c0 = (int(fu) + n.x) % n.x, c1 = (c0 + 1) % n.x;
    int r0 = int(fv), r1 = min(r0 + 1, n.y - 1);
    vec3 a = texelFetch(tex, ivec2(c0, r0), 0).rgb * (1.0 - au) +
             texelFetch(tex, ivec2(c1, r0), 0).rgb * au;
    vec3 b = texelFetch(tex, ivec2(c0, r1), 0).rgb * (1.0 - au) +
             texelFetch(tex, ivec2(c1, r1), 0).rgb * au;
    return a * (1.0 - av) + b * av;
}

/* The studio backdrop's gradient at unit direction d (hfs_view_background). */
float hfs_studio(vec3 d)
{
    return HFS_STUDIO_BASE + HFS_STUDIO_SLOPE * (1.0 + d.z);
}

/* hfs_haze_transmittance: haze = (sigma, z0, scale height, -); the segment
 * of length dist from height za to zb. */
float hfs_haze_t(vec4 haze, float dist, float za, float zb)
{
    float a = max(za - haze.y, 0.0) / haze.z;
    float b = max(zb - haze.y, 0.0) / haze.z;
    float x = b - a;
    float g = abs(x) < HFS_HAZE_SERIES ? exp(-a) * (1.0 - x / 2.0 + x * x / 6.0)
                                       : (exp(-a) - exp(-b)) / x;
    return exp(-haze.x * dist * g);
}

/* rgb seen through the haze from the eye (ortho: from the eye's plane,
 * along fwd) to the point rel away from the eye: hfs_haze_apply with
 * L_in = lin (both times the view's scale). */
vec3 hfs_haze(vec3 rgb, vec4 haze, vec3 lin, vec3 rel, vec3 eye, vec3 fwd, bool ortho)
{
    float dist = ortho ? dot(rel, fwd) : length(rel);
    float za = ortho ? eye.z + rel.z - dist * fwd.z : eye.z;
    float t = hfs_haze_t(haze, dist, za, eye.z + rel.z);
    return rgb * t + lin * (1.0 - t);
}
