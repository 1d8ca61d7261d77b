"""Floe layouts from a top-view photo of ice floes: the segmentation behind
scripts/layout_from_photo, as the seed paper made its initial layouts (watershed
segmentation of tank photos, Meyer 1992).

0. The floe size, unless given: from the photo's pattern spectrum (openings by
   growing disks), then refined to the median size of the floes it segments.
1. Ice from water: the photo's brightness is corrected for uneven lighting
   (the background, a Gaussian blur far wider than a floe, is divided out), then
   split by Otsu's threshold; ice is the bright class (or the dark one, ice="dark").
2. Touching floes apart: a watershed of the distance transform from one marker
   per floe (the distance transform's local maxima at least min_distance apart).
3. One convex polygon per floe: icedem floes are convex, so a non-convex segment
   becomes its convex hull; the area this adds is reported.
4. Pixels to the tank frame: pixel (u, v), u to the right and v down, maps to
   x = X + S u, z = Z - S v (a top view with the towing direction to the right),
   or through a projective transform fitted to four reference points (a photo
   taken at an angle).
"""
import csv
import io
import math

import numpy as np
from scipy import ndimage
from scipy.spatial import ConvexHull
from skimage import filters, measure, morphology, segmentation, transform
from skimage.feature import peak_local_max

from ..runs import output_guard
from ..runs.polygons import polygon_area, signed_area_xz


def to_gray(image):
    """Brightness in [0, 1] of an RGB(A) or grey image."""
    img = np.asarray(image, dtype=float)
    if img.max() > 1.0:
        img = img / 255.0
    if img.ndim == 3:
        img = img[..., :3] @ np.array([0.299, 0.587, 0.114])
    return img


def ice_mask(gray, floe_px, ice="bright"):
    """Ice pixels: brightness over a background as wide as a few floes, Otsu-thresholded."""
    background = filters.gaussian(gray, sigma=3.0 * floe_px)
    corrected = gray / np.maximum(background, 1e-6)
    if ice == "dark":
        corrected = corrected.max() - corrected
    mask = corrected > filters.threshold_otsu(corrected)
    # specks of glare or noise, and pinholes in floes
    r = max(1, int(round(floe_px / 30)))
    mask = morphology.binary_opening(mask, morphology.disk(r))
    return ndimage.binary_fill_holes(mask)


def opening_spectrum(mask, radii):
    """The ice's area left after a morphological opening by a disk of each radius (px): the
    granulometry of the mask. An opening by a disk removes every part of the ice narrower
    than the disk, so the area falls most where the disk outgrows the floes. Each opening
    is two distance transforms (erosion: points deeper than r; dilation of those by r)."""
    inside = ndimage.distance_transform_edt(mask)
    areas = []
    for r in radii:
        core = inside > r
        if not core.any():
            areas.append(0)
            continue
        areas.append(int((ndimage.distance_transform_edt(~core) <= r).sum()))
    return np.array(areas, dtype=float)


def estimate_floe_px(gray, ice="bright"):
    """The typical floe side in pixels, from the photo alone: the radius at which openings
    by growing disks remove the most ice per step of log radius (the peak of the pattern
    spectrum) is about half a floe's width. The mask for it is corrected for lighting over
    a tenth of the photo (floes are taken to be smaller than that)."""
    h, w = gray.shape
    mask = ice_mask(gray, min(h, w) / 30.0, ice)  # background sigma: 3 x this = a tenth of the photo
    radii = np.unique(np.round(np.geomspace(1.0, min(h, w) / 6.0, 40)).astype(int))
    areas = opening_spectrum(mask, radii)
    loss = -np.diff(areas) / np.diff(np.log(radii))
    k = int(np.argmax(loss))
    return 2.0 * np.sqrt(radii[k] * radii[k + 1])  # the peak's radius (geometric middle), doubled


def median_floe_px(labels):
    """The side of a square of the segments' median area, px."""
    areas = np.bincount(labels.ravel())[1:]
    areas = areas[areas > 0]
    return float(np.sqrt(np.median(areas))) if len(areas) else float("nan")


def segment(gray, ice="bright", floe_px=None, rounds=4, tolerance=0.05):
    """(labels, floe_px, estimates): the floes segmented, with the floe size in pixels used and
    every estimate on the way. Given floe_px, one segmentation at it. Without, the size
    starts at the pattern spectrum's estimate and is replaced by the segments' median
    side until it changes by less than `tolerance` (a fixed point: the segmentation at a
    size finds floes of that size), at most `rounds` times."""
    if floe_px is not None:
        mask = ice_mask(gray, floe_px, ice)
        return split_floes(mask, floe_px), floe_px, [floe_px]
    estimates = [estimate_floe_px(gray, ice)]
    for _ in range(rounds):
        used = estimates[-1]
        labels = split_floes(ice_mask(gray, used, ice), used)
        found = median_floe_px(labels)
        if not np.isfinite(found) or abs(found - used) <= tolerance * used:
            break
        estimates.append(found)
    return labels, used, estimates


