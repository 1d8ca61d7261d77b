"""A floe layout file from a top-view photo of the floes (tools/icedem_tools/photo/photolayout.py
says how): PHOTO in, LAYOUT.csv out (the CSV that layout.file reads), with a
PNG of the detected outlines over the photo to check them, and the floe count,
concentration and area distribution.

    scripts/layout_from_photo PHOTO -o LAYOUT.csv [--floe-size L]
        (--metres-per-pixel S [--origin X,Z] | --reference "u,v,x,z;u,v,x,z;u,v,x,z;u,v,x,z")
        [--channel X0,X1,Z0,Z1] [--min-area A] [--ice bright|dark] [--overlay PNG]

Scale and placement: pixel (u, v), u to the right and v down, maps to
x = X + S u, z = Z - S v (the towing direction to the right); or four reference
points "u,v,x,z" (pixel and tank coordinates, m) fit a projective transform, for a
photo taken at an angle. The typical floe side sets the scale of the lighting
correction and of the floe separation; without --floe-size (m) the tool finds it
from the photo (photolayout.segment: the pattern spectrum's estimate, refined to the
median size of the floes found) and reports it. --channel keeps the floes whose
centroid lies in the region (m; the concentration is taken over it, default the
photo's extent); --min-area drops smaller segments (m^2, default a tenth of a floe).
Non-convex segments become their convex hull (icedem floes are convex): the area
this adds is reported. Hulls of touching floes that overlap a neighbour (their
shared boundary is seldom straight) are cut apart along a straight line through
the middle of the overlap, as icedem requires; the count and the area cut are
reported.
"""
import argparse
import json
import os
import sys

import numpy as np

from ..runs import output_guard
from . import photolayout


def pair(text):
    a, b = (float(v) for v in text.split(","))
    return a, b


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("photo")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--floe-size", type=float, help="typical floe side, m (default: found from the photo)")
    ap.add_argument("--metres-per-pixel", type=float)
    ap.add_argument("--origin", type=pair, default=(0.0, 0.0), help="X,Z of pixel (0, 0), m")
    ap.add_argument("--reference", help="four 'u,v,x,z' points separated by ';'")
    ap.add_argument("--channel", help="X0,X1,Z0,Z1: keep floes whose centroid is inside, m")
    ap.add_argument("--min-area", type=float, help="m^2 (default a tenth of a floe)")
    ap.add_argument("--ice", choices=["bright", "dark"], default="bright")
    ap.add_argument("--overlay", help="PNG of the outlines over the photo (default OUTPUT with .png)")
    a = ap.parse_args(argv)
    from skimage import io  # noqa: E402 (Debian's python3-skimage)

    if (a.metres_per_pixel is None) == (a.reference is None):
        ap.error("give either --metres-per-pixel (and --origin) or --reference")
    reference = None
    if a.reference:
        reference = [tuple(float(v) for v in p.split(",")) for p in a.reference.split(";") if p.strip()]
        if len(reference) != 4 or any(len(r) != 4 for r in reference):
            ap.error("--reference: expected four 'u,v,x,z' points separated by ';'")
    # before any work: the overlay defaults to OUTPUT with .png, which may be the photo itself
    overlay = a.overlay or os.path.splitext(a.output)[0] + ".png"
    output_guard.guard([("-o", a.output, output_guard.FILE),
                        ("--overlay" if a.overlay else "the overlay (OUTPUT with .png)", overlay, output_guard.FILE)],
                       [a.photo])
    try:
        image = io.imread(a.photo)
    except Exception as e:  # noqa: BLE001 (an unreadable photo is the user's input)
        print(f"layout_from_photo: {a.photo}: cannot read the photo ({e})", file=sys.stderr)
        return 2
    gray = photolayout.to_gray(image)
    to_tank = photolayout.pixel_to_tank(a.metres_per_pixel, a.origin, reference)
    # metres per pixel at the photo's centre
    h, w = gray.shape
    x0, z0 = to_tank(np.array([w / 2]), np.array([h / 2]))
    x1, z1 = to_tank(np.array([w / 2 + 10]), np.array([h / 2]))
    m_per_px = np.hypot(x1 - x0, z1 - z0)[0] / 10
    given_px = a.floe_size / m_per_px if a.floe_size else None
    labels, floe_px, estimates = photolayout.segment(gray, a.ice, given_px)
    floe_size = floe_px * m_per_px
    if a.channel:
        region = tuple(float(v) for v in a.channel.split(","))
    else:
        xs, zs = to_tank(np.array([0, w, w, 0]), np.array([0, 0, h, h]))
        region = (xs.min(), xs.max(), zs.min(), zs.max())
    min_area = a.min_area if a.min_area is not None else 0.1 * floe_size ** 2
    floes = photolayout.floes_from_labels(labels, to_tank, min_area, region)
    if not floes:  # nothing written: a layout of no floes is not one icedem runs
        print(f"layout_from_photo: {a.photo}: no floes found (typical floe side {floe_size:.3f} m); check --ice "
              f"(bright or dark ice), the scale and --floe-size", file=sys.stderr)
        return 2
    cut = photolayout.separate(floes)
    photolayout.write_csv(floes, a.output)
    area = (region[1] - region[0]) * (region[3] - region[2])
    s = photolayout.summary(floes, area)
    photolayout.draw_overlay(image, floes, overlay)
    how = "given" if a.floe_size else ("found from the photo: " + " -> ".join(f"{e * m_per_px:.3f}" for e in estimates)
                                       + " m")
    s["floe_size_m"] = floe_size
    print(f"typical floe side {floe_size:.3f} m ({how})")
    print(f"{a.output}: {s['floes']} floes, concentration {100 * s['concentration']:.1f} % of "
          f"{area:.2f} m^2; floe area min {s['area_m2']['min']:.4f}, median {s['area_m2']['median']:.4f}, "
          f"max {s['area_m2']['max']:.4f} m^2; convex hulls add {100 * s['hull_added_fraction']['median']:.1f} % "
          f"(median), at most {100 * s['hull_added_fraction']['max']:.1f} %, to the segments' pixels; {len(cut)} "
          f"outlines cut, by at most {100 * max(cut.values(), default=0.0):.1f} % of their area, to stop overlapping a "
          f"neighbour; outlines over the photo: {overlay}")
    print(json.dumps(s))
    return 0


if __name__ == "__main__":
    sys.exit(main())
