#!/usr/bin/env python3
"""Checks gkt's include graph against its floors (docs/architecture.md).

Usage:
    python3 tools/check_layers.py [ROOT]      run the self-test, then check the tree at ROOT
                                              (default: the repository); CI runs this
    python3 tools/check_layers.py --self-test show on scratch trees that every rule fires
    python3 tools/check_layers.py --graph     print the include graph between floors and rooms

Rules (each violation is one line "file:line: rule: what"; exit status 1 if any):
  floor     a file under include/gkt/<floor>/ or lib/<floor>/ includes a header of a floor above
            it. Floors, low to high: support < algebra < collision < operators < transport <
            evolution < simulation < models < front ends. Public headers directly in include/gkt/ (the
            solver-facing cell.hpp and any other top-level header) are on the models floor.
  room      inside transport, a room includes a room it may not (ROOM_MAY_INCLUDE below), or a
            transport file is in no declared room.
  private   a public header (include/) includes a private header (lib/).
  front     a front end (tools/gkt, tools/benchmark, lib/c_api, examples/<name>) includes anything but a
            public header gkt/... or a header of its own folder.
  unknown   a quoted include in include/, lib/ or a front end that names no file of the tree.
Standard-library and third-party headers (<...> not starting with gkt/) are not checked.
"""

import os
import re
import sys
import tempfile

FLOORS = ["support", "algebra", "collision", "operators", "transport", "evolution", "simulation", "models", "front end"]
RANK = {name: i for i, name in enumerate(FLOORS)}

# The rooms of the transport floor and the rooms each may include (itself included).
ROOM_MAY_INCLUDE = {
    "common": {"common"},
    "monodisperse": {"common", "monodisperse"},
    "closed_forms": {"common", "monodisperse", "closed_forms"},
    "mixture": {"common", "mixture"},
    "viscoelastic": {"common", "viscoelastic"},
    "rough": {"common", "rough"},  # rough spheres and disks (issue 18)
    "aggregation": {"common", "aggregation"},  # sticking grains: success factor, kernels (issue 21)
}
# Declared exceptions (including room -> included room), each with its reason. Keep this empty.
ROOM_EXCEPTIONS = {}

FRONT_ENDS = ["tools/gkt", "tools/benchmark", "lib/c_api"]  # plus every examples/<name>
SOURCE_SUFFIXES = (".hpp", ".cpp", ".h", ".inc")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^">]+)[">]')


def front_end_root(rel):
    """Returns the front end folder holding rel (a path relative to the root), or None."""
    for root in FRONT_ENDS:
        if rel.startswith(root + "/"):
            return root
    parts = rel.split("/")
    if parts[0] == "examples" and len(parts) > 2:
        return "examples/" + parts[1]
    return None


def place(rel):
    """Returns (floor, room, is_public) of a library file, or None for files outside include/, lib/."""
    parts = rel.split("/")
    if parts[0] == "include" and len(parts) > 2 and parts[1] == "gkt":
        inner, public = parts[2:], True
        if len(inner) == 1:  # top-level public header: the façade floor
            return "models", None, True
    elif parts[0] == "lib" and len(parts) > 1:
        inner, public = parts[1:], False
        if front_end_root(rel) is not None:  # lib/c_api: the C API, a front end compiled as a library
            return "front end", None, False
    else:
        return None
    floor = inner[0]
    if floor not in RANK or floor == "front end":
        return "?" + floor, None, public
    room = None
    if floor == "transport":
        room = inner[1] if len(inner) > 2 else ""
    return floor, room, public


def resolve(root, rel, bracket, name):
    """Returns the included file relative to root, or None if it is not part of the tree."""
    if bracket == "<":
        if name.startswith("gkt/") and os.path.isfile(os.path.join(root, "include", name)):
            return "include/" + name
        return None
    candidates = []
    if name.startswith("gkt/"):
        candidates.append(os.path.join("include", name))
    candidates.append(os.path.normpath(os.path.join(os.path.dirname(rel), name)))
    candidates.append(os.path.join("lib", name))
    for c in candidates:
        if os.path.isfile(os.path.join(root, c)):
            return c.replace(os.sep, "/")
    return ""  # quoted but not found


