"""The impasto Python module against the command line: a replay renders to the same PNG
bytes, a stroke painted from Python lands where it was sent and is conserved, a painting
survives a save, and the examples in docs/python.md run. Run by CTest with PYTHONPATH set to
the module's folder and IMPASTO_CLI to the impasto executable."""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import impasto

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
DEMO = os.path.join(SOURCE, "data", "strokes", "demo.dat")
CLI = os.environ["IMPASTO_CLI"]


class Module(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def path(self, name):
        return os.path.join(self.dir.name, name)

    def test_a_replay_renders_as_the_command_line_does(self):
        painting = impasto.replay(DEMO)
        painting.render_to(self.path("module.png"))
        subprocess.run([CLI, "-q", "replay", DEMO, "-o", self.path("cli.png"),
                        "--save", self.path("cli.impasto")], check=True)
        with open(self.path("module.png"), "rb") as a, open(self.path("cli.png"), "rb") as b:
            self.assertEqual(a.read(), b.read(), "the same PNG, byte for byte")
        self.assertEqual(painting.state_hash,
                         impasto.Painting.load(self.path("cli.impasto")).state_hash)
        image = painting.render()
        self.assertEqual(image.shape, (768, 1024, 3))
        self.assertEqual(image.dtype, np.float32)

    def test_a_stroke_lands_where_it_was_sent_and_is_conserved(self):
        p = impasto.Painting(200, 120, dpi=254)
        p.set_brush("round", size_mm=3.0, stiffness=0.5)
        p.load_brush({"Red Oxide": 1.0, "White": 1.0}, 40.0)
        x = np.linspace(2.0, 15.0, 60)
        p.stroke(np.column_stack([x, np.full_like(x, 6.0), np.full_like(x, 0.7)]))
        heights = p.heights()
        self.assertEqual(heights.shape, (120, 200))
        row = int(round(6.0 / p.cell_mm))
        self.assertGreater(heights[row, 50:140].mean(), heights[110:, :].mean() + 0.05)
        self.assertEqual(sorted(p.pigments), ["Red Oxide", "White"])
        wet = p.wet()
        self.assertAlmostEqual(float(wet.sum()) * p.cell_mm ** 2,
                               p.totals()["canvas"]["volume_mm3"], delta=1e-3)
        loaded = p.totals()["loaded"]["volume_mm3"]
        on_brush = p.totals()["brush"]["volume_mm3"]
        self.assertAlmostEqual(p.totals()["canvas"]["volume_mm3"] + on_brush, loaded,
                               delta=1e-5 * loaded)
        red = p.pigment("Red Oxide")
        self.assertGreater(red.sum(), 0.0)
        with self.assertRaises(KeyError):
            p.pigment("Unobtainium")
        self.assertTrue(p.undo())
        self.assertEqual(p.wet().sum(), 0.0)

    def test_the_paint_models_constants_are_read_and_set_by_name(self):
        p = impasto.Painting(64, 64)
        self.assertEqual(p.params["deposit_share"], 0.25)
        p.params = {"long_step_share": 0.0, "drag": 0.3}
        self.assertEqual(p.params["long_step_share"], 0.0)
        self.assertEqual(p.params["drag"], 0.3)
        with self.assertRaises(KeyError):
            p.params = {"viscosity": 1.0}
        with self.assertRaises(RuntimeError):
            p.params = {"drag": 2.0}
        self.assertEqual(p.params["drag"], 0.3, "a refused value changes nothing")

    def test_a_painting_survives_a_save(self):
        p = impasto.Painting(96, 64)
        p.load_brush({"Blue Red Shade": 1.0}, 20.0)
        p.stroke([[2.0, 3.0, 0.8], [8.0, 5.0, 0.8], [12.0, 4.0, 0.0]])
        p.save(self.path("a.impasto"))
        again = impasto.Painting.load(self.path("a.impasto"))
        self.assertEqual(again.state_hash, p.state_hash)
        self.assertEqual(again.undo_depth, p.undo_depth)

    def test_compare_finds_a_stroke_and_nothing_else(self):
        base = impasto.Painting(128, 96)
        more = impasto.Painting(128, 96)
        more.load_brush({"Red Oxide": 1.0}, 40.0)
        more.stroke([[5.0 + 0.5 * i, 8.0, 0.7] for i in range(25)] + [[17.5, 8.0, 0.0]])
        same = impasto.compare(more, more)
        self.assertEqual(same["de00_max"], 0.0)
        self.assertEqual(same["height_mm_max"], 0.0)
        found = impasto.compare(base, more)
        self.assertGreater(found["de00_max"], 10.0)
        self.assertGreater(found["height_mm_max"], 0.1)
        de00 = found["de00"]
        self.assertEqual(de00.shape, (96, 128))
        row = int(round(8.0 / more.cell_mm))
        self.assertGreater(de00[row, 40:90].mean(), 10.0)
        self.assertLess(de00[85:, :].max(), 0.5)

    def test_bad_input_says_what_is_wrong(self):
        p = impasto.Painting(64, 64)
        with self.assertRaises(ValueError):
            p.stroke([[1.0, 2.0]])
        with self.assertRaises(ValueError):
            p.load_brush({"White": 1.0}, 5.0, body="gravy")
        with self.assertRaises(RuntimeError):
            p.load_brush({"Unobtainium Blue": 1.0}, 5.0)
        with self.assertRaises(RuntimeError):
            impasto.Painting.load(self.path("missing.impasto"))
        self.assertIn("White", impasto.pigments())

    def test_the_fit_gives_back_the_pigments_its_mixtures_were_made_of(self):
        # data/measurements/synthetic_mixtures.csv: mixtures computed from the bundled paints.
        fit = impasto.fit_pigments(os.path.join(SOURCE, "data", "measurements",
                                                "synthetic_mixtures.csv"))
        names = [p["name"] for p in fit["pigments"]]
        self.assertIn("Red", names)
        self.assertLess(max(r["max_reflectance"] for r in fit["residuals"]), 1e-3)
        white = impasto.pigment("White")
        self.assertEqual(white["K"].shape, white["wavelength_nm"].shape)
        red_fit = next(p for p in fit["pigments"] if p["name"] == "Red")
        red = impasto.pigment("Red")
        grid = red_fit["wavelength_nm"]
        ratio_fit = red_fit["K"] / red_fit["S"]
        ratio = np.interp(grid, red["wavelength_nm"], red["K"] / red["S"])
        self.assertLess(np.max(np.abs(ratio_fit - ratio) / ratio), 0.02, "K/S of the source")

    def test_the_type_stubs_name_what_the_module_has(self):
        import ast
        with open(os.path.join(SOURCE, "app", "python", "impasto.pyi")) as f:
            stubs = ast.parse(f.read())
        functions = {n.name for n in stubs.body if isinstance(n, ast.FunctionDef)}
        painting = next(n for n in stubs.body if isinstance(n, ast.ClassDef) and n.name == "Painting")
        methods = {n.name for n in painting.body if isinstance(n, ast.FunctionDef)} - {"__init__"}
        self.assertEqual(functions, {n for n in dir(impasto) if not n.startswith("_")} - {"Painting"})
        self.assertEqual(methods, {n for n in dir(impasto.Painting) if not n.startswith("_")})

    def test_the_documented_examples_run(self):
        examples = os.path.join(SOURCE, "docs", "examples")
        for name in sorted(os.listdir(examples)):
            if name.endswith(".py"):
                subprocess.run([sys.executable, os.path.join(examples, name), self.dir.name],
                               check=True, env=dict(os.environ))


if __name__ == "__main__":
    unittest.main(verbosity=2)
