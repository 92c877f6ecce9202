"""hullpack: convex collision hulls, compressed meshes and robot descriptions.

    import hullpack
    hulls, report = hullpack.decompose(vertices, faces)          # V-HACD 2.0
    stream = hullpack.encode(vertices, faces, position_bits=14)  # o3dgc bytes
    mesh = hullpack.decode(stream)                                # dict of numpy arrays
    hullpack.collision("part.obj", "out", format="urdf")          # URDF + one STL per hull
    hullpack.pack("scene.glb", "scene.packed.glb")                # compressed GLB with hulls

Every function takes numpy arrays (or file paths), releases the GIL while it works, stops on
Ctrl-C, and raises ValueError naming the problem for bad input. help(hullpack.decompose) lists
every parameter.
"""

from ._hullpack import (  # noqa: F401
    STREAM_VERSION,
    VHACD_VERSION,
    Cancelled,
    collision,
    decode,
    decompose,
    encode,
    info,
    load_mesh,
    pack,
    stream_info,
    unpack,
)

__version__ = "0.1.0"

__all__ = [
    "Cancelled",
    "STREAM_VERSION",
    "VHACD_VERSION",
    "collision",
    "decode",
    "decompose",
    "encode",
    "info",
    "load_mesh",
    "pack",
    "stream_info",
    "unpack",
]
