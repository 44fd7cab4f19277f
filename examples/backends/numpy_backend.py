#!/usr/bin/env python3
"""A conformance back end in Python + NumPy, written from docs/rasterization.md alone.

It speaks "recode-conform-1" (docs/conformance.md): a greeting, then one JSON request per
line on stdin (a golden vector's `commands` for a fresh width x height framebuffer) and one
JSON answer per line on stdout (both buffers, flat, bottom row first). Run it with

    recode conform --exec "python3 examples/backends/numpy_backend.py"

Each rule of the contract is one function or method below that cites its section. Work is
vectorised with NumPy per triangle over the candidate pixels of its bounding box, so even
16384-pixel frames cost no Python loop per pixel. The fill rule's tie decision is the module-level
function `inclusive`; numpy_backend_top_left.py replaces it to show a broken back end.
Needs Python 3.11 and NumPy only.
"""
import json
import sys

import numpy as np

PROTOCOL = "recode-conform-1"
NAME = "numpy_backend.py (example, rasterization.md sections 1-6)"
DEPTH_MAX = 16777215          # section 1: 24-bit depth, 2^24 - 1 is depth 1.0
COORD_MAX = 1 << 23           # section 2: |X|, |Y| <= 2^23 in 24.8 fixed point (32768 px)
SIZE_MAX = 16384              # section 1: 1 <= W, H <= 16384
BAND_SAMPLES = 1 << 20        # candidate samples per NumPy pass (memory, not bits)


class Refused(Exception):
    """The stream is invalid for the device (section 2): answered as {"refused": ...}."""


class ProtocolError(Exception):
    """Input that is not the protocol or not a command stream: we stop with a message."""


# --- Section 4: coverage and the fill rule -----------------------------------------------

def inclusive(dx, dy):
    """Does a counter-clockwise (y up) edge own the samples exactly on it? (section 4)

    Left edges (running down) and bottom edges (horizontal, running right) do. Exactly one
    of (dx, dy) and (-dx, -dy) is inclusive, so a shared edge draws each sample once. This
    is the one rule numpy_backend_top_left.py swaps, which is why it stands alone.
    """
    return dy < 0 or (dy == 0 and dx > 0)


def coverage(ccw, Xc, Yc):
    """Boolean grid of covered samples for counter-clockwise vertices (section 4).

    E = dx (Yc - Ya) - dy (Xc - Xa) in int64: products reach 2^48, which float32 (or
    int32) cannot hold exactly. E' = E - (0 if inclusive else 1) >= 0 on all three edges.
    """
    covered = np.ones(np.broadcast(Xc, Yc).shape, dtype=bool)
    for (Xa, Ya, _), (Xb, Yb, _) in zip(ccw, ccw[1:] + ccw[:1]):
        dx, dy = Xb - Xa, Yb - Ya
        E = dx * (Yc - Ya) - dy * (Xc - Xa)
        covered &= E >= (0 if inclusive(dx, dy) else 1)
    return covered


# --- Section 5: depth ----------------------------------------------------------------------

def plane_depth(v0, v1, v2, A2, Xc, Yc):
    """Plane depth (double) at fragment centres, in exactly section 5's order.

    Anchored at the first *submitted* vertex; every step is a separately rounded IEEE double
    operation (Python floats and NumPy float64 ufuncs never fuse a multiply into an add).
    """
    (X0, Y0, z0), (X1, Y1, z1), (X2, Y2, z2) = v0, v1, v2
    dz1 = z1 - z0
    dz2 = z2 - z0
    e1x, e1y = float(X1 - X0), float(Y1 - Y0)   # exact: |differences| <= 2^24
    e2x, e2y = float(X2 - X0), float(Y2 - Y0)
    a2 = float(A2)                                # exact: |A2| < 2^49
    dzdx = (dz1 * e2y - dz2 * e1y) / a2
    dzdy = (dz2 * e1x - dz1 * e2x) / a2
    tx = dzdx * (Xc - X0).astype(np.float64)
    ty = dzdy * (Yc - Y0).astype(np.float64)
    return (z0 + tx) + ty                         # (z0 + tx) first, then + ty


def quantise(z):
    """Clamp and quantise double depths to 24 bits (section 5), ties to even via np.rint."""
    z = np.asarray(z, dtype=np.float64)
    # Clamp before scaling; `z > 0` is False for NaN, which must give 0.
    scaled = np.where(z > 0, np.where(z < 1, z * 16777215.0, float(DEPTH_MAX)), 0.0)
    return np.rint(scaled).astype(np.int64)


