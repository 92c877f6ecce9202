"""Generated test meshes as numpy arrays (closed, outward-facing)."""

import numpy as np


def box(lo=(0, 0, 0), hi=(1, 1, 1)):
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    v = np.array([[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
                  [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]], dtype=np.float64)
    f = np.array([[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
                  [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]], dtype=np.uint32)
    return v, f


def prism(polygon, height):
    """Extrudes a counter-clockwise polygon that is star-shaped from its vertex 0 along z."""
    n = len(polygon)
    v = np.array([(x, y, 0.0) for x, y in polygon] + [(x, y, height) for x, y in polygon])
    f = []
    for i in range(1, n - 1):
        f.append([0, i + 1, i])              # bottom, facing -z
        f.append([n, n + i, n + i + 1])      # top, facing +z
    for i in range(n):
        j = (i + 1) % n
        f.append([i, j, n + j])
        f.append([i, n + j, n + i])
    return v, np.array(f, dtype=np.uint32)


def l_block():
    """An L: a 2 x 1 bar and a 1 x 1 block on one end, 1 thick; fanned from the inner corner."""
    return prism([(1, 1), (1, 2), (0, 2), (0, 0), (2, 0), (2, 1)], 1.0)


def torus(rings=40, sides=16, major=1.0, minor=0.3):
    u = np.linspace(0, 2 * np.pi, rings, endpoint=False)[:, None]
    w = np.linspace(0, 2 * np.pi, sides, endpoint=False)[None, :]
    x = (major + minor * np.cos(w)) * np.cos(u)
    y = (major + minor * np.cos(w)) * np.sin(u)
    z = minor * np.sin(w) * np.ones_like(u)
    v = np.stack([x, y, z], axis=-1).reshape(-1, 3)
    f = []
    for i in range(rings):
        for j in range(sides):
            a = i * sides + j
            b = ((i + 1) % rings) * sides + j
            c = ((i + 1) % rings) * sides + (j + 1) % sides
            d = i * sides + (j + 1) % sides
            f += [[a, b, c], [a, c, d]]
    return v, np.array(f, dtype=np.uint32)


def sphere(rings=24, segments=48):
    """A UV sphere of radius 1 with normals and texture coordinates."""
    pts, uvs = [], []
    for i in range(rings + 1):
        t = np.pi * i / rings
        for j in range(segments + 1):
            p = 2 * np.pi * j / segments
            pts.append([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)])
            uvs.append([j / segments, i / rings])
    f = []
    for i in range(rings):
        for j in range(segments):
            a = i * (segments + 1) + j
            b = a + segments + 1
            f += [[a, b, a + 1], [a + 1, b, b + 1]]
    v = np.array(pts, dtype=np.float32)
    return v, np.array(f, dtype=np.uint32), v.copy(), np.array(uvs, dtype=np.float32)


def write_obj(path, v, f):
    with open(path, "w") as out:
        for p in v:
            out.write("v %.9g %.9g %.9g\n" % tuple(p))
        for t in f:
            out.write("f %d %d %d\n" % tuple(int(i) + 1 for i in t))


def inside_hull(hull_vertices, hull_faces, point, eps=1e-9):
    a = hull_vertices[hull_faces[:, 0]]
    b = hull_vertices[hull_faces[:, 1]]
    c = hull_vertices[hull_faces[:, 2]]
    n = np.cross(b - a, c - a)
    return bool(np.all(np.einsum("ij,ij->i", n, point - a) <= eps))
