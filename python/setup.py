"""Builds and installs the msmesh Python package (docs/python.md).

    cd python && /usr/bin/python3 -m pip install --no-build-isolation --no-deps .

The compiled module msmesh._core is built by CMake from the repository one level up (the
same python/CMakeLists.txt as `-DMSMESH_BUILD_PYTHON=ON`), for the interpreter running this
script; the pure-Python files come from python/msmesh/. Environment variables:
  MSMESH_SOURCE_DIR   the msmesh repository (default: the parent of this folder)
  MSMESH_BUILD_JOBS   parallel build jobs (default: the number of CPUs)
  MSMESH_CMAKE_ARGS   extra CMake arguments, split on spaces
"""

import os
import pathlib
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = pathlib.Path(__file__).resolve().parent
SOURCE_DIR = pathlib.Path(os.environ.get("MSMESH_SOURCE_DIR", HERE.parent)).resolve()


class CMakeExtension(Extension):
    """An extension CMake builds; setuptools compiles nothing itself."""

    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if not (SOURCE_DIR / "CMakeLists.txt").exists():
            raise RuntimeError(f"msmesh sources not found in {SOURCE_DIR} (set MSMESH_SOURCE_DIR)")
        cmake = shutil.which("cmake")
        if cmake is None:
            raise RuntimeError("cmake not found (Debian package: cmake)")
        build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = [
            cmake, "-S", str(SOURCE_DIR), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DMSMESH_BUILD_PYTHON=ON", "-DMSMESH_BUILD_TESTS=OFF", "-DMSMESH_BUILD_BENCH=OFF",
            f"-DMSMESH_PYTHON={sys.executable}",
        ]
        if shutil.which("ninja") and not (build_dir / "CMakeCache.txt").exists():
            configure += ["-G", "Ninja"]
        configure += os.environ.get("MSMESH_CMAKE_ARGS", "").split()
        jobs = os.environ.get("MSMESH_BUILD_JOBS", str(os.cpu_count() or 1))
        subprocess.check_call(configure)
        subprocess.check_call([cmake, "--build", str(build_dir), "--target", "_core", "-j", jobs])

        built = build_dir / "python" / "msmesh" / ("_core" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.exists():
            raise RuntimeError(f"CMake did not produce {built}")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    name="msmesh",
    version="0.1.0",
    description="Feature-preserving mesh denoising: NMSTV normal filtering and vertex updating",
    packages=["msmesh"],
    package_dir={"msmesh": "msmesh"},
    ext_modules=[CMakeExtension("msmesh._core")],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.8",
    install_requires=["numpy"],
    zip_safe=False,
)
