"""Environment maps: SH projection and decomposition into key lights
(libhfshade's hfshade_envmap.h; `hfshade envmap decompose`)."""
import collections

import numpy as np

from ._errors import check, degrees, float32_array, integer, new_error, number
from ._ffi import ffi, lib

#: A light decomposed from a map.  The first four fields are what
#: render()'s `key` takes: key=[light[:4] for light in lights].
EnvLight = collections.namedtuple(
    "EnvLight", "azimuth elevation radius radiance energy share")
EnvLight.__doc__ = """A disk light taken from an environment map.

azimuth, elevation, radius: degrees (SPEC's azimuth, from +x towards +y;
the map's column 0 is azimuth 0); radiance: (R, G, B) linear radiance over
the disk; energy: (R, G, B), the radiance times the disk's solid angle,
what the light removed from the map; share: its luminance energy over the
map's."""


def env_map_array(env_map, name="env_map"):
    """An equirectangular map as a C-contiguous (h, w, 3) float32 array."""
    a = float32_array(name, env_map, ndim=3)
    if a.shape[2] != 3 or a.shape[0] < 1 or a.shape[1] < 1:
        raise ValueError(f"{name}: expected an (h, w, 3) RGB map, got shape {a.shape}")
    return a


def project_env(env_map):
    """The order-4 SH projection of an equirectangular map, (3, 16) float64.

    env_map: (h, w, 3) linear RGB, rows first, row 0 the zenith, column 0
    azimuth 0 (SPEC's equirectangular convention, as `--env-map` reads a
    file).  What render(env=...) takes as an SH environment; every texel
    must be finite (else hfshade.Error naming it)."""
    a = env_map_array(env_map)
    sh = ffi.new("double[3][16]")
    err = new_error()
    check(lib().hfs_envmap_project(ffi.from_buffer("float[]", a), a.shape[1], a.shape[0],
                                   b"env_map", sh, err), err)
    return np.array([[sh[c][k] for k in range(16)] for c in range(3)], dtype=np.float64)


def decompose_env(env_map, max_lights=4, min_share=0.02, contrast=4.0, max_radius=0.0):
    """Splits an equirectangular map into disk key lights and a residual,
    as `hfshade envmap decompose` does (DESIGN.md "Environment map
    decomposition"): each light holds exactly the energy it removes.

    env_map: (h, w, 3) linear RGB (see project_env); not modified.
    max_lights: 0..8; min_share: stop below this share of the map's
    energy, [0, 1]; contrast: a candidate's mean over its surround's,
    [1, 1e6]; max_radius: degrees, [0, 180], a wider candidate ends the
    search (0: no limit).  The defaults are the command's.

    Returns (lights, residual): a list of EnvLight, strongest first, and
    the (h, w, 3) float32 map without them."""
    a = env_map_array(env_map)
    residual = np.array(a, dtype=np.float32, order="C", copy=True)
    o = ffi.new("hfs_env_decompose_opts *")
    lib().hfs_env_decompose_defaults(o)
    o.max_lights = integer("max_lights", max_lights, 0, 8)
    o.min_share = number("min_share", min_share, 0.0, 1.0)
    o.contrast = number("contrast", contrast, 1.0, 1e6)
    # as the command converts --max-radius (tools/cli_envmap.c)
    o.max_radius = number("max_radius", max_radius, 0.0, 180.0) * 3.14159265358979323846 / 180.0
    d = ffi.new("hfs_env_decomp *")
    err = new_error()
    check(lib().hfs_env_decompose(ffi.from_buffer("float[]", residual), a.shape[1], a.shape[0],
                                  o, b"env_map", d, err), err)
    lights = []
    for k in range(d.n_lights):
        light = d.light[k]
        lights.append(EnvLight(degrees(light.phi), degrees(light.elev), degrees(light.alpha),
                               tuple(float(light.radiance[c]) for c in range(3)),
                               tuple(float(light.energy[c]) for c in range(3)),
                               float(light.share)))
    return lights, residual
