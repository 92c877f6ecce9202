"""`pip install --no-build-isolation .` from the checkout: the Python module hullpack (python/),
built with the project's CMake (python/cmake_build.py). Metadata: pyproject.toml."""

import sys
from pathlib import Path

from setuptools import setup

sys.path.insert(0, str(Path(__file__).resolve().parent / "python"))
from cmake_build import setup_args  # noqa: E402

# setuptools' scratch folder beside CMake's build/ rather than inside it.
setup(**setup_args("python/hullpack"), options={"build": {"build_base": "build-python"}})
