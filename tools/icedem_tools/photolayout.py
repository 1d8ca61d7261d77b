"""Floe layouts from a top-view photo of ice floes: the segmentation behind
scripts/layout_from_photo, as the seed paper made its initial layouts (watershed
segmentation of tank photos, Meyer 1992).

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
import math

import numpy as np
from scipy import ndimage
from scipy.spatial import ConvexHull
from skimage import filters, measure, morphology, segmentation, transform
from skimage.feature import peak_local_max


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


def split_floes(mask, floe_px, gap_px=1.0):
    """Label image: the watershed of the distance transform, one marker per floe peak."""
    distance = ndimage.distance_transform_edt(mask)
    # a floe's distance-transform peak is about half its width; two floes' peaks are at least
    # half a floe apart
    peaks = peak_local_max(distance, min_distance=max(2, int(0.35 * floe_px)),
                           threshold_abs=max(1.0, 0.15 * floe_px), labels=measure.label(mask), exclude_border=False)
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


def polygon_area(p):
    return abs(signed_area_xz(p))


def floes_from_labels(labels, to_tank, min_area=0.0, region=None):
    """One floe per labelled segment: {"centre": (x, z), "polygon": the convex outline relative to
    it (n x 2), "hull_added": hull area / segment area - 1, "pixels": the outline in pixels (u, v)},
    in the tank frame (m); segments under min_area (m^2) or with a centroid outside region
    (x0, x1, z0, z1) are left out."""
    floes = []
    for r in measure.regionprops(labels):
        # the segment's pixel corners, not centres: a segment covers its pixels whole
        rows, cols = r.coords[:, 0], r.coords[:, 1]
        corners = np.concatenate([np.column_stack([cols + du, rows + dv]) for du in (0, 1) for dv in (0, 1)])
        try:
            hull = ConvexHull(corners)
        except Exception:  # a line of pixels: no area
            continue
        pts = corners[hull.vertices]
        x, z = to_tank(pts[:, 0], pts[:, 1])
        poly = np.column_stack([x, z])
        area = polygon_area(poly)
        if area < min_area:
            continue
        segment_area = area * r.area / hull.volume  # the pixels' share of the hull, in m^2
        c = polygon_centroid(poly)
        if region is not None and not (region[0] <= c[0] <= region[1] and region[2] <= c[1] <= region[3]):
            continue
        floes.append({"centre": c, "polygon": simplify(poly - c), "hull_added": area / segment_area - 1.0,
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


def separate(floes, step=0.995, max_rounds=200):
    """Shrink the outlines of overlapping neighbours about their centroids until they only
    touch: two segments of touching floes share a pixel boundary that is seldom straight,
    and their convex hulls then overlap by a pixel or so. Returns {floe index: its scale}."""
    scale = {}
    radius = [np.hypot(*f["polygon"].T).max() for f in floes]
    for i in range(len(floes)):
        for j in range(i + 1, len(floes)):
            a, b = floes[i], floes[j]
            if np.hypot(*(a["centre"] - b["centre"])) > radius[i] + radius[j]:
                continue
            for _ in range(max_rounds):
                if not overlap(a["centre"] + a["polygon"], b["centre"] + b["polygon"]):
                    break
                for k, f in ((i, a), (j, b)):
                    f["polygon"] = f["polygon"] * step
                    c = f["pixels"].mean(axis=0)
                    f["pixels"] = c + (f["pixels"] - c) * step
                    scale[k] = scale.get(k, 1.0) * step
    return scale


def polygon_centroid(p):
    x, z = p[:, 0], p[:, 1]
    cross = x * np.roll(z, -1) - np.roll(x, -1) * z
    a = cross.sum() / 2
    return np.array([((x + np.roll(x, -1)) * cross).sum() / (6 * a), ((z + np.roll(z, -1)) * cross).sum() / (6 * a)])


def simplify(poly, tolerance_fraction=0.02):
    """Fewer hull vertices: drop those within tolerance_fraction of the floe's size of the
    line through their neighbours (pixel staircase), keeping it convex."""
    size = np.ptp(poly, axis=0).max()
    pts = list(poly)
    changed = True
    while changed and len(pts) > 3:
        changed = False
        for i in range(len(pts)):
            a, b, c = pts[i - 1], pts[i], pts[(i + 1) % len(pts)]
            d = abs((c[0] - a[0]) * (a[1] - b[1]) - (a[0] - b[0]) * (c[1] - a[1])) / max(np.hypot(*(c - a)), 1e-12)
            if d < tolerance_fraction * size:
                del pts[i]
                changed = True
                break
    return np.asarray(pts)


def write_csv(floes, path):
    """The layout file icedem reads (layout.file): x, z, yaw_deg, polygon (local vertices)."""
    with open(path, "w", newline="") as f:
        f.write("# floes from a photo (scripts/layout_from_photo): centroid x, z (m, tank frame),\n"
                "# yaw 0, outline vertices relative to the centroid (m), counter-clockwise seen from above\n")
        w = csv.writer(f)
        w.writerow(["x", "z", "yaw_deg", "polygon"])
        for f in floes:
            c, poly = f["centre"], f["polygon"]
            # icedem's outlines are counter-clockwise seen from above (+y): in (x, z) that is
            # a negative shoelace sum
            p = poly if signed_area_xz(poly) > 0 else poly[::-1]
            w.writerow([f"{c[0]:.5f}", f"{c[1]:.5f}", "0", "; ".join(f"{x:.5f} {z:.5f}" for x, z in p)])


def signed_area_xz(p):
    """Positive for counter-clockwise seen from above (+y), as icedem's polygon.hpp counts."""
    x, z = p[:, 0], p[:, 1]
    return -0.5 * (np.dot(x, np.roll(z, -1)) - np.dot(z, np.roll(x, -1)))


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
    fig.savefig(path, dpi=80 if path.lower().endswith((".jpg", ".jpeg")) else 110)
    plt.close(fig)
