"""Which golden vectors' stencil answers no native pipeline may change: the contract's model
(examples/backends/numpy_backend.py) rerun with, at every step that decides a stencil value, a
margin against the freedoms a native rasterizer has. A vector is *stencil-fixed* when

- every sample a triangle could reach (its box and a pixel around it, in the scissor) is on the
  same side of each edge, and every triangle has the same facing, for any snapping of the
  vertices to a grid of 1/16 pixel or finer (Vulkan's least subPixelPrecisionBits, 4; any
  rounding to that grid moves a coordinate by less than 16/256 pixel), and no sample lies on an
  edge (the tie rule is the implementation's);
- a triangle with a vertex outside the frame may be clipped (whether is the implementation's:
  the guard band), and the vertices clipping makes lie on its edges to within float rounding:
  they are taken as snapped vertices that move 2/256 pixel more;
- every depth test that a stencil op hangs on compares depths further apart than the bound on
  how far the plane at that sample moves under that snapping (barycentric coordinates, exact
  bounds), plus a generous allowance for float interpolation, plus one unit for a depth clear
  stored as a float;

so that compare functions, stencil ops, masks, facing, scissor and clears, which the APIs fix,
decide every stencil value. This is a sufficient condition, not the full account of what the
APIs allow: it is what the WebGPU native-pipeline test asserts on.
"""

import os
import sys

import numpy as np

sys.dont_write_bytecode = True  # importing the example must leave no __pycache__ in the tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "examples", "backends"))
import numpy_backend as model  # noqa: E402

SNAP = 16  # the largest move of a coordinate, in 1/256 pixel, under 4 sub-pixel bits
UNIT = 16777215.0


