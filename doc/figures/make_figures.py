#!/usr/bin/python3
"""Renders the manual's figures from the outputs of the deformseg tool.

Usage: /usr/bin/python3 doc/figures/make_figures.py TOOL OUT [--data DIR] [--work DIR] [--only NAME ...]

TOOL is the built `deformseg` program, OUT the folder the PNGs go into. The script makes every
input it needs with the tool: synthetic tubes (`deformseg synth`), and the horse gallop unpacked
from DATA/horse-gallop/horse-gallop.tar.xz into the work folder (DATA defaults to the shared data
folder beside the repository; without it, the horse figures are placeholders that say so).
Nothing is written into the repository. Same inputs, same PNGs: the figures are drawn with a
fixed camera, fixed sizes and no time stamps.

Needs Debian's python3-matplotlib and python3-numpy, and Graphviz's `dot`.
"""

import argparse
import os
import shutil
import subprocess
import sys
import tarfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Optional

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import colors as mcolors  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

from ply import PlyError, read_ply  # noqa: E402

WIDTH_INCHES = 12.0
DPI = 100  # so ~1200 px wide
PNG_METADATA = {"Software": None}  # no matplotlib version in the file: same bytes on every run

# The synthetic tubes, by name: `deformseg synth` arguments after the output folder.
TUBES = {
    # One joint bending to 90 degrees and back (the tool's default schedule).
    "bend_once": ["--schedule", "10:0", "10:90", "10:", "10:0"],
    # The same bend later and faster: warped onto bend_once by DTW, its path leaves the diagonal.
    "bend_once_late": ["--schedule", "20:0", "5:90", "10:", "5:0"],
    # Three held poses with short transitions: clear temporal segments.
    "three_poses": ["--joints", "0.3,0.7", "--schedule", "19:", "4:90,0", "19:", "4:0,90", "19:"],
    # Two joints bending in turn at constant speed: an evolving graph R, R-D-R, R, R-D-R, R.
    "two_joints": ["--joints", "0.3,0.7", "--directions", "0,180", "--easing", "linear",
                   "--schedule", "5:0,0", "10:90,0", "5:", "10:90,90", "5:"],
}

# Cameras: a rotation taking the data's coordinates to the plot's (z up), and matplotlib's view.
@dataclass(frozen=True)
class Camera:
    to_plot: np.ndarray  # 3 x 3
    elev: float
    azim: float


TUBE_CAMERA = Camera(np.eye(3), elev=12.0, azim=-90.0)  # the tube stands on z, bends towards +x
# The horse: x across, y up, z from tail to head; seen from its left side.
HORSE_CAMERA = Camera(np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]), elev=8.0, azim=-90.0)


class FigureError(RuntimeError):
    """A figure could not be made; the message says why."""


