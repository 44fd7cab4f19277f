"""setuptools drives CMake to build the Python module `recode` (pyproject.toml).

Debian 12 has no scikit-build-core, so this is the small equivalent: one extension whose
build_ext configures this checkout with RECODE_LIBRARY_ONLY=ON and RECODE_BUILD_PYTHON=ON for
the interpreter running pip, builds the target recode_python, and copies the module it writes
(build/python/recode.cpython-*.so) to where setuptools packs it. Extra CMake arguments come
from the environment variable CMAKE_ARGS (e.g. "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"); the
build's parallelism from CMAKE_BUILD_PARALLEL_LEVEL, as for any `cmake --build`.
"""
import os
import pathlib
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
            "-DRECODE_LIBRARY_ONLY=ON", "-DRECODE_BUILD_PYTHON=ON",
            f"-DPython_EXECUTABLE={sys.executable}",
        ]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        configure += shlex.split(os.environ.get("CMAKE_ARGS", ""))
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "recode_python"], check=True)
        built = sorted((build / "python").glob("recode.*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one module in {build / 'python'}, found {built}")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(ext_modules=[CMakeExtension("recode")], cmdclass={"build_ext": CMakeBuild})
