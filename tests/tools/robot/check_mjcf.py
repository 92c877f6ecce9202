#!/usr/bin/env python3
"""Checks an MJCF file against the rules of MuJoCo's XML reference (the elements hullpack writes):
known elements and attributes only, the required attributes, value types and ranges, unique
names, mesh references, mesh files that exist relative to the model with an extension MuJoCo
reads, a physically valid inertia, maxhullvert -1 or above 3 and respected by each hull file.
Usage: check_mjcf.py MODEL.xml   (exit 1 and one line per problem)"""

import math
import os
import sys
import xml.etree.ElementTree as ET

# Attributes MuJoCo's schema accepts on the elements hullpack writes (XML reference).
ATTRIBUTES = {
    "mujoco": {"model"},
    "asset": set(),
    "mesh": {"name", "class", "content_type", "file", "vertex", "normal", "texcoord", "face",
             "refpos", "refquat", "scale", "smoothnormal", "maxhullvert", "inertia", "builtin",
             "params", "material"},
    "worldbody": set(),
    "body": {"name", "childclass", "pos", "quat", "mocap", "axisangle", "xyaxes", "zaxis", "euler",
             "gravcomp", "user"},
    "freejoint": {"name", "group", "align"},
    "inertial": {"pos", "quat", "axisangle", "xyaxes", "zaxis", "euler", "mass", "diaginertia",
                 "fullinertia"},
    "geom": {"name", "class", "type", "contype", "conaffinity", "condim", "group", "priority",
             "size", "material", "friction", "mass", "density", "shellinertia", "solmix",
             "solref", "solimp", "margin", "gap", "fromto", "pos", "quat", "axisangle", "xyaxes",
             "zaxis", "euler", "hfield", "mesh", "fitscale", "rgba", "fluidshape", "fluidcoef",
             "user"},
}
CHILDREN = {
    "mujoco": {"compiler", "option", "size", "visual", "statistic", "default", "extension",
               "custom", "asset", "contact", "equality", "tendon", "actuator", "sensor",
               "keyframe", "worldbody", "deformable", "include"},
    "asset": {"mesh", "texture", "material", "hfield", "skin", "model"},
    "worldbody": {"body", "geom", "site", "camera", "light", "frame"},
    "body": {"body", "inertial", "joint", "freejoint", "geom", "site", "camera", "light", "frame",
             "composite", "flexcomp", "plugin", "attach"},
}
GEOM_TYPES = {"plane", "hfield", "sphere", "capsule", "ellipsoid", "cylinder", "box", "mesh", "sdf"}
MESH_EXTENSIONS = {".stl", ".obj", ".msh"}
NUM_GROUPS = 6  # mjNGROUP


def numbers(text, count, what, problems):
    try:
        values = [float(t) for t in text.split()]
    except (AttributeError, ValueError):
        problems.append(f"{what}: '{text}' is not a list of numbers")
        return None
    if len(values) != count or not all(math.isfinite(v) for v in values):
        problems.append(f"{what}: needs {count} finite numbers, got '{text}'")
        return None
    return values


def integer(text, what, problems):
    try:
        return int(text)
    except (TypeError, ValueError):
        problems.append(f"{what}: '{text}' is not an integer")
        return None


def obj_vertex_count(path):
    with open(path) as f:
        return sum(1 for line in f if line.startswith("v "))


def check_inertia(full, problems):
    ixx, iyy, izz, ixy, ixz, iyz = full
    m = [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]
    # Positive definite: leading principal minors > 0.
    d1 = m[0][0]
    d2 = m[0][0] * m[1][1] - m[0][1] ** 2
    d3 = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] ** 2) - m[0][1] * (m[0][1] * m[2][2] - m[1][2] * m[0][2])
          + m[0][2] * (m[0][1] * m[1][2] - m[1][1] * m[0][2]))
    if not (d1 > 0 and d2 > 0 and d3 > 0):
        problems.append("inertial: fullinertia is not positive definite")
        return
    # Principal moments satisfy the triangle inequality (MuJoCo rejects them otherwise).
    p, q, r = sorted(eigenvalues(m))
    if p + q < r * (1 - 1e-9):
        problems.append("inertial: principal moments violate A + B >= C")


def eigenvalues(m):
    """Eigenvalues of a symmetric 3x3 matrix (trigonometric method)."""
    p1 = m[0][1] ** 2 + m[0][2] ** 2 + m[1][2] ** 2
    q = (m[0][0] + m[1][1] + m[2][2]) / 3
    if p1 == 0:
        return [m[0][0], m[1][1], m[2][2]]
    p2 = sum((m[i][i] - q) ** 2 for i in range(3)) + 2 * p1
    p = math.sqrt(p2 / 6)
    b = [[(m[i][j] - (q if i == j else 0)) / p for j in range(3)] for i in range(3)]
    det = (b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0])
           + b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]))
    phi = math.acos(max(-1, min(1, det / 2))) / 3
    e1 = q + 2 * p * math.cos(phi)
    e3 = q + 2 * p * math.cos(phi + 2 * math.pi / 3)
    return [e1, 3 * q - e1 - e3, e3]