class Workspace:
    """The tool, the data folder and the work folder, and the inputs made in it, once each."""

    def __init__(self, tool: Path, data: Optional[Path], work: Path):
        self.tool, self.data, self.work = tool, data, work
        self._made: dict = {}

    def run(self, *args) -> str:
        command = [str(self.tool), *map(str, args)]
        try:
            done = subprocess.run(command, capture_output=True, text=True, check=False)
        except OSError as error:
            raise FigureError(f"cannot run {self.tool}: {error}") from error
        if done.returncode != 0:
            raise FigureError(f"`{' '.join(command)}` failed with exit code {done.returncode}:\n"
                              f"{done.stderr.strip()}")
        return done.stdout

    def _once(self, key, make: Callable[[Path], None]) -> Path:
        if key not in self._made:
            path = self.work / "_".join(part.lstrip("-") for part in key)
            shutil.rmtree(path, ignore_errors=True)
            make(path)
            self._made[key] = path
        return self._made[key]

    def tube(self, name: str) -> Path:
        """The frames of the synthetic tube `name` (see TUBES)."""
        return self._once(("tube", name), lambda path: self.run("synth", path, *TUBES[name]))

    def output(self, command: str, source: Path, option: str, *args) -> Path:
        """The folder or file the tool's `command` writes with `option` for `source`."""
        def make(path):
            self.run(command, source, option, path, *args)
        return self._once((command, source.name, option.lstrip("-"), *map(str, args)), make)

    def horse_gallop(self) -> Path:
        """The 48 frames of the horse gallop (two cycles), unpacked from the shared data."""
        archive = self.data / "horse-gallop" / "horse-gallop.tar.xz" if self.data else None
        if archive is None or not archive.is_file():
            raise DataMissing(f"no horse gallop data ({archive or 'no data folder'})")

        def unpack(path):
            with tarfile.open(archive) as tar:
                if hasattr(tarfile, "data_filter"):
                    tar.extractall(path, filter="data")
                else:
                    tar.extractall(path)
        return self._once(("horse", "gallop"), unpack) / "horse-gallop"

    def horse_gallop_cycle(self) -> Path:
        """One gallop cycle (24 frames) after the reference pose as frame 0, so that the strain
        of frame k is that of gallop frame k against the standing horse."""
        frames = self.horse_gallop()

        def link(path):
            path.mkdir(parents=True)
            os.symlink(frames.parent / "horse-gallop.obj", path / "0000.obj")
            for k in range(1, 25):
                os.symlink(frames / f"{k:04d}.obj", path / f"{k:04d}.obj")
        return self._once(("horse", "cycle"), link)


class DataMissing(FigureError):
    """The shared data a figure needs is not there: the figure becomes a placeholder."""


# ---- Drawing meshes ---------------------------------------------------------------------------

def face_normals(points: np.ndarray, faces: np.ndarray) -> np.ndarray:
    a, b, c = (points[faces[:, k]] for k in range(3))
    n = np.cross(b - a, c - a)
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return n / np.where(length > 0, length, 1.0)


def view_direction(camera: Camera) -> np.ndarray:
    """The unit vector from the scene towards matplotlib's eye, in plot coordinates."""
    e, a = np.radians(camera.elev), np.radians(camera.azim)
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def lambert_shade(rgb: np.ndarray, normals: np.ndarray, camera: Camera) -> np.ndarray:
    """Face colours lit by a light above and to the left of the eye, on both sides of a face,
    with enough ambient light that the colour scale still reads in the shadows."""
    eye = view_direction(camera)
    left = np.cross(eye, [0.0, 0.0, 1.0])
    left /= np.linalg.norm(left)
    light = eye + 0.5 * left + 0.6 * np.array([0.0, 0.0, 1.0])
    light /= np.linalg.norm(light)
    diffuse = np.abs(normals @ light)
    return np.clip(rgb * (0.45 + 0.55 * diffuse)[:, None], 0.0, 1.0)


def mesh_in_plot(path: Path, camera: Camera):
    """The points (in plot coordinates), triangles and face colours (0-1) of a PLY file."""
    try:
        mesh = read_ply(path)
    except (OSError, PlyError) as error:
        raise FigureError(str(error)) from error
    if mesh.colors is None:
        raise FigureError(f"{path} has no face colours")
    return mesh.points @ camera.to_plot.T, mesh.faces, mesh.colors / 255.0


def bounds(points_list) -> np.ndarray:
    """The 2 x 3 box around all the point sets, so that frames share one camera and scale."""
    stacked = np.vstack(points_list)
    return np.vstack([stacked.min(axis=0), stacked.max(axis=0)])


def draw_mesh(ax, points, faces, rgb, camera: Camera, box: np.ndarray, zoom: float):
    """Draws a mesh in `box` (2 x 3, the same for every mesh of a figure), one unit as long on
    every axis."""
    normals = face_normals(points, faces)
    polygons = Poly3DCollection(points[faces], facecolors=lambert_shade(rgb, normals, camera),
                                edgecolors="none", linewidths=0.0, antialiased=False)
    # Matplotlib draws a 3D axes in the largest square of its box: let the mesh use all the box.
    polygons.set_clip_on(False)
    ax.add_collection3d(polygons)
    ax.set_xlim(box[0, 0], box[1, 0])
    ax.set_ylim(box[0, 1], box[1, 1])
    ax.set_zlim(box[0, 2], box[1, 2])
    ax.set_box_aspect(box[1] - box[0], zoom=zoom)
    ax.set_proj_type("ortho")
    ax.view_init(elev=camera.elev, azim=camera.azim)
    ax.set_axis_off()