# --- Section 6: compare functions and stencil ops ----------------------------------------

# `incoming FUNC stored`: LESS passes when incoming < stored. Arrays of booleans out.
COMPARE = {"NEVER": lambda a, b: np.zeros(np.broadcast(a, b).shape, dtype=bool),
           "LESS": np.less, "EQUAL": np.equal, "LEQUAL": np.less_equal,
           "GREATER": np.greater, "NOTEQUAL": np.not_equal, "GEQUAL": np.greater_equal,
           "ALWAYS": lambda a, b: np.ones(np.broadcast(a, b).shape, dtype=bool)}

# Stencil ops on 8-bit values held in int32 arrays: (stored s, ref) -> new value.
STENCIL_OPS = {
    "KEEP": lambda s, ref: s,
    "ZERO": lambda s, ref: np.zeros_like(s),
    "REPLACE": lambda s, ref: np.full_like(s, ref),
    "INCR": lambda s, ref: np.minimum(s + 1, 255),      # saturates
    "INCR_WRAP": lambda s, ref: (s + 1) & 255,
    "DECR": lambda s, ref: np.maximum(s - 1, 0),        # saturates
    "DECR_WRAP": lambda s, ref: (s - 1) & 255,
    "INVERT": lambda s, ref: 255 - s,
}


