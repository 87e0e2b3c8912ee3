#!/usr/bin/env python3
"""Names a unity build could mix up: the glue targets (voltree_glue_code in CMakeLists.txt) compile
their files several to a unit, so a file-local function, constant or type defined in two files of
one target either fails to compile or, worse, becomes an overload that the other file's calls may
silently pick (a Pattern(int, int, int) beside a Pattern(int, int, uint8_t) did). Prints every such
name and exits 1 if there is one.  Usage: scripts/unity_names.py"""
import collections
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
targets = {f"tests/{d.name}": sorted(d.glob("*_test.cpp")) for d in sorted((root / "tests").iterdir()) if d.is_dir()}
for folder in ("apps", "pipeline", "web", "view"):
    targets[folder] = sorted(p for p in (root / folder).glob("*.cpp") if p.name != "main.cpp")

# A definition at the start of a line (the code is formatted without namespace indentation).
type_definition = re.compile(r"^(?:struct|class|enum(?: class)?)\s+(\w+)\s*[{:]")
definition = re.compile(r"^(?:static\s+|inline\s+|constexpr\s+)*(?:const\s+)?[\w:<>,*& ]+?[\s*&]+(\w+)\s*[(=\[{]")
skipped = ("TEST", "#", "//", "}", "namespace", "using", " ", "template", "return", "extern")

clashes = 0
for target, files in targets.items():
    owners = collections.defaultdict(set)
    for path in files:
        for line in path.read_text().splitlines():
            match = type_definition.match(line) or (None if line.startswith(skipped) else definition.match(line))
            if match and match.group(1) != "main":
                owners[match.group(1)].add(path.relative_to(root).as_posix())
    for name, where in sorted(owners.items()):
        if len(where) > 1:
            clashes += 1
            print(f"{target}: '{name}' is defined in {len(where)} files: {', '.join(sorted(where))}")
if clashes:
    print(f"unity_names: {clashes} names repeat within a target; rename them or move them to a shared header")
    sys.exit(1)
print(f"unity_names: no file-local name repeats within a target ({sum(map(len, targets.values()))} files)")
