"""The frames of an animated character as deformseg reads an animation: every frame's evaluated
meshes (armature, shape keys, any modifier) in world space, as one mesh, triangulated, its
coinciding vertices welded.

Blender's coordinates are turned into glTF's (Y up): the figures then equal the tool's on the
glTF file the character came from, and a motion store described from glTF files is searched with
the up direction its clips were described with.
"""
from dataclasses import dataclass

import numpy as np

# Blender's Z-up world to glTF's Y-up: (x, y, z) -> (x, z, -y), as the glTF exporter writes it.
BLENDER_TO_GLTF = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])

# Vertices coincide when they are this share of the bounding box's diagonal apart or closer, in
# every frame: the tolerance of deformseg's welding of glTF, FBX and Collada files.
WELD_TOLERANCE = 1e-6


class TopologyChanged(ValueError):
    """The mesh's triangles change over the frames: it is not one deforming mesh."""


@dataclass
class Frames:
    """An animation as deformseg takes it, and how it maps back onto the Blender meshes.

    faces: (F, 3) welded vertex indices; positions: (T, V, 3) float64, Y up; frame_numbers: the
    scene frames sampled, in order; objects: the names of the mesh objects sampled, as one mesh;
    triangle_object: (F,) the index in objects of each triangle's object; triangle_polygon: (F,)
    the polygon of that object's mesh it comes from; vertex_source: (V,) an input vertex of each
    welded vertex (the objects' vertices numbered one after the other).
    """

    faces: np.ndarray
    positions: np.ndarray
    frame_numbers: list
    objects: list
    triangle_object: np.ndarray
    triangle_polygon: np.ndarray
    vertex_source: np.ndarray
    fps: float


def _triangles(mesh):
    """The mesh's loop triangles as (vertex indices (N, 3), polygon of each (N,))."""
    if hasattr(mesh, "calc_loop_triangles"):  # Blender 4.2 computes them on demand, without it
        mesh.calc_loop_triangles()
    count = len(mesh.loop_triangles)
    vertices = np.empty(count * 3, dtype=np.int64)
    polygons = np.empty(count, dtype=np.int64)
    mesh.loop_triangles.foreach_get("vertices", vertices)
    mesh.loop_triangles.foreach_get("polygon_index", polygons)
    return vertices.reshape(count, 3), polygons


def _world_positions(mesh, matrix_world):
    """The mesh's vertex positions in world space, then in glTF's axes, as float64 (V, 3)."""
    co = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    co = co.reshape(-1, 3).astype(np.float64)
    matrix = np.array(matrix_world, dtype=np.float64)
    world = co @ matrix[:3, :3].T + matrix[:3, 3]
    return world @ BLENDER_TO_GLTF.T


class FrameSampler:
    """Samples mesh objects frame by frame as one mesh (a character's body, head and props), so
    that a modal operator can take one frame per step.

    Call step() once per frame until done, then result(). The scene's current frame is put back
    by restore().
    """

    def __init__(self, context, objects, frame_numbers):
        objects = list(objects)
        if not objects or any(obj is None or obj.type != 'MESH' for obj in objects):
            raise ValueError("select a character (its mesh, or the armature that deforms it)")
        self.context = context
        self.objects = objects
        self.frame_numbers = list(frame_numbers)
        if len(self.frame_numbers) < 2:
            raise ValueError("the frame range holds fewer than 2 frames")
        self.initial_frame = context.scene.frame_current
        self.topology = None  # per object: (triangles, polygons, vertex count) of the first frame
        self.positions = []

    @property
    def done(self):
        return len(self.positions) == len(self.frame_numbers)

    def step(self):
        """Evaluates the next frame: each mesh with every modifier, as the viewport shows it."""
        frame = self.frame_numbers[len(self.positions)]
        self.context.scene.frame_set(frame)
        depsgraph = self.context.evaluated_depsgraph_get()
        topology, positions = [], []
        for obj in self.objects:
            evaluated = obj.evaluated_get(depsgraph)
            mesh = evaluated.to_mesh()
            try:
                triangles, polygons = _triangles(mesh)
                topology.append((triangles, polygons, len(mesh.vertices)))
                positions.append(_world_positions(mesh, evaluated.matrix_world))
            finally:
                evaluated.to_mesh_clear()
        if self.topology is None:
            self.topology = topology
        else:
            self._check_topology(topology, frame)
        self.positions.append(np.concatenate(positions))

    def _check_topology(self, topology, frame):
        """Refuses a mesh whose triangles change: deformseg needs one connectivity for all frames."""
        for obj, (triangles, _, vertices), (first_triangles, _, first_vertices) in zip(
                self.objects, topology, self.topology):
            if len(triangles) != len(first_triangles) or vertices != first_vertices:
                raise TopologyChanged(
                    f"{obj.name} has {len(first_triangles)} triangles and {first_vertices} vertices at frame "
                    f"{self.frame_numbers[0]} but {len(triangles)} and {vertices} at frame {frame}: deformseg "
                    f"needs one mesh whose vertices move (a modifier such as Decimate, Remesh or a fluid "
                    f"changes the mesh over time)")
            if not np.array_equal(triangles, first_triangles):
                raise TopologyChanged(f"{obj.name}'s triangles change at frame {frame}: deformseg needs fixed "
                                      f"connectivity")

    def restore(self):
        """Puts the scene back on the frame it was on."""
        self.context.scene.frame_set(self.initial_frame)

    def result(self):
        """The sampled frames, the objects' meshes as one, welded (see weld)."""
        scene = self.context.scene
        offsets = np.cumsum([0] + [vertices for _, _, vertices in self.topology])
        triangles = np.concatenate([t + offsets[i] for i, (t, _, _) in enumerate(self.topology)])
        polygons = np.concatenate([p for _, p, _ in self.topology])
        owners = np.concatenate([np.full(len(t), i) for i, (t, _, _) in enumerate(self.topology)])
        frames = weld(triangles, polygons, owners, np.stack(self.positions), self.frame_numbers,
                      scene.render.fps / scene.render.fps_base)
        frames.objects = [obj.name for obj in self.objects]
        return frames


