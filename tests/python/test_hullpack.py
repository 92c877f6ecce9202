"""Tests of the Python module: run by ctest (tests/python/CMakeLists.txt) with PYTHONPATH set to
the build tree's python/ folder, or by hand:
    PYTHONPATH=build/python /usr/bin/python3 -m unittest discover -s tests/python -v
"""

import gc
import json
import os
import struct
import tempfile
import threading
import time
import unittest
import _thread

import numpy as np

import hullpack
import meshes


def required_extensions(path):
    """The extensionsRequired of a GLB file."""
    with open(path, "rb") as f:
        data = f.read()
    length = struct.unpack("<I", data[12:16])[0]
    return json.loads(data[20:20 + length]).get("extensionsRequired", [])


def rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


class Decompose(unittest.TestCase):
    def test_cube_is_one_hull(self):
        v, f = meshes.box()
        hulls, report = hullpack.decompose(v, f)
        self.assertEqual(len(hulls), 1)
        hv, hf = hulls[0]
        self.assertEqual(hv.shape[1], 3)
        self.assertEqual(hf.dtype, np.uint32)
        np.testing.assert_allclose(hv.min(axis=0), [0, 0, 0], atol=1e-6)
        np.testing.assert_allclose(hv.max(axis=0), [1, 1, 1], atol=1e-6)
        self.assertTrue(report["closed_input"])
        self.assertEqual(len(report["hulls"]), 1)
        self.assertGreater(report["volume_iou"], 0.95)

    def test_l_block_is_two_hulls(self):
        v, f = meshes.l_block()
        hulls, _ = hullpack.decompose(v, f)
        self.assertEqual(len(hulls), 2)

    def test_float32_and_int64_inputs_give_the_same_hulls(self):
        v, f = meshes.l_block()
        a, _ = hullpack.decompose(v, f, compute_report=False)
        b, _ = hullpack.decompose(v.astype(np.float32), f.astype(np.int64), compute_report=False)
        self.assertEqual(len(a), len(b))
        for (va, _), (vb, _) in zip(a, b):
            np.testing.assert_allclose(va, vb, atol=1e-5)

    def test_torus_hole_stays_empty(self):
        v, f = meshes.torus()
        hulls, _ = hullpack.decompose(v, f, resolution=50000)
        self.assertGreater(len(hulls), 2)
        for hv, hf in hulls:
            self.assertFalse(meshes.inside_hull(hv, hf, np.zeros(3)))
            self.assertFalse(meshes.inside_hull(hv, hf, np.array([0.5, 0.0, 0.0])))

    def test_progress_is_reported_and_false_cancels(self):
        v, f = meshes.torus()
        seen = []
        hullpack.decompose(v, f, resolution=100000, progress=lambda p, s: seen.append((p, s)))
        self.assertTrue(seen)
        self.assertTrue(all(0 <= p <= 100 for p, _ in seen))
        start = time.monotonic()
        with self.assertRaises(hullpack.Cancelled):
            hullpack.decompose(v, f, resolution=4000000, progress=lambda p, s: False)
        self.assertLess(time.monotonic() - start, 5)

    def test_ctrl_c_stops_a_run(self):
        v, f = meshes.torus()
        timer = threading.Timer(0.2, _thread.interrupt_main)
        start = time.monotonic()
        timer.start()
        try:
            with self.assertRaises(KeyboardInterrupt):
                hullpack.decompose(v, f, resolution=8000000)
        finally:
            timer.cancel()
        self.assertLess(time.monotonic() - start, 5)

    def test_callback_exception_propagates(self):
        v, f = meshes.torus()

        def boom(percent, stage):
            raise ZeroDivisionError("from the callback")

        with self.assertRaises(ZeroDivisionError):
            hullpack.decompose(v, f, resolution=400000, progress=boom)

    def test_bad_arrays_raise_value_error(self):
        v, f = meshes.box()
        cases = {
            "(n, 3), not (8, 2)": (v[:, :2], f),
            "(m, 3), not (12, 4)": (v, np.zeros((12, 4), np.uint32)),
            "not finite": (np.where(np.arange(24).reshape(8, 3) == 5, np.nan, v), f),
            "refers to vertex 8": (v, np.where(f == 7, 8, f).astype(np.uint32)),
            "refers to vertex -1": (v, np.where(f == 7, -1, f.astype(np.int64))),
            "integers": (v, f.astype(np.float64)),
            "numbers": (np.array([["a", "b", "c"]] * 8), f),
            "not (24,)": (v.ravel(), f),
        }
        for fragment, (vv, ff) in cases.items():
            with self.subTest(fragment):
                with self.assertRaises(ValueError) as caught:
                    hullpack.decompose(vv, ff)
                self.assertIn(fragment, str(caught.exception))
        with self.assertRaisesRegex(ValueError, "empty"):
            hullpack.decompose(v, np.zeros((0, 3), np.uint32))
        with self.assertRaisesRegex(ValueError, "resolution"):
            hullpack.decompose(v, f, resolution=5)
        with self.assertRaisesRegex(ValueError, "method must be 'vhacd' or 'hacd'"):
            hullpack.decompose(v, f, method="coacd")

    def test_help_explains_every_parameter(self):
        doc = hullpack.decompose.__doc__
        for name in ["vertices", "faces", "method", "preset", "resolution", "depth", "concavity",
                     "plane_downsampling", "convexhull_downsampling", "alpha", "beta", "gamma",
                     "pca", "mode", "max_vertices_per_hull", "min_volume_per_hull",
                     "max_convex_hulls", "max_distance", "num_threads", "compute_report",
                     "progress"]:
            self.assertIn("\n" + name + " :", doc)


