"""Run by ParaView's pvpython: open an XDMF file with ParaView's XDMF reader and
check its time steps, cells and the floe_id field against what the writer says.

    pvpython check_xdmf.py RUN.xdmf STEPS CELLS FLOES
"""
import sys

from paraview import servermanager
from paraview.simple import UpdatePipeline, XDMFReader

path, steps, cells, floes = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
reader = XDMFReader(FileNames=[path])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
assert len(times) == steps, f"{len(times)} time steps, expected {steps}"
for t in (times[0], times[-1]):
    UpdatePipeline(time=t, proxy=reader)
    info = reader.GetDataInformation()
    assert info.GetNumberOfCells() == cells, f"t = {t}: {info.GetNumberOfCells()} cells, expected {cells}"
    data = servermanager.Fetch(reader)
    block = data.GetBlock(0) if data.IsA("vtkMultiBlockDataSet") else data
    floe_id = block.GetCellData().GetArray("floe_id")
    assert floe_id is not None, "no floe_id cell data"
    lo, hi = floe_id.GetRange()
    assert (lo, hi) == (0, floes - 1), f"floe_id range {(lo, hi)}, expected (0, {floes - 1})"
print(f"ParaView read {path}: {steps} time steps, {cells} cells, floe ids 0-{floes - 1}")
