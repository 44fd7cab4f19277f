"""`pip install .` as docs/api.md says, in a fresh venv: the module it installs has the GPU
devices of the registry whose packages this machine has, and an exact one gives the cpu device's
result; the type stubs are installed beside it.

Slow (the libraries are compiled again for the module; tens of minutes on 2 cores the first
time), so it runs only when asked: RECODE_PIP_INSTALL_TEST=1 ctest -L pip (else it is skipped).
RECODE_PIP_WORK_DIR (ctest: build/python/tests/pip_install) holds a copy of the checkout, made
equal to it each run, a fresh venv each run, and the CMake build tree that setup.py uses
(RECODE_PIP_BUILD_DIR), kept between runs so that a second run compiles only what changed. RECODE_PIP_EXPECT_DEVICES
(default "vulkan-compute gl-exact") names the devices the module must have and use."""
import filecmp
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import textwrap
import time

import pytest

if os.environ.get("RECODE_PIP_INSTALL_TEST") != "1":
    pytest.skip("set RECODE_PIP_INSTALL_TEST=1 to build and install the module with pip",
                allow_module_level=True)

SOURCE = pathlib.Path(os.environ.get("RECODE_SOURCE_DIR",
                                     pathlib.Path(__file__).resolve().parents[2]))
EXPECTED = os.environ.get("RECODE_PIP_EXPECT_DEVICES", "vulkan-compute gl-exact").split()
# Build trees, caches and the like: not part of what pip is given.
IGNORED = shutil.ignore_patterns(".git", "build*", "out", ".venv", "*.egg-info", "__pycache__",
                                 ".cache")


def sync(source, copy):
    """Makes `copy` hold what `source` does (less IGNORED): a file whose bytes changed is written
    anew, so its time is now and the kept build tree recompiles what depends on it; an
    unchanged one keeps its time, so nothing is recompiled for it; what `source` lacks goes."""
    copy.mkdir(parents=True, exist_ok=True)
    names = set(os.listdir(source))
    names -= IGNORED(str(source), list(names))
    for name in set(os.listdir(copy)) - names - IGNORED(str(copy), os.listdir(copy)):
        gone = copy / name
        shutil.rmtree(gone) if gone.is_dir() and not gone.is_symlink() else gone.unlink()
    for name in sorted(names):
        s, c = source / name, copy / name
        if s.is_symlink() or not s.is_dir():
            if c.is_dir() and not c.is_symlink():
                shutil.rmtree(c)
            if s.is_symlink():
                if c.is_symlink() or c.exists():
                    c.unlink()
                c.symlink_to(os.readlink(s))
            elif not (c.is_file() and not c.is_symlink() and filecmp.cmp(s, c, shallow=False)):
                if c.is_symlink():
                    c.unlink()
                shutil.copyfile(s, c)
                shutil.copymode(s, c)
        else:
            if c.exists() and not c.is_dir():
                c.unlink()
            sync(s, c)


@pytest.fixture(scope="module")
def work():
    path = os.environ.get("RECODE_PIP_WORK_DIR")
    if not path:
        path = tempfile.mkdtemp(prefix="recode-pip-")
    return pathlib.Path(path)


def clean_env(**extra):
    """The caller's environment without the build tree's module (ctest's PYTHONPATH)."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    env.update(extra)
    return env


@pytest.fixture(scope="module")
def venv(work):
    """A copy of the checkout and a venv with the module pip built from it."""
    src, venv_dir, log = work / "src", work / "venv", work / "pip-install.log"
    shutil.rmtree(venv_dir, ignore_errors=True)
    sync(SOURCE, src)
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv_dir)],
                   check=True)
    python = venv_dir / "bin" / "python"
    start = time.monotonic()
    with open(log, "w") as out:
        done = subprocess.run(
            [str(python), "-m", "pip", "install", "-v", "--no-build-isolation", "--no-index", "."],
            cwd=src, stdout=out, stderr=subprocess.STDOUT,
            env=clean_env(RECODE_PIP_BUILD_DIR=str(work / "cmake")))
    seconds = time.monotonic() - start
    text = log.read_text(errors="replace")
    devices_line = [line for line in text.splitlines() if "recode: devices built:" in line]
    print(f"pip install: {seconds:.0f} s, exit {done.returncode}; log {log}")
    print("\n".join(devices_line))
    assert done.returncode == 0, text[-6000:]
    assert devices_line, "the build printed no 'recode: devices built:' line"
    return python, devices_line[-1]


def run_in(python, code):
    done = subprocess.run([str(python), "-c", textwrap.dedent(code)], capture_output=True,
                          text=True, cwd=python.parent, env=clean_env())
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def test_the_build_says_which_devices_it_built(venv):
    _, line = venv
    for name in EXPECTED:
        assert name in line.split("; not built:")[0], line


def test_the_installed_module_lists_and_uses_the_gpu_devices(venv):
    python, _ = venv
    out = run_in(python, f"""
        import pathlib, sys
        import numpy as np
        import recode
        venv = pathlib.Path(sys.prefix).resolve()
        assert venv in pathlib.Path(recode.__file__).resolve().parents, recode.__file__
        devices = {{d["name"]: d for d in recode.devices()}}
        for d in devices.values():
            print(d["name"], d["available"], d["missing"] or "-")
        cone = recode.cone(1.0, 2.0, 32)
        a = recode.CollisionObject(cone)
        b = recode.CollisionObject(cone, rotation=np.diag([1.0, -1.0, -1.0]),
                                   translation=[0, 0, 3.75])
        request = recode.CollisionRequest(pixel_size=0.02, axis="x")
        reference = recode.collide(a, b, request)
        assert reference and reference.interfering_pixels > 0
        for name in {EXPECTED!r}:
            assert devices[name]["available"] and devices[name]["exact"], devices[name]
            result = recode.collide(a, b, request, device=name)
            assert result.interfering_pixels == reference.interfering_pixels, name
            assert np.array_equal(result.case_map, reference.case_map), name
            assert np.array_equal(result.contact.points, reference.contact.points), name
            print(name, "collide:", bool(result), result.interfering_pixels, "pixels, as cpu")
    """)
    print(out)


def test_the_stubs_are_installed_beside_the_module(venv):
    python, _ = venv
    out = run_in(python, """
        import importlib.util, pathlib, recode
        spec = importlib.util.find_spec("recode")
        stubs = pathlib.Path(spec.origin).parent / "recode-stubs" / "__init__.pyi"
        assert stubs.is_file(), stubs
        assert "def collide(" in stubs.read_text()
        print(stubs)
    """)
    print(out)
