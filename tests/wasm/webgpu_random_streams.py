"""Random command streams (recode-commands-1) for the WebGPU check: every state, sloped planes
with z anywhere in [0, 1], slivers, vertices far outside the framebuffer (up to the +-32768 pixel
guard band), sub-pixel positions and positions on pixel centres and edges. Seeded, so a failure
names a stream that can be made again. The expected buffers are the module's CPU device's
(recode_gpu_commands replays a stream that has none)."""

import random
import struct

COMPARE = ["NEVER", "LESS", "EQUAL", "LEQUAL", "GREATER", "NOTEQUAL", "GEQUAL", "ALWAYS"]
STENCIL_OPS = ["KEEP", "ZERO", "REPLACE", "INCR", "INCR_WRAP", "DECR", "DECR_WRAP", "INVERT"]
GUARD = 32768 * 256  # the guard band in 24.8 fixed point


def as_float(x):
    """x rounded to a float (files must hold z exactly as a float)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def random_z(rng):
    kind = rng.random()
    if kind < 0.1:
        return rng.choice([0.0, 1.0, 0.5])
    if kind < 0.2:
        return as_float(rng.random() * 1e-6)  # tiny: subnormal-adjacent planes
    return as_float(rng.random())


def random_xy(rng, width, height):
    kind = rng.random()
    if kind < 0.1:  # far outside, up to the guard band
        return [rng.randint(-GUARD, GUARD), rng.randint(-GUARD, GUARD)]
    if kind < 0.3:  # on pixel centres and edges
        return [rng.randint(-2, 2 * width + 2) * 128, rng.randint(-2, 2 * height + 2) * 128]
    return [rng.randint(-256 * 4, 256 * (width + 4)), rng.randint(-256 * 4, 256 * (height + 4))]


def random_draw(rng, width, height):
    vertices = []
    for _ in range(rng.randint(3, 6)):
        xy = random_xy(rng, width, height)
        if vertices and rng.random() < 0.2:  # a sliver: near another vertex in one axis
            xy[rng.randint(0, 1)] = vertices[-1][rng.randint(0, 1)] + rng.randint(-3, 3)
        vertices.append(xy + [random_z(rng)])
    indices = [rng.randrange(len(vertices)) for _ in range(3 * rng.randint(1, 4))]
    return {"op": "draw", "vertices_fixed": vertices, "indices": indices}


def random_command(rng, width, height):
    kind = rng.random()
    if kind < 0.4:
        return random_draw(rng, width, height)
    op = rng.choice(["scissor", "clear_depth", "clear_stencil", "depth_func", "depth_write_mask",
                     "stencil_func", "stencil_ops", "stencil_write_mask", "cull"])
    if op == "scissor":
        return {"op": op, "rect": [rng.randint(-2, width), rng.randint(-2, height),
                                   rng.randint(0, width + 2), rng.randint(0, height + 2)]}
    if op == "clear_depth":
        return {"op": op, "value": random_z(rng)}
    if op == "clear_stencil":
        return {"op": op, "value": rng.randint(0, 255)}
    if op == "depth_func":
        return {"op": op, "func": rng.choice(COMPARE)}
    if op == "depth_write_mask":
        return {"op": op, "write": rng.random() < 0.7}
    if op == "stencil_func":
        return {"op": op, "func": rng.choice(COMPARE), "ref": rng.randint(0, 255),
                "value_mask": rng.choice([255, rng.randint(0, 255)])}
    if op == "stencil_ops":
        return {"op": op, "face": rng.choice(["front", "back", "both"]),
                "sfail": rng.choice(STENCIL_OPS), "dpfail": rng.choice(STENCIL_OPS),
                "dppass": rng.choice(STENCIL_OPS)}
    if op == "stencil_write_mask":
        return {"op": op, "mask": rng.choice([255, rng.randint(0, 255)])}
    return {"op": op, "mode": rng.choice(["none", "front", "back"])}


def random_stream(seed):
    """A stream of 30 commands on a framebuffer of 1 to 48 pixels a side."""
    rng = random.Random(seed)
    width, height = rng.randint(1, 48), rng.randint(1, 48)
    return {"format": "recode-commands-1", "width": width, "height": height,
            "commands": [random_command(rng, width, height) for _ in range(30)]}