class Stubs(unittest.TestCase):
    def test_stubs_declare_every_function_with_its_keywords(self):
        import ast
        import inspect
        path = os.path.join(os.path.dirname(hullpack.__file__), "_hullpack.pyi")
        with open(path) as f:
            tree = ast.parse(f.read())
        stubs = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
        for name in hullpack.__all__:
            obj = getattr(hullpack, name)
            if not callable(obj) or isinstance(obj, type):
                continue
            with self.subTest(name):
                self.assertIn(name, stubs)
                declared = [a.arg for a in stubs[name].args.args + stubs[name].args.kwonlyargs]
                # pybind11 writes the signature as the docstring's first line.
                signature = obj.__doc__.splitlines()[0]
                for arg in declared:
                    self.assertIn(arg + ":", signature)


class Codec(unittest.TestCase):
    def test_round_trip_within_half_a_step(self):
        v, f, n, uv = meshes.sphere()
        for bits in (8, 12, 16):
            with self.subTest(bits=bits):
                data = hullpack.encode(v, f, normals=n, uvs=uv, position_bits=bits, keep_order=True)
                self.assertIsInstance(data, bytes)
                out = hullpack.decode(data)
                self.assertEqual(out["vertices"].shape, v.shape)
                np.testing.assert_array_equal(out["faces"], f)
                step = (v.max(axis=0) - v.min(axis=0)).max() / ((1 << bits) - 1)
                self.assertLessEqual(np.abs(out["vertices"] - v).max(), step / 2 * 1.0001)
                self.assertEqual(out["uvs"].shape, uv.shape)
                self.assertEqual(out["normals"].shape, n.shape)
                info = hullpack.stream_info(data)
                self.assertEqual(info["vertices"], len(v))
                self.assertEqual(info["triangles"], len(f))
                self.assertEqual(info["bytes"]["total"], len(data))

    def test_max_compression_is_smaller_and_decodes_the_same(self):
        v, f, _, _ = meshes.sphere(80, 80)  # past 4096 vertices: format 1.3's adaptive low bits
        rng = np.random.default_rng(7)
        v = v + rng.uniform(-1e-3, 1e-3, v.shape)
        plain = hullpack.encode(v, f)
        small = hullpack.encode(v, f, max_compression=True)
        self.assertLess(len(small), len(plain))
        info = hullpack.stream_info(small)
        self.assertTrue(info["max_compression"])
        self.assertEqual(info["version"], "1.3")
        self.assertFalse(hullpack.stream_info(plain)["max_compression"])
        np.testing.assert_array_equal(hullpack.decode(small)["vertices"], hullpack.decode(plain)["vertices"])
        with self.assertRaises(ValueError):
            hullpack.encode(v, f, max_compression=True, fast_decode=True)

    def test_decode_reads_any_buffer(self):
        v, f, _, _ = meshes.sphere(8, 16)
        data = hullpack.encode(v, f, keep_degenerate_triangles=True)
        for buffer in (bytearray(data), memoryview(data), np.frombuffer(data, np.uint8)):
            self.assertEqual(hullpack.decode(buffer)["faces"].shape, f.shape)

    def test_degenerate_faces_are_left_out_unless_kept(self):
        v, f, _, _ = meshes.sphere(8, 16)  # the pole rows: two corners at one pole position
        corners = v[f]
        degenerate = (np.all(corners[:, 0] == corners[:, 1], axis=1) |
                      np.all(corners[:, 1] == corners[:, 2], axis=1) |
                      np.all(corners[:, 0] == corners[:, 2], axis=1))
        self.assertGreater(degenerate.sum(), 0)
        out = hullpack.decode(hullpack.encode(v, f))
        self.assertEqual(len(out["faces"]), len(f) - degenerate.sum())
        # Vertices only the left-out faces use go too.
        self.assertEqual(len(out["vertices"]), len(np.unique(f[~degenerate])))
        for keep in ({"keep_degenerate_triangles": True}, {"keep_order": True}):
            self.assertEqual(len(hullpack.decode(hullpack.encode(v, f, **keep))["faces"]), len(f))

    def test_hostile_streams_raise_value_error(self):
        v, f, _, _ = meshes.sphere(8, 16)
        data = bytearray(hullpack.encode(v, f))
        for cut in (0, 3, 10, len(data) // 2, len(data) - 1):
            with self.assertRaises(ValueError):
                hullpack.decode(bytes(data[:cut]))
        data[len(data) // 2] ^= 0x55
        with self.assertRaisesRegex(ValueError, "checksum"):
            hullpack.decode(bytes(data))
        with self.assertRaises(ValueError):
            hullpack.decode(b"not a stream at all")

    def test_bad_encode_input_raises_value_error(self):
        v, f, n, uv = meshes.sphere(8, 16)
        with self.assertRaisesRegex(ValueError, "uvs has 3 rows"):
            hullpack.encode(v, f, uvs=uv[:3])
        with self.assertRaisesRegex(ValueError, "position_bits"):
            hullpack.encode(v, f, position_bits=31)
        with self.assertRaisesRegex(ValueError, "not finite"):
            hullpack.encode(np.full_like(v, np.inf), f)


class Files(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.obj = os.path.join(self.dir.name, "torus.obj")
        meshes.write_obj(self.obj, *meshes.torus(24, 12))

    def tearDown(self):
        self.dir.cleanup()

    def test_pack_unpack_info(self):
        glb = os.path.join(self.dir.name, "torus.packed.glb")
        report = hullpack.pack(self.obj, glb, resolution=20000)
        self.assertGreater(report["meshes"][0]["hull_count"], 2)
        self.assertEqual(report["output_bytes"], os.path.getsize(glb))
        with self.assertRaisesRegex(ValueError, "exists"):
            hullpack.pack(self.obj, glb)
        out = os.path.join(self.dir.name, "back.obj")
        back = hullpack.unpack(glb, out)
        self.assertEqual(back["meshes"], 1)
        self.assertEqual(back["triangles"], 24 * 12 * 2)
        hulls = report["meshes"][0]["hull_count"]
        self.assertEqual(back["hulls"], hulls)
        # The OBJ holds the render mesh, then each hull as a closed mesh (object hull_N).
        summary = hullpack.info(out)
        self.assertEqual(summary["format"].lower(), "obj")
        self.assertEqual(summary["meshes"], 1 + hulls)
        self.assertGreater(summary["triangles"], back["triangles"] + 4 * hulls - 1)
        # OFF holds one mesh: the hulls go to a file of their own beside it.
        off = hullpack.unpack(glb, os.path.join(self.dir.name, "back.off"))
        self.assertTrue(off["hulls_output"].endswith("back.hulls.off"))
        self.assertEqual(hullpack.info(off["hulls_output"])["triangles"],
                         summary["triangles"] - back["triangles"])
        # .gltf: the JSON and its buffer beside it; read back like the GLB.
        gltf = hullpack.unpack(glb, os.path.join(self.dir.name, "back.gltf"))
        self.assertTrue(gltf["buffer_output"].endswith("back.bin"))
        self.assertEqual(hullpack.info(gltf["output"])["triangles"], back["triangles"])
        with self.assertRaises(OSError):
            hullpack.info(os.path.join(self.dir.name, "missing.obj"))

    def test_pack_in_parts(self):
        # A mesh above part_triangles becomes one glTF mesh per part, on one grid.
        glb = os.path.join(self.dir.name, "torus.parts.glb")
        report = hullpack.pack(self.obj, glb, resolution=20000, part_triangles=200)
        self.assertEqual(report["meshes"][0]["parts"], 3)
        back = hullpack.unpack(glb, os.path.join(self.dir.name, "parts.obj"))
        self.assertEqual(back["meshes"], 3)
        self.assertEqual(back["triangles"], 24 * 12 * 2)
        whole = hullpack.pack(self.obj, os.path.join(self.dir.name, "whole.glb"),
                              resolution=20000, part_triangles=0)
        self.assertEqual(whole["meshes"][0]["parts"], 1)
        with self.assertRaises(ValueError):
            hullpack.pack(self.obj, os.path.join(self.dir.name, "bad.glb"), part_triangles=-1)

    def test_pack_quantized_hulls(self):
        # Default hulls are floats (nothing required because of them); quantized_hulls stores the
        # same grid integers as bytes/shorts and requires KHR_mesh_quantization.
        floats = os.path.join(self.dir.name, "f.glb")
        quantized = os.path.join(self.dir.name, "q.glb")
        hullpack.pack(self.obj, floats, resolution=20000)
        hullpack.pack(self.obj, quantized, resolution=20000, quantized_hulls=True)
        self.assertNotIn("KHR_mesh_quantization", required_extensions(floats))
        self.assertIn("KHR_mesh_quantization", required_extensions(quantized))
        self.assertLess(os.path.getsize(quantized), os.path.getsize(floats))

    def test_pack_plain_animations(self):
        # Key frames are stored with EXT_meshopt_compression unless plain_animations is set.
        character = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                 "samples", "assets", "kenney_character.glb")
        compressed = os.path.join(self.dir.name, "c.glb")
        plain = os.path.join(self.dir.name, "p.glb")
        report = hullpack.pack(character, compressed, hulls="none")
        plain_report = hullpack.pack(character, plain, hulls="none", plain_animations=True)
        self.assertLess(report["key_frame_bytes_after"], report["key_frame_bytes_before"])
        self.assertEqual(plain_report["key_frame_bytes_after"],
                         plain_report["key_frame_bytes_before"])
        self.assertIn("EXT_meshopt_compression", required_extensions(compressed))
        self.assertNotIn("EXT_meshopt_compression", required_extensions(plain))
        self.assertLess(os.path.getsize(compressed), os.path.getsize(plain))
        self.assertEqual(hullpack.info(compressed)["animations"], 4)

    def test_pack_with_hacd(self):
        hacd = os.path.join(self.dir.name, "hacd.glb")
        vhacd = os.path.join(self.dir.name, "vhacd.glb")
        report = hullpack.pack(self.obj, hacd, method="hacd", max_vertices=8)["meshes"][0]
        self.assertGreater(report["hull_count"], 2)
        self.assertLessEqual(report["hull_vertices"], 8 * report["hull_count"])
        hullpack.pack(self.obj, vhacd, resolution=20000, max_vertices=8)
        with open(hacd, "rb") as a, open(vhacd, "rb") as b:
            self.assertNotEqual(a.read(), b.read())  # the method reached the decomposer
        with self.assertRaisesRegex(ValueError, "V-HACD options"):
            hullpack.pack(self.obj, vhacd + "2.glb", method="hacd", resolution=20000)
        with self.assertRaisesRegex(ValueError, "'vhacd' or 'hacd'"):
            hullpack.pack(self.obj, vhacd + "3.glb", method="coacd")

    def test_load_mesh_feeds_decompose_and_encode(self):
        mesh = hullpack.load_mesh(self.obj)
        self.assertEqual(mesh["vertices"].dtype, np.float32)
        self.assertEqual(mesh["faces"].shape, (24 * 12 * 2, 3))
        hulls, _ = hullpack.decompose(mesh["vertices"], mesh["faces"], resolution=20000)
        self.assertGreater(len(hulls), 2)
        self.assertGreater(len(hullpack.encode(mesh["vertices"], mesh["faces"])), 0)
        bad = os.path.join(self.dir.name, "bad.obj")
        with open(bad, "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n")
        with self.assertRaises(ValueError):
            hullpack.load_mesh(bad)

    def test_collision_writes_a_description(self):
        for fmt, ext in (("urdf", ".urdf"), ("mjcf", ".xml"), ("sdf", ".sdf")):
            with self.subTest(fmt):
                out = os.path.join(self.dir.name, fmt)
                r = hullpack.collision(self.obj, out, format=fmt, density=500, resolution=20000)
                self.assertTrue(r["description"].endswith("torus" + ext))
                self.assertTrue(all(os.path.exists(p) for p in r["files"]))
                self.assertGreater(r["hull_count"], 2)
                self.assertLessEqual(r["largest_hull_vertices"], 64)
                self.assertAlmostEqual(r["mass"], 500 * r["volume"])
        with self.assertRaisesRegex(ValueError, "format"):
            hullpack.collision(self.obj, self.dir.name, format="usd")


class Memory(unittest.TestCase):
    def test_memory_stays_flat_over_1000_calls(self):
        v, f = meshes.box()
        sv, sf, sn, _ = meshes.sphere(8, 16)

        def calls(n):
            for _ in range(n):
                hulls, _ = hullpack.decompose(v, f, resolution=10000, compute_report=False)
                data = hullpack.encode(sv, sf, normals=sn)
                hullpack.decode(data)
                hullpack.simplify(sv, sf, target_triangles=50)
                hullpack.decompose(v, f, method="hacd", compute_report=False)
                try:
                    hullpack.decompose(v[:, :2], f)
                except ValueError:
                    pass

        calls(100)
        gc.collect()
        before = rss_bytes()
        calls(1000)
        gc.collect()
        grown = rss_bytes() - before
        self.assertLess(grown, 1 << 20, "RSS grew by %d bytes over 1000 calls" % grown)


if __name__ == "__main__":
    unittest.main()
