#!/usr/bin/env python3
"""The build's CPU time, per translation unit and link (docs/building.md, "Build time").

    scripts/compile_times.py [--build DIR] [--target T ...] [--top N] [-- cmake options]

Configures DIR afresh (default build-times/, Release, no compiler cache; a DIR that exists
must be one this script made) with this script as CMake's compiler and linker launcher,
builds the targets (default: all) on every core, records each unit's CPU time (user +
system of each compiler and linker process) in DIR/compile_times.tsv, and prints the total,
the wall time, and the N units that cost the most. Each compile or link is timed by the kernel's
accounting of the child process (getrusage), so the figures do not depend on how many
jobs ran beside it.

As a launcher (internal): compile_times.py --record LOG -- COMMAND... runs COMMAND and
appends "cpu_seconds<TAB>output" to LOG.
"""
import argparse
import os
import resource
import shutil
import subprocess
import sys
import time


def record(log, command):
    status = subprocess.call(command)
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    output = command[command.index("-o") + 1] if "-o" in command else command[-1]
    with open(log, "a") as f:
        f.write(f"{usage.ru_utime + usage.ru_stime:.3f}\t{output}\n")
    return status


def report(log, wall, top):
    units = []
    with open(log) as f:
        for line in f:
            seconds, output = line.rstrip("\n").split("\t", 1)
            units.append((float(seconds), output))
    units.sort(reverse=True)
    links = [u for u in units if not u[1].endswith(".o")]
    total = sum(s for s, _ in units)
    print(f"{len(units) - len(links)} compiles and {len(links)} links: "
          f"{total / 60:.1f} CPU-minutes ({sum(s for s, _ in links) / 60:.1f} of them linking), "
          f"{wall / 60:.1f} minutes of wall time on {os.cpu_count()} cores")
    print(f"the {top} costliest:")
    for seconds, output in units[:top]:
        print(f"  {seconds:7.1f} s  {output}")


def main():
    if len(sys.argv) > 2 and sys.argv[1] == "--record":
        sys.exit(record(sys.argv[2], sys.argv[sys.argv.index("--") + 1:]))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build-times")
    parser.add_argument("--target", action="append", default=[])
    parser.add_argument("--top", type=int, default=10)
    parser.add_argument("cmake_options", nargs="*")
    args = parser.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    build = os.path.abspath(args.build)
    log = os.path.join(build, "compile_times.tsv")
    # It starts from nothing, so it removes the folder: only one it made itself.
    if os.path.exists(build) and not os.path.exists(log):
        sys.exit(f"compile_times: {build} exists and is not a folder of this script's; name another with --build")
    shutil.rmtree(build, ignore_errors=True)
    os.makedirs(build)
    open(log, "w").close()   # marks the folder as this script's
    launcher = f"{sys.executable};{os.path.abspath(__file__)};--record;{log};--"
    subprocess.check_call(["cmake", "-S", root, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                           f"-DCMAKE_CXX_COMPILER_LAUNCHER={launcher}",
                           f"-DCMAKE_CXX_LINKER_LAUNCHER={launcher}", *args.cmake_options],
                          stdout=subprocess.DEVNULL)
    open(log, "w").close()   # the build's units only, not the configure's checks
    targets = [a for t in args.target for a in ("--target", t)]
    start = time.monotonic()
    subprocess.check_call(["cmake", "--build", build, f"-j{os.cpu_count()}", *targets],
                          stdout=subprocess.DEVNULL)
    report(log, time.monotonic() - start, args.top)


if __name__ == "__main__":
    main()