def check(path):
    problems = []
    base = os.path.dirname(os.path.abspath(path))
    root = ET.parse(path).getroot()
    if root.tag != "mujoco":
        return [f"root element is <{root.tag}>, not <mujoco>"]
    meshes = {}
    names = {"mesh": set(), "body": set(), "geom": set(), "joint": set()}

    def walk(elem, parent):
        tag = elem.tag
        if parent is not None and tag not in CHILDREN.get(parent.tag, set()):
            problems.append(f"<{tag}> is not allowed inside <{parent.tag}>")
        if tag not in ATTRIBUTES:
            problems.append(f"<{tag}>: not an element hullpack should write")
            return
        for attr in elem.attrib:
            if attr not in ATTRIBUTES[tag]:
                problems.append(f"<{tag}>: unknown attribute '{attr}'")
        name = elem.get("name")
        kind = "joint" if tag == "freejoint" else tag
        if name is not None and kind in names:
            if name in names[kind]:
                problems.append(f"<{tag}>: name '{name}' used twice")
            names[kind].add(name)
        if tag == "mesh":
            f = elem.get("file")
            if not f:
                problems.append(f"mesh '{name}': no file")
            else:
                if os.path.isabs(f):
                    problems.append(f"mesh '{name}': absolute path {f}")
                if os.path.splitext(f)[1].lower() not in MESH_EXTENSIONS:
                    problems.append(f"mesh '{name}': {f} is not .stl, .obj or .msh")
                full = os.path.join(base, f)
                if not os.path.isfile(full):
                    problems.append(f"mesh '{name}': {f} does not exist beside the model")
                elif f.lower().endswith(".obj") and obj_vertex_count(full) < 4:
                    problems.append(f"mesh '{name}': {f} has fewer than 4 vertices")
                if "maxhullvert" in elem.attrib:
                    cap = integer(elem.get("maxhullvert"), f"mesh '{name}' maxhullvert", problems)
                    if cap is not None and cap != -1 and cap <= 3:
                        problems.append(f"mesh '{name}': maxhullvert must be -1 or > 3")
                    elif cap is not None and cap > 3 and os.path.isfile(full) and f.lower().endswith(".obj"):
                        if obj_vertex_count(full) > cap:
                            problems.append(f"mesh '{name}': {f} has more than {cap} vertices")
            meshes[name] = elem
        if tag == "freejoint" and (parent is None or parent.tag != "body" or parent not in worldbody_children):
            problems.append("<freejoint> must be in a top-level body")
        if tag == "inertial":
            if "pos" not in elem.attrib or "mass" not in elem.attrib:
                problems.append("inertial: pos and mass are required")
            else:
                numbers(elem.get("pos"), 3, "inertial pos", problems)
                mass = numbers(elem.get("mass"), 1, "inertial mass", problems)
                if mass and not mass[0] > 0:
                    problems.append("inertial: mass must be positive")
            has_diag, has_full = "diaginertia" in elem.attrib, "fullinertia" in elem.attrib
            if has_diag == has_full:
                problems.append("inertial: exactly one of diaginertia and fullinertia")
            if has_full:
                full = numbers(elem.get("fullinertia"), 6, "inertial fullinertia", problems)
                if full:
                    check_inertia(full, problems)
        if tag == "geom":
            gtype = elem.get("type", "sphere")
            if gtype not in GEOM_TYPES:
                problems.append(f"geom '{name}': unknown type {gtype}")
            if gtype == "mesh" and elem.get("mesh") is None:
                problems.append(f"geom '{name}': type mesh without a mesh")
            for attr in ("contype", "conaffinity"):
                if attr in elem.attrib:
                    integer(elem.get(attr), f"geom '{name}' {attr}", problems)
            if "group" in elem.attrib:
                g = integer(elem.get("group"), f"geom '{name}' group", problems)
                if g is not None and not 0 <= g < NUM_GROUPS:
                    problems.append(f"geom '{name}': group {g} outside 0..{NUM_GROUPS - 1}")
            geoms.append(elem)
        for child in elem:
            walk(child, elem)

    geoms = []
    worldbody = root.find("worldbody")
    worldbody_children = list(worldbody) if worldbody is not None else []
    walk(root, None)
    for g in geoms:
        ref = g.get("mesh")
        if ref is not None and ref not in meshes:
            problems.append(f"geom '{g.get('name')}': mesh '{ref}' is not an asset")
    if not any(g.get("type") == "mesh" and g.get("contype", "1") != "0" for g in geoms):
        problems.append("no colliding mesh geom")
    return problems


if __name__ == "__main__":
    found = check(sys.argv[1])
    for p in found:
        print(f"{sys.argv[1]}: {p}")
    sys.exit(1 if found else 0)
