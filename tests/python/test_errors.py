"""Errors: what the library refuses raises hfshade.Error with its one-line
message and status; arguments of the wrong kind ValueError/TypeError
naming the argument; never a crash, never a NaN in an output."""
import unittest

import numpy as np

import util
import hfshade


class Errors(unittest.TestCase):
    def setUp(self):
        self.z = util.terrain(16, 20)

    def one_line(self, e):
        text = str(e)
        self.assertTrue(text and "\n" not in text, repr(text))

    def test_nan_height(self):
        z = self.z.copy()
        z[2, 3] = np.nan
        with self.assertRaises(hfshade.Error) as c:
            hfshade.render(z, backend="cpu")
        self.assertEqual(c.exception.status, "invalid")
        self.assertLess(c.exception.code, 0)
        self.assertIn("non-finite height at texel 43", str(c.exception))
        self.one_line(c.exception)

    def test_bad_shapes(self):
        for bad, what in ((self.z[0], "2-D"), (self.z[:1], "2x2"), (np.zeros((3, 4, 2)), "2-D")):
            with self.assertRaisesRegex(ValueError, f"^heights: .*{what}") as c:
                hfshade.render(bad, backend="cpu")
            self.one_line(c.exception)
        with self.assertRaisesRegex(ValueError, r"^heights: masked \(nodata\) values"):
            hfshade.render(np.ma.masked_less(self.z, 0.0), backend="cpu")
        with self.assertRaisesRegex(TypeError, "^heights: not an array of numbers"):
            hfshade.render([["a", "b"], ["c", "d"]], backend="cpu")
        with self.assertRaisesRegex(ValueError, r"^albedo_map: expected a 3-D array"):
            hfshade.render(self.z, backend="cpu", albedo_map=np.ones((16, 20)))
        with self.assertRaisesRegex(ValueError, r"^albedo_map: expected shape \(16, 20, 3\)"):
            hfshade.render(self.z, backend="cpu", albedo_map=np.ones((16, 21, 3)))
        with self.assertRaisesRegex(ValueError, r"^env: expected SH coefficients"):
            hfshade.render(self.z, backend="cpu", env=np.ones((4, 16)))

    def test_bad_backend_and_arguments(self):
        with self.assertRaisesRegex(ValueError, "^backend: 'vulkan' is not one of"):
            hfshade.Renderer("vulkan")
        with self.assertRaisesRegex(ValueError, "^backend: "):
            hfshade.svf(self.z, 1.0, backend="vulkan")
        with self.assertRaisesRegex(ValueError, "^key 1: elevation: 95"):
            hfshade.render(self.z, backend="cpu", key=[(0, 95, 2, 1)])
        with self.assertRaisesRegex(ValueError, "^key 2: expected"):
            hfshade.render(self.z, backend="cpu", key=[(0, 45, 2, 1), (1, 2)])
        with self.assertRaisesRegex(TypeError, "^dx: expected a number"):
            hfshade.render(self.z, backend="cpu", dx="2")
        with self.assertRaisesRegex(ValueError, "^quality: 'fast' is not a preset"):
            hfshade.render(self.z, backend="cpu", quality="fast")
        with self.assertRaisesRegex(ValueError, "^quality: 'speed' is not a quality field"):
            hfshade.render(self.z, backend="cpu", quality={"speed": 1})
        with self.assertRaisesRegex(ValueError, "^env_lights: needs an environment map"):
            hfshade.render(self.z, backend="cpu", env_lights="auto")

    def test_library_refusals(self):
        with self.assertRaises(hfshade.Error) as c:
            hfshade.render(self.z, backend="cpu", dx=-1.0)
        self.one_line(c.exception)
        with self.assertRaises(hfshade.Error) as c:
            hfshade.render(self.z, backend="cpu", quality={"k": 99})
        self.assertEqual(c.exception.status, "invalid")
        with self.assertRaises(hfshade.Error) as c:
            hfshade.render(self.z, backend="cpu", albedo=7.0)
        self.one_line(c.exception)

    def test_closed_renderer(self):
        r = hfshade.Renderer("cpu")
        r.close()
        r.close()
        with self.assertRaisesRegex(ValueError, "^renderer: closed"):
            r.render(self.z)

    def test_outputs_finite(self):
        z = self.z * 1e6
        img = hfshade.render(z, backend="cpu", key=[(10, 5, 1, 1e6)], env=np.ones(16))
        self.assertTrue(np.isfinite(img).all())


if __name__ == "__main__":
    util.main()
