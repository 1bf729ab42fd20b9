"""Peak memory and time of the tool's commands on long takes, run by hand (never as a timed test):

    /usr/bin/python3 test/bench/long_takes.py build/tools/deformseg [--data DIR] [--work DIR]

Long takes made cheaply: one clip of a shared character (Knight.glb, 3,665 vertices once welded,
a 4 s clip) sampled at three frame rates, so that its frames grow fourfold twice while its
vertices stay (motion signatures, which hold the frames of their longest lag, 4.3 s, then hold
more frames too); and a synthetic tube written as a point cache played at 30 fps (`deformseg
synth --format pc2`), 8,258 vertices for three lengths and 32,834 for one. Each command runs
alone in a fresh process, on one thread; its peak resident memory is the process's own
(`os.wait4`), its time the wall clock. Prints one table, in Markdown, for the manual's chapter on
performance ("Long takes").
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

# The clip and the frame rates: 4 s at 60, 240 and 960 fps, 241, 961 and 3,841 frames.
CLIP = "Knight.glb#Sit_Floor_Idle"
FRAME_RATES = [60, 240, 960]
# The tubes, written as point caches played at 30 fps: (sectors, rings, frames per phase of 4):
# 8,258 vertices for 401, 1,601 and 4,001 frames; 32,834 vertices for 401 frames.
TUBES = [(64, 128, 100), (64, 128, 400), (64, 128, 1000), (64, 512, 100)]


def measured(command):
    """(peak resident MiB, seconds, exit status) of `command` run in a fresh process."""
    start = time.monotonic()
    process = subprocess.Popen([str(c) for c in command], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    seconds = time.monotonic() - start
    error = process.stderr.read().decode(errors="replace")
    process.stderr.close()
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        print(f"long_takes: {' '.join(map(str, command))} failed:\n{error}", file=sys.stderr)
    return usage.ru_maxrss / 1024, seconds, process.returncode


def commands(tool, input_args, work):
    """The commands to measure on one input, by name: the streamed ones first, for comparison."""
    shutil.rmtree(work / "store", ignore_errors=True)  # describe describes the clip anew
    return {
        "similarity": [tool, "similarity", *input_args[:1], *input_args, "--threads", "1"],
        "describe": [tool, "describe", *input_args, "--store", work / "store", "--threads", "1"],
        "info": [tool, "info", *input_args, "--threads", "1"],
        "view": [tool, "view", *input_args, "--out", work / "page", "--threads", "1"],
        "spatiotemporal": [tool, "spatiotemporal", *input_args, "--threads", "1"],
    }


def input_rows(tool, data, work):
    """(label, frames, vertices, input arguments) of every long take."""
    for fps in FRAME_RATES:
        yield f"Knight clip at {fps} fps", [data / "characters" / CLIP, "--fps", str(fps)]
    for sectors, rings, phase in TUBES:
        tube = work / f"tube-{sectors}x{rings}x{phase}"
        if not (tube / "tube.pc2").exists():
            subprocess.run([str(tool), "synth", str(tube), "--sectors", str(sectors), "--rings", str(rings),
                            "--format", "pc2", "--schedule", f"{phase}:0", f"{phase}:90", f"{phase}:", f"{phase}:0"],
                           check=True, capture_output=True)
        yield f"tube {sectors}x{rings}, pc2 at 30 fps", [tube / "tube.pc2", "--topology", tube / "tube.obj"]


def counts(tool, input_args):
    """(frames, vertices) of an input, as info gives them."""
    info = subprocess.run([str(tool), "info", *map(str, input_args), "--json", "-"], check=True,
                          capture_output=True, text=True)
    document = json.loads(info.stdout)
    return document["frames"], document["vertices"]


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("tool", type=Path)
    parser.add_argument("--data", type=Path, default=Path(os.environ.get("DEFORMSEG_DATA_DIR", "/work/shared/data")))
    parser.add_argument("--work", type=Path, default=None)
    parser.add_argument("--only", nargs="*", default=None, help="commands to measure (default: all)")
    args = parser.parse_args()
    if not (args.data / "characters" / "Knight.glb").exists():
        print(f"long_takes: {args.data}/characters/Knight.glb not found (--data DIR)", file=sys.stderr)
        return 1
    work = args.work or Path(tempfile.mkdtemp(prefix="deformseg-long-takes-"))
    work.mkdir(parents=True, exist_ok=True)
    print("| input | frames | vertices | command | peak MiB | seconds |")
    print("|---|---:|---:|---|---:|---:|")
    failed = False
    for label, input_args in input_rows(args.tool, args.data, work):
        frames, vertices = counts(args.tool, input_args)
        for name, command in commands(args.tool, input_args, work).items():
            if args.only and name not in args.only:
                continue
            mib, seconds, status = measured(command)
            failed |= status != 0
            shown = f"{mib:.0f}" if status == 0 else f"failed ({mib:.0f})"
            print(f"| {label} | {frames} | {vertices} | {name} | {shown} | {seconds:.1f} |", flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
