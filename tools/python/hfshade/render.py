"""The renderer: a height field lit by an environment, key and local
lights, with soft shadows (libhfshade's hfs_renderer_render), numpy in and
out, with the command line's units and defaults (`hfshade render`,
docs/SCENE.md)."""
import numbers

import numpy as np

from . import envmap as _envmap
from ._errors import (Error, check, float32_array, integer, new_error, number, radians)
from ._ffi import ffi, lib

_BACKENDS = {"gles": 1, "cpu": 2, "truth": 3}
_VISIBILITY = {"legendre": 1, "wedge": 2, "slice": 3}
_PRECISION = {"fp16": 1, "fp32": 2}
_QUALITY_FIELDS = (
    "k", "offset", "nphi_env", "nphi_key", "refine", "split", "far_from", "far_dirs",
    "far_step", "nphi_bounce", "bounce_refine", "bounce_subsample", "bounce_near",
    "nphi_local", "local_full_swath", "subsample", "precision", "visibility", "threads",
    "truth_azimuths", "truth_elev_order", "truth_light_samples")


class Renderer:
    """A renderer bound to one backend, made once and used for many frames.

    backend: "gles" (the product: OpenGL ES 3, fp16; the default, as on
    the command line), "cpu" (the reference, double precision) or "truth"
    (brute force).  context: GLES only, "surfaceless" (default), "osmesa"
    or "auto".  A context manager; close() frees it (GL context and
    textures) at once, else the garbage collector does.  One renderer per
    thread."""

    def __init__(self, backend="gles", context=None):
        if backend not in _BACKENDS:
            raise ValueError(f"backend: {backend!r} is not one of gles, cpu, truth")
        if context is not None and context not in ("surfaceless", "osmesa", "auto"):
            raise ValueError(f"context: {context!r} is not one of surfaceless, osmesa, auto")
        desc = ffi.new("hfs_renderer_desc *")
        desc.backend = _BACKENDS[backend]
        keep = ffi.new("char[]", context.encode()) if context else ffi.NULL
        desc.context = keep
        out = ffi.new("hfs_renderer **")
        err = new_error()
        check(lib().hfs_renderer_create(desc, out, err), err)
        self._r = ffi.gc(out[0], lib().hfs_renderer_destroy)

    @property
    def backend(self):
        """The backend in use ("cpu", "truth", "gles") and, for GLES, its context."""
        return ffi.string(lib().hfs_renderer_backend_name(self.handle)).decode()

    @property
    def handle(self):
        """The hfs_renderer * (cffi), for the GIS functions."""
        if self._r is None:
            raise ValueError("renderer: closed")
        return self._r

    def close(self):
        """Frees the renderer now (idempotent)."""
        if self._r is not None:
            ffi.release(self._r)
            self._r = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def render(self, heights, dx=1.0, zscale=1.0, env=None, env_rotate=0.0, env_lights=0,
               key=(), local=(), albedo=1.0, albedo_map=None, bounces=0, specular=0.0,
               gloss=32.0, quality="kiosk"):
        """Renders the exit radiance of every grid point: (H, W, 3) float32,
        linear RGB, row 0 first, as `hfshade render ... --pfm` writes it.

        heights: (H, W) array, H, W >= 2, row-major, row j = 0 first (for a
            north-up DEM row 0 is north: x runs east, y south); finite.
        dx: world units per texel (> 0); zscale: world z = zscale * height.
        env: None; an SH environment, (3, 16) or (16, 3) per channel or
            (16,) grey (SPEC's basis, what `--env-sh` takes); or an
            equirectangular map (h, w, 3) (what `--env-map` reads: row 0
            the zenith), lit exactly as the command line lights it
            (projection, open sky, `env_lights`).
        env_rotate: degrees, the environment turned about +z.
        env_lights: with a map, 0 (off), "auto" (up to 4) or N: its bright
            regions as key lights + residual (`--env-lights`).
        key: key (disk) lights, each (azimuth, elevation, radius, radiance)
            in degrees (SPEC's azimuth, from +x towards +y; elevation above
            the plane; the disk's angular radius) and a radiance, one
            number or (R, G, B), as `--key PHI,ELEV,ALPHA,LE[,G,B]`; at most 8
            with the map's.
        local: local spherical lights, each (x, y, z, radius, radiance) in
            world units (`--local X,Y,Z,R,LE`); at most 16.
        albedo: Lambertian albedo; albedo_map: None or (H, W, 3) in [0, 1].
        bounces: indirect bounces 0..3; specular, gloss: glossy surfaces.
        quality: a preset ("kiosk", the default; "panel", "headless") or a
            dict of hfs_quality fields (hfshade_inputs.h: "k", "nphi_env",
            "subsample", "visibility": "slice"|"legendre"|"wedge",
            "precision": "fp16"|"fp32", ...; "preset" names the start).

        Raises hfshade.Error with the library's one-line message for a
        value it refuses (a NaN height, an elevation out of range, ...),
        ValueError/TypeError for an argument of the wrong kind."""
        if np.ma.is_masked(heights):
            raise ValueError("heights: masked (nodata) values cannot be rendered; fill them "
                             "first (the GIS functions take masked DEMs)")
        z = float32_array("heights", heights, ndim=2)
        if z.shape[0] < 2 or z.shape[1] < 2:
            raise ValueError(f"heights: expected at least 2x2 heights, got shape {z.shape}")
        field = ffi.new("hfs_field *")
        field.width, field.height = z.shape[1], z.shape[0]
        field.z = zbuf = ffi.from_buffer("float[]", z)
        field.dx = number("dx", dx)
        field.zscale = number("zscale", zscale)
        q = quality_struct(quality)
        l = ffi.new("hfs_lighting *")
        lib().hfs_lighting_defaults(l)
        keep = [zbuf]
        _set_lights(l, key, local, albedo, bounces, specular, gloss)
        l.env_rotate = radians(number("env_rotate", env_rotate))
        if albedo_map is not None:
            a = float32_array("albedo_map", albedo_map, ndim=3, shape=(z.shape[0], z.shape[1], 3))
            keep.append(a)
            l.albedo_map = ffi.from_buffer("float[]", a)
        state = _set_env(l, env, env_lights, len(key), q, keep)
        out = np.empty((z.shape[0], z.shape[1], 3), dtype=np.float32)
        img = ffi.new("hfs_image *")
        img.width, img.height = z.shape[1], z.shape[0]
        img.rgb = ffi.from_buffer("float[]", out)
        err = new_error()
        try:
            check(lib().hfs_renderer_render(self.handle, field, l, q, img, ffi.NULL, ffi.NULL,
                                            err), err)
        finally:
            if state is not None:
                lib().hfs_env_lighting_free(state)
        del keep
        return out


