"""ParaView view of a run's snapshots: writes RUN.xdmf and RUN_views.h5 beside
RUN.h5. The views file holds every snapshot's floe (and element) outlines as
prisms in the tank frame (top and bottom faces, m), the XDMF a temporal
collection of grids over them with each body's floe id and awake flag as cell
data. Open RUN.xdmf in ParaView (XDMF reader). Awake is 0 at rest, 1 awake and 2
for a body not in the run at that snapshot (a floe split into pieces, or a piece not
yet made, fracture.mode = "analytic"): threshold awake below 2 to hide them; 3 for a floe left
behind the structure (activation.leave_behind), out of the run where it left.

A run with breakable floes gets a second grid per snapshot, "joints": the glued
face of every joint (a quadrilateral across the ice's thickness, on its first
element's side), with cell data `broken` (1 once /fracture/events has its break),
`failure_mode` (the mode code of its break, -1 while intact; the names are in the
XDMF's Information and in /fracture/events' mode_names), `break_time` (s, -1 if
it never broke) and `floe_id`. Threshold on `broken` to see the cracks.

A moored run (structure.motion = "moored") gets a grid "mooring": each line as a polyline from its
anchor to its fairlead (/snapshots/mooring_lines; the linear mooring: its attachment's offset from
rest), with cell data `tension` (N, /mooring/tension at the snapshot's step).

    scripts/xdmf_snapshots.py RUN.h5
"""
import html
import os
import sys

import h5py
import numpy as np

from . import output_guard
from .results import snapshot_field


def quat_to_matrix(q):
    w, x, y, z = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])


def nearest_edge(outline, point):
    """The edge (two vertices) of a closed polygon nearest to a point (x, z)."""
    a = outline
    b = np.roll(outline, -1, axis=0)
    ab = b - a
    t = np.clip(np.einsum("ij,ij->i", point - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-300), 0, 1)
    d = np.linalg.norm(a + t[:, None] * ab - point, axis=1)
    i = int(np.argmin(d))
    return a[i], b[i]


def joint_faces(h, off, verts, thick):
    """Per joint: its glued face as 4 points (x, y, z) in its first body's frame, its first
    body, floe id, break time (-1: never) and failure mode code (-1: never)."""
    if "/joints/bodies" not in h or len(h["/joints/bodies"]) == 0:
        return None
    bodies = h["/joints/bodies"][:]
    floe = h["/joints/floe"][:]
    index = h["/joints/index"][:]
    mid = h["/joints/midpoint"][:]
    row = {(int(f), int(i)): r for r, (f, i) in enumerate(zip(floe, index))}
    break_time = np.full(len(bodies), -1.0)
    mode = np.full(len(bodies), -1, dtype=np.int32)
    for e in h["/fracture/events"][:]:
        r = row[(int(e["floe"]), int(e["joint"]))]
        if break_time[r] < 0:
            break_time[r], mode[r] = e["time"], e["mode"]
    quads = np.empty((len(bodies), 4, 3))
    for r, (a, _) in enumerate(bodies):
        p, q = nearest_edge(verts[off[a]:off[a + 1]], mid[r, [0, 2]])
        half = thick[a] / 2
        quads[r] = [[p[0], half, p[1]], [q[0], half, q[1]], [q[0], -half, q[1]], [p[0], -half, p[1]]]
    names = h["/fracture/events"].attrs.get("mode_names", "")
    names = names.decode() if isinstance(names, bytes) else str(names)
    return quads, bodies[:, 0], floe, break_time, mode, names