def mesh_axes(fig, rect):
    ax = fig.add_axes(rect, projection="3d")
    ax.set_facecolor("white")
    ax.patch.set_alpha(0.0)
    return ax


def row_of_meshes(fig, files, camera, titles, top, bottom, zoom=1.0):
    """Draws the meshes side by side at one scale, each under its title."""
    meshes = [mesh_in_plot(f, camera) for f in files]
    box = bounds([m[0] for m in meshes])
    margin = 0.02 * (box[1] - box[0]).max()
    box += [[-margin] * 3, [margin] * 3]
    width = 1.0 / len(meshes)
    for k, ((points, faces, rgb), title) in enumerate(zip(meshes, titles)):
        ax = mesh_axes(fig, [k * width, bottom, width, top - bottom])
        draw_mesh(ax, points, faces, rgb, camera, box, zoom)
        fig.text((k + 0.5) * width, top, title, ha="center", va="bottom", fontsize=12)


def strain_colorbar(fig, rect):
    ax = fig.add_axes(rect)
    bar = fig.colorbar(plt.cm.ScalarMappable(norm=mcolors.Normalize(0, 1), cmap="viridis"),
                       cax=ax, orientation="horizontal")
    ax.set_title("normalised strain (0: as in the rest pose)", fontsize=10)
    bar.ax.tick_params(labelsize=9)


def save(fig, out: Path):
    fig.savefig(out, dpi=DPI, metadata=PNG_METADATA, facecolor="white")
    plt.close(fig)


# ---- The figures ------------------------------------------------------------------------------

HORSE_FRAMES = (3, 9, 15, 21)  # four phases of the 24-frame gallop
TUBE_STRAIN_FRAMES = (10, 13, 16, 20)  # straight, then bending to 90 degrees


def strain_horse(ws: Workspace, out: Path):
    meshes = ws.output("strain", ws.horse_gallop_cycle(), "--mesh-dir")
    fig = plt.figure(figsize=(WIDTH_INCHES, 3.2))
    row_of_meshes(fig, [meshes / f"frame_{k:04d}.ply" for k in HORSE_FRAMES], HORSE_CAMERA,
                  [f"gallop frame {k}" for k in HORSE_FRAMES], top=0.9, bottom=0.2, zoom=1.4)
    strain_colorbar(fig, [0.35, 0.07, 0.3, 0.04])
    save(fig, out)


def strain_tube(ws: Workspace, out: Path):
    meshes = ws.output("strain", ws.tube("bend_once"), "--mesh-dir")
    fig = plt.figure(figsize=(WIDTH_INCHES, 3.6))
    row_of_meshes(fig, [meshes / f"frame_{k:04d}.ply" for k in TUBE_STRAIN_FRAMES], TUBE_CAMERA,
                  [f"frame {k}" for k in TUBE_STRAIN_FRAMES], top=0.88, bottom=0.2, zoom=1.2)
    strain_colorbar(fig, [0.35, 0.07, 0.3, 0.04])
    save(fig, out)


def tool_png(command: Callable[[Workspace, Path], list]):
    """A figure the tool draws itself: `command(ws, png)` gives the tool's arguments."""
    def make(ws: Workspace, out: Path):
        ws.run(*command(ws, out))
        if not out.is_file():
            raise FigureError(f"the tool did not write {out}")
    return make


def read_frames(folder: Path):
    return sorted(p for p in folder.iterdir() if p.suffix in (".obj", ".off", ".ply"))


