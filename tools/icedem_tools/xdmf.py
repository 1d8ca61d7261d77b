"""ParaView view of a run's snapshots: writes RUN.xdmf and RUN_views.h5 beside
RUN.h5. The views file holds every snapshot's floe (and element) outlines as
prisms in the tank frame (top and bottom faces, m), the XDMF a temporal
collection of grids over them with each body's floe id and awake flag as cell
data. Open RUN.xdmf in ParaView (XDMF reader).

    scripts/xdmf_snapshots.py RUN.h5
"""
import os
import sys

import h5py
import numpy as np


def quat_to_matrix(q):
    w, x, y, z = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])


def write_views(path):
    """Writes RUN.xdmf and RUN_views.h5 beside the run's HDF5 file `path`."""
    stem = os.path.splitext(path)[0]
    views = stem + "_views.h5"
    with h5py.File(path, "r") as h:
        off = h["/bodies/vertex_offset"][:]
        verts = h["/bodies/vertices"][:]
        thick = h["/bodies/thickness"][:]
        floe = h["/bodies/floe_id"][:]
        times = h["/snapshots/time"][:]
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
        with h5py.File(views, "w") as out:
            out["topology"] = np.asarray(topo, dtype=np.int64)
            out["floe_id"] = np.repeat(floe, 2).astype(np.int32)
            for k in range(len(times)):
                pos = h["/snapshots/position"][k]
                q = h["/snapshots/orientation"][k]
                pts = np.empty((npts, 3))
                i = 0
                for b, (top, bottom) in enumerate(local):
                    R = quat_to_matrix(q[b])
                    for face in (top, bottom):
                        pts[i:i + len(face)] = face @ R.T + pos[b]
                        i += len(face)
                out[f"points/{k}"] = pts
                out[f"awake/{k}"] = np.repeat(h["/snapshots/awake"][k], 2).astype(np.int32)
    name = os.path.basename(views)
    cells = 2 * nb
    grids = []
    for k, t in enumerate(times):
        grids.append(f"""      <Grid Name="t{k}" GridType="Uniform">
        <Time Value="{t:.6g}"/>
        <Topology TopologyType="Mixed" NumberOfElements="{cells}">
          <DataItem Dimensions="{len(topo)}" NumberType="Int" Precision="8" Format="HDF">{name}:/topology</DataItem>
        </Topology>
        <Geometry GeometryType="XYZ">
          <DataItem Dimensions="{npts} 3" NumberType="Float" Precision="8" Format="HDF">{name}:/points/{k}</DataItem>
        </Geometry>
        <Attribute Name="floe_id" AttributeType="Scalar" Center="Cell">
          <DataItem Dimensions="{cells}" NumberType="Int" Precision="4" Format="HDF">{name}:/floe_id</DataItem>
        </Attribute>
        <Attribute Name="awake" AttributeType="Scalar" Center="Cell">
          <DataItem Dimensions="{cells}" NumberType="Int" Precision="4" Format="HDF">{name}:/awake/{k}</DataItem>
        </Attribute>
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
    print(f"wrote {stem}.xdmf and {views} ({len(times)} snapshots, {nb} bodies)")


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        sys.exit(__doc__)
    write_views(argv[0])
    return 0


if __name__ == "__main__":
    sys.exit(main())
