#!/usr/bin/python3
"""examples/backends/numpy_backend.py with one rule of docs/rasterization.md read wrong.

Usage: own_readings_backend.py READING   (READINGS below lists them, each with the stage of the
contract it breaks). The readings are mistakes an implementer could make reading sections 3 to 6
of rasterization.md, written from that page and not from the kit's list of wrong readings: the
operands of a comparison swapped or masked wrongly, a write mask ignored,
the ops of two outcomes swapped, wrapping ops that saturate, the fill rule's ties read as all or
none, the cull modes swapped, a typo in the plane's slope, a clear that ignores the scissor.
ctest conform/own-readings (check_own_readings.py) runs each through `recode conform --exec` and
holds the stage the report gives each failing vector to the stage the reading breaks.
"""
import os
import sys

sys.dont_write_bytecode = True   # importing the example must not leave __pycache__ in the tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "examples", "backends"))
import numpy as np               # noqa: E402
import numpy_backend as nb       # noqa: E402

COMPARE, STENCIL_OPS = nb.COMPARE, nb.STENCIL_OPS


def fragments(dev, i, j, q, ops, reading):
    """Section 6's per-fragment operations (numpy_backend.Device.fragments), with `reading`'s
    mistake where it has one."""
    s, d = dev.stencil[j, i], dev.depth[j, i]
    vm, ref = dev.value_mask, dev.ref
    if reading == "stencil_operands_swapped":      # stored FUNC ref, not ref FUNC stored
        s_pass = COMPARE[dev.stencil_func](s & vm, ref & vm)
    elif reading == "stencil_ref_unmasked":        # the value mask applied to the stored value only
        s_pass = COMPARE[dev.stencil_func](ref, s & vm)
    else:
        s_pass = COMPARE[dev.stencil_func](ref & vm, s & vm)
    if reading == "depth_operands_swapped":        # stored FUNC incoming
        d_test = COMPARE[dev.depth_func](d, q)
    else:
        d_test = COMPARE[dev.depth_func](q, d)
    d_pass = s_pass & d_test
    sfail, dpfail, dppass = (STENCIL_OPS[name](s, ref) for name in ops)
    if reading == "dpfail_dppass_swapped":         # the depth test's two ops the other way round
        dpfail, dppass = dppass, dpfail
    n = np.where(~s_pass, sfail, np.where(d_pass, dppass, dpfail))
    wm = dev.write_mask
    if reading == "op_write_mask_drops_bits":      # n & mask, without keeping the masked-off bits
        dev.stencil[j, i] = n & wm
    else:
        dev.stencil[j, i] = (n & wm) | (s & ~wm & 0xFF)
    if dev.depth_write or reading == "depth_write_mask_ignored":
        dev.depth[j[d_pass], i[d_pass]] = q[d_pass]


def plane_depth_dzdy_typo(v0, v1, v2, A2, Xc, Yc):
    """Section 5's plane with dz1 and dz2 exchanged in dzdy's numerator, a slip of the pen."""
    (X0, Y0, z0), (X1, Y1, z1), (X2, Y2, z2) = v0, v1, v2
    dz1, dz2 = z1 - z0, z2 - z0
    e1x, e1y = float(X1 - X0), float(Y1 - Y0)
    e2x, e2y = float(X2 - X0), float(Y2 - Y0)
    a2 = float(A2)
    dzdx = (dz1 * e2y - dz2 * e1y) / a2
    dzdy = (dz1 * e1x - dz2 * e2x) / a2
    tx = dzdx * (Xc - X0).astype(np.float64)
    ty = dzdy * (Yc - Y0).astype(np.float64)
    return (z0 + tx) + ty


def clear_stencil_everywhere(dev, v):
    """clear_stencil over the whole frame, through the write mask but not the scissor."""
    wm = dev.write_mask
    dev.stencil[:, :] = (v & wm) | (dev.stencil & ~wm & 0xFF)


def clear_stencil_value_mask(dev, v):
    """clear_stencil through the stencil test's value mask instead of the write mask."""
    region = dev._scissored()
    vm = dev.value_mask
    dev.stencil[region] = (v & vm) | (dev.stencil[region] & ~vm & 0xFF)


OTHER_FACE = {"front": "back", "back": "front", "none": "none"}

# Each reading: the stage of the contract it breaks, as `recode conform` names stages.
READINGS = {
    "stencil_operands_swapped": "stencil",
    "stencil_ref_unmasked": "stencil",
    "dpfail_dppass_swapped": "stencil",
    "op_write_mask_drops_bits": "stencil",
    "wrap_ops_saturate": "stencil",
    "depth_operands_swapped": "depth test",
    "depth_write_mask_ignored": "depth test",
    "every_edge_inclusive": "coverage",
    "no_edge_inclusive": "coverage",
    "cull_modes_swapped": "facing",
    "dzdy_typo": "depth value",
    "stencil_clear_ignores_scissor": "clear",
    "stencil_clear_value_mask": "clear",
}


def install(reading):
    original = nb.run_command

    def run_command(dev, c, where):
        original(dev, c, where)
        if reading == "cull_modes_swapped" and c.get("op") == "cull":
            dev.cull = OTHER_FACE[dev.cull]

    nb.run_command = run_command
    nb.Device.fragments = lambda dev, i, j, q, ops: fragments(dev, i, j, q, ops, reading)
    if reading == "wrap_ops_saturate":
        nb.STENCIL_OPS["INCR_WRAP"] = nb.STENCIL_OPS["INCR"]
        nb.STENCIL_OPS["DECR_WRAP"] = nb.STENCIL_OPS["DECR"]
    elif reading == "every_edge_inclusive":
        nb.inclusive = lambda dx, dy: True
    elif reading == "no_edge_inclusive":
        nb.inclusive = lambda dx, dy: False
    elif reading == "dzdy_typo":
        nb.plane_depth = plane_depth_dzdy_typo
    elif reading == "stencil_clear_ignores_scissor":
        nb.Device.clear_stencil = clear_stencil_everywhere
    elif reading == "stencil_clear_value_mask":
        nb.Device.clear_stencil = clear_stencil_value_mask
    nb.NAME = "own_readings_backend.py (deliberately wrong: %s)" % reading


if __name__ == "__main__":
    if len(sys.argv) != 2 or sys.argv[1] not in READINGS:
        print("usage: own_readings_backend.py READING (one of %s)" % ", ".join(READINGS),
              file=sys.stderr)
        sys.exit(2)
    install(sys.argv[1])
    sys.exit(nb.main())
