"""Build of the msmesh Python package; the metadata is in pyproject.toml (docs/python.md).

    /usr/bin/python3 -m venv --system-site-packages V
    V/bin/pip install -v --no-build-isolation .        # -v shows CMake's and ninja's progress

CMake builds, from this repository, the extension msmesh._core (python/CMakeLists.txt) and the
msmesh program for the interpreter running pip, in a folder outside the sources; nothing is
written into the source tree. The package holds python/msmesh/*.py, the extension and the
program (msmesh/_bin/msmesh), which the `msmesh` command and `python -m msmesh` run.

Environment variables:
  MSMESH_BUILD_DIR   the CMake build folder (default: <temp>/msmesh-pip-<uid>-<hash of this
                     folder and the interpreter>, kept, so that a second install is incremental)
  MSMESH_BUILD_JOBS  parallel build jobs (default: the number of CPUs)
  MSMESH_CMAKE_ARGS  extra CMake arguments, split on spaces
ccache is used when it is installed (unless CMAKE_CXX_COMPILER_LAUNCHER says otherwise).
"""

import atexit
import hashlib
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = Path(__file__).resolve().parent


def _version():
    """The project's version: project(msmesh VERSION x.y.z) in CMakeLists.txt."""
    text = (SOURCE_DIR / "CMakeLists.txt").read_text()
    found = re.search(r"project\(\s*msmesh\s+VERSION\s+([0-9.]+)", text)
    if not found:
        raise RuntimeError(f"no project(msmesh VERSION ...) in {SOURCE_DIR / 'CMakeLists.txt'}")
    return found.group(1)


def _cmake_build_dir():
    if os.environ.get("MSMESH_BUILD_DIR"):
        return Path(os.environ["MSMESH_BUILD_DIR"]).resolve()
    key = hashlib.sha1(f"{SOURCE_DIR}\n{sys.executable}\n{sys.version}".encode()).hexdigest()[:12]
    return Path(tempfile.gettempdir()) / f"msmesh-pip-{os.getuid()}-{key}"


# setuptools' own folders (build/, msmesh.egg-info) go to a scratch folder rather than into the
# sources; it is removed when this process ends.
_SCRATCH = Path(tempfile.mkdtemp(prefix="msmesh-setuptools-"))
atexit.register(shutil.rmtree, _SCRATCH, ignore_errors=True)


def _say(message):
    print(f"msmesh setup.py: {message}", flush=True)


class CMakeExtension(Extension):
    """An extension CMake builds; setuptools compiles nothing itself."""

    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    """Builds the targets _core and msmesh with CMake and puts them into the package."""

    def build_extension(self, ext):
        cmake = shutil.which("cmake")
        if cmake is None:
            raise RuntimeError("cmake not found (Debian package: cmake; scripts/deps installs everything)")
        build_dir = _cmake_build_dir()
        extra = os.environ.get("MSMESH_CMAKE_ARGS", "").split()
        configure = [
            cmake, "-S", str(SOURCE_DIR), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DMSMESH_BUILD_PYTHON=ON", "-DMSMESH_BUILD_TESTS=OFF", "-DMSMESH_BUILD_BENCH=OFF",
            f"-DMSMESH_PYTHON={sys.executable}",
        ]
        if not (build_dir / "CMakeCache.txt").exists() and shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        if (shutil.which("ccache") and "CMAKE_CXX_COMPILER_LAUNCHER" not in os.environ
                and not any("CMAKE_CXX_COMPILER_LAUNCHER" in a for a in extra)):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        configure += extra
        jobs = os.environ.get("MSMESH_BUILD_JOBS", str(os.cpu_count() or 1))

        _say(f"configuring in {build_dir}")
        subprocess.check_call(configure)
        _say(f"building the module and the program with {jobs} jobs (several minutes from scratch)")
        subprocess.check_call([cmake, "--build", str(build_dir), "--target", "_core", "msmesh", "-j", jobs])

        module = build_dir / "python" / "msmesh" / ("_core" + sysconfig.get_config_var("EXT_SUFFIX"))
        program = build_dir / "msmesh"
        for built in (module, program):
            if not built.exists():
                raise RuntimeError(f"CMake did not produce {built}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(module, target)
        # The program goes inside the package; the console script msmesh (msmesh._cli) runs it.
        bin_dir = target.parent / "_bin"
        bin_dir.mkdir(exist_ok=True)
        shutil.copy2(program, bin_dir / "msmesh")
        _say(f"built {target.name} and the program msmesh")


setup(
    version=_version(),
    packages=["msmesh"],
    package_dir={"": "python"},
    license_files=["LICENSE"],
    include_package_data=False,
    zip_safe=False,
    ext_modules=[CMakeExtension("msmesh._core")],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(_SCRATCH / "build")}, "egg_info": {"egg_base": str(_SCRATCH)}},
)