def key_frames(dot_dir: Path):
    """(first, last, dot file) of each key frame, from the first line the tool writes in each
    DOT file: `// key frame K: frames FIRST-LAST`."""
    found = []
    for dot in sorted(dot_dir.glob("key_frame_*.dot")):
        first_line = dot.read_text().splitlines()[0]
        try:
            first, last = first_line.rsplit(" ", 1)[1].split("-")
            found.append((int(first), int(last), dot))
        except (IndexError, ValueError) as error:
            raise FigureError(f"{dot}: no frame interval in its first line {first_line!r}") from error
    if not found:
        raise FigureError(f"the tool wrote no key frame graph into {dot_dir}")
    return found


def render_dot(dot: Path) -> np.ndarray:
    if shutil.which("dot") is None:
        raise FigureError("Graphviz's `dot` is not installed (apt-get install graphviz)")
    png = dot.with_suffix(".png")
    done = subprocess.run(["dot", "-Tpng", "-Gdpi=110", "-Gbgcolor=white", "-Nfontname=DejaVu Sans",
                           str(dot), "-o", str(png)], capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise FigureError(f"dot failed on {dot}:\n{done.stderr.strip()}")
    return plt.imread(png)


def evolving_graph_tube(ws: Workspace, out: Path):
    tube = ws.tube("two_joints")
    dots = ws.output("spatiotemporal", tube, "--dot", "--threshold", "0.01")
    meshes = ws.output("spatiotemporal", tube, "--mesh-dir", "--threshold", "0.01")
    frames = key_frames(dots)
    graphs = [render_dot(dot) for _, _, dot in frames]
    # One scale for all the graphs: each drawn in a box as large as the largest.
    box_w = max(g.shape[1] for g in graphs)
    box_h = max(g.shape[0] for g in graphs)
    fig = plt.figure(figsize=(WIDTH_INCHES, 5.6))
    width = 1.0 / len(frames)
    for k, ((first, last, _), graph) in enumerate(zip(frames, graphs)):
        ax = fig.add_axes([k * width + 0.01, 0.55, width - 0.02, 0.33])
        h, w = graph.shape[:2]
        ax.imshow(graph, extent=((box_w - w) / 2, (box_w + w) / 2, (box_h + h) / 2, (box_h - h) / 2),
                  interpolation="antialiased")
        ax.set_xlim(0, box_w)
        ax.set_ylim(box_h, 0)
        ax.set_axis_off()
        fig.text((k + 0.5) * width, 0.9, f"key frame {k}\nframes {first}\u2013{last}",
                 ha="center", va="bottom", fontsize=11)
    shown = [(first + last + 1) // 2 for first, last, _ in frames]
    row_of_meshes(fig, [meshes / f"frame_{f:04d}.ply" for f in shown], TUBE_CAMERA,
                  [f"frame {f}" for f in shown], top=0.48, bottom=0.0)
    save(fig, out)


def character_clip(file: str, clip: str) -> Callable[[Workspace], str]:
    """A clip of the shared characters, as FILE.glb#CLIP."""
    def make(ws: Workspace) -> str:
        path = ws.data / "characters" / file if ws.data else None
        if path is None or not path.is_file():
            raise DataMissing(f"the shared characters/{file} is not there")
        return f"{path}#{clip}"
    return make


def view_page(*inputs, frame: int, options=()):
    """A screenshot, in headless Chromium, of the page `deformseg view` writes for `inputs(ws)`
    with `options`, opened from disk at ?frame=FRAME."""
    def make(ws: Workspace, out: Path):
        chromium = shutil.which("chromium") or shutil.which("chromium-browser")
        if chromium is None:
            raise DataMissing("Chromium is not installed (Debian: chromium)")
        page = ws.work / ("view_" + out.stem)
        ws.run("view", *(make_input(ws) for make_input in inputs), *options, "--out", page)
        url = f"{(page / 'index.html').resolve().as_uri()}?frame={frame}"
        done = subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
                               "--enable-unsafe-swiftshader", "--hide-scrollbars", "--window-size=1400,820",
                               "--virtual-time-budget=8000", f"--screenshot={out}", url],
                              capture_output=True, text=True, check=False)
        if not out.is_file():
            raise FigureError(f"Chromium did not take the screenshot of {url}:\n{done.stderr.strip()[-2000:]}")
    return make