def split_floes(mask, floe_px, gap_px=1.0):
    """Label image: the watershed of the distance transform, one marker per floe peak."""
    distance = ndimage.distance_transform_edt(mask)
    # a floe's distance-transform peak is about half its width; two floes' peaks are at least
    # half a floe apart
    peaks = peak_local_max(distance, min_distance=max(2, int(0.35 * floe_px)),
                           threshold_abs=max(1.0, 0.15 * floe_px), labels=measure.label(mask), exclude_border=False)
    # a peak marks a floe of its own only if it stands a twentieth of a floe above the ridge
    # to any higher peak: two floes touching over part of an edge meet at a neck far lower
    # than their peaks, while an elongated floe's two peaks are joined by a ridge nearly as
    # high (without this, 40 % fields of 0.2 m floes were split into up to 3.6 % too many)
    prominent = morphology.h_maxima(distance, 0.05 * floe_px).astype(bool)
    peaks = np.array([p for p in peaks if prominent[tuple(p)]], dtype=int).reshape(-1, 2)  # none: still whole numbers
    markers = np.zeros(mask.shape, dtype=int)
    markers[tuple(peaks.T)] = np.arange(1, len(peaks) + 1)
    return segmentation.watershed(-distance, markers, mask=mask)


def pixel_to_tank(metres_per_pixel=None, origin=(0.0, 0.0), reference=None):
    """A function (u, v) arrays -> (x, z) arrays, m."""
    if reference is not None:
        ref = np.asarray(reference, dtype=float)  # rows u, v, x, z
        t = transform.ProjectiveTransform()
        if not t.estimate(ref[:, :2], ref[:, 2:]):
            raise ValueError("the reference points do not define a projective transform")
        return lambda u, v: tuple(t(np.column_stack([u, v])).T)
    s, (x0, z0) = metres_per_pixel, origin
    return lambda u, v: (x0 + s * np.asarray(u, dtype=float), z0 - s * np.asarray(v, dtype=float))


def floes_from_labels(labels, to_tank, min_area=0.0, region=None):
    """One floe per labelled segment: {"centre": (x, z), "polygon": the convex outline relative to
    it (n x 2), "hull_added": hull area / segment area - 1, "pixels": the outline in pixels (u, v)},
    in the tank frame (m); segments under min_area (m^2) or with a centroid outside region
    (x0, x1, z0, z1) are left out."""
    floes = []
    for r in measure.regionprops(labels):
        # the midpoints of the segment's pixels' sides: a pixel is ice when the edge passes
        # beyond its centre, so along a row or column the edge lies half a pixel beyond the
        # last centre on average (where the sides' midpoints are), and across a slanted edge
        # the midpoints stand out half as far as the corners would (the corners' hull read the
        # concentration about one point high at 40-60 %)
        rows, cols = r.coords[:, 0] + 0.5, r.coords[:, 1] + 0.5
        corners = np.concatenate([np.column_stack([cols + du, rows + dv])
                                  for du, dv in ((-0.5, 0), (0.5, 0), (0, -0.5), (0, 0.5))])
        try:
            hull = ConvexHull(corners)
        except Exception:  # a line of pixels: no area
            continue
        pts = simplify(corners[hull.vertices])
        x, z = to_tank(pts[:, 0], pts[:, 1])
        poly = np.column_stack([x, z])
        area = polygon_area(poly)
        if area < min_area:
            continue
        segment_area = area * r.area / hull.volume  # the pixels' share of the hull, in m^2
        c = polygon_centroid(poly)
        if region is not None and not (region[0] <= c[0] <= region[1] and region[2] <= c[1] <= region[3]):
            continue
        floes.append({"centre": c, "polygon": poly - c, "hull_added": area / segment_area - 1.0,
                      "pixels": pts})
    return floes


def overlap(p, q):
    """True if two convex polygons overlap by more than touching (separating axis test)."""
    for poly in (p, q):
        edges = np.roll(poly, -1, axis=0) - poly
        for nx, nz in np.column_stack([-edges[:, 1], edges[:, 0]]):
            a, b = p @ (nx, nz), q @ (nx, nz)
            tol = 1e-9 * (abs(a).max() + abs(b).max())
            if a.max() <= b.min() + tol or b.max() <= a.min() + tol:
                return False
    return True


def clip_half_plane(poly, normal, offset):
    """The part of a convex polygon with p . normal <= offset (Sutherland-Hodgman, one plane)."""
    out = []
    for k in range(len(poly)):
        p, q = poly[k], poly[(k + 1) % len(poly)]
        dp, dq = p @ normal - offset, q @ normal - offset
        if dp <= 0:
            out.append(p)
        if dp * dq < 0:
            out.append(p + (q - p) * (dp / (dp - dq)))
    return np.asarray(out)