class Device:
    """One depth/stencil framebuffer and its state (sections 1 and 6).

    Buffers are (height, width) arrays indexed [j, i] with row j = 0 at the bottom, so a
    C-order ravel is already the protocol's "bottom row first" order.
    """

    def __init__(self, width, height):
        self.width, self.height = width, height
        # int32 is plenty for 24-bit depth and 8-bit stencil and halves a 16384^2 frame.
        self.depth = np.full((height, width), DEPTH_MAX, dtype=np.int32)
        self.stencil = np.zeros((height, width), dtype=np.int32)
        # Section 6 defaults (GL's).
        self.depth_func, self.depth_write = "LESS", True
        self.stencil_func, self.ref, self.value_mask = "ALWAYS", 0, 0xFF
        self.ops = {"front": ("KEEP", "KEEP", "KEEP"), "back": ("KEEP", "KEEP", "KEEP")}
        self.write_mask, self.cull = 0xFF, "none"
        self.scissor = (0, 0, width, height)

    # Section 1/8: rectangles are half-open; the scissor is clamped to the framebuffer and an
    # inverted one is simply empty.
    def set_scissor(self, x0, y0, x1, y1):
        clamp = lambda v, hi: min(max(v, 0), hi)
        x0, x1 = clamp(x0, self.width), clamp(x1, self.width)
        y0, y1 = clamp(y0, self.height), clamp(y1, self.height)
        self.scissor = (x0, y0, max(x0, x1), max(y0, y1))

    def _scissored(self):
        x0, y0, x1, y1 = self.scissor
        return np.s_[y0:y1, x0:x1]

    # Section 6: clears honour the scissor and the write masks, as in GL.
    def clear_depth(self, d):
        if not np.isfinite(d):               # the interface throws; [0, 1] is clamped below
            raise Refused(f"clear_depth value {d} is not finite")
        if self.depth_write:
            self.depth[self._scissored()] = quantise(d)

    def clear_stencil(self, v):
        region = self._scissored()
        wm = self.write_mask
        self.stencil[region] = (v & wm) | (self.stencil[region] & ~wm & 0xFF)

    # Section 2: the whole draw is validated before anything is drawn.
    def draw(self, vertices, indices):
        if len(indices) % 3:
            raise Refused(f"index count {len(indices)} is not a multiple of 3")
        for k in indices:
            if not 0 <= k < len(vertices):
                raise Refused(f"index {k} out of range 0..{len(vertices) - 1}")
        for k in sorted(set(indices)):       # only referenced vertices are checked
            X, Y, z = vertices[k]
            if abs(X) > COORD_MAX or abs(Y) > COORD_MAX:
                raise Refused(f"vertex {k}: |X| or |Y| above 2^23 (32768 pixels)")
            if not 0.0 <= z <= 1.0:          # also False for NaN
                raise Refused(f"vertex {k}: depth {z} outside [0, 1]")
        for t in range(0, len(indices), 3):  # triangles in index order (section 6)
            self.triangle(*(vertices[k] for k in indices[t:t + 3]))

    def triangle(self, v0, v1, v2):
        (X0, Y0, _), (X1, Y1, _), (X2, Y2, _) = v0, v1, v2
        # Section 3: exact doubled area (Python ints are exact), facing and culling.
        A2 = (X1 - X0) * (Y2 - Y0) - (X2 - X0) * (Y1 - Y0)
        if A2 == 0:
            return
        front = A2 > 0
        if self.cull == ("front" if front else "back"):
            return
        ccw = (v0, v1, v2) if front else (v0, v2, v1)    # section 4 wants CCW edges
        ops = self.ops["front" if front else "back"]
        # Candidates (section 7, informative): pixels whose centre 256 i + 128 lies in the
        # snapped bounding box, clipped to the scissor. ceil(a / 256) is -((-a) // 256).
        sx0, sy0, sx1, sy1 = self.scissor
        i_lo = max(-((128 - min(X0, X1, X2)) // 256), sx0)
        i_hi = min((max(X0, X1, X2) - 128) // 256, sx1 - 1)
        j_lo = max(-((128 - min(Y0, Y1, Y2)) // 256), sy0)
        j_hi = min((max(Y0, Y1, Y2) - 128) // 256, sy1 - 1)
        if i_lo > i_hi or j_lo > j_hi:
            return
        Xc = np.arange(i_lo, i_hi + 1, dtype=np.int64)[None, :] * 256 + 128
        # Bands of rows keep the int64 grids near a million samples even on a 16384^2 frame;
        # a triangle's fragments are independent, so cutting it up changes no bits.
        band = max(1, BAND_SAMPLES // (i_hi - i_lo + 1))
        for b in range(j_lo, j_hi + 1, band):
            Yc = np.arange(b, min(b + band, j_hi + 1), dtype=np.int64)[:, None] * 256 + 128
            jj, ii = np.nonzero(coverage(ccw, Xc, Yc))
            if ii.size:
                i, j = ii + i_lo, jj + b
                q = quantise(plane_depth(v0, v1, v2, A2, i * 256 + 128, j * 256 + 128))
                self.fragments(i, j, q, ops)

    # Section 6: per-fragment stencil test, depth test and stencil update. A triangle covers
    # each pixel at most once, so one vectorised gather/scatter per triangle is exact.
    def fragments(self, i, j, q, ops):
        s, d = self.stencil[j, i], self.depth[j, i]
        vm = self.value_mask
        s_pass = COMPARE[self.stencil_func](self.ref & vm, s & vm)
        d_pass = s_pass & COMPARE[self.depth_func](q, d)
        sfail, dpfail, dppass = (STENCIL_OPS[name](s, self.ref) for name in ops)
        n = np.where(~s_pass, sfail, np.where(d_pass, dppass, dpfail))
        wm = self.write_mask
        self.stencil[j, i] = (n & wm) | (s & ~wm & 0xFF)
        if self.depth_write:
            self.depth[j[d_pass], i[d_pass]] = q[d_pass]


# --- Section 8 and docs/conformance.md: commands and the protocol -----------------------
# Malformed input (a wrong type, a missing key, an unknown name) is not a refusal of section 2
# but a broken protocol: it raises ProtocolError and main() stops with a message.

def _int(value, what, lo=-2**31, hi=2**31 - 1):
    # type() rather than isinstance(): JSON true/false are bools, which Python counts as ints.
    if type(value) is not int or not lo <= value <= hi:
        raise ProtocolError(f"{what}: expected an integer in {lo}..{hi}, got {value!r}")
    return value


def _number(value, what):
    if type(value) not in (int, float):
        raise ProtocolError(f"{what}: expected a number, got {value!r}")
    return float(value)


def _name(value, allowed, what):
    if value not in allowed:
        raise ProtocolError(f"{what}: unknown name {value!r}")
    return value


def _vertex(v, what):
    if not isinstance(v, list) or len(v) != 3:
        raise ProtocolError(f"{what}: expected [X, Y, z]")
    # X, Y are already 24.8 fixed point (section 8), so section 2's snapping is the identity;
    # their range is section 2's to refuse, not ours. z is a single-precision float: round
    # the JSON double to float32, then widen it exactly to the double section 5 starts from.
    return (_int(v[0], what, -2**63, 2**63 - 1), _int(v[1], what, -2**63, 2**63 - 1),
            float(np.float32(_number(v[2], what))))


def run_command(dev, c, where):
    op = c["op"]
    if op == "scissor":
        if not isinstance(c["rect"], list) or len(c["rect"]) != 4:
            raise ProtocolError(f"{where}.rect: expected [x0, y0, x1, y1]")
        dev.set_scissor(*(_int(v, where + ".rect") for v in c["rect"]))
    elif op == "clear_depth":                # a double, not rounded to float like vertex z
        dev.clear_depth(_number(c["value"], where + ".value"))
    elif op == "clear_stencil":
        dev.clear_stencil(_int(c["value"], where + ".value", 0, 255))
    elif op == "depth_func":
        dev.depth_func = _name(c["func"], COMPARE, where + ".func")
    elif op == "depth_write_mask":
        if type(c["write"]) is not bool:     # not `in (True, False)`: 1 == True in Python
            raise ProtocolError(f"{where}.write: expected true or false")
        dev.depth_write = c["write"]
    elif op == "stencil_func":
        dev.stencil_func = _name(c["func"], COMPARE, where + ".func")
        dev.ref = _int(c["ref"], where + ".ref", 0, 255)
        dev.value_mask = _int(c["value_mask"], where + ".value_mask", 0, 255)
    elif op == "stencil_ops":
        ops = tuple(_name(c[k], STENCIL_OPS, f"{where}.{k}")
                    for k in ("sfail", "dpfail", "dppass"))
        face = _name(c["face"], ("front", "back", "both"), where + ".face")
        for f in (("front", "back") if face == "both" else (face,)):
            dev.ops[f] = ops
    elif op == "stencil_write_mask":
        dev.write_mask = _int(c["mask"], where + ".mask", 0, 255)
    elif op == "cull":
        dev.cull = _name(c["mode"], ("none", "front", "back"), where + ".mode")
    elif op == "draw":
        dev.draw([_vertex(v, f"{where}.vertices_fixed[{k}]")
                  for k, v in enumerate(c["vertices_fixed"])],
                 [_int(k, where + ".indices", -2**63, 2**63 - 1) for k in c["indices"]])
    else:
        raise ProtocolError(f"{where}.op: unknown command {op!r}")


def run_request(request):
    """Run one request on a fresh framebuffer: (id, Device) or (id, reason it was refused)."""
    if not isinstance(request, dict) or not {"id", "width", "height", "commands"} <= request.keys():
        raise ProtocolError("a request is an object with keys id, width, height, commands")
    rid, commands = request["id"], request["commands"]
    w, h = _int(request["width"], "width"), _int(request["height"], "height")
    if not (1 <= w <= SIZE_MAX and 1 <= h <= SIZE_MAX):
        return rid, f"framebuffer {w}x{h} outside 1..{SIZE_MAX} (section 1)"
    if not isinstance(commands, list):
        raise ProtocolError("commands: expected an array")
    dev = Device(w, h)
    for n, c in enumerate(commands):
        try:
            run_command(dev, c, f"commands[{n}]")
        except Refused as e:
            return rid, f"commands[{n}]: {e}"
        except (KeyError, TypeError) as e:   # a missing key, or not an object/array
            raise ProtocolError(f"commands[{n}]: malformed command ({e!r})") from None
    return rid, dev


def send(obj):
    sys.stdout.write(json.dumps(obj, separators=(",", ":")) + "\n")
    sys.stdout.flush()   # the next request comes only after this answer is read


def send_buffers(rid, dev):
    """Write {"id", "depth", "stencil"} (flat, bottom row first) as one line, in pieces.

    A 16384^2 frame makes a line of gigabytes: building it whole would need a Python int per
    pixel, and CPython 3.11 silently drops all but the first 2 GiB of one such write.
    """
    out = sys.stdout
    out.write('{"id":' + json.dumps(rid))
    for key, flat in (("depth", dev.depth.ravel()), ("stencil", dev.stencil.ravel())):
        out.write(f',"{key}":[')
        for k in range(0, flat.size, BAND_SAMPLES):
            out.write(("," if k else "") + ",".join(map(str, flat[k:k + BAND_SAMPLES].tolist())))
        out.write("]")
    out.write("}\n")
    out.flush()


def read_message():
    line = sys.stdin.readline()
    if not line:
        return None                      # stdin closed: the run is over
    try:
        return json.loads(line)
    except json.JSONDecodeError as e:
        raise ProtocolError(f"not JSON: {e}: {line[:200]!r}") from None


def main():
    try:
        greeting = read_message()
        if greeting != {"protocol": PROTOCOL}:
            raise ProtocolError(f"expected the greeting {{\"protocol\":\"{PROTOCOL}\"}}, "
                                f"got {greeting!r}")
        send({"protocol": PROTOCOL, "name": NAME})
        while (request := read_message()) is not None:
            rid, result = run_request(request)
            if isinstance(result, Device):
                send_buffers(rid, result)
            else:
                send({"id": rid, "refused": result})
    except ProtocolError as e:
        print(f"{sys.argv[0]}: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
