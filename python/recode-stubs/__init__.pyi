# Type stubs for the compiled module `recode` (python/src, pybind11), so that editors complete
# its API and type checkers check calls to it: a PEP 561 stub-only package, installed by
# `pip install .` beside the module and copied next to build/python's module by CMake.
# python/tests/test_stubs.py fails when a public name of the module, a parameter name or a
# property's writability differs from this file: change both together (docs/api.md#python).
import os
from typing import Callable, List, Optional, Sequence, Tuple, TypedDict, Union, overload

import numpy as np
import numpy.typing as npt

from . import conformance as conformance

__version__: str

_Path = Union[str, os.PathLike[str]]
# A pose: a 4 x 4 rigid motion [[R, t], [0, 0, 0, 1]] (any array-like of real numbers).
_Pose = npt.ArrayLike
_FloatArray = npt.NDArray[np.float64]
# ConvexBlock, ClosedMesh, CollisionGeometry, CollisionObject, CollisionRequest, CollisionResult
# and BatchResult pickle and deep-copy (object's __getstate__/__setstate__; docs/api.md#pickling).

class MeshError(ValueError):
    """A block that is not a valid closed convex block, a mesh that is not a valid closed mesh,
    or a malformed mesh file."""

class _DeviceEntry(TypedDict):
    """One entry of devices() (a dict at run time)."""

    name: str
    description: str
    exact: bool
    available: bool
    missing: str

def devices() -> List[_DeviceEntry]:
    """Every device of the registry: name, description, exact (gives the CPU reference's bits),
    available (built into this module) and missing (why not and what to install, else "")."""

class ConvexBlock:
    """A closed convex block, validated when made (recode.MeshError names the problem)."""

    @staticmethod
    def from_arrays(vertices: npt.ArrayLike, faces: npt.ArrayLike, name: str = "block") -> ConvexBlock:
        """(n, 3) vertices and (m, 3) vertex indices, counter-clockwise seen from outside."""
    @staticmethod
    def from_file(path: _Path) -> ConvexBlock:
        """A block from an OBJ or OFF file, named by its path."""
    @staticmethod
    def from_hull(points: npt.ArrayLike, name: str = "hull") -> ConvexBlock:
        """The exact convex hull of an (n, 3) array of points."""
    @staticmethod
    def from_file_hull(path: _Path) -> ConvexBlock:
        """The convex hull of all vertices of an OBJ or OFF file."""
    @property
    def name(self) -> str: ...
    @property
    def vertices(self) -> _FloatArray:
        """(n, 3) float64, read-only."""
    @property
    def faces(self) -> npt.NDArray[np.uint32]:
        """(m, 3) uint32 vertex indices (a copy)."""

class ClosedMesh:
    """A closed mesh of any shape (a torus, a bowl, a hollow part), validated when made; its
    pairs are decided by the layered pair (overlap volume, containment, layers)."""

    @staticmethod
    def from_arrays(vertices: npt.ArrayLike, faces: npt.ArrayLike, name: str = "mesh") -> ClosedMesh:
        """(n, 3) vertices and (m, 3) vertex indices, counter-clockwise seen from outside the solid."""
    @staticmethod
    def from_file(path: _Path) -> ClosedMesh:
        """A closed mesh from an OBJ, OFF, STL or PLY file, named by its path."""
    @property
    def name(self) -> str: ...
    @property
    def vertices(self) -> _FloatArray:
        """(n, 3) float64, read-only."""
    @property
    def faces(self) -> npt.NDArray[np.uint32]:
        """(m, 3) uint32 vertex indices (a copy)."""

def torus(radius: float, tube_radius: float, segments: int = 48, rings: int = 24,
          name: str = "torus") -> ClosedMesh:
    """A torus about the z axis: the tube's centre circle of `radius` in z = 0, tube `tube_radius`."""

def cone(radius: float, height: float, segments: int = 32, name: str = "cone") -> ConvexBlock:
    """Base disc of `radius` in z = 0 centred at the origin, apex at (0, 0, height)."""

def cylinder(radius: float, height: float, segments: int = 32, name: str = "cylinder") -> ConvexBlock:
    """A cylinder along z from z = 0 to z = height."""