def separate(floes):
    """Cut the outlines of overlapping neighbours apart: two segments of touching floes share
    a pixel boundary that is seldom straight, and their convex hulls then overlap by a
    pixel or so. Each pair is cut along the line across the line between their centroids,
    in the middle of their overlap along it, so each keeps all but its share of the
    sliver. Returns {floe index: the share of its area cut off}."""
    cut = {}
    area0 = [polygon_area(f["polygon"]) for f in floes]
    radius = [np.hypot(*f["polygon"].T).max() for f in floes]
    for i in range(len(floes)):
        for j in range(i + 1, len(floes)):
            a, b = floes[i], floes[j]
            gap = b["centre"] - a["centre"]
            dist = np.hypot(*gap)
            if dist > radius[i] + radius[j] or dist == 0:
                continue
            pa, pb = a["centre"] + a["polygon"], b["centre"] + b["polygon"]
            if not overlap(pa, pb):
                continue
            n = gap / dist
            middle = 0.5 * ((pa @ n).max() + (pb @ n).min())
            for k, f, poly, sign in ((i, a, pa, 1.0), (j, b, pb, -1.0)):
                f["polygon"] = clip_half_plane(poly, sign * n, sign * middle) - f["centre"]
                cut[k] = 1.0 - polygon_area(f["polygon"]) / area0[k]
    return cut


def polygon_centroid(p):
    x, z = p[:, 0], p[:, 1]
    cross = x * np.roll(z, -1) - np.roll(x, -1) * z
    a = cross.sum() / 2
    return np.array([((x + np.roll(x, -1)) * cross).sum() / (6 * a), ((z + np.roll(z, -1)) * cross).sum() / (6 * a)])


def simplify(hull_px, tolerance_px=0.75):
    """Fewer hull vertices: the pixel staircase of a segment's hull straightened by
    Douglas-Peucker to within tolerance_px of it (a subset of its vertices, so still
    convex, and nowhere more than a pixel inside it: at most a pixel's width of area
    along the outline is lost)."""
    if len(hull_px) <= 4:
        return hull_px
    ring = np.vstack([hull_px, hull_px[:1]])
    out = measure.approximate_polygon(ring, tolerance=tolerance_px)[:-1]
    return out if len(out) >= 3 else hull_px


def write_csv(floes, path):
    """The layout file icedem reads (layout.file): x, z, yaw_deg, polygon (local vertices); written
    whole or not at all (output_guard.write_text)."""
    out = io.StringIO()
    out.write("# floes from a photo (scripts/layout_from_photo): centroid x, z (m, tank frame),\n"
              "# yaw 0, outline vertices relative to the centroid (m), counter-clockwise seen from above\n")
    w = csv.writer(out)
    w.writerow(["x", "z", "yaw_deg", "polygon"])
    for f in floes:
        c, poly = f["centre"], f["polygon"]
        # icedem's outlines are counter-clockwise seen from above (+y): in (x, z) that is
        # a negative shoelace sum
        p = poly if signed_area_xz(poly) > 0 else poly[::-1]
        w.writerow([f"{c[0]:.5f}", f"{c[1]:.5f}", "0", "; ".join(f"{x:.5f} {z:.5f}" for x, z in p)])
    output_guard.write_text(path, out.getvalue())


def summary(floes, region_area):
    """Floe count, concentration and area quantiles."""
    areas = np.array([polygon_area(f["polygon"]) for f in floes]) if floes else np.array([0.0])
    added = np.array([f["hull_added"] for f in floes]) if floes else np.array([0.0])
    return {"floes": len(floes), "concentration": float(areas.sum() / region_area) if region_area else math.nan,
            "area_m2": {"min": float(areas.min()), "median": float(np.median(areas)), "max": float(areas.max())},
            "hull_added_fraction": {"median": float(np.median(added)), "max": float(added.max())}}


def draw_overlay(image, floes, path):
    """The photo with each floe's convex outline and centroid drawn over it (PNG)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    h, w = np.asarray(image).shape[:2]
    fig, ax = plt.subplots(figsize=(10, 10 * h / w))
    ax.imshow(image, cmap="gray" if np.asarray(image).ndim == 2 else None)
    for f in floes:
        p = np.vstack([f["pixels"], f["pixels"][:1]])
        ax.plot(p[:, 0], p[:, 1], "-", color="tab:red", lw=0.8)
        ax.plot(*f["pixels"].mean(axis=0), ".", color="tab:red", ms=2)
    ax.set_title(f"{len(floes)} floes detected (outlines: their convex hulls)", fontsize=9)
    ax.set_axis_off()
    fig.tight_layout()
    output_guard.save_figure(fig, path, dpi=80 if path.lower().endswith((".jpg", ".jpeg")) else 110)
    plt.close(fig)
