#!/usr/bin/env python3
"""numpy_backend.py with one rule broken: the top-left fill rule instead of the contract's.

This copy exists so that tests (and readers) can check that `recode conform` does not merely
count failures but names the rule a back end broke: it changes nothing but the tie decision of
section 4, letting horizontal edges own the samples on them when they are *top* edges
(dy == 0 and dx < 0 in the counter-clockwise, y-up orientation, as Direct3D and most GPUs
do) instead of bottom edges, while left edges (dy < 0) stay inclusive. Coverage of shared
horizontal edges then moves by a row, so the kit's slivers, fans and shared_edges vectors
fail, and the report should name the variant "top_left_fill". Everything else, protocol
included, is numpy_backend.py's, found beside this file.
"""
import sys

sys.dont_write_bytecode = True   # importing the sibling must not leave __pycache__ in the tree
import numpy_backend             # noqa: E402  (found beside this file: sys.path[0])


def top_left_inclusive(dx, dy):
    """Left edges and *top* edges own their samples (the rule section 4 does not use)."""
    return dy < 0 or (dy == 0 and dx < 0)


numpy_backend.inclusive = top_left_inclusive   # coverage() looks it up at call time
numpy_backend.NAME = "numpy_backend_top_left.py (deliberately broken: top-left fill rule)"

if __name__ == "__main__":
    sys.exit(numpy_backend.main())
