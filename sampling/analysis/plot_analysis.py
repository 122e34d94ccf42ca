#!/usr/bin/env python3
"""Plots for `pdrt analyze` (run by the C++ command, not by hand).

Usage: plot_analysis.py STAGING_DIR

STAGING_DIR holds stats.json, periodogram.f32 and the first file's points.f64 (+ radius.f64)
as written by `pdrt analyze`; the PNGs listed in stats.json["plots"] are written beside them.
The command moves them into the output directory once all exist.
"""
import json
import math
import os
import sys

os.environ.setdefault("MPLBACKEND", "Agg")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

DPI = 110


def arr(values):
    """JSON list (nulls for non-finite values) -> float array with NaNs."""
    if values is None:
        return None
    return np.array([np.nan if v is None else v for v in values], dtype=float)


def save(fig, path):
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def draw_disks(ax, xy, radii, color, alpha, lw):
    """Disks of the given radii (data units) around xy."""
    diam = 2.0 * radii
    ax.add_collection(
        EllipseCollection(diam, diam, np.zeros_like(diam), units="xy", offsets=xy,
                          transOffset=ax.transData, facecolors=color, edgecolors="none", alpha=alpha,
                          linewidths=lw))


def tile_copies(xy, lo, hi):
    """Periodic images of xy (from the 8 neighbouring tiles) that fall inside [lo, hi]^2."""
    out = []
    for ex in (-1, 0, 1):
        for ey in (-1, 0, 1):
            if ex == 0 and ey == 0:
                continue
            s = xy + np.array([ex, ey], dtype=float)
            keep = (s[:, 0] >= lo[0]) & (s[:, 0] <= hi[0]) & (s[:, 1] >= lo[1]) & (s[:, 1] <= hi[1])
            if keep.any():
                out.append((s[keep], keep))
    return out


def plot_points_2d(ax, xy, half_r, periodic, lo, hi, title):
    n = len(xy)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    width = hi[0] - lo[0]
    # Marker size: about a third of the mean spacing in the visible window, in points^2.
    visible = max(1.0, n * width * width)
    dot = (72.0 * 5.0 / math.sqrt(visible) / 3.0) ** 2
    dot = min(max(dot, 0.05), 16.0)
    if periodic:
        for s, keep in tile_copies(xy, lo, hi):
            if half_r is not None:
                draw_disks(ax, s, half_r[keep], "tab:blue", 0.12, 0)
            ax.scatter(s[:, 0], s[:, 1], s=dot, c="0.65", linewidths=0)
    if half_r is not None:
        draw_disks(ax, xy, half_r, "tab:blue", 0.35, 0)
    ax.scatter(xy[:, 0], xy[:, 1], s=dot, c="k", linewidths=0)
    ax.add_patch(Rectangle((0, 0), 1, 1, fill=False, ec="tab:red", lw=0.8))
    ax.set_xlabel("x0")
    ax.set_ylabel("x1")
    ax.set_title(title + " (red: the unit square)", fontsize=9)


