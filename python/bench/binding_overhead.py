#!/usr/bin/env python3
"""The cost of the Python binding over the bare C++ call, per mesh, in one process.

For each mesh: hullpack.decompose (V-HACD, one thread), hullpack.encode and hullpack.decode are
timed from Python, and the same library calls on the same arrays are timed inside C++
(hullpack._hullpack._decompose_seconds / _codec_seconds), alternating which goes first, `--repeats` times (encode and
decode averaged over as many calls as fill 50 ms each time), after one warm-up call, in
process CPU time (all threads; steadier than wall time on a shared machine); the overhead is median(Python) / median(C++) - 1. Python's side includes reading the arrays, the
worker thread and the Ctrl-C polling, and building the result arrays and dicts (decompose also
computes its error report in both).

    PYTHONPATH=build/python /usr/bin/python3 python/bench/binding_overhead.py \
        /work/shared/corpus --repeats 5 [--resolution 100000] [--only bunny,cup]
"""

import argparse
import os
import statistics
import sys
import time

import hullpack
from hullpack import _hullpack


def timed(f, calls):
    start = time.process_time()
    for _ in range(calls):
        f()
    return (time.process_time() - start) / calls


def calls_for(f, budget=0.05):
    """How many calls of f take about `budget` CPU seconds (at least 1): fast calls are averaged
    over many, so the clock's granularity and one-off costs do not dominate."""
    one = timed(f, 1)
    return max(1, min(10000, int(budget / max(one, 1e-7))))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("folder", help="folder of .obj meshes (the corpus)")
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--resolution", type=int, default=100000)
    ap.add_argument("--only", default="", help="comma-separated mesh names")
    args = ap.parse_args()
    only = set(filter(None, args.only.split(",")))
    names = sorted(f for f in os.listdir(args.folder) if f.endswith(".obj"))
    if only:
        names = [n for n in names if n[:-4] in only]
    print("%-16s %9s %10s %10s %8s %10s %10s %8s %10s %10s %8s" % (
        "mesh", "triangles", "vhacd py", "vhacd c++", "over", "enc py", "enc c++", "over",
        "dec py", "dec c++", "over"))
    totals = {"vhacd": [0, 0], "enc": [0, 0], "dec": [0, 0]}
    for name in names:
        mesh = hullpack.load_mesh(os.path.join(args.folder, name))
        v, f = mesh["vertices"], mesh["faces"]
        py_d, cpp_d, py_e, cpp_e, py_x, cpp_x = [], [], [], [], [], []
        stream = hullpack.encode(v, f)
        decompose = lambda: hullpack.decompose(v, f, resolution=args.resolution, num_threads=1)
        decompose()  # warm-up: first-call costs (page faults, lazy binding) are not the binding's
        hullpack.decode(stream)
        codec_calls = calls_for(lambda: hullpack.encode(v, f))
        for repeat in range(args.repeats):
            def python_side():
                py_d.append(timed(decompose, 1))
                py_e.append(timed(lambda: hullpack.encode(v, f), codec_calls))
                py_x.append(timed(lambda: hullpack.decode(stream), codec_calls))

            def cpp_side():
                cpp_d.append(_hullpack._decompose_seconds(v, f, args.resolution, 1, False))
                both = [_hullpack._codec_seconds(v, f) for _ in range(codec_calls)]
                cpp_e.append(sum(e for e, _ in both) / codec_calls)
                cpp_x.append(sum(x for _, x in both) / codec_calls)

            # Alternate which side runs first: caches and clock boosts favour neither.
            for side in ((python_side, cpp_side) if repeat % 2 else (cpp_side, python_side)):
                side()
        row = []
        for key, p, c in (("vhacd", py_d, cpp_d), ("enc", py_e, cpp_e), ("dec", py_x, cpp_x)):
            mp, mc = statistics.median(p), statistics.median(c)
            totals[key][0] += mp
            totals[key][1] += mc
            row += [mp, mc, 100 * (mp / mc - 1)]
        print("%-16s %9d %9.4fs %9.4fs %7.1f%% %9.5fs %9.5fs %7.1f%% %9.5fs %9.5fs %7.1f%%" % (
            (name[:-4], len(f)) + tuple(row)))
        sys.stdout.flush()
    print("%-16s %9s" % ("sum of medians", ""), end="")
    for key in ("vhacd", "enc", "dec"):
        p, c = totals[key]
        print(" %9.4fs %9.4fs %7.1f%%" % (p, c, 100 * (p / c - 1)), end="")
    print()


if __name__ == "__main__":
    main()
