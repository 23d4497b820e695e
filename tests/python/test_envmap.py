"""hfshade.decompose_env agrees with `hfshade envmap decompose` (the lines
it prints: each light's key line and the residual's SH), and
project_env with the decomposition's residual SH."""
import re

import numpy as np

import util
import hfshade


def parse(text):
    keys, sh = [], {}
    for line in text.splitlines():
        if line.startswith("key = "):
            keys.append(line[len("key = "):].split(","))
        m = re.match(r"env-sh-([rgb]) = (.*)", line)
        if m:
            sh[m.group(1)] = m.group(2).split(",")
    return keys, [sh[c] for c in "rgb"]


class EnvMap(util.TempDir):
    def check(self, m, *flags, **kwargs):
        util.write_pfm(self.path("sky.pfm"), m)
        keys, sh = parse(util.run_cli("envmap", "decompose", self.path("sky.pfm"), *flags))
        before = m.copy()
        lights, residual = hfshade.decompose_env(m, **kwargs)
        self.assertTrue(util.same_bits(m, before), "the input map was modified")
        self.assertEqual(len(lights), len(keys))
        for light, key in zip(lights, keys):
            self.assertIsInstance(light, hfshade.EnvLight)
            self.assertEqual(["%.4f" % light.azimuth, "%.4f" % light.elevation,
                              "%.4f" % light.radius], key[:3])
            rgb = light.radiance
            text = ["%.9g" % rgb[0]] if rgb[0] == rgb[1] == rgb[2] else ["%.9g" % c for c in rgb]
            self.assertEqual(text, key[3:])
        got_sh = hfshade.project_env(residual)
        self.assertEqual(got_sh.shape, (3, 16))
        self.assertEqual([["%.4g" % v for v in row] for row in got_sh], sh)
        self.assertEqual(residual.shape, m.shape)
        self.assertEqual(residual.dtype, np.float32)
        return lights, residual

    def test_default_options(self):
        m = util.sky(64, 128, sun=(40, 12), sun_value=2000.0)
        lights, residual = self.check(m)
        self.assertEqual(len(lights), 1)
        self.assertLess(float(residual.max()), 2000.0)
        self.assertAlmostEqual(lights[0].energy[0] / lights[0].radiance[0],
                               lights[0].energy[1] / lights[0].radiance[1], places=9)

    def test_options_and_two_suns(self):
        m = util.sky(64, 128, sun=(40, 12), sun_value=2000.0)
        m[20:22, 100:102] = (900.0, 900.0, 900.0)
        self.check(m, "--max-lights", 3, "--min-share", 0.01, "--contrast", 3,
                   "--max-radius", 20, max_lights=3, min_share=0.01, contrast=3,
                   max_radius=20)
        lights, _ = self.check(m, "--max-lights", 0, max_lights=0)
        self.assertEqual(lights, [])

    def test_lights_render_as_keys(self):
        m = util.sky(64, 128, sun=(40, 12), sun_value=2000.0)
        lights, residual = hfshade.decompose_env(m)
        z = util.terrain()
        img = hfshade.render(z, backend="cpu", env=residual, key=[l[:4] for l in lights])
        self.assertTrue(np.isfinite(img).all())

    def test_bad_maps(self):
        m = util.sky()
        m[3, 7, 1] = np.nan
        with self.assertRaisesRegex(hfshade.Error, r"^env_map: texel \(7, 3\) G is NaN$"):
            hfshade.decompose_env(m)
        with self.assertRaisesRegex(hfshade.Error, r"^env_map: texel \(7, 3\) G is NaN$"):
            hfshade.project_env(m)
        with self.assertRaisesRegex(ValueError, r"^env_map: expected an \(h, w, 3\) RGB map"):
            hfshade.decompose_env(np.zeros((8, 16, 4)))
        with self.assertRaisesRegex(ValueError, "^max_lights: "):
            hfshade.decompose_env(util.sky(), max_lights=9)


if __name__ == "__main__":
    util.main()