def render(heights, backend="gles", context=None, **kwargs):
    """One frame on a renderer made for it: Renderer(backend,
    context).render(heights, **kwargs) (see Renderer.render).  Making a
    GLES renderer costs a GL context: keep a Renderer for many frames."""
    with Renderer(backend, context) as r:
        return r.render(heights, **kwargs)


def quality_struct(quality):
    """An hfs_quality from a preset name or a dict of fields."""
    q = ffi.new("hfs_quality *")
    fields = {}
    preset = quality
    if isinstance(quality, dict):
        fields = dict(quality)
        preset = fields.pop("preset", "kiosk")
    if not isinstance(preset, str) or lib().hfs_quality_preset(q, preset.encode()) != 0:
        raise ValueError(f"quality: {preset!r} is not a preset (kiosk, panel, headless) "
                         "or a dict of quality fields")
    for name, value in fields.items():
        if name not in _QUALITY_FIELDS:
            raise ValueError(f"quality: {name!r} is not a quality field "
                             f"({', '.join(_QUALITY_FIELDS)})")
        table = _VISIBILITY if name == "visibility" else _PRECISION if name == "precision" else None
        if table is not None and isinstance(value, str):
            if value not in table:
                raise ValueError(f"quality: {name} {value!r} is not one of {', '.join(table)}")
            value = table[value]
        setattr(q, name, integer(f"quality: {name}", value, -2**31, 2**31 - 1))
    err = new_error()
    check(lib().hfs_validate_quality(q, err), err)
    return q


def _rgb(name, value):
    """A radiance: one number (grey) or three, as floats (>= 0)."""
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        return [number(name, value, 0.0)] * 3, False
    try:
        values = [number(name, v, 0.0) for v in value]
    except TypeError:
        raise TypeError(f"{name}: expected a number or (R, G, B)") from None
    if len(values) != 3:
        raise ValueError(f"{name}: expected a number or (R, G, B), got {len(values)} values")
    return values, True


