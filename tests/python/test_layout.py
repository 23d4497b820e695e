"""The cdef's structs laid out as the C compiler lays out the headers
(tests/python_layout.c prints them; its path: HFSHADE_LAYOUT), its
constants the headers', and the module's major version the library's."""
import os
import subprocess
import unittest

import util  # noqa: F401 (skips without numpy/cffi)
import hfshade
from hfshade import _ffi


class Layout(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        out = subprocess.run([os.environ["HFSHADE_LAYOUT"]], capture_output=True, text=True,
                             check=True).stdout
        cls.sizes, cls.fields, cls.consts = {}, {}, {}
        for line in out.splitlines():
            name, *rest = line.split()
            if name.startswith("#"):
                cls.consts[name[1:]] = int(rest[0])
            elif "." in name:
                s, f = name.split(".")
                cls.fields.setdefault(s, {})[f] = (int(rest[0]), int(rest[1]))
            else:
                cls.sizes[name] = int(rest[0])

    def test_every_struct_of_the_cdef_is_printed(self):
        self.assertEqual(set(_ffi.STRUCTS), set(self.sizes))

    def test_sizes_and_offsets(self):
        ffi = _ffi.ffi
        for s in _ffi.STRUCTS:
            with self.subTest(struct=s):
                self.assertEqual(ffi.sizeof(s), self.sizes[s], f"sizeof({s})")
                cdef = {f for f, _ in ffi.typeof(s).fields}
                self.assertEqual(cdef, set(self.fields[s]), f"{s}: fields")
                for f, (off, size) in self.fields[s].items():
                    self.assertEqual(ffi.offsetof(s, f), off, f"offsetof({s}, {f})")
                    ftype = dict(ffi.typeof(s).fields)[f].type
                    self.assertEqual(ffi.sizeof(ftype), size, f"sizeof({s}.{f})")

    def test_constants(self):
        lib, gis = _ffi.lib(), _ffi.gis_lib()
        for name, value in self.consts.items():
            with self.subTest(constant=name):
                if name == "HFS_VERSION_MAJOR":
                    self.assertEqual(value, hfshade.MAJOR)
                elif name.startswith("HFS_GIS_"):
                    self.assertEqual(getattr(gis, name), value)
                elif name.startswith(("HFS_BACKEND", "HFS_VIS", "HFS_PRECISION")):
                    self.assertEqual(getattr(lib, name), value)
                elif name in ("HFS_SH_COEFFS",):
                    self.assertEqual(_ffi.ffi.sizeof("double[16]") // 8, value)
                elif name in ("HFS_MAX_KEY_LIGHTS", "HFS_ENV_MAX_LIGHTS"):
                    self.assertEqual(len(_ffi.ffi.new("hfs_lighting *").key), value)
                elif name == "HFS_MAX_LOCAL_LIGHTS":
                    self.assertEqual(len(_ffi.ffi.new("hfs_lighting *").local), value)

    def test_version(self):
        self.assertEqual(hfshade.library_version(), os.environ["HFSHADE_VERSION"])
        self.assertEqual(hfshade.__version__, os.environ["HFSHADE_VERSION"])


if __name__ == "__main__":
    util.main()
