"""The shape of the code (docs/architecture.md), checked so that it stays: the layers of src/ include only
their own and lower layers (so there is no include circle between layers) and call only functions of their own and
lower layers (a function declared in the public roller.h but defined in a higher layer counts as that layer's), no
include circle between files, no C file over 400 lines, no struct over 20 fields, no source file left out of
libroller's list."""
import os
import re
import sys

from rollertest import SOURCE

LAYERS = ["mesh", "model", "verify", "friction", "contact", "io", "integrate", "modes", "app"]  # low to high
FOLDERS = {"sweep": "app"}  # a folder of its own at a layer's level (-sweep: app-level, docs/architecture.md)


def level(folder):
    """The layer index of a folder of src/."""
    return LAYERS.index(FOLDERS.get(folder, folder))


MAX_LINES, MAX_FIELDS = 400, 20
src = os.path.join(SOURCE, "src")
failures = []

files = {}
for layer in os.listdir(src):
    for name in os.listdir(os.path.join(src, layer)):
        if name.endswith((".c", ".h")):
            files[f"{layer}/{name}"] = open(os.path.join(src, layer, name)).read()
assert set(f.split("/")[0] for f in files) <= set(LAYERS) | set(FOLDERS), f"unknown layer folders: {set(f.split('/')[0] for f in files) - set(LAYERS) - set(FOLDERS)}"

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
        if level(target.split("/")[0]) > level(layer):
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
        if owner and level(owner) > level(layer):
            failures.append(f"{path} (layer {layer}) calls {name} of the higher layer {owner}")

# calls between the files of a folder: B -> A when a function body of B calls a function A defines (not a static one of
# a .c file, which only its own file sees); a circle means no file of it can be read, tested or changed alone
DEFINITION = re.compile(r"^(static\s+)?(?:inline\s+)?(?:const\s+)?[A-Za-z_][\w\s\*]*?\b([A-Za-z_]\w*)\s*\(([^;{}]*?)\)\s*\{", re.M)


def code(text):
    """text without comments and string literals"""
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    return re.sub(r'"(?:\\.|[^"\\])*"', '""', text)


def functions(text):
    """(static, name, body) of every function defined in text (code only)"""
    for m in DEFINITION.finditer(text):
        depth, i = 1, m.end()
        while depth:
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
        yield bool(m.group(1)), m.group(2), text[m.end():i - 1]


for folder in LAYERS + list(FOLDERS):
    members = {p: code(t) for p, t in files.items() if p.split("/")[0] == folder}
    owner, own = {}, {p: set() for p in members}
    for p, t in members.items():
        for static, name, _ in functions(t):
            if static and p.endswith(".c"):
                own[p].add(name)
            else:
                owner.setdefault(name, p)
    calls = {p: {} for p in members}
    for p, t in members.items():
        body = " ".join(b for _, _, b in functions(t))
        for name in set(re.findall(r"\b([A-Za-z_]\w*)\s*\(", body)) - own[p]:
            if owner.get(name, p) != p:
                calls[p].setdefault(owner[name], name)
    # the strongly connected sets of files (Tarjan): every set of more than one file is a circle
    index, low, stack, sets = {}, {}, [], []

    def connect(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in sorted(calls[v]):
            if w not in index:
                connect(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            members_of = stack[stack.index(v):]
            del stack[stack.index(v):]
            if len(members_of) > 1:
                sets.append(sorted(members_of))

    for node in sorted(members):
        if node not in index:
            connect(node)
    for circle in sets:
        edges = [f"{a} -> {b} ({calls[a][b]})" for a in circle for b in sorted(calls[a]) if b in circle]
        failures.append(f"circle of calls in src/{folder}/ between {', '.join(circle)}: " + "; ".join(edges))

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

print(f"architecture: {len(files)} files in {len(LAYERS)} layers ({len(FOLDERS)} more folder at a layer's level) checked")
if failures:
    sys.exit("FAIL:\n  " + "\n  ".join(failures))
print("PASS")
