"""Tests of hullpack.decompose(method="hacd") and hullpack.simplify, on meshes generated here."""

import threading
import time
import unittest
import _thread

import numpy as np

import hullpack
import meshes


class Hacd(unittest.TestCase):
    def test_cube_is_one_hull(self):
        v, f = meshes.box()
        hulls, report = hullpack.decompose(v, f, method="hacd", num_threads=1)
        self.assertEqual(len(hulls), 1)
        hv, hf = hulls[0]
        self.assertEqual(hv.dtype, np.float64)
        self.assertEqual(hf.dtype, np.uint32)
        np.testing.assert_allclose(hv.min(axis=0), [0, 0, 0], atol=1e-6)
        np.testing.assert_allclose(hv.max(axis=0), [1, 1, 1], atol=1e-6)
        self.assertAlmostEqual(meshes.volume(hv, hf), 1.0, places=6)
        self.assertEqual(len(report["hulls"]), 1)
        self.assertGreater(report["volume_iou"], 0.95)

    def test_two_boxes_joined_by_a_bar_give_three_hulls(self):
        v, f = meshes.dumbbell()
        hulls, _ = hullpack.decompose(v, f, method="hacd", preset="recommended",
                                      compute_report=False)
        self.assertEqual(len(hulls), 3)
        # No hull spans the gap beside the bar.
        for hv, hf in hulls:
            self.assertFalse(meshes.inside_hull(hv, hf, np.array([3.0, 1.6, 1.0])))
            self.assertFalse(meshes.inside_hull(hv, hf, np.array([3.0, 1.0, 0.4])))

    def test_keywords_reach_the_library(self):
        v, f = meshes.dumbbell()
        # The three boxes only touch (no shared vertices): one hull needs them connected.
        hulls, _ = hullpack.decompose(v, f, method="hacd", preset="recommended", concavity=1e7,
                                      min_clusters=1, compute_report=False)
        self.assertEqual(len(hulls), 3)
        hulls, _ = hullpack.decompose(v, f, method="hacd", preset="recommended", concavity=1e7,
                                      min_clusters=1, connect_distance=1e7, compute_report=False)
        self.assertEqual(len(hulls), 1)
        cube_v, cube_f = meshes.box()
        hulls, _ = hullpack.decompose(cube_v, cube_f, method="hacd", min_clusters=4,
                                      compute_report=False)
        self.assertEqual(len(hulls), 4)
        hulls, _ = hullpack.decompose(v, f, method="hacd", preset="recommended",
                                      max_vertices_per_hull=6, compute_report=False)
        self.assertTrue(all(len(hv) <= 6 for hv, _ in hulls))

    def test_progress_and_cancel(self):
        v, f = meshes.torus()
        seen = []
        hullpack.decompose(v, f, method="hacd", target_triangles=0,
                           progress=lambda p, s: seen.append((p, s)))
        self.assertTrue(seen)
        self.assertTrue(all(0 <= p <= 100 for p, _ in seen))
        with self.assertRaises(hullpack.Cancelled):  # 0.1 to 0.3 s of work
            hullpack.decompose(v, f, method="hacd", target_triangles=0, progress=lambda p, s: False)

    def test_ctrl_c_stops_a_run(self):
        v, f = meshes.torus(120, 48)  # 3 s of clustering when not stopped
        timer = threading.Timer(0.1, _thread.interrupt_main)
        start = time.monotonic()
        timer.start()
        try:
            with self.assertRaises(KeyboardInterrupt):
                hullpack.decompose(v, f, method="hacd", target_triangles=0, compute_report=False)
        finally:
            timer.cancel()
        self.assertLess(time.monotonic() - start, 1.5)

    def test_hacd_hull_count_budget_and_target(self):
        v, f = meshes.l_block()
        hulls, report = hullpack.decompose(v, f, method="hacd", hulls=3)
        self.assertEqual(len(hulls), 3)
        self.assertTrue(report["target_reached"])
        hulls, _ = hullpack.decompose(v, f, method="hacd", max_convex_hulls=1)
        self.assertEqual(len(hulls), 1)
        hulls, report = hullpack.decompose(v, f, method="hacd", max_concavity=0.02)
        self.assertEqual(report["target_reached"], report["concavity"] <= 0.02)
        _, report = hullpack.decompose(v, f, method="hacd", hulls=100000)
        self.assertFalse(report["target_reached"])
        self.assertIn("could be clustered into only", report["target_note"])

    def test_keyword_of_the_other_method_raises_value_error(self):
        v, f = meshes.box()
        cases = [
            ("hacd", {"resolution": 100000}, 'resolution is a V-HACD keyword (method="vhacd")'),
            ("hacd", {"max_distance": 0.01}, 'max_distance is a V-HACD keyword'),
            ("hacd", {"mode": "voxel"}, 'mode is a V-HACD keyword'),
            ("vhacd", {"min_clusters": 2}, 'min_clusters is a HACD keyword (method="hacd")'),
            ("vhacd", {"target_triangles": 500}, 'target_triangles is a HACD keyword'),
            ("hacd", {"preset": "high"}, "'default' or 'recommended'"),
            ("vhacd", {"preset": "recommended"}, "'default', 'high' or 'pack'"),
            ("hacd", {"concavity": -1.0}, "concavity must be in [0, 1e7]"),
            ("hacd", {"scale_factor": 0.5}, "scale_factor"),
            ("hacd", {"min_clusters": 0}, "min_clusters"),
            ("hacd", {"connect_distance": float("nan")}, "connect_distance"),
            ("hacd", {"min_clusters": -1}, "min_clusters must be a non-negative integer"),
            ("vhacd", {"resolution": -5}, "resolution must be a non-negative integer"),
        ]
        for method, kwargs, fragment in cases:
            with self.subTest(method=method, **{k: str(x) for k, x in kwargs.items()}):
                with self.assertRaises(ValueError) as caught:
                    hullpack.decompose(v, f, method=method, **kwargs)
                self.assertIn(fragment, str(caught.exception))
        with self.assertRaisesRegex(ValueError, "'vhacd' or 'hacd', not 'coacd'"):
            hullpack.decompose(v, f, method="coacd")

    def test_bad_arrays_raise_value_error(self):
        v, f = meshes.box()
        with self.assertRaisesRegex(ValueError, "refers to vertex 8"):
            hullpack.decompose(v, np.where(f == 7, 8, f).astype(np.uint32), method="hacd")
        with self.assertRaisesRegex(ValueError, "not finite"):
            hullpack.decompose(np.where(v == 1, np.inf, v), f, method="hacd")
        with self.assertRaisesRegex(ValueError, "empty"):
            hullpack.decompose(v, np.zeros((0, 3), np.uint32), method="hacd")

    def test_help_explains_every_parameter(self):
        doc = hullpack.decompose.__doc__
        for name in ["method", "preset", "concavity", "max_vertices_per_hull", "num_threads",
                     "target_triangles", "scale_factor", "small_cluster_threshold",
                     "add_face_points", "add_extra_dist_points", "invert_input_faces",
                     "min_clusters", "connect_distance", "volume_weight", "compacity_weight",
                     "flat_region_threshold", "computation_weight"]:
            self.assertIn("\n" + name + " :", doc)
        doc = hullpack.simplify.__doc__
        for name in ["vertices", "faces", "target_triangles", "target_error", "lock_boundary",
                     "progress"]:
            self.assertIn("\n" + name + " :", doc)


