"""Run by ParaView's pvpython: open an XDMF file with ParaView's XDMF reader and
check its time steps, cells and the floe_id field against what the writer says;
for a run with breakable floes also the joints' block: its cells, and how many of
them are broken at the first and at the last time step; for a moored run (lines=N) its mooring
block: N polylines, each with its tension, every one pulling.

    pvpython check_xdmf.py RUN.xdmf STEPS CELLS FLOES [JOINTS BROKEN_FIRST BROKEN_LAST] [lines=N]
"""
import sys

from paraview import servermanager
from paraview.simple import UpdatePipeline, XDMFReader

lines = [int(a.split("=")[1]) for a in sys.argv if a.startswith("lines=")]
args = [a for a in sys.argv if not a.startswith("lines=")]
path, steps, cells, floes = args[1], int(args[2]), int(args[3]), int(args[4])
joints = [int(a) for a in args[5:8]] if len(args) > 5 else None
reader = XDMFReader(FileNames=[path])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
assert len(times) == steps, f"{len(times)} time steps, expected {steps}"


def blocks(data):
    """The grids of one time step by name (a lone grid is 'floes')."""
    if not data.IsA("vtkMultiBlockDataSet"):
        return {"floes": data}
    out = {}
    for i in range(data.GetNumberOfBlocks()):
        # the reader names a block by its grid and time index: "joints[8]"
        name = data.GetMetaData(i).Get(data.NAME()).split("[")[0] if data.HasMetaData(i) else f"block{i}"
        block = data.GetBlock(i)
        if block is not None and block.IsA("vtkMultiBlockDataSet"):
            out.update(blocks(block))
        elif block is not None:
            out[name] = block
    return out


for t, broken_expected in ((times[0], joints[1] if joints else None), (times[-1], joints[2] if joints else None)):
    UpdatePipeline(time=t, proxy=reader)
    grids = blocks(servermanager.Fetch(reader))
    floe_grid = grids["floes"]
    assert floe_grid.GetNumberOfCells() == cells, f"t = {t}: {floe_grid.GetNumberOfCells()} cells, expected {cells}"
    floe_id = floe_grid.GetCellData().GetArray("floe_id")
    assert floe_id is not None, "no floe_id cell data"
    lo, hi = floe_id.GetRange()
    assert (lo, hi) == (0, floes - 1), f"floe_id range {(lo, hi)}, expected (0, {floes - 1})"
    if lines:
        assert "mooring" in grids, f"t = {t}: no mooring block (blocks: {sorted(grids)})"
        mg = grids["mooring"]
        assert mg.GetNumberOfCells() == lines[0], f"t = {t}: {mg.GetNumberOfCells()} lines, expected {lines[0]}"
        tension = mg.GetCellData().GetArray("tension")
        assert tension is not None and min(tension.GetValue(i) for i in range(lines[0])) > 0, \
            f"t = {t}: every line pulls (tension > 0)"
    else:
        assert "mooring" not in grids, "a towed run has no mooring block"
    if joints is None:
        assert "joints" not in grids, "a run without joints has no joints block"
        continue
    assert "joints" in grids, f"t = {t}: no joints block (blocks: {sorted(grids)})"
    jg = grids["joints"]
    assert jg.GetNumberOfCells() == joints[0], f"t = {t}: {jg.GetNumberOfCells()} joint cells, expected {joints[0]}"
    for name in ("broken", "failure_mode", "break_time", "floe_id"):
        assert jg.GetCellData().GetArray(name) is not None, f"t = {t}: no joint cell data '{name}'"
    broken = jg.GetCellData().GetArray("broken")
    count = sum(int(broken.GetValue(i)) for i in range(broken.GetNumberOfTuples()))
    assert count == broken_expected, f"t = {t}: {count} broken joints, expected {broken_expected}"
    modes = jg.GetCellData().GetArray("failure_mode")
    for i in range(modes.GetNumberOfTuples()):
        assert (modes.GetValue(i) >= 0) == bool(broken.GetValue(i)), f"t = {t}: joint {i}: mode and state disagree"
joined = (f", {joints[0]} joints, {joints[2]} broken at the end" if joints else "") + (f", {lines[0]} mooring lines" if lines else "")
print(f"ParaView read {path}: {steps} time steps, {cells} cells, floe ids 0-{floes - 1}{joined}")
