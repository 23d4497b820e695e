"""hfshade: soft shadows on height fields, and the GIS rasters of DEMs,
from numpy (issue 40).  A thin layer over the installed libraries
libhfshade (the renderer) and libhfshade_gis (sky-view factor, horizons,
openness, the sun, insolation), through cffi: the numbers are the C library's, the same as the
`hfshade` command's on the same inputs.

    import numpy as np, hfshade
    z = np.load("dem.npy")                          # (H, W), row 0 north
    rgb = hfshade.render(z, dx=30, backend="cpu", key=[(336, 15, 2, 1500)])
    v = hfshade.svf(z, cell_size=30)                # masked float32 array

Arrays are row-major, north-up; inputs are converted to float32; outputs
are float32 and never hold NaN or Inf.  Angles are degrees.  Errors the
library reports raise hfshade.Error (its one-line message, .status);
arguments of the wrong kind raise ValueError or TypeError naming them.
docs/PYTHON.md is the manual.
"""
from ._errors import Error
from ._ffi import MAJOR, VERSION as __version__
from ._ffi import lib as _lib
from .envmap import EnvLight, decompose_env, project_env
from .gis import horizon, insolation, openness, sun, svf
from .render import Renderer, render

_lib()  # the library found and of this major version, or ImportError


def library_version():
    """The version of libhfshade in use ("MAJOR.MINOR.PATCH")."""
    from ._ffi import ffi
    return ffi.string(_lib().hfs_version()).decode()


__all__ = ["Error", "Renderer", "render", "svf", "horizon", "openness", "sun", "insolation",
           "project_env", "decompose_env", "EnvLight", "library_version", "MAJOR",
           "__version__"]