def box(hx: float, hy: float, hz: float, name: str = "box") -> ConvexBlock:
    """An axis-aligned box centred at the origin with half extents hx, hy, hz."""

def sphere(radius: float, segments: int = 32, rings: int = 16, name: str = "sphere") -> ConvexBlock:
    """A tessellated sphere centred at the origin."""

class CollisionGeometry:
    """An object's shape: one or several convex blocks fixed together, or one closed mesh."""

    @staticmethod
    def single(block: ConvexBlock) -> CollisionGeometry: ...
    @staticmethod
    def closed(mesh: ClosedMesh) -> CollisionGeometry:
        """A closed mesh as an object's whole shape (block 0 in results)."""
    @property
    def closed_mesh(self) -> Optional[ClosedMesh]:
        """The ClosedMesh of a geometry made by closed(); None for convex blocks."""
    @staticmethod
    def compound(parts: Sequence[Union[ConvexBlock, Tuple[ConvexBlock, _Pose]]],
                 name: str = "compound") -> CollisionGeometry:
        """Blocks, each a ConvexBlock or a (ConvexBlock, 4 x 4 pose in the object) tuple."""
    @staticmethod
    def from_obj_groups(path: _Path, hull: bool = False) -> CollisionGeometry:
        """One block per object or group of an OBJ file, validated or, with hull=True, hulled."""
    @property
    def block_count(self) -> int: ...
    def __len__(self) -> int: ...
    def block(self, index: int) -> ConvexBlock: ...
    def block_pose(self, index: int) -> _FloatArray:
        """Block `index`'s pose in the object, 4 x 4."""

class CollisionObject:
    """A shape at a pose (object -> world): a 4 x 4 matrix, or rotation and translation."""

    def __init__(self, shape: Union[ConvexBlock, ClosedMesh, CollisionGeometry], pose: Optional[_Pose] = None, *,
                 rotation: Optional[npt.ArrayLike] = None,
                 translation: Optional[npt.ArrayLike] = None) -> None: ...
    def set_transform(self, pose: Optional[_Pose] = None, *, rotation: Optional[npt.ArrayLike] = None,
                      translation: Optional[npt.ArrayLike] = None) -> None:
        """Moves the object (its world boxes follow)."""
    @property
    def transform(self) -> _FloatArray:
        """The pose, 4 x 4 (a copy)."""
    @property
    def geometry(self) -> CollisionGeometry: ...
    @property
    def world_box(self) -> Optional[_FloatArray]:
        """[[min x, y, z], [max x, y, z]] of the object at its pose."""

class CollisionRequest:
    """What collide() measures and how finely (docs/api.md)."""

    def __init__(self, *, pixel_size: Optional[float] = None, resolution: int = 256, mor: str = "min",
                 axis: str = "auto", contact: bool = True, normal: bool = False,
                 mode: str = "reference", threads: int = 1) -> None: ...
    pixel_size: Optional[float]
    resolution: int
    mor: str
    """'min', 'max' or 'full'."""
    axis: str
    """'x', 'y', 'z' or 'auto'."""
    contact: bool
    normal: bool
    mode: str
    """'reference', 'adaptive', 'conservative' or 'skip-apart'."""
    threads: int

class Frame:
    """The frame a block pair was drawn in."""

    @property
    def axis(self) -> str: ...
    @property
    def window(self) -> Tuple[float, float, float, float]:
        """(umin, vmin, umax, vmax) in world units on the image plane."""
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def pixel_size(self) -> float: ...

class ContactRegion:
    @property
    def points(self) -> _FloatArray:
        """(n, 3) float64, one world point per interfering pixel (read-only)."""
    @property
    def box(self) -> Optional[_FloatArray]:
        """[[min], [max]] of the overlap intervals' ends, or None."""
    @property
    def pixels(self) -> int: ...
    @property
    def area(self) -> float: ...
    @property
    def max_depth(self) -> float: ...
    @property
    def collapsed_pixels(self) -> int: ...
    @property
    def normal(self) -> Optional[_FloatArray]:
        """Unit normal from block A towards block B (3,); None unless the request asked for it."""
    @property
    def penetration_depth(self) -> Optional[float]: ...

