"""The start of the tool, run by hand (never as a timed test):

    /usr/bin/python3 test/bench/tool_start.py build/tools/deformseg [OTHER_TOOL...] [--runs N]

Runs `TOOL --version`, which does no work, for each tool given (a build before a change and one
after, say) and /bin/true for scale, N times each (default 300), interleaved so that a change in
the machine's load falls on all alike. Prints, per program, the median and the best of the wall
time around the process (fork, exec and the loader's mapping and relocating of the shared
libraries, as `subprocess` makes them) and of the CPU time it used (user + system, from
`os.wait4`), in milliseconds, as chapter 10's section "The tool's start" gives them.
"""
import argparse
import os
import statistics
import subprocess
import time


def timed(command):
    """The wall and CPU seconds of one run of `command`, its output discarded."""
    started = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - started
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        raise SystemExit(f"{' '.join(command)} exited with {process.returncode}")
    return wall, usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("tools", nargs="+", help="the tools to start, each with --version")
    parser.add_argument("--runs", type=int, default=300, help="runs of each program (default 300)")
    args = parser.parse_args()
    programs = {"/bin/true": ["/bin/true"]}
    programs.update({tool: [tool, "--version"] for tool in args.tools})
    wall = {name: [] for name in programs}
    cpu = {name: [] for name in programs}
    for _ in range(args.runs):
        for name, command in programs.items():
            w, c = timed(command)
            wall[name].append(w * 1e3)
            cpu[name].append(c * 1e3)
    print(f"load average {os.getloadavg()[0]:.2f}, {args.runs} runs each, median (best), ms")
    print("| program | wall | CPU |\n|---|---|---|")
    for name in programs:
        print(f"| `{name}` | {statistics.median(wall[name]):.2f} ({min(wall[name]):.2f}) | "
              f"{statistics.median(cpu[name]):.2f} ({min(cpu[name]):.2f}) |")


if __name__ == "__main__":
    main()
