"""setuptools glue shared by the two setup.py files (the checkout's top folder and python/): builds
hullpack._hullpack with the project's CMake."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension
from setuptools.command.build_ext import build_ext

CHECKOUT = Path(__file__).resolve().parent.parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    """Configures the checkout (tests off, the Python module on, this interpreter) and builds only
    the module's target, then copies it where setuptools expects the extension."""

    def build_extension(self, ext):
        if not (CHECKOUT / "vhacd" / "include" / "vhacd" / "vhacd.h").exists():
            raise RuntimeError(f"{CHECKOUT} is not a hullpack checkout")
        target = Path(self.get_ext_fullpath(ext.name)).resolve()
        build = Path(os.environ.get("HULLPACK_PY_BUILD_DIR", Path(self.build_temp).resolve() / "cmake"))
        build.mkdir(parents=True, exist_ok=True)
        configure = [
            "cmake", "-S", str(CHECKOUT), "-B", str(build),
            "-DCMAKE_BUILD_TYPE=Release", "-DHULLPACK_BUILD_TESTS=OFF", "-DHULLPACK_PYTHON=ON",
            f"-DPython3_EXECUTABLE={sys.executable}",
        ]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        if shutil.which("ccache"):
            configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
        if not (build / "CMakeCache.txt").exists():
            subprocess.check_call(configure)
        jobs = str(os.cpu_count() or 2)
        subprocess.check_call(["cmake", "--build", str(build), "--target", "_hullpack", "-j", jobs])
        built = sorted((build / "python" / "hullpack").glob("_hullpack*.so"))
        if not built:
            raise RuntimeError(f"no _hullpack module under {build}/python/hullpack")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


def setup_args(package_dir):
    """setup() keywords: the pure-Python package from `package_dir` plus the CMake-built module."""
    return dict(
        packages=["hullpack"],
        package_dir={"hullpack": package_dir},
        package_data={"hullpack": ["*.pyi", "py.typed"]},
        ext_modules=[CMakeExtension("hullpack._hullpack")],
        cmdclass={"build_ext": CMakeBuild},
        zip_safe=False,
    )
