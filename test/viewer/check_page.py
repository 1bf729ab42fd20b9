"""Opens a page `deformseg view` wrote in headless Chromium, from disk, and checks it plays.

    check_page.py CHROMIUM PAGE_DIR FRAME_A FRAME_B [--work DIR]

At ?frame=FRAME_A and ?frame=FRAME_B: the page says it is ready at that frame (its status line,
read from the DOM) and Chromium's console has no error; the screenshots are not blank and differ
from one frame to the other inside the first animation's view, where the mesh moves. Exits 0
when all holds, 1 with the reason otherwise.
"""
import argparse
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
from matplotlib import image as mpimg

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
         "--enable-unsafe-swiftshader", "--hide-scrollbars", "--window-size=1400,1000",
         "--virtual-time-budget=8000", "--enable-logging=stderr", "--v=0"]


def chromium(binary: str, url: str, *extra: str) -> subprocess.CompletedProcess:
    return subprocess.run([binary, *FLAGS, *extra, url], capture_output=True, text=True, timeout=120, check=False)


def console_errors(stderr: str) -> list:
    return [line for line in stderr.splitlines()
            if "CONSOLE" in line and re.search(r"error|uncaught", line, re.IGNORECASE)]


def open_at(binary: str, page: Path, frame: int, screenshot: Path) -> np.ndarray:
    url = f"{page.resolve().as_uri()}?frame={frame}"
    screenshot.unlink(missing_ok=True)  # so that an old one is never taken for this one
    # One launch does both: headless Chromium dumps the DOM and takes the screenshot of the same page.
    dom = chromium(binary, url, "--dump-dom", f"--screenshot={screenshot}")
    status = re.search(r'<div id="status"[^>]*data-state="(\w+)"[^>]*>([^<]*)<', dom.stdout)
    if not status:
        raise AssertionError(f"{url}: no status line in the page (Chromium said: {dom.stderr[-2000:]})")
    if status.group(1) != "ready" or f'data-frame="{frame}"' not in status.group(0):
        raise AssertionError(f"{url}: the page is not ready at frame {frame}: {status.group(2)}")
    errors = console_errors(dom.stderr)
    if errors:
        raise AssertionError(f"{url}: errors on the console:\n" + "\n".join(errors))
    if not screenshot.is_file():
        raise AssertionError(f"{url}: no screenshot ({dom.stderr[-2000:]})")
    return mpimg.imread(screenshot)[..., :3]


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("chromium")
    parser.add_argument("page_dir", type=Path)
    parser.add_argument("frames", type=int, nargs=2)
    parser.add_argument("--work", type=Path, default=None)
    args = parser.parse_args()
    work = args.work or args.page_dir
    page = args.page_dir / "index.html"
    try:
        shots = [open_at(args.chromium, page, f, work / f"screenshot_{f}.png") for f in args.frames]
        # The first view's canvas: below the title and the controls, on the left (index.html's layout).
        view = [shot[60:480, 10:500] for shot in shots]
        for frame, v in zip(args.frames, view):
            if v.std() < 0.02:
                raise AssertionError(f"frame {frame}: the view is blank (pixel deviation {v.std():.4f})")
        changed = np.abs(view[0] - view[1]).max(axis=2) > 0.1
        if changed.mean() < 0.002:
            raise AssertionError(f"frames {args.frames}: the views hardly differ ({100 * changed.mean():.3f} % of pixels)")
        print(f"{page}: ready at frames {args.frames[0]} and {args.frames[1]}, "
              f"{100 * changed.mean():.1f} % of the view changed, no console error")
        return 0
    except (AssertionError, subprocess.TimeoutExpired) as failure:
        print(f"check_page: {failure}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
