"""The vertical edge load that breaks a square floe floating on water, in bending:
the statics behind docs/model/breakage.md.

    scripts/edge_load.py [--size L] [--thickness H] [--element-size LE] [--modulus E]
                         [--poisson NU] [--bending-strength SB] [--water-density RHO]

A floe of side L is a beam of width L on an elastic (Winkler) foundation of
stiffness k = rho_w g L per metre, the water's buoyancy. A vertical load P on one
edge bends it; it breaks where the bending moment reaches the section's capacity
M_c = sigma_b L H^2 / 6 (the seed paper's eq. 3 summed over the joints of one
joint line: n joints of L_e H^2 sigma_b / 6 with n L_e = L).

Two solutions, printed side by side:
- rigid floe (L much shorter than the characteristic length): the foundation
  reaction is linear, q(s) = P/L (4 - 6 s/L) from the loaded edge, and the moment
  M(s) = P s (1 - s/L)^2 peaks at s = L/3 with 4 P L / 27;
- elastic floe: EI w'''' + k w = 0 on 0 < s < L with free ends and the point load
  at s = 0, solved as a boundary-value problem (scipy's solve_bvp), with
  EI = E H^3 L / (12 (1 - nu^2)).
Both give the breaking load at the section of the largest moment and at the first
joint line of the lattice (s = L_e), where a lattice can break.
"""
import argparse

import numpy as np
from scipy.integrate import solve_bvp

G = 9.81  # m/s^2


def rigid_moment(s, length, load=1.0):
    """Bending moment at s from the loaded edge of a rigid floe on water, N m."""
    return load * s * (1.0 - s / length) ** 2


def elastic_moment(s, length, ei, k, load=1.0):
    """Bending moment at s of an elastic beam on a Winkler foundation, free ends, point load at 0."""
    def rhs(x, y):  # y = (w, w', w'', w''')
        return np.vstack([y[1], y[2], y[3], -(k / ei) * y[0]])

    def bc(a, b):  # no moment at either end; the load is the shear at s = 0; no shear at s = L
        return np.array([a[2], ei * a[3] - load, b[2], b[3]])

    x = np.linspace(0.0, length, 200)
    sol = solve_bvp(rhs, bc, x, np.zeros((4, x.size)), tol=1e-10, max_nodes=100000)
    if not sol.success:
        raise RuntimeError(f"solve_bvp: {sol.message}")
    return np.abs(ei * sol.sol(np.atleast_1d(s))[2])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--size", type=float, default=0.6, help="floe side L, m (paper's larger floes)")
    ap.add_argument("--thickness", type=float, default=0.033, help="ice thickness H, m (Table 3)")
    ap.add_argument("--element-size", type=float, nargs="+", default=[0.15, 0.20], help="lattice element sizes, m")
    ap.add_argument("--modulus", type=float, default=60e6, help="elastic modulus E, Pa (Table 3)")
    ap.add_argument("--poisson", type=float, default=0.33, help="Poisson ratio")
    ap.add_argument("--bending-strength", type=float, default=36.4e3, help="sigma_b, Pa (Table 3)")
    ap.add_argument("--water-density", type=float, default=1000.0, help="kg/m^3 (Table 3)")
    a = ap.parse_args(argv)

    L, H = a.size, a.thickness
    D = a.modulus * H ** 3 / (12 * (1 - a.poisson ** 2))  # flexural rigidity per width, N m
    l_c = (D / (a.water_density * G)) ** 0.25             # characteristic length, m
    ei, k = D * L, a.water_density * G * L
    capacity = a.bending_strength * L * H ** 2 / 6         # one joint line across the floe, N m
    s = np.linspace(0.0, L, 2001)
    m_rigid = rigid_moment(s, L)
    m_elastic = elastic_moment(s, L, ei, k)
    print(f"floe {L} m x {L} m x {H} m: flexural rigidity D = {D:.1f} N m, characteristic length "
          f"{l_c:.3f} m, L / l_c = {L / l_c:.2f}")
    print(f"bending capacity of a section across the floe: {capacity:.3f} N m")
    print(f"{'':28s} {'rigid floe':>12s} {'elastic floe':>14s}")
    i_r, i_e = int(np.argmax(m_rigid)), int(np.argmax(m_elastic))
    print(f"{'largest moment per N at s =':28s} {s[i_r]:9.3f} m {s[i_e]:11.3f} m")
    print(f"{'breaking edge load there':28s} {capacity / m_rigid[i_r]:10.1f} N {capacity / m_elastic[i_e]:12.1f} N")
    for le in a.element_size:
        r, e = rigid_moment(le, L), float(elastic_moment(le, L, ei, k)[0])
        print(f"{f'at the first joint line, {le} m':28s} {capacity / r:10.1f} N {capacity / e:12.1f} N")


if __name__ == "__main__":
    main()