def write_views(path):
    """Writes RUN.xdmf and RUN_views.h5 beside the run's HDF5 file `path`."""
    stem = os.path.splitext(path)[0]
    views = stem + "_views.h5"
    output_guard.guard([("the views", views, output_guard.VIEWS), ("the XDMF file", stem + ".xdmf", output_guard.FILE)],
                       [path])
    with h5py.File(path, "r") as h:
        off = h["/bodies/vertex_offset"][:]
        verts = h["/bodies/vertices"][:]
        thick = h["/bodies/thickness"][:]
        floe = h["/bodies/floe_id"][:]
        times = h["/snapshots/time"][:]
        positions, orientations, awakes = snapshot_field(h)  # the full field of each snapshot
        nb = len(off) - 1
        # each body a polygonal prism: its outline at +-h/2 about the centre of mass (body frame)
        local = []
        for b in range(nb):
            v = verts[off[b]:off[b + 1]]
            top = np.column_stack([v[:, 0], np.full(len(v), thick[b] / 2), v[:, 1]])
            bottom = top.copy()
            bottom[:, 1] = -thick[b] / 2
            local.append((top, bottom))
        # XDMF "Mixed" topology: per body a polyhedron would need XDMF3; two polygons (top,
        # bottom) per body read everywhere: type 3 (polygon), vertex count, vertex ids
        topo = []
        base = 0
        for top, _ in local:
            n = len(top)
            topo += [3, n] + list(range(base, base + n))
            topo += [3, n] + list(range(base + n, base + 2 * n))
            base += 2 * n
        npts = base
        joints = joint_faces(h, off, verts, thick)
        lines = h["/snapshots/mooring_lines"][:] if "/snapshots/mooring_lines" in h else None  # k x l x p x 3
        if lines is not None:
            load_time, tension = h["/load/time"][:], h["/mooring/tension"][:]
        with h5py.File(views, "w") as out:
            if joints is not None:
                quads, first, jfloe, break_time, mode, mode_names = joints
                nj = len(first)
                out["joint_topology"] = np.arange(4 * nj, dtype=np.int64).reshape(nj, 4)
                out["joint_floe_id"] = jfloe.astype(np.int32)
                out["joint_break_time"] = break_time
            if lines is not None:
                nl, npl = lines.shape[1], lines.shape[2]
                out["line_topology"] = np.arange(nl * npl, dtype=np.int64).reshape(nl, npl)
                for k in range(len(times)):
                    out[f"line_points/{k}"] = lines[k].reshape(-1, 3)
                    at = min(np.searchsorted(load_time, times[k]), len(load_time) - 1) if len(load_time) else None
                    out[f"line_tension/{k}"] = tension[at] if at is not None else np.zeros(nl)
            out["topology"] = np.asarray(topo, dtype=np.int64)
            out["floe_id"] = np.repeat(floe, 2).astype(np.int32)
            for k in range(len(times)):
                pos = positions[k]
                q = orientations[k]
                pts = np.empty((npts, 3))
                i = 0
                for b, (top, bottom) in enumerate(local):
                    R = quat_to_matrix(q[b])
                    for face in (top, bottom):
                        pts[i:i + len(face)] = face @ R.T + pos[b]
                        i += len(face)
                out[f"points/{k}"] = pts
                out[f"awake/{k}"] = np.repeat(awakes[k], 2).astype(np.int32)
                if joints is not None:
                    R = np.array([quat_to_matrix(qb) for qb in q[first]])  # nj x 3 x 3
                    out[f"joint_points/{k}"] = (np.einsum("jab,jpb->jpa", R, quads) + pos[first][:, None, :]).reshape(-1, 3)
                    broken = (break_time >= 0) & (break_time <= times[k])
                    out[f"joint_broken/{k}"] = broken.astype(np.int32)
                    out[f"joint_failure_mode/{k}"] = np.where(broken, mode, -1).astype(np.int32)
    name = os.path.basename(views)
    cells = 2 * nb

    def attribute(label, count, item, kind="Int", precision=4):
        return f"""        <Attribute Name="{label}" AttributeType="Scalar" Center="Cell">
          <DataItem Dimensions="{count}" NumberType="{kind}" Precision="{precision}" Format="HDF">{name}:/{item}</DataItem>
        </Attribute>"""

    def grid(label, time, topology, geometry, attributes, info=""):
        return f"""      <Grid Name="{label}" GridType="Uniform">
{time}{info}        <Topology {topology}
        </Topology>
        <Geometry GeometryType="XYZ">
          <DataItem {geometry}
        </Geometry>
{chr(10).join(attributes)}
      </Grid>"""

    grids = []
    alone = joints is None and lines is None  # the floes' grid alone at each time, or a spatial collection
    for k, t in enumerate(times):
        time = f'        <Time Value="{t:.6g}"/>\n'
        floes = grid("floes" if not alone else f"t{k}", "" if not alone else time,
                     f'TopologyType="Mixed" NumberOfElements="{cells}">\n          <DataItem Dimensions="{len(topo)}" '
                     f'NumberType="Int" Precision="8" Format="HDF">{name}:/topology</DataItem>',
                     f'Dimensions="{npts} 3" NumberType="Float" Precision="8" Format="HDF">{name}:/points/{k}</DataItem>',
                     [attribute("floe_id", cells, "floe_id"), attribute("awake", cells, f"awake/{k}")])
        if alone:
            grids.append(floes)
            continue
        parts = [floes]
        if lines is not None:
            parts.append(grid("mooring", "", f'TopologyType="Polyline" NodesPerElement="{npl}" NumberOfElements="{nl}">\n'
                              f'          <DataItem Dimensions="{nl} {npl}" NumberType="Int" Precision="8" Format="HDF">'
                              f'{name}:/line_topology</DataItem>',
                              f'Dimensions="{nl * npl} 3" NumberType="Float" Precision="8" Format="HDF">{name}:/line_points/{k}'
                              '</DataItem>', [attribute("tension", nl, f"line_tension/{k}", "Float", 8)]))
        if joints is None:
            grids.append(f"""      <Grid Name="t{k}" GridType="Collection" CollectionType="Spatial">
{time}{chr(10).join(parts)}
      </Grid>""")
            continue
        # with joints, a spatial collection per time: the floes, the joints' faces (and the lines)
        faces = grid("joints", "", f'TopologyType="Quadrilateral" NumberOfElements="{nj}">\n          <DataItem '
                     f'Dimensions="{nj} 4" NumberType="Int" Precision="8" Format="HDF">{name}:/joint_topology</DataItem>',
                     f'Dimensions="{4 * nj} 3" NumberType="Float" Precision="8" Format="HDF">{name}:/joint_points/{k}'
                     '</DataItem>',
                     [attribute("broken", nj, f"joint_broken/{k}"),
                      attribute("failure_mode", nj, f"joint_failure_mode/{k}"),
                      attribute("break_time", nj, "joint_break_time", "Float", 8),
                      attribute("floe_id", nj, "joint_floe_id")],
                     f'        <Information Name="failure_mode" Value="{html.escape(mode_names)}"/>\n')
        parts.insert(1, faces)
        grids.append(f"""      <Grid Name="t{k}" GridType="Collection" CollectionType="Spatial">
{time}{chr(10).join(parts)}
      </Grid>""")
    with open(stem + ".xdmf", "w") as f:
        f.write(f"""<?xml version="1.0" ?>
<Xdmf Version="2.0">
  <Domain>
    <Grid Name="floes" GridType="Collection" CollectionType="Temporal">
{chr(10).join(grids)}
    </Grid>
  </Domain>
</Xdmf>
""")
    joined = (f", {nj} joints" if joints is not None else "") + (f", {nl} mooring lines" if lines is not None else "")
    print(f"wrote {stem}.xdmf and {views} ({len(times)} snapshots, {nb} bodies{joined})")


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        sys.exit(__doc__)
    write_views(argv[0])
    return 0


if __name__ == "__main__":
    sys.exit(main())
