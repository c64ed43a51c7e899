"""The shape of the code (docs/architecture.md), checked so that it stays: the layers of src/ include only
their own and lower layers (so there is no include circle between layers) and call only functions of their own and
lower layers (a function declared in the public roller.h but defined in a higher layer counts as that layer's), no
include circle between files, no C file over 400 lines, no struct over 20 fields, no source file left out of
libroller's list."""
import os
import re
import sys

from rollertest import SOURCE

LAYERS = ["mesh", "model", "verify", "contact", "io", "integrate", "modes", "rom", "app"]  # low to high
MAX_LINES, MAX_FIELDS = 400, 20
src = os.path.join(SOURCE, "src")
failures = []

files = {}
for layer in os.listdir(src):
    for name in os.listdir(os.path.join(src, layer)):
        if name.endswith((".c", ".h")):
            files[f"{layer}/{name}"] = open(os.path.join(src, layer, name)).read()
assert set(f.split("/")[0] for f in files) <= set(LAYERS), f"unknown layer folders: {set(f.split('/')[0] for f in files) - set(LAYERS)}"

# includes: "layer/file.h" or a same-folder "file.h"
graph = {}
for path, text in files.items():
    layer = path.split("/")[0]
    deps = []
    for inc in re.findall(r'^#include\s+"([^"]+)"', text, re.M):
        target = inc if "/" in inc else f"{layer}/{inc}"
        if target not in files:
            failures.append(f"{path}: includes {inc}, not a file of src/")
            continue
        if LAYERS.index(target.split("/")[0]) > LAYERS.index(layer):
            failures.append(f"{path} (layer {layer}) includes the higher layer's {target}")
        deps.append(target)
    graph[path] = deps


def cycle_from(node, stack, done):
    stack.append(node)
    for d in graph[node]:
        if d in stack:
            return stack[stack.index(d):] + [d]
        if d not in done:
            c = cycle_from(d, stack, done)
            if c:
                return c
    stack.pop()
    done.add(node)
    return None


done = set()
for node in graph:
    if node not in done:
        c = cycle_from(node, [], done)
        if c:
            failures.append("include circle: " + " -> ".join(c))
            break

# calls: every Roller* function is defined in one layer; a call from a lower layer is an upward call
defined = {}
for path, text in files.items():
    if path.endswith(".c"):
        for name in re.findall(r"^(?:static\s+)?(?:inline\s+)?[A-Za-z_][\w\s\*]*?\b(Roller\w+)\s*\([^;]*?\)\s*\{", text, re.M):
            defined.setdefault(name, path.split("/")[0])
for path, text in files.items():
    layer = path.split("/")[0]
    body = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    for name in sorted(set(re.findall(r"\b(Roller[A-Z]\w*)\s*\(", body))):
        owner = defined.get(name)
        if owner and LAYERS.index(owner) > LAYERS.index(layer):
            failures.append(f"{path} (layer {layer}) calls {name} of the higher layer {owner}")

for path, text in files.items():
    n = text.count("\n")
    if n > MAX_LINES:
        failures.append(f"{path}: {n} lines (> {MAX_LINES})")

# struct bodies: count declarators (a, b, *c) of every member declaration
headers = dict(files)
for name in os.listdir(os.path.join(SOURCE, "include")):
    headers["include/" + name] = open(os.path.join(SOURCE, "include", name)).read()
for path, text in headers.items():
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    for m in re.finditer(r"struct\s*(\w*)\s*\{", text):
        depth, i = 1, m.end()
        while depth:
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
        body = text[m.end():i - 1]
        body = re.sub(r"\{[^{}]*\}", "", body)  # nested (anonymous) bodies count as one member
        fields = sum(len(re.sub(r"\[[^\]]*\]|\([^)]*\)", "", decl).split(",")) for decl in body.split(";") if decl.strip())
        name = m.group(1) or text[i:i + 40].split(";")[0].strip(" }")
        if fields > MAX_FIELDS:
            failures.append(f"{path}: struct {name} has {fields} fields (> {MAX_FIELDS})")

cmake = open(os.path.join(SOURCE, "CMakeLists.txt")).read()
for path in files:
    if path.endswith(".c") and path != "app/main.c" and f"src/{path}" not in cmake:
        failures.append(f"src/{path} is not in libroller's source list (CMakeLists.txt)")

print(f"architecture: {len(files)} files in {len(LAYERS)} layers checked")
if failures:
    sys.exit("FAIL:\n  " + "\n  ".join(failures))
print("PASS")