def check_include(root, rel, line_number, bracket, name):
    """Returns the violations of one include line."""
    where = f"{rel}:{line_number}"
    target = resolve(root, rel, bracket, name)
    if target is None:
        return []
    front = front_end_root(rel)
    if target == "":
        if front is not None or place(rel) is not None:
            return [f'{where}: unknown: "{name}" is not a file of the tree']
        return []
    if front is not None:
        if target.startswith("include/gkt/") or target.startswith(front + "/"):
            return []
        return [f"{where}: front: the front end {front} includes {target}; front ends may include only "
                f"public headers (gkt/...) and headers of their own folder"]
    source, included = place(rel), place(target)
    if source is None:
        return []
    floor, room, public = source
    out = []
    if public and target.startswith("lib/"):
        out.append(f"{where}: private: the public header includes the private header {target}; move what it "
                   f"needs into a public header or hide it behind a pImpl")
    if included is None:
        out.append(f"{where}: floor: the {floor} floor includes {target}, which belongs to no floor")
        return out
    for f in (floor, included[0]):
        if f.startswith("?"):
            out.append(f"{where}: floor: '{f[1:]}' is not a floor ({' < '.join(FLOORS[:-1])})")
            return out
    if RANK[included[0]] > RANK[floor]:
        out.append(f"{where}: floor: the {floor} floor includes {target} from the {included[0]} floor above it "
                   f"(order: {' < '.join(FLOORS)})")
    elif floor == "transport" and included[0] == "transport":
        src_room, dst_room = room, included[1]
        for r, path in ((src_room, rel), (dst_room, target)):
            if r not in ROOM_MAY_INCLUDE:
                out.append(f"{where}: room: {path} is in no transport room ({', '.join(ROOM_MAY_INCLUDE)})")
                return out
        if dst_room not in ROOM_MAY_INCLUDE[src_room] and (src_room, dst_room) not in ROOM_EXCEPTIONS:
            allowed = ", ".join(sorted(ROOM_MAY_INCLUDE[src_room]))
            out.append(f"{where}: room: transport/{src_room} includes {target} from transport/{dst_room}; "
                       f"transport/{src_room} may include only {allowed}")
    return out


def checked_files(root):
    """Yields the files (relative to root) whose includes are checked."""
    tops = ["include", "lib", "tools", "examples"]
    for top in tops:
        for directory, _, files in os.walk(os.path.join(root, top)):
            for f in sorted(files):
                if f.endswith(SOURCE_SUFFIXES):
                    rel = os.path.relpath(os.path.join(directory, f), root).replace(os.sep, "/")
                    if place(rel) is not None or front_end_root(rel) is not None:
                        yield rel


def check(root):
    """Returns every violation in the tree at root."""
    out = []
    for rel in sorted(checked_files(root)):
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if m:
                    out.extend(check_include(root, rel, number, m.group(1), m.group(2)))
    return out


def unit(rel):
    """Returns the floor (transport: floor/room) or front end of a file, for the graph."""
    front = front_end_root(rel)
    if front is not None:
        return front
    floor, room, _ = place(rel)
    return f"{floor}/{room}" if floor == "transport" else floor


def graph(root):
    """Returns {(from, to): count} of the includes between different floors and rooms."""
    edges = {}
    for rel in sorted(checked_files(root)):
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            for line in f:
                m = INCLUDE.match(line)
                if not m:
                    continue
                target = resolve(root, rel, m.group(1), m.group(2))
                if not target or (place(target) is None and front_end_root(target) is None):
                    continue
                a, b = unit(rel), unit(target)
                if a != b:
                    edges[(a, b)] = edges.get((a, b), 0) + 1
    return edges