class BlockContact:
    """One pair of blocks whose pixels interfere."""

    @property
    def block_a(self) -> int: ...
    @property
    def block_b(self) -> int: ...
    @property
    def frame(self) -> Frame: ...
    @property
    def layered(self) -> bool:
        """Decided by the layered pair (a closed mesh took part): no cases, an empty case map."""
    @property
    def case_counts(self) -> npt.NDArray[np.int64]:
        """Pixels of each case 0-8 inside the MOR, int64 (9,); zeros for a layered contact."""
    @property
    def case_map(self) -> npt.NDArray[np.uint8]:
        """uint8 (rows, columns) over the MOR, read-only, row 0 the bottom row; (0, 0) if layered."""
    @property
    def mor(self) -> Tuple[int, int, int, int]:
        """(x0, y0, x1, y1) in pixels, half-open, y from the bottom."""
    @property
    def interfering_pixels(self) -> int: ...
    @property
    def contact(self) -> ContactRegion: ...
    @property
    def refine_level(self) -> int: ...
    @property
    def timing_us(self) -> float: ...

class LayeredResult:
    """What the layered pair found for two objects of which one or both are closed meshes."""

    @property
    def frame(self) -> Frame:
        """The frame it was drawn in (width 0 when the boxes did not meet)."""
    @property
    def collide(self) -> bool: ...
    @property
    def interfering_pixels(self) -> int: ...
    @property
    def overlap_volume(self) -> float:
        """Estimated volume of the intersection, world units cubed."""
    @property
    def containment(self) -> str:
        """'none', 'a_inside_b', 'b_inside_a' or 'same'."""
    @property
    def layers(self) -> Tuple[int, int]:
        """The most entries of A and of B at one pixel."""
    @property
    def passes(self) -> int: ...
    @property
    def mor(self) -> Tuple[int, int, int, int]: ...
    @property
    def overlap_steps(self) -> npt.NDArray[np.uint32]:
        """(rows, columns) over the MOR: each pixel's overlap length in depth steps (read-only)."""
    @property
    def interferes(self) -> npt.NDArray[np.uint8]:
        """(rows, columns) over the MOR: 1 where the pixel interferes (read-only)."""
    @property
    def contact(self) -> ContactRegion: ...
    @property
    def timing_us(self) -> float: ...

class CollisionResult:
    @property
    def collide(self) -> bool: ...
    def __bool__(self) -> bool: ...
    @property
    def interfering_pixels(self) -> int: ...
    @property
    def contact(self) -> ContactRegion:
        """The union over the block pairs in contact."""
    @property
    def contacts(self) -> List[BlockContact]: ...
    @property
    def case_counts(self) -> npt.NDArray[np.int64]: ...
    @property
    def case_map(self) -> Optional[npt.NDArray[np.uint8]]:
        """The one block pair's case map (None without contact; ValueError with several)."""
    @property
    def layered(self) -> Optional[LayeredResult]:
        """The layered pair's result when a closed mesh took part; None for convex blocks."""
    @property
    def box_tests(self) -> int: ...
    @property
    def block_pairs_drawn(self) -> int: ...
    @property
    def block_pairs_skipped(self) -> int: ...
    @property
    def collision_us(self) -> float: ...
    @property
    def device_setup_us(self) -> float: ...
    @property
    def apart_at_limit(self) -> int: ...

def collide(a: CollisionObject, b: CollisionObject, request: Optional[CollisionRequest] = None, *,
            device: str = "cpu") -> CollisionResult:
    """Collides two objects at their current poses. device: a name of devices()."""

