#!/usr/bin/python3
"""Every unit of dem/ is in the file map of docs/model/architecture.md, and every unit the map
names exists; every room of dem/ is a room of dem/CMakeLists.txt and of the map's table of rooms;
every Python command of scripts/ is a link to scripts/icedem_tool.py with a row in its table, and
every row has its link.

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
    if not os.path.exists(os.path.join(root, "tools", "icedem_tools", module + ".py")):
        failures.append(f"scripts/icedem_tool.py names tools/icedem_tools/{module}.py, which does not exist")

for f in failures:
    print("FAILED:", f)
print(f"{len(rooms)} rooms checked, {len(failures)} failures")
sys.exit(1 if failures else 0)
