"""Outlines in the (x, z) plane, as icedem writes them (/bodies/vertices) and reads them (layout
files): their shoelace area. Kept apart from photolayout so that reading a run's bodies does not
load scikit-image."""
import numpy as np


def signed_area_xz(p):
    """Positive for counter-clockwise seen from above (+y), as icedem's polygon.hpp counts."""
    x, z = p[:, 0], p[:, 1]
    return -0.5 * (np.dot(x, np.roll(z, -1)) - np.dot(z, np.roll(x, -1)))


def polygon_area(p):
    """The area of an outline (n x 2, either winding)."""
    return abs(signed_area_xz(p))
