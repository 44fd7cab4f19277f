"""Two cones, tip into tip: the Python twin of examples/two_cones.cpp (docs/api.md#python).

Run from a build tree: PYTHONPATH=build/python python3 examples/python/two_cones.py
"""
import numpy as np

import recode

# A cone of radius 1 and height 2 along z, its apex at z = 2.
cone = recode.cone(radius=1.0, height=2.0, segments=32)
lower = recode.CollisionObject(cone)
# Upside down (a half turn about x), apex at z = 1.75: the tips overlap by 0.25.
half_turn = np.diag([1.0, -1.0, -1.0])
upper = recode.CollisionObject(cone, rotation=half_turn, translation=[0.0, 0.0, 3.75])

# Pixels of 0.01 world units: a tenth of the smallest feature we care about.
result = recode.collide(lower, upper, recode.CollisionRequest(pixel_size=0.01))

print(f"collide: {result.collide}")
print(f"interfering pixels: {result.interfering_pixels}")
box = result.contact.box  # [[min x, y, z], [max x, y, z]], or None without contact
print(f"contact box: {np.round(box, 2).tolist()}")
print(f"greatest depth: {result.contact.max_depth:.3f}, area: {result.contact.area:.4f}")
print(f"case map: {result.case_map.shape} {result.case_map.dtype}, "
      f"{len(result.contact.points)} contact points, {result.collision_us:.0f} us")
