"""The conformance suite in your own pytest suite (docs/api.md#the-conformance-kit-in-python).

A back end of your own is a function `rasterize(width, height, commands)` that runs a golden
vector's commands (rasterization.md section 8) on a fresh width x height framebuffer and returns
its depth and stencil buffers, (height, width) arrays with row 0 the bottom row (or flat, bottom
row first). Here it is the NumPy example back end, examples/backends/numpy_backend.py, imported
and run in this process. One test per golden vector; a failing one's message is what `recode
conform` says of that vector: where the answer departs from the contract, at which stage and
section, what the graphics APIs allow there, and the first bad pixels with their histories.

Run from a build tree (the ctest example/python/test_numpy_backend):

    PYTHONPATH=build/python python3 -m pytest -q examples/python/test_numpy_backend.py

The golden vectors are read from conformance.golden_dir(); set RECODE_GOLDEN_DIR, or pass a
directory to conformance.vectors(), to read others.
"""
import pathlib
import sys

import pytest

from recode import conformance

# The NumPy example back end, beside this directory; a back end of your own is imported instead.
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "backends"))
import numpy_backend  # noqa: E402


def rasterize(width, height, commands):
    """The back end under test: its buffers, or conformance.Refused when its validation
    (rasterization.md section 2) refuses the stream."""
    _, result = numpy_backend.run_request(
        {"id": 0, "width": width, "height": height, "commands": commands})
    if isinstance(result, str):
        raise conformance.Refused(result)
    return result.depth, result.stencil


@pytest.mark.parametrize("vector", conformance.vectors(), ids=lambda v: v.name)
def test_conforms(vector):
    try:
        depth, stencil = rasterize(vector.width, vector.height, vector.commands)
        result = conformance.check(vector, depth, stencil)
    except conformance.Refused as refusal:
        result = conformance.check(vector, refused=str(refusal))
    if not result.passed:
        pytest.fail(str(result), pytrace=False)
