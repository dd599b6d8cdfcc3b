#!/usr/bin/env python3
"""Checks every #include "..." of shadowlab's sources against the dependency rule in
docs/architecture.md (the ```rules block), and two things the rule alone cannot show: that
no two of its keys may include each other (a rule that lets folders include each other is
no layering), and that no files include each other, even within one folder (a stage file
counts with its header: a.cpp including b.h and b.cpp including a.h is a cycle). Prints one
line per violation and exits 1 if there is any; exits 0 silently otherwise.
Usage: check_includes.py [SOURCE_ROOT]"""
import pathlib
import re
import sys

CHECKED_SUFFIXES = {".h", ".cpp", ".inl"}
NOT_CHECKED = ("tests/", "build")   # tests may include anything; build trees are not ours


def read_rules(doc):
    block = re.search(r"```rules\n(.*?)```", doc.read_text(), re.S)
    if not block:
        sys.exit(f"{doc}: no ```rules block")
    rules = {}
    for line in block.group(1).splitlines():
        if line.strip():
            key, _, allowed = line.partition(":")
            rules[key.strip()] = allowed.split()
    return rules


def owner(path, rules):
    """The longest rule key that is the path itself or one of its folders."""
    keys = [k for k in rules if path == k or path.startswith(k + "/")]
    return max(keys, key=len) if keys else None


def reachable(key, rules):
    """Every key `key` may include, directly or through others, itself included."""
    seen, todo = {key}, [key]
    while todo:
        for target in rules.get(todo.pop(), []):
            if target not in seen:
                seen.add(target)
                todo.append(target)
    return seen


def mutual_rules(rules):
    """Pairs of keys each of which may include the other."""
    reach = {key: reachable(key, rules) for key in rules}
    return [f"docs/architecture.md: the rule lets {a} and {b} include each other"
            for a in sorted(rules) for b in sorted(rules) if a < b and b in reach[a] and a in reach[b]]


def include_cycles(units):
    """One line per cycle among units (a path without its suffix: a stage's .h and .cpp),
    found by depth-first search over their includes."""
    cycles, state = [], {}

    def visit(unit, stack):
        state[unit] = "open"
        stack.append(unit)
        for target in sorted(units.get(unit, ())):
            if target == unit or target not in units:
                continue
            if state.get(target) == "open":
                cycle = stack[stack.index(target):] + [target]
                cycles.append("include cycle: " + " -> ".join(cycle))
            elif target not in state:
                visit(target, stack)
        stack.pop()
        state[unit] = "done"

    for unit in sorted(units):
        if unit not in state:
            visit(unit, [])
    return cycles


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    rules = read_rules(root / "docs/architecture.md")
    violations = mutual_rules(rules)
    units = {}
    for file in sorted(root.rglob("*")):
        path = file.relative_to(root).as_posix()
        if file.suffix not in CHECKED_SUFFIXES or path.startswith(NOT_CHECKED):
            continue
        source = owner(path, rules)
        if source is None:
            violations.append(f"{path}: its folder has no line in the dependency rule")
            continue
        allowed = reachable(source, rules)
        for number, line in enumerate(file.read_text().splitlines(), 1):
            match = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
            if not match or "/" not in match.group(1):
                continue   # a file beside it, or a system header
            units.setdefault(path.rsplit(".", 1)[0], set()).add(match.group(1).rsplit(".", 1)[0])
            target = owner(match.group(1), rules)
            if target is None or target not in allowed:
                violations.append(f"{path}:{number}: includes {match.group(1)}, but {source} may not include "
                                  f"{target or 'that folder'} (docs/architecture.md, the dependency rule)")
    violations += include_cycles(units)
    for v in violations:
        print(v)
    return 1 if violations else 0


if __name__ == "__main__":
    sys.exit(main())
