"""The C interface: the cdef of the public structs and functions of
libhfshade (runtime/hfshade.h, hfshade_inputs.h, hfshade_envmap.h) and
libhfshade_gis (tools/gis/hfshade_gis.h), mirrored by hand for cffi's ABI
mode, and the two libraries opened.

The layouts are pinned by the test suite: tests/python_layout.c prints the
C compiler's sizeof/offsetof of every struct and field declared here and
tests/python/test_layout.py compares them with ffi.sizeof/ffi.offsetof, so
a header change that is not mirrored here fails the suite.

The libraries are found by the environment variables HFSHADE_LIBRARY and
HFSHADE_GIS_LIBRARY (paths; the tests point them at the build tree), else
by their SONAMEs libhfshade.so.MAJOR and libhfshade_gis.so.MAJOR (where
the Debian packages put them).
"""
import os

import cffi

#: The library's major version this module speaks (its SONAME's number).
MAJOR = 0
#: The version of this module (that of the hfshade release it ships with).
VERSION = "0.1.0"

CDEF_CORE = r"""
typedef struct hfs_error { char msg[512]; } hfs_error;
const char *hfs_status_name(int code);
const char *hfs_version(void);
int hfs_version_number(void);

typedef struct hfs_field {
    int width;
    int height;
    const float *z;
    double dx;
    double zscale;
} hfs_field;

typedef struct hfs_key_light {
    double phi, elev, alpha;
    float radiance[3];
    int disabled;
    int from_env;
} hfs_key_light;

typedef struct hfs_local_light {
    double pos[3];
    double radius;
    float radiance[3];
    int disabled;
} hfs_local_light;

typedef struct hfs_lighting {
    int has_env;
    double env_sh[3][16];
    double env_rotate;
    const float *env_map;
    int env_map_width, env_map_height;
    const float *env_open;
    const float *env_shade_map;
    int n_key;
    hfs_key_light key[8];
    int n_local;
    hfs_local_light local[16];
    double albedo;
    const float *albedo_map;
    int bounces;
    double specular;
    double gloss;
    double view_dir[3];
    int view_from_eye;
    double view_eye[3];
} hfs_lighting;

void hfs_lighting_defaults(hfs_lighting *l);

typedef enum hfs_backend {
    HFS_BACKEND_DEFAULT = 0,
    HFS_BACKEND_GLES = 1,
    HFS_BACKEND_CPU = 2,
    HFS_BACKEND_TRUTH = 3
} hfs_backend;

typedef enum hfs_visibility_path {
    HFS_VIS_LEGENDRE = 1,
    HFS_VIS_WEDGE_TABLE = 2,
    HFS_VIS_SLICE = 3
} hfs_visibility_path;

typedef enum hfs_precision {
    HFS_PRECISION_FP16 = 1,
    HFS_PRECISION_FP32 = 2
} hfs_precision;

typedef struct hfs_quality {
    int k;
    int offset;
    int nphi_env;
    int nphi_key;
    int refine;
    int split;
    int far_from;
    int far_dirs;
    int far_step;
    int nphi_bounce;
    int bounce_refine;
    int bounce_subsample;
    int bounce_near;
    int nphi_local;
    int local_full_swath;
    int subsample;
    hfs_precision precision;
    hfs_visibility_path visibility;
    int threads;
    int truth_azimuths;
    int truth_elev_order;
    int truth_light_samples;
} hfs_quality;

void hfs_quality_defaults(hfs_quality *q);
int hfs_quality_preset(hfs_quality *q, const char *use);

typedef struct hfs_image {
    int width, height;
    float *rgb;
} hfs_image;

typedef struct hfs_renderer hfs_renderer;

typedef struct hfs_renderer_desc {
    hfs_backend backend;
    const char *context;
    const char *gl_profile;
    int gl_strict_limits;
    void *egl_display;
    void *egl_share_context;
} hfs_renderer_desc;

int hfs_renderer_create(const hfs_renderer_desc *desc, hfs_renderer **out, hfs_error *err);
void hfs_renderer_destroy(hfs_renderer *r);
const char *hfs_renderer_backend_name(const hfs_renderer *r);
int hfs_renderer_render(hfs_renderer *r, const hfs_field *field, const hfs_lighting *lighting,
                        const hfs_quality *quality, hfs_image *out, void *progress, void *user,
                        hfs_error *err);
int hfs_validate_quality(const hfs_quality *quality, hfs_error *err);

typedef struct hfs_env_decompose_opts {
    int max_lights;
    double min_share;
    double contrast;
    double max_radius;
    int threads;
} hfs_env_decompose_opts;

typedef struct hfs_env_light {
    double phi, elev, alpha;
    float radiance[3];
    double energy[3];
    double share;
    int id;
} hfs_env_light;

typedef struct hfs_env_decomp {
    int n_lights;
    hfs_env_light light[8];
    double residual_sh[3][16];
    double total_energy[3];
    double residual_energy[3];
} hfs_env_decomp;

typedef struct hfs_env_lighting_opts {
    int lights;
    int n_scene_keys;
    int shade_sh;
    int truth_sh;
    int nphi_env;
} hfs_env_lighting_opts;

typedef struct hfs_env_lighting {
    double sh[3][16];
    int n_keys;
    hfs_key_light keys[8];
    float *residual;
    float *open;
} hfs_env_lighting;

int hfs_envmap_project(const float *rgb, int w, int h, const char *name, double sh[3][16],
                       hfs_error *err);
void hfs_env_decompose_defaults(hfs_env_decompose_opts *o);
int hfs_env_decompose(float *rgb, int w, int h, const hfs_env_decompose_opts *o,
                      const char *name, hfs_env_decomp *out, hfs_error *err);
int hfs_env_lighting_build(const float *rgb, int w, int h, const hfs_env_lighting_opts *o,
                           const char *name, hfs_env_lighting *out, hfs_error *err);
void hfs_env_lighting_apply(const hfs_env_lighting *e, const hfs_env_lighting_opts *o,
                            const float *map, int w, int h, hfs_lighting *l);
void hfs_env_lighting_free(hfs_env_lighting *e);
"""