class Simplify(unittest.TestCase):
    def test_flat_grid_becomes_two_triangles(self):
        v, f = meshes.grid(20)
        sv, sf, info = hullpack.simplify(v, f, target_triangles=2)
        self.assertEqual(sf.shape, (2, 3))
        self.assertEqual(sv.dtype, np.float64)
        self.assertEqual(sf.dtype, np.uint32)
        # The square's four corners remain and the area is kept.
        corners = {tuple(p) for p in np.round(sv, 9)}
        self.assertEqual(corners, {(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)})
        a, b, c = sv[sf[:, 0]], sv[sf[:, 1]], sv[sf[:, 2]]
        normals = np.cross(b - a, c - a)
        self.assertAlmostEqual(float(np.linalg.norm(normals, axis=1).sum()) / 2, 1.0)
        self.assertTrue(np.all(normals[:, 2] > 0))  # the winding is kept
        np.testing.assert_array_equal(v[info["point_source"]], sv)
        self.assertEqual(info["triangle_source"].shape, (2,))
        self.assertTrue(np.all(info["triangle_source"] < len(f)))
        self.assertAlmostEqual(info["error"], 0.0)

    def test_sphere_to_ten_percent_keeps_its_volume(self):
        v, f = meshes.closed_sphere(48, 96)  # 9024 triangles -> 902
        target = len(f) // 10
        sv, sf, info = hullpack.simplify(v.astype(np.float32), f.astype(np.int64),
                                         target_triangles=target)
        self.assertLessEqual(len(sf), target)
        self.assertGreater(len(sf), target * 0.9)
        before, after = meshes.volume(v, f), meshes.volume(sv, sf)
        self.assertLess(abs(after - before) / before, 0.01, "volume %g -> %g" % (before, after))
        self.assertEqual(info["point_source"].shape, (len(sv),))
        self.assertGreater(info["error"], 0.0)

    def test_target_error_stops_early(self):
        v, f = meshes.closed_sphere()
        _, coarse, e_coarse = hullpack.simplify(v, f, target_error=1e-2)
        _, fine, e_fine = hullpack.simplify(v, f, target_error=1e-4)
        self.assertLess(len(coarse), len(fine))
        self.assertLess(len(fine), len(f))
        self.assertLessEqual(e_fine["error"], 1e-4)

    def test_lock_boundary_keeps_an_open_border(self):
        v, f = meshes.grid(10)
        v = v.copy()
        v[:, 2] = 0.1 * np.sin(3 * v[:, 0]) * np.cos(2 * v[:, 1])  # curved, so collapses cost
        border = (v[:, 0] == 0) | (v[:, 0] == 1) | (v[:, 1] == 0) | (v[:, 1] == 1)
        sv, _, info = hullpack.simplify(v, f, target_triangles=20, lock_boundary=True)
        kept = set(info["point_source"].tolist())
        self.assertTrue(set(np.nonzero(border)[0].tolist()) <= kept)

    def test_bad_input_raises_value_error(self):
        v, f = meshes.grid(4)
        cases = {
            "(n, 3), not (25, 2)": ((v[:, :2], f), {"target_triangles": 2}),
            "refers to vertex 25": ((v, np.where(f == 0, 25, f).astype(np.uint32)),
                                    {"target_triangles": 2}),
            "not finite": ((np.where(v == 1, np.nan, v), f), {"target_triangles": 2}),
            "integers": ((v, f.astype(np.float32)), {"target_triangles": 2}),
            "empty": ((v, np.zeros((0, 3), np.uint32)), {"target_triangles": 2}),
            "set target_triangles or target_error": ((v, f), {}),
            "target_error must be in [0, 1]": ((v, f), {"target_error": 2.0}),
            "target_triangles must be a non-negative": ((v, f), {"target_triangles": -2}),
        }
        for fragment, (args, kwargs) in cases.items():
            with self.subTest(fragment):
                with self.assertRaises(ValueError) as caught:
                    hullpack.simplify(*args, **kwargs)
                self.assertIn(fragment, str(caught.exception))

    def test_cancel(self):
        v, f = meshes.closed_sphere(100, 200)  # 0.1 to 0.3 s of work: the callback runs first
        with self.assertRaises(hullpack.Cancelled):
            hullpack.simplify(v, f, target_triangles=10, progress=lambda p, s: False)


if __name__ == "__main__":
    unittest.main()