class BatchResult:
    """The answers of collide_batch or collide_poses as arrays, one entry per query (leading
    shape `shape`): what collide() returns for the same pair at the same poses."""

    @property
    def collide(self) -> npt.NDArray[np.bool_]: ...
    @property
    def interfering_pixels(self) -> npt.NDArray[np.int64]: ...
    @property
    def contact_pixels(self) -> npt.NDArray[np.int64]: ...
    @property
    def case_counts(self) -> npt.NDArray[np.int64]:
        """(..., 9): cases 0-8 summed over the block pairs in contact."""
    @property
    def contact_box(self) -> _FloatArray:
        """(..., 2, 3): [[min], [max]] of result.contact.box; NaN without one."""
    @property
    def contact_area(self) -> _FloatArray: ...
    @property
    def max_depth(self) -> _FloatArray: ...
    @property
    def normal(self) -> _FloatArray:
        """(..., 3) with request.normal (the block contact with the most pixels); else NaN."""
    @property
    def penetration_depth(self) -> _FloatArray: ...
    @property
    def block_pairs_drawn(self) -> npt.NDArray[np.int64]: ...
    @property
    def collision_us(self) -> _FloatArray: ...
    @property
    def layered(self) -> npt.NDArray[np.bool_]:
        """A closed mesh took part: the layered pair decided the query."""
    @property
    def overlap_volume(self) -> _FloatArray:
        """The layered pair's intersection volume; NaN where no closed mesh took part."""
    @property
    def containment(self) -> npt.NDArray[np.int8]:
        """Index into CONTAINMENT; -1 where no closed mesh took part."""
    @property
    def layers(self) -> npt.NDArray[np.int32]:
        """(..., 2): the most entries of A and of B at one pixel; 0 where not layered."""
    @property
    def passes(self) -> npt.NDArray[np.int64]: ...
    @property
    def shape(self) -> Tuple[int, ...]: ...
    def __len__(self) -> int: ...

CONTAINMENT: Tuple[str, ...]
"""BatchResult.containment's codes by index: ('none', 'a_inside_b', 'b_inside_a', 'same')."""

def collide_batch(objects: Sequence[CollisionObject], pairs: npt.ArrayLike,
                  poses: Optional[npt.ArrayLike] = None, *, request: Optional[CollisionRequest] = None,
                  device: str = "cpu", progress: Optional[Callable[[int], object]] = None) -> BatchResult:
    """objects[pairs[k, 0]] with objects[pairs[k, 1]] for each row of pairs (K, 2): at the
    objects' poses, at `poses` (M, 4, 4) or (M, 7), or at frames of them (F, M, 4, 4) or
    (F, M, 7). Runs without the GIL; Ctrl-C raises KeyboardInterrupt. progress(n), e.g. a tqdm
    bar's update: the queries done since its last call, at most five times a second."""

def collide_poses(a: CollisionObject, b: CollisionObject, poses_a: Optional[npt.ArrayLike] = None,
                  poses_b: Optional[npt.ArrayLike] = None, *, request: Optional[CollisionRequest] = None,
                  device: str = "cpu", progress: Optional[Callable[[int], object]] = None) -> BatchResult:
    """a with b at N poses: poses_a and/or poses_b (N, 4, 4) or (N, 7) x, y, z, qx, qy, qz, qw.
    Ctrl-C and progress as in collide_batch."""

class ObjectContact:
    """One pair of objects in contact, a < b."""

    @property
    def a(self) -> int: ...
    @property
    def b(self) -> int: ...
    @property
    def result(self) -> CollisionResult: ...

class _ManagerStats(TypedDict):
    """CollisionManager.stats (a dict at run time)."""

    candidate_pairs: int
    pairs_in_contact: int

class CollisionManager:
    """Many objects: sort and sweep on their world boxes, then collide() on each candidate pair."""

    def __init__(self, *, device: str = "cpu") -> None: ...
    def add(self, object: CollisionObject) -> int:
        """Adds an object (shared: moving it moves it here); returns its id."""
    def remove(self, id: int) -> None: ...
    def update(self, id: int, pose: Optional[_Pose] = None, *, rotation: Optional[npt.ArrayLike] = None,
               translation: Optional[npt.ArrayLike] = None) -> None: ...
    def object(self, id: int) -> CollisionObject: ...
    def __len__(self) -> int: ...
    @overload
    def collide(self, request: Optional[CollisionRequest] = None, callback: None = None) -> List[ObjectContact]: ...
    @overload
    def collide(self, request: Optional[CollisionRequest],
                callback: Callable[[int, int, CollisionResult], None]) -> None: ...
    @property
    def stats(self) -> _ManagerStats:
        """Of the last collide(): candidate_pairs, pairs_in_contact."""