CDEF_GIS = r"""
typedef struct hfs_gis_dem {
    int width, height;
    const float *z;
    const unsigned char *hole;
    int has_nodata;
    double nodata;
    double cell;
    double zscale;
} hfs_gis_dem;

typedef enum hfs_gis_product {
    HFS_GIS_SVF = 0,
    HFS_GIS_HORIZON = 1,
    HFS_GIS_OPENNESS = 2,
    HFS_GIS_SUN = 3,
    HFS_GIS_INSOLATION = 4
} hfs_gis_product;

typedef struct hfs_gis_site {
    double lat, lon, elevation_m, linke, convergence_deg;
} hfs_gis_site;

float hfs_gis_nodata(const hfs_gis_dem *dem, hfs_gis_product product);
int hfs_gis_svf(hfs_renderer *r, const hfs_gis_dem *dem, int directions, int lambertian,
                double radius, float *out, hfs_error *err);
int hfs_gis_horizon(hfs_renderer *r, const hfs_gis_dem *dem, double azimuth, int compass,
                    double radius, float *out, hfs_error *err);
int hfs_gis_openness(hfs_renderer *r, const hfs_gis_dem *dem, int directions, double radius,
                     float *positive, float *negative, hfs_error *err);
int hfs_gis_julian_day(double unix_utc, double *jd, hfs_error *err);
int hfs_gis_sun(hfs_renderer *r, const hfs_gis_dem *dem, const hfs_gis_site *site,
                double unix_utc, double radius, float *beam, float *visible, hfs_error *err);
int hfs_gis_insolation(hfs_renderer *r, const hfs_gis_dem *dem, const hfs_gis_site *site,
                       double from_unix_utc, double to_unix_utc, double step_min,
                       int directions, double radius, float *beam, float *diffuse,
                       float *global, hfs_error *err);
int hfs_gis_insolation_sky(hfs_renderer *r, const hfs_gis_dem *dem, const hfs_gis_site *site,
                           double from_unix_utc, double to_unix_utc, double step_min,
                           int directions, double radius, const float *sky_rgb, int sky_w,
                           int sky_h, double sky_north, double albedo, float *beam,
                           float *diffuse, float *global, hfs_error *err);
"""

#: Every struct the cdef declares, with its fields (the layout test walks
#: them; tests/python_layout.c prints the same list from the headers).
STRUCTS = (
    "hfs_error", "hfs_field", "hfs_key_light", "hfs_local_light", "hfs_lighting",
    "hfs_quality", "hfs_image", "hfs_renderer_desc", "hfs_env_decompose_opts",
    "hfs_env_light", "hfs_env_decomp", "hfs_env_lighting_opts", "hfs_env_lighting",
    "hfs_gis_dem", "hfs_gis_site",
)

ffi = cffi.FFI()
ffi.cdef(CDEF_CORE)
ffi.cdef(CDEF_GIS)

_libs = {}


def _open(var, soname):
    path = os.environ.get(var) or soname
    try:
        return ffi.dlopen(path)
    except OSError as e:
        hint = "" if os.environ.get(var) else f" (install libhfshade{MAJOR}, or set {var})"
        raise ImportError(f"hfshade: cannot load {path}{hint}: {e}") from None


def lib():
    """libhfshade, opened once; its major version checked against MAJOR."""
    if "core" not in _libs:
        core = _open("HFSHADE_LIBRARY", f"libhfshade.so.{MAJOR}")
        number = core.hfs_version_number()
        if number // 10000 != MAJOR:
            version = ffi.string(core.hfs_version()).decode()
            raise ImportError(f"hfshade: the library is version {version}, this module "
                              f"speaks major version {MAJOR}")
        _libs["core"] = core
    return _libs["core"]


def gis_lib():
    """libhfshade_gis, opened on first use (after libhfshade, which it links)."""
    if "gis" not in _libs:
        lib()
        _libs["gis"] = _open("HFSHADE_GIS_LIBRARY", f"libhfshade_gis.so.{MAJOR}")
    return _libs["gis"]