def self_test():
    """Builds scratch trees with one violation of each rule and checks that each is found, and that
    a clean tree passes. Returns 0 on success."""
    clean = {
        "include/gkt/algebra/rational.hpp": "",
        "include/gkt/operators/op.hpp": '#include "gkt/algebra/rational.hpp"\n#include <vector>\n',
        "include/gkt/transport/common/gas.hpp": '#include "gkt/operators/op.hpp"\n',
        "include/gkt/transport/monodisperse/ns.hpp": '#include "gkt/transport/common/gas.hpp"\n',
        "include/gkt/transport/mixture/mix.hpp": '#include "gkt/transport/common/gas.hpp"\n',
        "include/gkt/cell.hpp": '#include "gkt/transport/mixture/mix.hpp"\n',
        "lib/support/strings.hpp": "",
        "lib/transport/common/pieces.hpp": '#include "gkt/algebra/rational.hpp"\n',
        "lib/transport/mixture/mix.cpp": '#include "transport/common/pieces.hpp"\n#include "support/strings.hpp"\n',
        "tools/gkt/scene.hpp": "",
        "tools/gkt/main.cpp": '#include "scene.hpp"\n#include "gkt/cell.hpp"\n#include <CLI/CLI.hpp>\n',
        "examples/consumer/main.cpp": "#include <gkt/cell.hpp>\n",
        "include/gkt/gkt.h": "#include <stddef.h>\n",
        "lib/c_api/guard.hpp": '#include "gkt/gkt.h"\n',
        "lib/c_api/api.cpp": '#include "gkt/cell.hpp"\n#include "guard.hpp"\n',
    }
    cases = [
        ("floor", {"include/gkt/operators/op.hpp": '#include "gkt/transport/common/gas.hpp"\n'}),
        ("floor", {"lib/transport/mixture/mix.cpp": '#include "c_api/guard.hpp"\n'}),
        ("room", {"lib/transport/mixture/mix.cpp": '#include "gkt/transport/monodisperse/ns.hpp"\n'}),
        ("private", {"include/gkt/transport/common/gas.hpp": '#include "transport/common/pieces.hpp"\n'}),
        ("front", {"tools/gkt/main.cpp": '#include "transport/common/pieces.hpp"\n'}),
        ("front", {"lib/c_api/api.cpp": '#include "transport/common/pieces.hpp"\n'}),
        ("unknown", {"lib/transport/mixture/mix.cpp": '#include "transport/common/missing.hpp"\n'}),
    ]

    def run(files):
        with tempfile.TemporaryDirectory() as root:
            for rel, text in files.items():
                path = os.path.join(root, rel)
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, "w", encoding="utf-8") as f:
                    f.write(text)
            return check(root)

    failures = []
    found = run(clean)
    if found:
        failures.append("the clean tree fails: " + "; ".join(found))
    for rule, change in cases:
        found = run({**clean, **change})
        if len(found) != 1 or f": {rule}: " not in found[0]:
            failures.append(f"rule {rule}: expected one '{rule}' violation, got {found}")
    for f in failures:
        print("check_layers self-test: " + f, file=sys.stderr)
    if not failures:
        print(f"check_layers self-test: ok (clean tree passes; {len(cases)} violations caught: {', '.join(r for r, _ in cases)})")
    return 1 if failures else 0


def main(argv):
    if len(argv) > 1 and argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0
    if len(argv) > 1 and argv[1] == "--self-test":
        return self_test()
    if len(argv) > 1 and argv[1] == "--graph":
        root = argv[2] if len(argv) > 2 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
        for (a, b), n in sorted(graph(root).items()):
            print(f"{a} -> {b}  ({n})")
        return 0
    if self_test() != 0:
        return 1
    root = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    violations = check(root)
    for v in violations:
        print(v, file=sys.stderr)
    if violations:
        print(f"check_layers: {len(violations)} include(s) break the layering (docs/architecture.md)", file=sys.stderr)
        return 1
    print("check_layers: ok (every include runs down the floors)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