def plot_points(stats, stage, out):
    dim, n = stats["dim"], stats["count"]
    pts = np.fromfile(os.path.join(stage, "points.f64"), dtype="<f8").reshape(n, dim)
    periodic = stats["periodic"]
    rpath = os.path.join(stage, "radius.f64")
    if dim == 1:
        fig, ax = plt.subplots(figsize=(8, 3.2))
        ax.scatter(pts[:, 0], np.arange(n), s=2 if n > 2000 else 6, c="k", linewidths=0)
        ax.set_xlim(0, 1)
        ax.set_xlabel("x0")
        ax.set_ylabel("generation order")
        ax.set_title(f"{n} points (1-D)", fontsize=9)
        fig.tight_layout()
        save(fig, out)
        return
    if dim > 2:
        pairs = [(0, 1), (0, 2), (1, 2)]
        fig, axes = plt.subplots(1, 3, figsize=(13, 4.6))
        dot = min(max((72.0 * 4.0 / math.sqrt(n) / 3.0) ** 2, 0.05), 16.0)
        for ax, (a, b) in zip(axes, pairs):
            ax.scatter(pts[:, a], pts[:, b], s=dot, c="k", linewidths=0)
            ax.set_xlim(0, 1)
            ax.set_ylim(0, 1)
            ax.set_aspect("equal")
            ax.set_xlabel(f"x{a}")
            ax.set_ylabel(f"x{b}")
            ax.set_title(f"projection (x{a}, x{b})", fontsize=9)
        fig.suptitle(f"{n} points in {dim}-D (projections; disks only drawn in 2-D)", fontsize=10)
        fig.tight_layout()
        save(fig, out)
        return

    # 2-D: disks at half the radius, so they touch exactly when points are one radius apart.
    if os.path.exists(rpath):
        half_r = 0.5 * np.fromfile(rpath, dtype="<f8")
        src = "CSV radius"
    elif stats.get("min_distance") is not None:
        half_r = np.full(n, 0.5 * stats["min_distance"])
        src = "min distance"
    else:
        half_r, src = None, "none"
    title = f"{n} points, disks of radius r/2 (r from {src})" + (", periodic" if periodic else "")
    zoom = n > 1500
    fig, axes = plt.subplots(1, 2 if zoom else 1, figsize=(13 if zoom else 6.8, 6.6), squeeze=False)
    margin = 0.08 if periodic else 0.02
    plot_points_2d(axes[0][0], pts, half_r if not zoom or n <= 20000 else None, periodic,
                   (-margin, -margin), (1 + margin, 1 + margin), title)
    if zoom:
        # About 400 points around the corner, where boundary or tiling effects show.
        w = min(0.5, math.sqrt(400.0 / n))
        lo = (-0.5 * w, -0.5 * w) if periodic else (-0.02 * w, -0.02 * w)
        hi = (lo[0] + w, lo[1] + w)
        plot_points_2d(axes[0][1], pts, half_r, periodic, lo, hi, f"zoom on the corner ({w:.3g} wide)")
    fig.tight_layout()
    save(fig, out)


