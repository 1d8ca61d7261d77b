#!/usr/bin/python3
"""Every unit of dem/ is in the file map of docs/model/architecture.md, and every unit the map
names exists; every room of dem/ is a room of dem/CMakeLists.txt and of the map's table of rooms;
every Python command of scripts/ is a link to scripts/icedem_tool.py with a row in its table, and
every row has its link; every module of tools/icedem_tools/ is in a room and in the map, imports only
from the rooms its room uses, and does not import itself back.

Usage: test_architecture.py SOURCE_DIR
"""
import os
import re
import sys

root = sys.argv[1]
dem = os.path.join(root, "dem")
text = open(os.path.join(root, "docs/model/architecture.md"), encoding="utf-8").read()
cmake = open(os.path.join(dem, "CMakeLists.txt"), encoding="utf-8").read()
failures = []

rooms = sorted(d for d in os.listdir(dem) if os.path.isdir(os.path.join(dem, d)))
loose = sorted(f for f in os.listdir(dem) if f.endswith((".hpp", ".cpp")))
if loose:
    failures.append(f"units of dem/ outside a room: {', '.join(loose)}")
cmake_rooms = re.findall(r"^icedem_room\((\w+)", cmake, re.M)
if sorted(cmake_rooms) != rooms:
    failures.append(f"rooms in dem/CMakeLists.txt {sorted(cmake_rooms)}, folders of dem/ {rooms}")
table = text[text.index("| room | uses |"):]
table = table[:table.index("\n\n")]
table_rooms = re.findall(r"^\| (\w+) \|", table, re.M)[1:]  # below the header
if sorted(table_rooms) != rooms:
    failures.append(f"rooms in the map's table {sorted(table_rooms)}, folders of dem/ {rooms}")

for room in rooms:
    units = {os.path.splitext(f)[0] for f in os.listdir(os.path.join(dem, room)) if f.endswith((".hpp", ".cpp"))}
    m = re.search(rf"^### dem/{room}/\n(.*?)(?=^### |^## |\Z)", text, re.M | re.S)
    if not m:
        failures.append(f"docs/model/architecture.md has no section ### dem/{room}/")
        continue
    named = set()
    for row in re.findall(r"^\| ([^|]+) \|", m.group(1), re.M):
        if row.strip() in ("file", "---"):
            continue
        for name in row.split(","):
            named.add(os.path.splitext(name.strip())[0])
    for u in sorted(units - named):
        failures.append(f"dem/{room}/{u} is not in the file map (docs/model/architecture.md, ### dem/{room}/)")
    for u in sorted(named - units):
        failures.append(f"the file map names dem/{room}/{u}, which does not exist")

# the Python commands: one entry point, a link per command
import importlib.util  # noqa: E402
scripts = os.path.join(root, "scripts")
spec = importlib.util.spec_from_file_location("icedem_tool", os.path.join(scripts, "icedem_tool.py"))
tool = importlib.util.module_from_spec(spec)
spec.loader.exec_module(tool)
links = {f for f in os.listdir(scripts) if os.path.islink(os.path.join(scripts, f))}
for f in sorted(links):
    if os.readlink(os.path.join(scripts, f)) != "icedem_tool.py":
        failures.append(f"scripts/{f} links to {os.readlink(os.path.join(scripts, f))}, not icedem_tool.py")
for f in sorted(links - set(tool.COMMANDS)):
    failures.append(f"scripts/{f} is a link without a row in scripts/icedem_tool.py")
for f in sorted(set(tool.COMMANDS) - links):
    failures.append(f"scripts/icedem_tool.py names {f}, which is not a link in scripts/")
for f in sorted(os.listdir(scripts)):
    path = os.path.join(scripts, f)
    if (not os.path.islink(path) and f != "icedem_tool.py"
            and re.search(r"^from icedem_tools\.\w+ import main", open(path, errors="replace").read(), re.M)):
        failures.append(f"scripts/{f} is a shim of its own: make it a link to icedem_tool.py")
