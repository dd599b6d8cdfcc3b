#!/usr/bin/env python3
"""Every target's sources compile as one translation unit.

    scripts/check_one_unit.py SOURCE_DIR SCRATCH_DIR [CXX_COMPILER [PYTHON3]]

CXX_COMPILER and PYTHON3 are those of the calling build (the Python module is built for the
interpreter it was configured with, which need not be the first python3 in PATH).

The build compiles each target's files in batches of eight (CMake's unity build, docs/building.md,
"Build time"), so the names a file keeps to itself, in its unnamed namespace, share a unit
with the rest of its batch. Two files that define the same such name compile only while
they fall in different batches, and a file added elsewhere may put them together. This
check configures SCRATCH_DIR with each target as one batch (CMAKE_UNITY_BUILD_BATCH_SIZE=0)
and runs the compiler's front end (-fsyntax-only) on every such unit, so any clash, in any
batching, fails here; it cannot see a file-local overload that wins a call in a neighbour's
file without an error. Exits 1, with the compiler's messages, if a unit does not compile.
"""
import concurrent.futures
import json
import os
import shlex
import subprocess
import sys


def syntax_only(entry):
    """The compile command of one unit, changed to check its syntax and write nothing."""
    words = shlex.split(entry["command"])
    checked, skip = [], False
    for word in words:
        if skip:
            skip = False
        elif word in ("-o", "-MF", "-MT", "-MQ"):
            skip = True
        elif word not in ("-c", "-MD", "-MMD"):
            checked.append(word)
    return checked + ["-fsyntax-only"], entry["directory"]


def main():
    source, scratch = sys.argv[1], sys.argv[2]
    compiler = [f"-DCMAKE_CXX_COMPILER={sys.argv[3]}"] if len(sys.argv) > 3 else []
    compiler += [f"-DPython3_EXECUTABLE={sys.argv[4]}"] if len(sys.argv) > 4 else []
    subprocess.run(["cmake", "-S", source, "-B", scratch, "-DCMAKE_BUILD_TYPE=Release", *compiler,
                    "-DCMAKE_UNITY_BUILD=ON", "-DCMAKE_UNITY_BUILD_BATCH_SIZE=0",
                    "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON"], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(scratch, "compile_commands.json")) as f:
        units = [e for e in json.load(f) if os.sep + "Unity" + os.sep in e["file"]]
    if not units:
        print("check_one_unit: the configure made no unity sources")
        return 1

    def check(entry):
        command, directory = syntax_only(entry)
        result = subprocess.run(command, cwd=directory, capture_output=True, text=True)
        return entry["file"], result.returncode, result.stderr

    failed = 0
    with concurrent.futures.ThreadPoolExecutor(os.cpu_count()) as pool:
        for unit, status, messages in pool.map(check, units):
            if status != 0:
                failed += 1
                print(f"{unit} does not compile as one unit:\n{messages}")
    print(f"check_one_unit: {len(units) - failed} of {len(units)} targets compile as one unit")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
