"""How fast `deformseg view` writes, and Chromium opens, the page of a 20,000-triangle, 500-frame
animation (a synthetic tube), run by hand:

    /usr/bin/python3 test/bench/view_page.py build/tools/deformseg [--work DIR]

Prints the page's size, the tool's time to write it and the time from navigation to the page's
first frame shown (its status line's data-ready-ms), from disk in headless Chromium: real time,
with no virtual time budget, since the page shows its first frame before its load event.
"""
import argparse
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("tool", type=Path)
    parser.add_argument("--work", type=Path, default=None)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        print("view_page: Chromium is not installed (Debian: chromium)", file=sys.stderr)
        return 1
    work = args.work or Path(tempfile.mkdtemp(prefix="deformseg-view-bench-"))
    tube, page = work / "tube", work / "page"
    # 40 sectors x 250 rings: 20,000 triangles on the side (and the caps); 500 frames.
    subprocess.run([str(args.tool), "synth", str(tube), "--sectors", "40", "--rings", "250",
                    "--schedule", "100:0", "150:90", "100:", "150:0", "--format", "ply"],
                   check=True, capture_output=True)
    start = time.monotonic()
    subprocess.run([str(args.tool), "view", str(tube), "--out", str(page)], check=True, capture_output=True)
    written = time.monotonic() - start
    size = sum(f.stat().st_size for f in page.iterdir())
    ready = []
    for _ in range(args.runs):
        dom = subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
                              "--enable-unsafe-swiftshader", "--dump-dom",
                              (page / "index.html").resolve().as_uri() + "?frame=0"],
                             capture_output=True, text=True, check=False, timeout=300)
        found = re.search(r'data-ready-ms="(\d+)"', dom.stdout)
        if not found:
            print(f"view_page: the page did not get ready: {dom.stdout[-500:]}", file=sys.stderr)
            return 1
        ready.append(int(found.group(1)))
    print(f"view_page: {size / 1e6:.1f} MB written in {written:.1f} s; ready in "
          f"{min(ready)} ms (best of {args.runs}; all {ready})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