def edge(a, b, Xc, Yc, move):
    """E(a -> b) at the samples; whether its sign survives a and b moving by up to `move`
    (1/256 pixel) along each axis; and a bound on how far E itself can change.

    The sign: a sample at distance d from the line, at parameter t along it, stays on its side
    when d cos(theta) > move sqrt(2) (|1 - t| + |t|), the moved line's offset there, with theta
    the largest turn of the line, sin(theta) <= 2 sqrt(2) move / length."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    E = dx * (Yc - a[1]) - dy * (Xc - a[0])
    length2 = float(dx * dx + dy * dy)
    t = ((Xc - a[0]) * float(dx) + (Yc - a[1]) * float(dy)) / length2
    offset = move * 2**0.5 * (np.abs(1 - t) + np.abs(t))
    turn = min(1.0, 8 * move * move / length2)
    kept = np.abs(E) / length2**0.5 * (1 - turn)**0.5 > offset * (1 + 1e-9) + 1e-6
    bound = move * (2 * np.abs(Yc - a[1]) + 2 * np.abs(Xc - a[0]) + abs(dx) + abs(dy)) \
        + 4 * move * move
    return E, kept, bound


class MarginDevice(model.Device):
    def __init__(self, width, height):
        super().__init__(width, height)
        self.fixed = True
        self.why = None
        # How far each stored depth may be from the contract's, in depth units.
        self.slack = np.zeros((height, width), dtype=np.float64)

    def unfix(self, why):
        if self.fixed:
            self.fixed, self.why = False, why

    def clear_depth(self, d):
        super().clear_depth(d)
        if self.depth_write:  # stored as a float, then converted: a unit either way
            self.slack[self._scissored()] = 1.0

    def triangle(self, v0, v1, v2):
        vs = (v0, v1, v2)
        # A vertex outside the frame: the pipeline may clip, and the vertices clipping makes lie
        # on the edges to within float rounding: taken as 2/256 pixel more.
        outside = any(not (0 <= v[0] <= 256 * self.width and 0 <= v[1] <= 256 * self.height)
                      for v in vs)
        move = SNAP + 2 if outside else SNAP
        A2 = (v1[0] - v0[0]) * (v2[1] - v0[1]) - (v2[0] - v0[0]) * (v1[1] - v0[1])
        bA = 2 * move * (abs(v1[0] - v0[0]) + abs(v2[1] - v0[1]) + abs(v2[0] - v0[0]) +
                         abs(v1[1] - v0[1])) + 8 * move * move
        sx0, sy0, sx1, sy1 = self.scissor
        i_lo = max(min(v[0] for v in vs) // 256 - 1, sx0)
        i_hi = min(max(v[0] for v in vs) // 256 + 1, sx1 - 1)
        j_lo = max(min(v[1] for v in vs) // 256 - 1, sy0)
        j_hi = min(max(v[1] for v in vs) // 256 + 1, sy1 - 1)
        if not self.fixed or i_lo > i_hi or j_lo > j_hi:
            return super().triangle(v0, v1, v2)
        if abs(A2) <= bA:
            self.unfix("a triangle whose facing or area snapping may change")
            return super().triangle(v0, v1, v2)
        Xc = np.arange(i_lo, i_hi + 1, dtype=np.int64)[None, :] * 256 + 128
        Yc = np.arange(j_lo, j_hi + 1, dtype=np.int64)[:, None] * 256 + 128
        sign = 1 if A2 > 0 else -1
        # The barycentric coordinate of vertex k is E(opposite edge) / A2.
        surely_in = np.ones(np.broadcast(Xc, Yc).shape, dtype=bool)
        surely_out = np.zeros_like(surely_in)
        lam_move = np.zeros(surely_in.shape)
        for k in range(3):
            E, kept, b = edge(vs[(k + 1) % 3], vs[(k + 2) % 3], Xc, Yc, move)
            E = sign * E
            surely_in &= (E > 0) & kept
            surely_out |= (E < 0) & kept
            a = float(abs(A2))
            lam_move += (b * a + np.abs(E) * float(bA)) / (a * (a - bA))
        culled = self.cull == ("front" if A2 > 0 else "back")
        if not culled and not (surely_in | surely_out).all():
            self.unfix("a sample within 1/16 pixel of an edge, or on one")
        # How far the fragment depth may move: the plane's move under snapping, then float
        # interpolation (8 ulps of its largest term, measured from a vertex or from the origin).
        zs = [v[2] for v in vs]
        X0, Y0 = v0[0], v0[1]
        e1x, e1y, e2x, e2y = v1[0] - X0, v1[1] - Y0, v2[0] - X0, v2[1] - Y0
        dzdx = ((zs[1] - zs[0]) * e2y - (zs[2] - zs[0]) * e1y) / A2
        dzdy = ((zs[2] - zs[0]) * e1x - (zs[1] - zs[0]) * e2x) / A2
        term = 1 + abs(dzdx) * (np.abs(Xc - X0) + 256 * self.width) + \
            abs(dzdy) * (np.abs(Yc - Y0) + 256 * self.height)
        self._move = (max(zs) - min(zs)) / 2 * lam_move * UNIT + 8 * 2.0**-24 * UNIT * term + 2
        self._box = (i_lo, j_lo)
        super().triangle(v0, v1, v2)

    def fragments(self, i, j, q, ops):
        if not self.fixed:  # decided: the model only runs on
            return super().fragments(i, j, q, ops)
        move = self._move[j - self._box[1], i - self._box[0]]
        s, d = self.stencil[j, i], self.depth[j, i]
        vm = self.value_mask
        s_pass = model.COMPARE[self.stencil_func](self.ref & vm, s & vm)
        if self.depth_func not in ("NEVER", "ALWAYS"):
            close = np.abs(q.astype(np.float64) - d) <= move + self.slack[j, i]
            names = np.array(ops)
            hangs = names[1] != names[2] or self.depth_write
            if hangs and (s_pass & close).any():
                self.unfix("a depth test closer than the native pipeline's depth can be sure of")
        d_pass = s_pass & model.COMPARE[self.depth_func](q, d)
        super().fragments(i, j, q, ops)
        if self.depth_write:
            self.slack[j[d_pass], i[d_pass]] = move[d_pass]


def stencil_fixed(vector):
    """(True, None) when the vector's stencil answer is fixed (the module's doc), else
    (False, the first reason)."""
    dev = MarginDevice(vector["width"], vector["height"])
    for n, c in enumerate(vector["commands"]):
        model.run_command(dev, c, "commands[%d]" % n)
    return dev.fixed, dev.why
