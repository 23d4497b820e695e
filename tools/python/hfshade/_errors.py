"""Errors: the library's, and the checks of arguments made in Python."""
import math
import numbers

import numpy as np

from ._ffi import ffi, lib


class Error(Exception):
    """An error the library reported: str() is its one-line message
    ("key light 2: elevation 1.6 is out of range ..."), .status the name
    of its hfs_status ("invalid", "format", "nomem", "context", "gl",
    ...), .code the negative status number."""

    def __init__(self, message, status="invalid", code=-1):
        super().__init__(message)
        self.status = status
        self.code = code


def check(rc, err):
    """Raises Error for a non-zero status rc with err's message."""
    if rc:
        message = ffi.string(err.msg).decode("utf-8", "replace")
        status = ffi.string(lib().hfs_status_name(rc)).decode()
        raise Error(message or status, status, rc)


def new_error():
    return ffi.new("hfs_error *")


def number(name, value, lo=-math.inf, hi=math.inf):
    """A finite real in [lo, hi], else ValueError/TypeError naming it."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name}: expected a number, got {type(value).__name__}")
    x = float(value)
    if not math.isfinite(x) or x < lo or x > hi:
        raise ValueError(f"{name}: {value!r} is not a finite number in [{lo:g}, {hi:g}]")
    return x


def integer(name, value, lo, hi):
    """A whole number in [lo, hi], else ValueError/TypeError naming it."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name}: expected a whole number, got {type(value).__name__}")
    if not lo <= int(value) <= hi:
        raise ValueError(f"{name}: {value!r} is not a whole number in [{lo}, {hi}]")
    return int(value)


def float32_array(name, value, ndim=None, shape=None):
    """value as a C-contiguous float32 array (a copy when it must be), its
    dimensions checked; masked values refused (the caller handles masks)."""
    if isinstance(value, np.ma.MaskedArray):
        value = value.data
    try:
        a = np.ascontiguousarray(value, dtype=np.float32)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{name}: not an array of numbers ({e})") from None
    if ndim is not None and a.ndim != ndim:
        raise ValueError(f"{name}: expected a {ndim}-D array, got shape {a.shape}")
    if shape is not None:
        for k, n in enumerate(shape):
            if n is not None and a.shape[k] != n:
                raise ValueError(f"{name}: expected shape {_shape_text(shape)}, got {a.shape}")
    return a


def _shape_text(shape):
    return "(" + ", ".join("N" if n is None else str(n) for n in shape) + ")"


# Degrees to the library's radians, exactly as the command line converts
# them (runtime/core/scene_keys.c hfs_key_to_lib: x * (pi / 180)), so that
# the same numbers give the same bits.
def radians(x):
    return x * (3.14159265358979323846 / 180.0)


def degrees(x):
    return x * (180.0 / 3.14159265358979323846)