def weld(triangles, polygons, owners, positions, frame_numbers, fps):
    """Merges the vertices that coincide in every frame, as deformseg welds a character file.

    Blender keeps a vertex per glTF vertex, so a triangle soup (the Fox) or a seam of UVs is a
    mesh of separate pieces there; deformseg welds them (rest position and influences equal), so
    the strain's normalisation and the segments see one surface. Welding by the positions in
    every frame (rounded to WELD_TOLERANCE of the diagonal, so exact copies always weld) gives
    the same vertices for a skinned mesh. Triangles that repeat a vertex after
    the weld, and repeats of a triangle, are dropped as deformseg drops them.
    """
    frames, count = positions.shape[0], positions.shape[1]
    low, high = positions.reshape(-1, 3).min(axis=0), positions.reshape(-1, 3).max(axis=0)
    step = max(float(np.linalg.norm(high - low)) * WELD_TOLERANCE, 1e-30)
    trajectories = np.round(positions.transpose(1, 0, 2).reshape(count, frames * 3) / step).astype(np.int64)
    # Vertices of different objects are never welded: deformseg welds vertices of one node only
    # (a sword's vertex on its hand's stays apart, as do two shields held in one hand).
    vertex_owner = np.zeros(count, dtype=np.int64)
    vertex_owner[triangles.ravel()] = np.repeat(owners, 3)
    trajectories = np.concatenate([vertex_owner[:, None], trajectories], axis=1)
    # Only vertices used by a triangle are kept, numbered by their first use.
    _, first_of_class, class_of = np.unique(trajectories, axis=0, return_index=True, return_inverse=True)
    class_of = class_of.ravel()
    representative = first_of_class[class_of]          # each vertex's first coinciding vertex
    order = np.unique(representative[triangles.ravel()], return_index=True)[1]
    kept = representative[triangles.ravel()][np.sort(order)]  # welded vertices by first use
    new_index = np.full(count, -1, dtype=np.int64)
    new_index[kept] = np.arange(len(kept))
    faces = new_index[representative[triangles]]
    keep = (faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 0] != faces[:, 2])
    _, unique_rows = np.unique(np.sort(faces, axis=1), axis=0, return_index=True)
    first = np.zeros(len(faces), dtype=bool)
    first[unique_rows] = True
    keep &= first
    return Frames(faces=faces[keep].astype(np.uint32), positions=np.ascontiguousarray(positions[:, kept]),
                  frame_numbers=list(frame_numbers), objects=[], triangle_object=owners[keep],
                  triangle_polygon=polygons[keep], vertex_source=kept, fps=fps)


def sample(context, objects, frame_numbers):
    """Samples every frame at once (the blocking path: scripts, tests, background mode)."""
    sampler = FrameSampler(context, objects, frame_numbers)
    try:
        while not sampler.done:
            sampler.step()
    finally:
        sampler.restore()
    return sampler.result()