def _set_key(k, i, light):
    if isinstance(light, _envmap.EnvLight):
        light = light[:4]
    try:
        az, el, radius, radiance = light
    except (TypeError, ValueError):
        raise ValueError(f"key {i + 1}: expected (azimuth, elevation, radius, radiance)") from None
    k.phi = radians(number(f"key {i + 1}: azimuth", az, -3600.0, 3600.0))
    k.elev = radians(number(f"key {i + 1}: elevation", el, -90.0, 90.0))
    radius = number(f"key {i + 1}: radius", radius, 0.0, 89.0)
    if radius <= 0.0:
        raise ValueError(f"key {i + 1}: radius: {radius!r} is not in (0, 89] degrees")
    k.alpha = radians(radius)
    rgb, colour = _rgb(f"key {i + 1}: radiance", radiance)
    # The command line's arithmetic (runtime/scene: le the largest
    # channel, tint the ratios, radiance le * tint), for the same bits.
    le = max(rgb)
    tint = [c / le for c in rgb] if colour and le > 0.0 else [1.0, 1.0, 1.0]
    for c in range(3):
        k.radiance[c] = float(np.float32(le * tint[c])) if colour else float(np.float32(rgb[c]))


def _set_lights(l, key, local, albedo, bounces, specular, gloss):
    key, local = list(key), list(local)
    if len(key) > 8:
        raise ValueError(f"key: {len(key)} key lights, at most 8")
    if len(local) > 16:
        raise ValueError(f"local: {len(local)} local lights, at most 16")
    l.n_key = len(key)
    for i, light in enumerate(key):
        _set_key(l.key[i], i, light)
    l.n_local = len(local)
    for i, light in enumerate(local):
        try:
            x, y, zz, radius, radiance = light
        except (TypeError, ValueError):
            raise ValueError(f"local {i + 1}: expected (x, y, z, radius, radiance)") from None
        m = l.local[i]
        m.pos = [number(f"local {i + 1}: {n}", v) for n, v in (("x", x), ("y", y), ("z", zz))]
        m.radius = number(f"local {i + 1}: radius", radius, 0.0)
        rgb, _ = _rgb(f"local {i + 1}: radiance", radiance)
        m.radiance = [float(np.float32(c)) for c in rgb]
    l.albedo = number("albedo", albedo)
    l.bounces = integer("bounces", bounces, 0, 3)
    l.specular = number("specular", specular)
    l.gloss = number("gloss", gloss)


def _sh_array(env):
    sh = np.asarray(env, dtype=np.float64)
    if sh.shape == (16,):
        return np.stack([sh, sh, sh])
    if sh.shape == (16, 3):
        return np.ascontiguousarray(sh.T)
    return sh


def _set_env(l, env, env_lights, n_keys, q, keep):
    """The environment into l: SH, or a map through
    hfs_env_lighting_build/apply (returned, to be freed after the frame)."""
    lights = -1 if env_lights == "auto" else 0 if env_lights in (0, "off", None) else \
        integer("env_lights", env_lights, 1, 8)
    if env is None:
        if lights:
            raise ValueError("env_lights: needs an environment map (env)")
        return None
    shape = np.shape(env)
    if len(shape) != 3:
        sh = _sh_array(env)
        if sh.shape != (3, 16):
            raise ValueError(f"env: expected SH coefficients (3, 16), (16, 3) or (16,), or an "
                             f"(h, w, 3) map, got shape {shape}")
        if lights:
            raise ValueError("env_lights: needs an environment map, not SH coefficients")
        l.has_env = 1
        for c in range(3):
            for k in range(16):
                l.env_sh[c][k] = float(sh[c][k])
        return None
    m = _envmap.env_map_array(env, "env")
    keep.append(m)
    o = ffi.new("hfs_env_lighting_opts *")
    o.lights, o.n_scene_keys, o.nphi_env = lights, n_keys, q.nphi_env
    state = ffi.new("hfs_env_lighting *")
    buf = ffi.from_buffer("float[]", m)
    keep.extend([o, buf])
    err = new_error()
    check(lib().hfs_env_lighting_build(buf, m.shape[1], m.shape[0], o, b"env", state, err), err)
    lib().hfs_env_lighting_apply(state, o, buf, m.shape[1], m.shape[0], l)
    return state


__all__ = ["Renderer", "render", "Error"]