for module, _ in tool.COMMANDS.values():
    if not os.path.exists(os.path.join(root, "tools", "icedem_tools", module.replace(".", "/") + ".py")):
        failures.append(f"scripts/icedem_tool.py names tools/icedem_tools/{module.replace('.', '/')}.py, "
                        "which does not exist")

# the Python tools' rooms: every module in a room and in the map; a room imports only from itself and
# the rooms it uses; no module imports itself back through others (lazy imports inside functions count)
import ast  # noqa: E402
package = os.path.join(root, "tools", "icedem_tools")
loose = sorted(f for f in os.listdir(package) if f.endswith(".py") and f != "__init__.py")
if loose:
    failures.append(f"modules of tools/icedem_tools/ outside a room: {', '.join(loose)}")
tools_table = text[text.index("| tools room | uses |"):]
tools_table = tools_table[:tools_table.index("\n\n")]
uses = {}
for row in re.findall(r"^\| (\w+) \|([^|]*)\|", tools_table, re.M):  # the header is two words
    uses[row[0]] = {u.strip() for u in row[1].split(",") if u.strip()}
tool_rooms = sorted(d for d in os.listdir(package) if os.path.isdir(os.path.join(package, d)) and d != "__pycache__")
if sorted(uses) != tool_rooms:
    failures.append(f"rooms in the map's table of tools {sorted(uses)}, folders of tools/icedem_tools/ {tool_rooms}")
graph = {}
for room in tool_rooms:
    modules = {f[:-3] for f in os.listdir(os.path.join(package, room)) if f.endswith(".py") and f != "__init__.py"}
    m = re.search(rf"^#### tools/icedem_tools/{room}/\n(.*?)(?=^#+ |\Z)", text, re.M | re.S)
    named = set()
    if not m:
        failures.append(f"docs/model/architecture.md has no section #### tools/icedem_tools/{room}/")
    else:
        for row in re.findall(r"^\| ([^|]+) \|", m.group(1), re.M):
            if row.strip() not in ("module", "---"):
                named |= {n.strip() for n in row.split(",")}
    for u in sorted(modules - named):
        failures.append(f"tools/icedem_tools/{room}/{u}.py is not in the map (docs/model/architecture.md)")
    for u in sorted(named - modules):
        failures.append(f"the map names tools/icedem_tools/{room}/{u}.py, which does not exist")
    for mod in sorted(modules):
        tree = ast.parse(open(os.path.join(package, room, mod + ".py"), encoding="utf-8").read())
        deps = set()
        for node in ast.walk(tree):
            if not isinstance(node, ast.ImportFrom) or node.level == 0:
                continue
            if node.level == 1:  # from .x import y / from . import x: this room
                targets = [(room, node.module)] if node.module else [(room, a.name) for a in node.names]
            elif node.level == 2 and node.module:  # from ..room import x / from ..room.x import y
                other, _, rest = node.module.partition(".")
                targets = [(other, rest)] if rest else [(other, a.name) for a in node.names]
            else:
                failures.append(f"tools/icedem_tools/{room}/{mod}.py: an import the rooms do not allow (line {node.lineno})")
                continue
            for other, target in targets:
                if other != room and other not in uses.get(room, set()):
                    failures.append(f"tools/icedem_tools/{room}/{mod}.py imports {other}.{target}: room {room} does not "
                                    f"use room {other}")
                deps.add(f"{other}.{target}")
        graph[f"{room}.{mod}"] = deps
# a module that reaches itself through its imports
def reaches(start):
    seen, todo = set(), list(graph.get(start, ()))
    while todo:
        n = todo.pop()
        if n == start:
            return True
        if n not in seen:
            seen.add(n)
            todo.extend(graph.get(n, ()))
    return False
for node in sorted(graph):
    if reaches(node):
        failures.append(f"tools/icedem_tools/{node.replace('.', '/')}.py imports itself back through other modules")

for f in failures:
    print("FAILED:", f)
print(f"{len(rooms)} rooms of dem/ and {len(tool_rooms)} of tools/ ({len(graph)} modules) checked, "
      f"{len(failures)} failures")
sys.exit(1 if failures else 0)