@dataclass(frozen=True)
class Figure:
    name: str
    make: Callable[[Workspace, Path], None]


# Every figure of the manual; a figure of a new tool command is one more line.
FIGURES = [
    Figure("strain_horse", strain_horse),
    Figure("strain_tube", strain_tube),
    Figure("temporal_tube", tool_png(lambda ws, png: ["temporal", ws.tube("three_poses"), "--png", png])),
    Figure("temporal_horse", tool_png(lambda ws, png: ["temporal", ws.horse_gallop(), "--png", png])),
    Figure("strain_strip_horse", tool_png(lambda ws, png: ["strain", ws.horse_gallop(), "--png", png])),
    Figure("evolving_graph_tube", evolving_graph_tube),
    Figure("alignment_path", tool_png(lambda ws, png: ["similarity", ws.tube("bend_once"), ws.tube("bend_once_late"), "--alignment", "dtw", "--png", png])),
    Figure("similarity_matrix", tool_png(lambda ws, png: ["matrix", *map(ws.tube, TUBES), "--png", png])),
    Figure("view_tubes", view_page(lambda ws: ws.tube("bend_once"), lambda ws: ws.tube("bend_once_late"), frame=17)),
    Figure("view_fox", view_page(character_clip("Fox.glb", "Walk"), frame=10, options=("--color", "previous-strain"))),
    Figure("view_knight_segments", view_page(character_clip("Knight.glb", "Walking_A"), frame=12,
                                             options=("--color", "segments"))),
]


def placeholder(out: Path, reason: str):
    """A small PNG that says why a figure is missing, so that the manual still builds."""
    fig = plt.figure(figsize=(6.0, 1.2))
    fig.text(0.5, 0.5, f"Figure not made: {reason}", ha="center", va="center", fontsize=10, wrap=True)
    save(fig, out)


def parse_arguments():
    here = Path(__file__).resolve().parent
    parser = argparse.ArgumentParser(description="Renders the manual's figures with the deformseg tool.")
    parser.add_argument("tool", type=Path, help="the built deformseg program")
    parser.add_argument("out", type=Path, help="folder to write the PNGs into")
    parser.add_argument("--data", type=Path, default=here.parents[2] / "shared" / "data",
                        help="the shared data folder (default: shared/data beside the repository)")
    parser.add_argument("--work", type=Path, help="folder for the tool's outputs (default: OUT-work)")
    parser.add_argument("--only", nargs="+", metavar="NAME", choices=[f.name for f in FIGURES],
                        help="make only these figures")
    return parser.parse_args()


def main() -> int:
    args = parse_arguments()
    if not os.access(args.tool, os.X_OK):
        print(f"make_figures: error: the deformseg tool {args.tool} does not exist or cannot run",
              file=sys.stderr)
        return 1
    data = args.data if args.data.is_dir() else None
    if data is None:
        print(f"make_figures: no data folder {args.data}: the figures of its animations are skipped")
    work = args.work or args.out.with_name(args.out.name + "-work")
    args.out.mkdir(parents=True, exist_ok=True)
    work.mkdir(parents=True, exist_ok=True)
    ws = Workspace(args.tool.resolve(), data, work.resolve())
    plt.rcParams.update({"font.family": "DejaVu Sans", "svg.hashsalt": "deformseg"})
    for figure in FIGURES:
        if args.only and figure.name not in args.only:
            continue
        out = args.out / f"{figure.name}.png"
        start = time.monotonic()
        try:
            figure.make(ws, out)
        except DataMissing as missing:
            print(f"make_figures: {figure.name}: skipped, {missing}")
            placeholder(out, str(missing))
            continue
        except FigureError as error:
            print(f"make_figures: error: {figure.name}: {error}", file=sys.stderr)
            return 1
        print(f"make_figures: {out} ({out.stat().st_size // 1024} KB, {time.monotonic() - start:.1f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
