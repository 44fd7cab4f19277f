"""One batch split over processes: the module's objects, requests and results pickle, so a batch
can be cut into chunks for a multiprocessing pool (or dask, or any executor that pickles what it
sends) and the chunks' results put back together (docs/api.md#pickling).

Run from a build tree: PYTHONPATH=build/python python3 examples/python/batch_processes.py
"""
import multiprocessing

import numpy as np

import recode


def collide_frames(objects, pairs, frames, request):
    """A worker's share of the batch: its arguments arrive pickled, its result goes back so."""
    return recode.collide_batch(objects, pairs, frames, request=request)


if __name__ == "__main__":
    # Three objects, and 40 frames of their poses: the upper cone comes down, the box passes by.
    cone = recode.cone(radius=1.0, height=2.0, segments=32)
    half_turn = np.diag([1.0, -1.0, -1.0])
    objects = [recode.CollisionObject(cone), recode.CollisionObject(cone, rotation=half_turn),
               recode.CollisionObject(recode.box(0.5, 0.5, 0.5))]
    frames = np.tile(np.eye(4), (40, 3, 1, 1))
    frames[:, 1, :3, :3] = half_turn
    frames[:, 1, 2, 3] = np.linspace(4.5, 3.0, 40)
    frames[:, 2, 0, 3] = np.linspace(-2.0, 2.0, 40)
    pairs = np.array([[0, 1], [0, 2], [1, 2]])
    request = recode.CollisionRequest(pixel_size=0.02)

    # "spawn": fresh interpreters, as on macOS and Windows; all they get is pickled.
    chunks = [(objects, pairs, chunk, request) for chunk in np.array_split(frames, 4)]
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        parts = pool.starmap(collide_frames, chunks)
    collide = np.concatenate([p.collide for p in parts])  # (40, 3): frame-major, as one call
    pixels = np.concatenate([p.interfering_pixels for p in parts])

    one = recode.collide_batch(objects, pairs, frames, request=request)
    same = np.array_equal(collide, one.collide) and np.array_equal(pixels, one.interfering_pixels)
    print(f"frames with a contact: {int(collide.any(axis=1).sum())} of {len(frames)}")
    print(f"same as one process: {same}")
