"""`pip install ./python`: builds hullpack._hullpack with the project's CMake (cmake_build.py)."""

import sys
from pathlib import Path

from setuptools import setup

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cmake_build import setup_args  # noqa: E402

setup(**setup_args("hullpack"))
