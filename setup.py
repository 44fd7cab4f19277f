"""setuptools drives CMake to build the Python module `recode` (pyproject.toml).

Debian 12 has no scikit-build-core, so this is the small equivalent: one extension whose
build_ext configures this checkout with RECODE_LIBRARY_ONLY=ON and RECODE_BUILD_PYTHON=ON for
the interpreter running pip, builds the target recode_python, and copies the module it writes
(build/python/recode.cpython-*.so) to where setuptools packs it. The libraries-only build has
the registry's GPU devices whose development packages it finds (cmake/gpu_devices.cmake: Vulkan
with glslangValidator, EGL, OSMesa); CMake prints one line naming the devices built and why not
the others (`pip install -v` shows it; recode.devices() tells the same at run time).

Beside the module, the type stubs python/recode-stubs (a PEP 561 stub-only package) are
installed, so that editors and type checkers know the module's API.

Extra CMake arguments come from the environment variable CMAKE_ARGS (e.g.
"-DCMAKE_CXX_COMPILER_LAUNCHER=ccache" or "-DRECODE_WITH_VULKAN=OFF"); the build's parallelism
from CMAKE_BUILD_PARALLEL_LEVEL, as for any `cmake --build`. RECODE_PIP_BUILD_DIR names the CMake
build tree to use (default: setuptools' temporary folder, build/temp.*/cmake in the checkout);
a second install with the same tree compiles only what changed.
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
        build = pathlib.Path(os.environ.get("RECODE_PIP_BUILD_DIR") or
                             pathlib.Path(self.build_temp) / "cmake").resolve()
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
            "-DRECODE_LIBRARY_ONLY=ON", "-DRECODE_BUILD_PYTHON=ON", "-DRECODE_PYTHON_PIP=ON",
            f"-DPython_EXECUTABLE={sys.executable}",
        ]
        if shutil.which("ninja") and not (build / "CMakeCache.txt").exists():
            configure += ["-G", "Ninja"]
        configure += shlex.split(os.environ.get("CMAKE_ARGS", ""))
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "recode_python"], check=True)
        built = sorted((build / "python").glob("recode.*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one module in {build / 'python'}, found {built}")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    ext_modules=[CMakeExtension("recode")],
    cmdclass={"build_ext": CMakeBuild},
    # The stubs: a package named recode-stubs (PEP 561), set here since pyproject.toml's schema
    # in setuptools 66 takes only importable package names.
    packages=["recode-stubs"],
    package_dir={"recode-stubs": "python/recode-stubs"},
    package_data={"recode-stubs": ["*.pyi"]},
)
