"""Tests of V-HACD's targets from Python (decompose's max_concavity / hulls / min_opening, pack's
max_concavity and hulls=N) and of pack against the `hullpack pack` command, on generated meshes."""

import os
import subprocess
import tempfile
import unittest

import numpy as np

import hullpack
import meshes


class DecomposeTargets(unittest.TestCase):
    def test_hull_count_is_exact(self):
        v, f = meshes.l_block()
        for n in (1, 4):
            with self.subTest(hulls=n):
                hulls, report = hullpack.decompose(v, f, hulls=n, resolution=50000)
                self.assertEqual(len(hulls), n)
                self.assertTrue(report["target_reached"], report["target_note"])

    def test_max_concavity_is_reached(self):
        v, f = meshes.l_block()
        hulls, report = hullpack.decompose(v, f, max_concavity=0.05)
        self.assertTrue(report["target_reached"], report["target_note"])
        self.assertEqual(report["target_note"], "")
        self.assertGreaterEqual(report["attempts"], 1)
        self.assertGreaterEqual(len(hulls), 2)  # one hull over the L's notch sticks out too far
        self.assertLessEqual(report["concavity"], 0.05)

    def test_without_a_target_the_report_says_reached(self):
        v, f = meshes.box()
        _, report = hullpack.decompose(v, f)
        self.assertTrue(report["target_reached"])
        self.assertEqual(report["target_note"], "")

    def test_min_opening_keeps_an_open_box_empty(self):
        # A box without its top: the fill rule decides whether its inside is solid.
        v, f = meshes.box((0, 0, 0), (1, 1, 1))
        top = [i for i, t in enumerate(f) if all(v[t][:, 2] > 0.999)]
        f = np.delete(f, top, axis=0)
        inside = np.array([0.5, 0.5, 0.6])

        def covered(min_opening):
            hulls, _ = hullpack.decompose(v, f, min_opening=min_opening, compute_report=False)
            return any(meshes.inside_hull(hv, hf, inside) for hv, hf in hulls)

        self.assertFalse(covered(0.2))
        self.assertTrue(covered(0.0))  # parity vote only: the open box is filled

    def test_points_in_place_gives_the_same_hulls(self):
        v, f = meshes.l_block()
        copied, _ = hullpack.decompose(v, f, max_concavity=0.05, compute_report=False)
        in_place, _ = hullpack.decompose(v, f, max_concavity=0.05, compute_report=False,
                                         points_in_place=True)
        self.assertEqual(len(in_place), len(copied))
        for (av, af), (bv, bf) in zip(in_place, copied):
            np.testing.assert_array_equal(av, bv)
            np.testing.assert_array_equal(af, bf)
        with self.assertRaisesRegex(ValueError, "points_in_place"):
            hullpack.decompose(v, f, method="hacd", points_in_place=True)

    def test_bad_values_name_the_keyword(self):
        v, f = meshes.l_block()
        for kw, value in (("max_concavity", -0.1), ("max_concavity", 2.0),
                          ("max_concavity", float("nan")), ("hulls", -1), ("hulls", 100001),
                          ("min_opening", 1.5)):
            with self.subTest(kw=kw, value=value):
                with self.assertRaisesRegex(ValueError, kw):
                    hullpack.decompose(v, f, **{kw: value})
        with self.assertRaisesRegex(ValueError, "min_opening is a V-HACD keyword"):
            hullpack.decompose(v, f, method="hacd", min_opening=0.1)
        for kw, value in (("max_concavity", 2.0), ("hulls", 100001)):
            with self.subTest(method="hacd", kw=kw):
                with self.assertRaisesRegex(ValueError, kw):
                    hullpack.decompose(v, f, method="hacd", **{kw: value})


class PackTargets(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.obj = os.path.join(self.dir.name, "l_block.obj")
        meshes.write_obj(self.obj, *meshes.l_block())

    def tearDown(self):
        self.dir.cleanup()

    def out(self, name):
        return os.path.join(self.dir.name, name)

    def test_hulls_n_and_max_concavity(self):
        for hulls in (3, "3"):
            with self.subTest(hulls=hulls):
                r = hullpack.pack(self.obj, self.out("n%s.glb" % type(hulls).__name__),
                                  hulls=hulls)
                self.assertEqual(r["meshes"][0]["hull_count"], 3)
        r = hullpack.pack(self.obj, self.out("d.glb"), max_concavity=0.05)
        self.assertGreaterEqual(r["meshes"][0]["hull_count"], 2)
        self.assertLessEqual(r["meshes"][0]["hull_concavity"], 0.05)

    def test_bad_values_name_the_keyword(self):
        for value in (0, -2, 100001, "many", "", 2.5, True):
            with self.subTest(hulls=value):
                with self.assertRaisesRegex(ValueError, "hulls"):
                    hullpack.pack(self.obj, self.out("bad.glb"), hulls=value)
        for value in (-0.1, 2.0):
            with self.subTest(max_concavity=value):
                with self.assertRaisesRegex(ValueError, "max_concavity"):
                    hullpack.pack(self.obj, self.out("bad.glb"), max_concavity=value)
        with self.assertRaisesRegex(ValueError, "V-HACD options"):
            hullpack.pack(self.obj, self.out("bad.glb"), method="hacd", resolution=20000)
        self.assertFalse(os.path.exists(self.out("bad.glb")))

    def test_hacd_takes_the_count_the_budget_and_the_target(self):
        r = hullpack.pack(self.obj, self.out("h3.glb"), method="hacd", hulls=3)
        self.assertEqual(r["meshes"][0]["hull_count"], 3)
        r = hullpack.pack(self.obj, self.out("h1.glb"), method="hacd", max_hulls=1)
        self.assertEqual(r["meshes"][0]["hull_count"], 1)
        r = hullpack.pack(self.obj, self.out("hd.glb"), method="hacd", max_concavity=0.05)
        self.assertLessEqual(r["meshes"][0]["hull_concavity"], 0.05)

    @unittest.skipUnless(os.environ.get("HULLPACK_EXE"), "HULLPACK_EXE (the hullpack program) "
                         "is not set; ctest sets it")
    def test_same_bytes_as_the_command(self):
        exe = os.environ["HULLPACK_EXE"]
        cases = (
            ({}, []),
            ({"hulls": 4, "max_vertices": 16}, ["--hulls", "4", "--max-vertices", "16"]),
            # A coarser error than the default's: for this block, whose coordinates lie on a grid,
            # the default and --max-error 0.001 give the same file since format 1.2.
            ({"max_concavity": 0.05, "max_error": 0.01},
             ["--max-concavity", "0.05", "--max-error", "0.01"]),
            ({"method": "hacd", "fallback": True, "physics": "khr"},
             ["--method", "hacd", "--fallback", "--physics", "khr"]),
        )
        outputs = []
        for i, (kwargs, args) in enumerate(cases):
            with self.subTest(args=args):
                py_out, cli_out = self.out("py%d.glb" % i), self.out("cli%d.glb" % i)
                hullpack.pack(self.obj, py_out, **kwargs)
                subprocess.run([exe, "pack", self.obj, "-o", cli_out, "--quiet"] + args,
                               check=True, stdout=subprocess.DEVNULL)
                with open(py_out, "rb") as a, open(cli_out, "rb") as b:
                    outputs.append(a.read())
                    self.assertEqual(outputs[-1], b.read())
        # Each case's options reached the packer: no two files are the same.
        self.assertEqual(len(set(outputs)), len(cases))


if __name__ == "__main__":
    unittest.main()
