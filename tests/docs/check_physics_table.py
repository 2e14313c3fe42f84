#!/usr/bin/env python3
"""Checks every `file` : `name` pair of the Equation -> code table of docs/physics.md.

The last cell of a row is `path` [: `name`, `name` ...] [; `path` : ...], optionally followed
by a remark in parentheses. Every path must exist (a glob must match). Every name must be in
that file or in the header beside it (same stem .h, or the public header under
include/vesica/<stage>/):
  - `f`        a function f(...) or a class/struct f;
  - `A::f`     the literal text A::f (an out-of-line definition), or f(...) or a class/struct f
               inside the body of class/struct A (an inline member);
  - `A::B::f`  the same with B, whose declaration must name A (`class A::B`) or sit inside A.
A bare name after a qualified one (`A::f`, `g`) may be `A::g` (the table's shorthand) or a
free function g.
Usage: check_physics_table.py REPO_ROOT   (exit status 1 on any miss)
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
text = (root / "docs/physics.md").read_text()
table = text.split("## Equation → code", 1)[1]
rows = [l for l in table.splitlines()
        if l.startswith("| ") and not l.startswith("| §") and not l.startswith("|---")]


def sources(path):
    files = [path]
    if path.suffix == ".cpp":
        files.append(path.with_suffix(".h"))
        parts = path.parts
        if "src" in parts:
            i = parts.index("src")
            stage = parts[i - 1]
            rest = pathlib.Path(*parts[i + 1:]).with_suffix(".h")
            files.append(root / stage / "include" / "vesica" / stage / rest)
    return [f for f in files if f.exists()]


def bodies(code, scope, outer=None):
    """Bodies of the class/struct `scope` (declared as `outer::scope`, or plainly)."""
    qual = rf"(?:{outer}::)?" if outer else r"(?:\w+::)*"
    for m in re.finditer(rf"\b(?:class|struct)\s+{qual}{scope}\b[^;{{]*\{{", code):
        depth, i = 1, m.end()
        while depth and i < len(code):
            depth += {"{": 1, "}": -1}.get(code[i], 0)
            i += 1
        yield code[m.end():i]


def member(name, code):
    return bool(re.search(rf"\b{name}\s*\(", code) or
                re.search(rf"\b(?:class|struct)\s+{name}\b", code))


def defined(name, code):
    parts = name.split("::")
    if len(parts) == 1:
        return member(parts[0], code)
    if name in code:
        return True
    scopes, func = parts[:-1], parts[-1]
    candidates = list(bodies(code, scopes[0]))
    for k in range(1, len(scopes)):
        # nested in the outer body, or defined out of line as `class Outer::Inner`
        candidates = [b for c in candidates for b in bodies(c, scopes[k])]
        candidates += list(bodies(code, scopes[k], scopes[k - 1]))
    return any(member(func, c) for c in candidates)


bad = checked = 0
for row in rows:
    cells = [c.strip() for c in row.strip("|").split("|")]
    section, ref = cells[0], re.sub(r"\s*\([^`]*\)\s*$", "", cells[-1])
    for group in ref.split(";"):
        group = group.strip()
        m = re.match(r"`([^`]+)`\s*(?::\s*(.*))?$", group)
        if not m:
            print(f"UNPARSED §{section}: {group}")
            bad += 1
            continue
        path = m.group(1)
        checked += 1
        if any(ch in path for ch in "*?["):
            if not list(root.glob(path)):
                print(f"NO MATCH §{section}: {path}")
                bad += 1
            continue
        p = root / path
        if not p.exists():
            print(f"MISSING FILE §{section}: {path}")
            bad += 1
            continue
        code = "\n".join(f.read_text() for f in sources(p))
        scope = None
        for n in re.findall(r"`([^`]+)`", m.group(2) or ""):
            n = re.sub(r"\s*\(.*\)$", "", n)
            names = [n]
            if "::" in n:
                scope = n.rsplit("::", 1)[0]
            elif scope:
                names.insert(0, f"{scope}::{n}")
            checked += 1
            if not any(defined(name, code) for name in names):
                print(f"MISSING NAME §{section}: {path} : {n}")
                bad += 1
print(f"{len(rows)} rows, {checked} file and name checks, {bad} missing")
sys.exit(1 if bad else 0)