def plot_periodogram(stats, stage, out):
    sp = stats["spectrum"]
    R, sd, K = sp["resolution"], sp["spectral_dim"], sp["realizations"]
    p = np.fromfile(os.path.join(stage, "periodogram.f32"), dtype="<f4").astype(float)
    with np.errstate(divide="ignore"):
        db = 10.0 * np.log10(p)
    if sd == 1:
        f = np.arange(R) - R // 2
        keep = f > 0
        fig, ax = plt.subplots(figsize=(8, 4))
        ax.plot(f[keep] / sp["mean_count"], db[keep], lw=0.6)
        ax.axhline(0, color="0.5", lw=0.8, ls="--")
        ax.set_xlabel("frequency / N (cycles per mean spacing)")
        ax.set_ylabel("power (dB)")
        ax.set_title(f"1-D periodogram, R = {R}, K = {K}", fontsize=9)
        fig.tight_layout()
        save(fig, out)
        return
    img = db.reshape(R, R)
    img[R // 2, R // 2] = np.nan  # DC
    finite = img[np.isfinite(img)]
    vmax = float(np.percentile(finite, 99.9)) if finite.size else 10.0
    vmin = max(float(np.percentile(finite, 1.0)) if finite.size else -30.0, vmax - 40.0)
    fig, ax = plt.subplots(figsize=(7.2, 6.2))
    h = R / 2
    im = ax.imshow(img, origin="lower", extent=(-h - 0.5, h - 0.5, -h - 0.5, h - 0.5), cmap="magma", vmin=vmin,
                   vmax=vmax, interpolation="nearest")
    fig.colorbar(im, ax=ax, label="power (dB, 10 log10; white noise = 0 dB)")
    ax.set_xlabel("kx (cycles per unit)")
    ax.set_ylabel("ky (cycles per unit)")
    proj = " of the (x0, x1) projection" if stats["dim"] > 2 else ""
    ax.set_title(f"periodogram{proj}, R = {R}, averaged over K = {K}, DC removed", fontsize=9)
    fig.tight_layout()
    save(fig, out)


def radial_plot(stats, key, ylabel, out, reference, reference_label):
    sp = stats["spectrum"]
    fine, ann = sp["fine_annuli"], sp["annuli"]
    unit = sp["mean_count"] ** (1.0 / sp["spectral_dim"])
    fig, ax = plt.subplots(figsize=(8, 4.6))
    ax.plot(arr(fine["frequency_normalized"]), arr(fine[key]), lw=0.9, color="tab:blue",
            label="one-pixel annuli (PSA-style)")
    ax.plot(arr(ann["frequency_normalized"]), arr(ann[key]), "o-", ms=4, lw=1.0, color="tab:orange",
            label="20 annuli DC..corner (McCool & Fiume §2)")
    ax.axhline(reference, color="0.4", lw=0.8, ls="--", label=reference_label)
    if sp["spectral_dim"] == 2:
        ax.axvline(sp["nyquist_frequency"] / unit, color="0.4", lw=0.8, ls=":", label="edge of the square")
    ax.set_xlabel("frequency / sqrt(N) (cycles per mean sample spacing)" if sp["spectral_dim"] == 2
                  else "frequency / N (cycles per mean sample spacing)")
    ax.set_ylabel(ylabel)
    ax.set_xlim(left=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"{ylabel} of the periodogram: N = {stats['count']}, K = {sp['realizations']} realization(s), "
                 f"R = {sp['resolution']}", fontsize=9)
    fig.tight_layout()
    save(fig, out)


def plot_prefix(stats, out):
    rho = arr(stats["prefix_relative_radius"])
    fig, ax = plt.subplots(figsize=(8, 4.4))
    if rho is not None and rho.size:
        n = np.arange(stats["prefix_relative_radius_first_n"], stats["prefix_relative_radius_first_n"] + rho.size)
        ax.plot(n, rho, lw=0.9)
        ax.set_xscale("log")
        ax.axhline(rho[-1], color="0.5", lw=0.8, ls="--", label=f"final rho = {rho[-1]:.4g}")
        ax.legend(fontsize=8)
    else:
        ax.text(0.5, 0.5, "fewer than 2 points", ha="center", va="center", transform=ax.transAxes)
    ax.set_xlabel("prefix length n (generation order)")
    ax.set_ylabel("rho = min distance / max packing distance")
    ax.grid(alpha=0.3, which="both")
    ax.set_title(f"relative radius of each prefix of {os.path.basename(stats['file'])}", fontsize=9)
    fig.tight_layout()
    save(fig, out)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: plot_analysis.py STAGING_DIR")
    stage = sys.argv[1]
    with open(os.path.join(stage, "stats.json")) as f:
        stats = json.load(f)
    plots = set(stats["plots"])
    sp = stats["spectrum"]
    if "points.png" in plots:
        plot_points(stats, stage, os.path.join(stage, "points.png"))
    if "periodogram.png" in plots:
        plot_periodogram(stats, stage, os.path.join(stage, "periodogram.png"))
    if "radial_power.png" in plots:
        radial_plot(stats, "power_db", "radial power (dB)", os.path.join(stage, "radial_power.png"), 0.0,
                    "white noise (0 dB)")
    if "anisotropy.png" in plots:
        radial_plot(stats, "anisotropy_db", "anisotropy (dB)", os.path.join(stage, "anisotropy.png"),
                    sp["anisotropy_white_noise_db"], "white noise: -10 log10 K")
    if "prefix_rho.png" in plots:
        plot_prefix(stats, os.path.join(stage, "prefix_rho.png"))


if __name__ == "__main__":
    main()
