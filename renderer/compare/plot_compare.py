#!/usr/bin/env python3
"""Plots and the HTML report of `pdrt compare`: reads DIR/results.json and writes
rmse_vs_spp.png (log-log, fitted slopes, 95 % interval bars over the seeds), rmse_vs_time.png
(equal-time view on CPU seconds, and on CPU seconds less the sampler's share),
error_spectra.png (radially averaged power of the error images), used_spectra.png (the
periodogram of the samples the renders used, per family), errors/heat-N.png (the
error heat maps at N spp with their colour bar), screen_vs_spp.png (blurred RMSE, low-frequency
share and FLIP against spp), errors/flip-ldr-N.png and errors/flip-hdr-N.png (FLIP maps with
their colour bar), spectra/spectrum-N.png (2-D error spectra with their colour bar),
errors/blurred-heat-N.png (the blurred-error heat maps with their colour bar), with --adaptive adaptive_vs_spp.png (the
threshold sweep against uniform sampling) and images/adaptive-samples.png (sample counts),
and index.html."""
import html
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import LinearSegmentedColormap, LogNorm, Normalize  # noqa: E402

COLORS = {"random": "#7f7f7f", "regular": "#9467bd", "jitter": "#1f77b4", "poisson": "#d62728", "poisson-065": "#ff7f0e",
          "pmj02bn": "#17becf", "sobol": "#2ca02c", "zsobol": "#bcbd22",
          "poisson-ss": "#e377c2", "poisson-bn": "#393b79", "poisson-ip": "#8c564b"}
SLOPE_NOTE = ("slope: least-squares slope of log RMSE against log spp; -0.5 is plain Monte Carlo's rate, "
              "lower (more negative) is faster convergence")


def main(out):
    with open(os.path.join(out, "results.json")) as f:
        r = json.load(f)
    runs = r["runs"]
    samplers = r["samplers"]

    k = len(r.get("seeds", [r["seed"]]))
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for s in samplers:
        pts = sorted((u["spp"], u["rmse"], u.get("rmse_ci95", 0)) for u in runs if u["sampler"] == s)
        errorbar(ax, [p[0] for p in pts], pts, COLORS.get(s), "%s (slope %.2f)" % (s, r["slopes"][s]))
    ax.set_xlabel("samples per pixel")
    ax.set_ylabel("RMSE vs reference (mean of %d seeds, 95%% interval)" % k)
    ax.set_title("%s: convergence" % os.path.basename(r["scene"]))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.text(0.01, 0.005, "slope: log-log fit of RMSE vs spp; -0.5 = Monte Carlo, lower = faster", fontsize=7)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    fig.savefig(os.path.join(out, "rmse_vs_spp.png"), dpi=110)
    plt.close(fig)

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    for ax, net in zip(axes, (False, True)):
        for s in samplers:
            pts = sorted((cpu_seconds(u, net), u["rmse"], u.get("rmse_ci95", 0)) for u in runs if u["sampler"] == s)
            share = (r.get("sampler_share", {}).get(s) or {}).get("share")
            label = s if share is None else "%s (sampler %.1f%% of CPU)" % (s, 100 * share)
            errorbar(ax, [p[0] for p in pts], pts, COLORS.get(s), label)
        ax.set_xlabel("CPU seconds of the render%s (user + sys, mean over seeds)" %
                      (" less the sampler's share" if net else ""))
        ax.set_title("equal time: paths only (sampler time removed)" if net else "equal time: whole render")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize="small")
    axes[0].set_ylabel("RMSE vs reference (95% interval)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "rmse_vs_time.png"), dpi=110)
    plt.close(fig)

    plot_spectra(out, r)
    plot_used_spectra(out, r)
    plot_heat_maps(out, r)
    if r.get("blurred_error_maps"):
        plot_blurred_heat_maps(out, r)
    if runs and "blurred_rmse" in runs[0]:
        plot_screen_measures(out, r)
        plot_flip_maps(out, r)
        plot_spectra_2d(out, r)
    if r.get("adaptive"):
        plot_sample_maps(out, r)
    if r.get("adaptive_sweep"):
        plot_adaptive(out, r)
    write_html(out, r)


def cpu_seconds(u, net):
    """A run's mean CPU seconds; with net, less the sampler's measured share."""
    t = u.get("cpu_seconds", u["render_seconds"])
    share = (u.get("sampler_share") or {}).get("share")
    return t * (1 - share) if net and share is not None else t


def errorbar(ax, xs, pts, color, label):
    """Log-log mean RMSE with its 95 % interval; a lower end at or below 0 is drawn to the bottom."""
    ys = [p[1] for p in pts]
    lo = [min(p[2], 0.999 * p[1]) for p in pts]
    ax.errorbar(xs, ys, yerr=[lo, [p[2] for p in pts]], fmt="o-", color=color, label=label, capsize=3)
    ax.set_xscale("log")
    ax.set_yscale("log")


def plot_spectra(out, r):
    """Radially averaged power spectrum of the luminance error (image - reference) at the
    lowest, middle and highest spp, averaged over the seeds. Top row: the power itself, one
    scale for all panels (the y limits come from the data). Bottom row: each curve divided by
    its own mean, so its shape reads directly: flat is white noise, rising with frequency is
    blue noise (error pushed out of the low frequencies the eye sees). The DC term (the mean
    error) and empty rings (power 0, which a log axis cannot show) are left out."""
    runs, samplers, spps = r["runs"], r["samplers"], r["spp"]
    show = sorted(set([spps[0], spps[len(spps) // 2], spps[-1]]))
    fig, axes = plt.subplots(2, len(show), figsize=(5 * len(show), 7.5), squeeze=False)
    lo, hi = math.inf, 0.0
    for col, n in enumerate(show):
        ax, axn = axes[0][col], axes[1][col]
        for s in samplers:
            for u in runs:
                if u["sampler"] == s and u["spp"] == n:
                    pts = [(f, p) for f, p in zip(u["spectrum"]["frequency"], u["spectrum"]["power"])
                           if f > 0 and p is not None and p > 0]
                    if not pts:
                        continue
                    lo, hi = min(lo, min(p for _, p in pts)), max(hi, max(p for _, p in pts))
                    ax.semilogy([f for f, _ in pts], [p for _, p in pts], color=COLORS.get(s), label=s, lw=1)
                    mean = sum(p for _, p in pts) / len(pts)
                    axn.semilogy([f for f, _ in pts], [p / mean for _, p in pts], color=COLORS.get(s), label=s, lw=1)
        ax.set_title("error spectrum, %d spp, mean of %d seeds" % (n, len(r.get("seeds", [0]))), fontsize=10)
        axn.set_title("the same, each curve / its mean (flat = white)", fontsize=10)
        ax.set_ylabel("error power (radial mean |FFT|^2 / pixels)")
        axn.set_ylabel("error power / its mean over frequency")
        axn.axhline(1.0, color="black", lw=0.6, ls=":")
        for a in (ax, axn):
            a.set_xlabel("frequency (cycles per pixel; 0.5 = Nyquist)")
            a.set_xlim(0, 0.5)
            a.grid(True, which="both", alpha=0.3)
            a.legend(fontsize="small")
    if hi > 0:
        for ax in axes[0]:
            ax.set_ylim(lo / 1.5, hi * 1.5)  # one scale, so the panels compare
    fig.suptitle("radially averaged power spectrum of (image - reference) luminance, DC removed", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error_spectra.png"), dpi=110)
    plt.close(fig)


FAMILIES = ["pixel", "lens", "time", "light", "gloss"]


def plot_used_spectra(out, r):
    """The periodogram of the samples each render used, per family (each pixel's bounce-0
    prefix, averaged over pixels), at the middle and highest spp: power 1 is white noise;
    Poisson-disk and stratified patterns have little power below their mean-spacing frequency."""
    runs, samplers, spps = r["runs"], r["samplers"], [n for n in r["spp"] if n >= 2]
    if not spps or not any(u.get("used_samples") for u in runs):
        return
    show = sorted(set([spps[len(spps) // 2], spps[-1]]))
    fig, axes = plt.subplots(len(show), len(FAMILIES), figsize=(4 * len(FAMILIES), 3.4 * len(show)), squeeze=False)
    for row, n in enumerate(show):
        for col, fam in enumerate(FAMILIES):
            ax = axes[row][col]
            for s in samplers:
                for u in runs:
                    if u["sampler"] != s or u["spp"] != n:
                        continue
                    for a in u.get("used_samples", []):
                        if a["family"] != fam:
                            continue
                        pts = [(f, p) for f, p in zip(a["spectrum"]["frequency"], a["spectrum"]["power"])
                               if p is not None and p > 0]
                        rho = a.get("rho_mean")
                        label = s if rho is None else "%s (mean rho %.2f)" % (s, rho)
                        ax.semilogy([f for f, _ in pts], [p for _, p in pts], color=COLORS.get(s), lw=1, label=label)
            ax.axhline(1.0, color="black", lw=0.6, ls=":")
            ax.set_title("%s family, %d spp" % (fam, n), fontsize=10)
            ax.set_xlabel("frequency (cycles per %s)" % ("pixel" if fam == "pixel" else "unit"))
            if col == 0:
                ax.set_ylabel("power (1 = white noise)")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize="x-small")
    fig.suptitle("periodogram of the samples the renders used (each pixel's bounce-0 prefix, mean over pixels)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "used_spectra.png"), dpi=100)
    plt.close(fig)


def heat_colormap(r):
    """The ramp the C++ side coloured the heat maps with (display RGB at 0, 1/4, ..., 1)."""
    return LinearSegmentedColormap.from_list("pdrt_heat", [tuple(c) for c in r["heat_colormap"]])


def heat_map_file(n):
    return "errors/heat-%d.png" % n


def panels_with_colorbar(out, r, path, panels, mappable, label, extend="neither", ticks=None, extent=None):
    """A row of report PNGs (file, title) with one colour bar for all of them; with extent
    (left, right, bottom, top) the panels get axes in those units (the 2-D spectra)."""
    import matplotlib.image as mpimg
    w, aspect = 3.2, r["height"] / max(1, r["width"])
    fig, axes = plt.subplots(1, len(panels), figsize=(w * len(panels) + 1.2, w * aspect + 1.0), squeeze=False)
    for i, (ax, (file, title)) in enumerate(zip(axes[0], panels)):
        ax.imshow(mpimg.imread(os.path.join(out, file)), interpolation="nearest", extent=extent)
        ax.set_title(title, fontsize=9)
        if extent:
            ax.set_xlabel("fx (cycles per pixel)", fontsize=8)
            if i == 0:
                ax.set_ylabel("fy (cycles per pixel)", fontsize=8)
            ax.tick_params(labelsize=7)
        else:
            ax.set_xticks([])
            ax.set_yticks([])
    cb = fig.colorbar(mappable, ax=list(axes[0]), extend=extend, fraction=0.04, pad=0.02)
    cb.set_label(label, fontsize=9)
    if ticks:
        cb.set_ticks(ticks)
        cb.set_ticklabels([("%.2g" % t) if isinstance(t, float) else str(t) for t in ticks])
        cb.minorticks_off()
    fig.savefig(os.path.join(out, path), dpi=110, bbox_inches="tight")
    plt.close(fig)


def plot_heat_maps(out, r):
    """One figure per spp: every sampler's error heat map on the shared scale of that spp,
    with the colour bar in the error's unit."""
    cmap = heat_colormap(r)
    for n in r["spp"]:
        panels = [(u["error_map"], "%s, %d spp: error vs reference" % (s, n))
                  for s in r["samplers"] for u in r["runs"] if u["spp"] == n and u["sampler"] == s]
        sm = plt.cm.ScalarMappable(norm=Normalize(0, r["error_maps"]["scale"][str(n)]), cmap=cmap)
        panels_with_colorbar(out, r, heat_map_file(n), panels, sm, "|luminance error| per pixel", extend="max")


def blurred_heat_map_file(n):
    return "errors/blurred-heat-%d.png" % n


def plot_blurred_heat_maps(out, r):
    """One figure per spp: every sampler's blurred-error heat map on the shared scale of that spp."""
    cmap, b = heat_colormap(r), r["blurred_error_maps"]
    for n in r["spp"]:
        panels = [(u["blurred_error_map"], "%s, %d spp: blurred error" % (s, n))
                  for s in r["samplers"] for u in r["runs"] if u["spp"] == n and u["sampler"] == s]
        sm = plt.cm.ScalarMappable(norm=Normalize(0, b["scale"][str(n)]), cmap=cmap)
        panels_with_colorbar(out, r, blurred_heat_map_file(n), panels, sm,
                             "|blurred luminance error| (sigma %g px)" % b["sigma"], extend="max")


def write_demonstration_html(p, r):
    """The demonstration sheet: what the project exists to show, first."""
    d = r.get("demonstration")
    if not d:
        return
    c = d["crop"]
    p.append("<h2>Demonstration</h2><figure><img src='%s'><figcaption>Rows: samplers; columns: samples per pixel. "
             "Each cell: seed 0's render of the %d&times;%d square at (%d, %d) (%s), zoomed %d&times;, and beside it "
             "the luminance of its error blurred by a Gaussian of &sigma; = %g px (what the eye integrates), on "
             "one heat scale for the whole sheet (0 to %.3g, the 99th percentile of its cells; brighter is "
             "clipped). Last column: the reference. Error the blur removes sat at high frequencies (blue "
             "noise); error that survives it is what the eye sees.</figcaption></figure>" % (
                 html.escape(d["file"]), c["size"], c["size"], c["x"], c["y"], html.escape(d["crop_rule"]),
                 c["zoom"], d["sigma"], d["scale"]))


SCREEN_MEASURES = [  # (title, value of a run as (mean, ci95), log y axis)
    ("RMSE of the error blurred by sigma = 1 px", lambda u: blurred(u, 0), True),
    ("RMSE of the error blurred by sigma = 2 px", lambda u: blurred(u, 1), True),
    ("share of error power below 1/4 cycle/px (white: 0.196)",
     lambda u: (u["low_frequency_share"]["mean"], u["low_frequency_share"]["ci95"]), False),
    ("mean LDR-FLIP", lambda u: (u["flip"]["ldr"]["mean"], u["flip"]["ldr"]["ci95"]), True),
    ("mean HDR-FLIP", lambda u: (u["flip"]["hdr"]["mean"], u["flip"]["hdr"]["ci95"]), True),
]


def blurred(u, i):
    b = u["blurred_rmse"][i]
    return b["rmse"], b["rmse_ci95"]


def plot_screen_measures(out, r):
    """The screen-space measures against spp, one panel each, mean over seeds with 95 % bars."""
    fig, axes = plt.subplots(1, len(SCREEN_MEASURES), figsize=(4.4 * len(SCREEN_MEASURES), 4), squeeze=False)
    for ax, (title, get, log) in zip(axes[0], SCREEN_MEASURES):
        for s in r["samplers"]:
            pts = sorted((u["spp"],) + tuple(get(u)) for u in r["runs"] if u["sampler"] == s)
            pts = [p for p in pts if p[1] is not None]
            ys = [p[1] for p in pts]
            lo = [min(p[2] or 0, 0.999 * p[1]) if log else (p[2] or 0) for p in pts]
            ax.errorbar([p[0] for p in pts], ys, yerr=[lo, [p[2] or 0 for p in pts]], fmt="o-", color=COLORS.get(s),
                        label=s, capsize=3)
        ax.set_xscale("log")
        if log:
            ax.set_yscale("log")
        ax.set_xlabel("samples per pixel")
        ax.set_title(title, fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize="small")
    axes[0][0].set_ylabel("mean over %d seeds (95%% interval)" % len(r.get("seeds", [0])))
    fig.tight_layout()
    fig.savefig(os.path.join(out, "screen_vs_spp.png"), dpi=100)
    plt.close(fig)


def flip_map_file(variant, n):
    return "errors/flip-%s-%d.png" % (variant, n)


def plot_flip_maps(out, r):
    """Per spp and variant, every sampler's seed-0 FLIP map with the colour bar over [0, 1]."""
    sm = plt.cm.ScalarMappable(norm=Normalize(0, 1), cmap=heat_colormap(r))
    for variant in ("ldr", "hdr"):
        for n in r["spp"]:
            panels = [(u["flip"][variant + "_map"], "%s, %d spp: %s-FLIP" % (s, n, variant.upper()))
                      for s in r["samplers"] for u in r["runs"] if u["spp"] == n and u["sampler"] == s]
            panels_with_colorbar(out, r, flip_map_file(variant, n), panels, sm,
                                 "%s-FLIP per pixel (0 = none, 1 = largest)" % variant.upper())


def spectrum_2d_file(n):
    return "spectra/spectrum-%d.png" % n


def plot_spectra_2d(out, r):
    """Per spp, every sampler's 2-D luminance error spectrum (mean over seeds, DC at the centre)
    on one log colour scale."""
    W, H = r["width"], r["height"]
    extent = (-0.5, 0.5 - 1.0 / W, 0.5 - 1.0 / H, -0.5)  # fy grows downwards, as the image rows
    for n in r["spp"]:
        lo, hi = r["error_spectra_2d"]["scale"][str(n)]
        sm = plt.cm.ScalarMappable(norm=LogNorm(10 ** lo, 10 ** hi), cmap=heat_colormap(r))
        panels = [(u["spectrum_2d"], "%s, %d spp: error spectrum" % (s, n))
                  for s in r["samplers"] for u in r["runs"] if u["spp"] == n and u["sampler"] == s]
        ticks = [10 ** (lo + (hi - lo) * k / 4) for k in range(5)]  # labelled even when under a decade
        panels_with_colorbar(out, r, spectrum_2d_file(n), panels, sm, "error power |FFT|^2 / pixels (log scale)",
                             extend="min", ticks=ticks, extent=extent)


def plot_sample_maps(out, r):
    """The adaptive runs' samples per pixel at the default threshold, with a log2 colour bar."""
    runs = r["adaptive"]
    top = max(2, max(a["max_spp"] for a in runs))
    sm = plt.cm.ScalarMappable(norm=LogNorm(1, top), cmap=heat_colormap(r))
    panels = [(a["sample_map"], "%s adaptive: samples per pixel" % a["sampler"]) for a in runs]
    panels_with_colorbar(out, r, os.path.join("images", "adaptive-samples.png"), panels, sm,
                         "samples traced per pixel (log scale)", ticks=[2 ** k for k in range(int(math.log2(top)) + 1)])


def plot_adaptive(out, r):
    """RMSE against mean traced spp: each sampler's uniform curve (solid) and its adaptive
    threshold sweep (dashed), with the uniform RMSE at the target spp as the bar to reach."""
    pixels = r["width"] * r["height"]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for s in r["samplers"]:
        uni = sorted((u["samples"] / pixels, u["rmse"]) for u in r["runs"] if u["sampler"] == s)
        ada = sorted((a["spp_mean"], a["rmse"]) for a in r["adaptive_sweep"] if a["sampler"] == s)
        ax.loglog([p[0] for p in uni], [p[1] for p in uni], "o-", color=COLORS.get(s), label="%s uniform" % s)
        ax.loglog([p[0] for p in ada], [p[1] for p in ada], "s--", color=COLORS.get(s), label="%s adaptive" % s)
        t = r["adaptive_target"]["samplers"][s]
        ax.axhline(t["uniform_rmse"], color=COLORS.get(s), lw=0.6, alpha=0.5)
    ax.set_xlabel("mean samples per pixel (traced)")
    ax.set_ylabel("RMSE vs reference")
    ax.set_title("adaptive sweep vs uniform (lines: uniform RMSE at %d spp)" % r["adaptive_target"]["spp"])
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "adaptive_vs_spp.png"), dpi=110)
    plt.close(fig)


def fmt(x):
    return "n/a" if x is None or (isinstance(x, float) and math.isnan(x)) else "%.5f" % x


def write_screen_html(p, r):
    """The screen-space measures: one table per measure (mean over seeds &plusmn; 95 % interval,
    the lowest mean in bold), their plot against spp, the FLIP maps and the 2-D spectra."""
    e = html.escape
    runs, samplers, spps = r["runs"], r["samplers"], r["spp"]
    p.append("<h2>Screen-space measures</h2><p>Where on screen the error sits, which per-pixel RMSE does not see: "
             "the RMSE of the error image blurred by a Gaussian of &sigma; = 1 and 2 pixels (what the eye "
             "integrates), the share of the luminance error's power below 1/4 cycle per pixel (white error: "
             "&pi;/16 = 0.196; lower means the error sits at high frequencies the eye forgives), and "
             "&#xA7FB;LIP (Andersson et al. 2020, HDR-FLIP 2021; %.0f pixels per degree; 0 is no visible "
             "difference). Lower is better for all of them.</p><img src='screen_vs_spp.png'>" %
             r["flip"]["pixels_per_degree"])
    for title, get, _ in SCREEN_MEASURES:
        p.append("<h3>%s</h3><table><tr><th>spp</th>%s</tr>" % (e(title), "".join("<th>%s</th>" % e(s) for s in samplers)))
        for n in spps:
            at = {u["sampler"]: get(u) for u in runs if u["spp"] == n}
            best = min((v[0] for v in at.values() if v[0] is not None), default=None)
            cells = []
            for s in samplers:
                m, ci = at[s]
                cell = "%s &plusmn; %s" % (fmt(m), fmt(ci))
                cells.append("<td>%s</td>" % ("<b>%s</b>" % cell if m is not None and m == best else cell))
            p.append("<tr><td>%d</td>%s</tr>" % (n, "".join(cells)))
        p.append("</table>")
    p.append("<p><small>%s</small></p>" % " ".join(e(r["statistics"].get(k, "")) for k in (
        "blurred_rmse", "low_frequency_share", "flip")))
    ex = r["flip"]["hdr_exposures"]
    p.append("<h3>&#xA7FB;LIP maps (seed 0)</h3><p>HDR-FLIP exposures from the reference: %d from %.2f to %.2f "
             "stops.</p>" % (ex["count"], ex["start"], ex["stop"]))
    for n in spps:
        for variant in ("ldr", "hdr"):
            p.append("<figure><img src='%s'><figcaption>%s-FLIP at %d spp, colour scale 0 to 1 for every spp."
                     "</figcaption></figure><br>" % (e(flip_map_file(variant, n)), variant.upper(), n))
    p.append("<h3>2-D error spectra (mean over seeds)</h3>")
    for n in spps:
        lo, hi = r["error_spectra_2d"]["scale"][str(n)]
        p.append("<figure><img src='%s'><figcaption>Power spectrum of the luminance error at %d spp, DC at the "
                 "centre, one log colour scale for all samplers at this spp (10^%.1f to 10^%.1f). White error is "
                 "flat; blue-noise error is dark in the middle.</figcaption></figure><br>" % (
                     e(spectrum_2d_file(n)), n, lo, hi))


def write_html(out, r):
    e = html.escape
    runs = r["runs"]
    samplers, spps = r["samplers"], r["spp"]
    p = []
    p.append("<!doctype html><html><head><meta charset='utf-8'><title>pdrt compare: %s</title>" % e(r["scene"]))
    p.append("<style>body{font-family:sans-serif;margin:1.5em;max-width:1400px}"
             "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:3px 7px;text-align:right}"
             "img{image-rendering:pixelated;max-width:100%}figure{display:inline-block;margin:4px;text-align:center}"
             "figcaption{font-size:small}</style></head><body>")
    p.append("<h1>pdrt compare: %s</h1>" % e(r["scene"]))
    ref = r["reference"]
    seeds = r.get("seeds", [r["seed"]])
    p.append("<p>%dx%d pixels, %d seeds per sampler and spp (%s; %s). Reference: %s at %d spp (seed %s%s), "
             "rendered as two independent halves; its variance, %.3g per pixel channel (RMSE %.3g), is "
             "subtracted from every MSE.</p>" % (
                 r["width"], r["height"], len(seeds), ", ".join(str(x) for x in seeds), e(r.get("seed_rule", "")),
                 e(ref["sampler"]), ref["spp"], ref["seed"], ", cached" if ref["cached"] else "",
                 ref.get("variance", 0.0), ref.get("rmse", 0.0)))
    if r.get("regularize"):
        p.append("<p><b>Biased:</b> the renders use path regularisation (<code>--regularize</code>: "
                 "near-specular lobes roughened after the first non-specular bounce); the reference does not, "
                 "so bias&sup2; includes the regularisation's bias.</p>")
    write_demonstration_html(p, r)
    p.append("<h2>Convergence</h2><img src='rmse_vs_spp.png'> <img src='rmse_vs_time.png'>")
    p.append("<h3>RMSE at equal samples (mean over seeds &plusmn; 95%% interval)</h3><table><tr><th>spp</th>%s</tr>" %
             "".join("<th>%s</th>" % e(s) for s in samplers))
    for n in spps:
        row = []
        best = min(u["rmse"] for u in runs if u["spp"] == n)
        for s in samplers:
            u = [u for u in runs if u["spp"] == n and u["sampler"] == s][0]
            b = "<b>%s</b>" if u["rmse"] == best else "%s"
            row.append("<td>" + b % ("%s &plusmn; %s" % (fmt(u["rmse"]), fmt(u.get("rmse_ci95")))) + "</td>")
        traced = sorted(set(u["samples"] for u in runs if u["spp"] == n))
        p.append("<tr><td>%d (%s samples traced)</td>%s</tr>" % (n, " / ".join(str(t) for t in traced), "".join(row)))
    p.append("<tr><td>slope</td>%s</tr></table>" % "".join("<td>%.2f</td>" % r["slopes"][s] for s in samplers))
    p.append("<p><small>%s. Bold: the lowest mean; where intervals overlap, call it a tie.</small></p>" % e(SLOPE_NOTE))
    p.append("<h3>Every run</h3><table><tr><th>sampler</th><th>spp</th><th>samples traced (per seed)</th>"
             "<th>mean RMSE</th><th>95% interval</th><th>bias&sup2;</th><th>variance</th><th>MSE</th>"
             "<th>CPU s (mean)</th><th>wall s (mean)</th></tr>")
    for u in runs:
        p.append("<tr><td>%s</td><td>%d</td><td>%d</td><td>%s</td><td>[%s, %s]</td><td>%.3g</td><td>%.3g</td>"
                 "<td>%.3g</td><td>%.3f</td><td>%.3f</td></tr>" % (
                     e(u["sampler"]), u["spp"], u["samples"], fmt(u["rmse"]), fmt(u.get("rmse_low")),
                     fmt(u.get("rmse_high")), u.get("bias2", 0.0), u.get("variance", 0.0), u.get("mse", 0.0),
                     u.get("cpu_seconds", 0.0), u["render_seconds"]))
    p.append("</table><p><small>MSE = bias&sup2; + variance, both with the reference's variance taken out: "
             "bias&sup2; is the seed-average image against the reference (less variance / seeds), variance the "
             "per-pixel spread across seeds; a slightly negative bias&sup2; is 0 within noise. Every seed's numbers "
             "are in results.json (per_seed) and results.csv.</small></p>")
    if r.get("sampler_share"):
        p.append("<h3>The sampler's share of render time</h3><table><tr><th>sampler</th><th>share of CPU</th>"
                 "<th>standard error</th><th>profiler ticks</th>%s</tr>" % "".join("<th>%d spp</th>" % n for n in spps))
        for s in samplers:
            c = r["sampler_share"][s]
            cells = []
            for n in spps:
                u = [u for u in runs if u["spp"] == n and u["sampler"] == s][0]
                sh = (u.get("sampler_share") or {}).get("share")
                cells.append("<td>%s</td>" % ("n/a" if sh is None else "%.1f%%" % (100 * sh)))
            p.append("<tr><td>%s</td><td>%s</td><td>%s</td><td>%d</td>%s</tr>" % (
                e(s), "n/a" if c["share"] is None else "%.1f%%" % (100 * c["share"]),
                "n/a" if c["standard_error"] is None else "%.1f%%" % (100 * c["standard_error"]), c["ticks"],
                "".join(cells)))
        p.append("</table><p><small>%s. The right panel of the equal-time plot takes it out of the CPU "
                 "seconds.</small></p>" % e(r["statistics"].get("sampler_share", "")))
    et = r["equal_time"]
    if et["seconds"]:
        p.append("<h3>RMSE at equal CPU time (log-log interpolation)</h3><table><tr><th>CPU seconds</th>%s</tr>" %
                 "".join("<th>%s</th>" % e(s) for s in samplers))
        for i, t in enumerate(et["seconds"]):
            p.append("<tr><td>%.3f</td>%s</tr>" % (t, "".join("<td>%s</td>" % fmt(et["rmse"][s][i]) for s in samplers)))
        p.append("</table>")
    if runs and "blurred_rmse" in runs[0]:
        write_screen_html(p, r)
    p.append("<h2>Error spectra</h2><figure><img src='error_spectra.png'><figcaption>Radially averaged power "
             "spectrum of each image's luminance error against the reference (DC removed), averaged over the seeds, at the lowest, middle "
             "and highest spp; white noise is flat, blue noise has less power at low frequencies.</figcaption>"
             "</figure>")
    if any(u.get("used_samples") for u in runs):
        p.append("<h2>The samples the renders used</h2><figure><img src='used_spectra.png'><figcaption>%s"
                 "</figcaption></figure>" % e(r["statistics"].get("used_samples", "")))
        p.append("<table><tr><th>sampler</th><th>spp</th>%s</tr>" % "".join(
            "<th>%s: mean &rho; (5%%, min)</th>" % f for f in FAMILIES))
        for u in runs:
            if u["spp"] < 2:
                continue
            cells = []
            for f in FAMILIES:
                a = [a for a in u.get("used_samples", []) if a["family"] == f]
                cells.append("<td>n/a</td>" if not a or a[0]["rho_mean"] is None else "<td>%.3f (%.3f, %.3f)</td>" % (
                    a[0]["rho_mean"], a[0]["rho_p05"], a[0]["rho_min"]))
            p.append("<tr><td>%s</td><td>%d</td>%s</tr>" % (e(u["sampler"]), u["spp"], "".join(cells)))
        p.append("</table>")
    p.append("<h2>Crops (same region; last column: reference)</h2>")
    for c in r["crops"]:
        p.append("<figure><img src='%s'><figcaption>%d spp: %s | reference</figcaption></figure><br>" % (
            e(c["file"]), c["spp"], " | ".join(e(s) for s in samplers)))
    p.append("<h2>Images</h2><table><tr><th>spp</th>%s</tr>" % "".join("<th>%s</th>" % e(s) for s in samplers))
    for n in spps:
        cells = []
        for s in samplers:
            u = [u for u in runs if u["spp"] == n and u["sampler"] == s][0]
            cells.append("<td><img src='%s' width=200></td>" % e(u["image"]))
        p.append("<tr><td>%d</td>%s</tr>" % (n, "".join(cells)))
    p.append("</table><p><img src='images/reference.png' width=300><br>reference</p>")
    p.append("<h2>Error heat maps</h2>")
    for n in spps:
        p.append("<figure><img src='%s'><figcaption>Absolute luminance error per pixel against the reference at "
                 "%d spp. All samplers share one colour scale at this spp (0 to the 99th percentile of their "
                 "errors, %.3g; brighter is clipped), so they compare directly; scales differ between spp."
                 "</figcaption></figure><br>" % (e(heat_map_file(n)), n, r["error_maps"]["scale"][str(n)]))
    if r.get("blurred_error_maps"):
        b = r["blurred_error_maps"]
        p.append("<h2>Blurred-error heat maps</h2>")
        for n in spps:
            p.append("<figure><img src='%s'><figcaption>Seed 0's luminance error blurred by a Gaussian of &sigma; = "
                     "%g px at %d spp, one colour scale for all samplers at this spp (0 to the 99th percentile, "
                     "%.3g; brighter is clipped).</figcaption></figure><br>" % (
                         e(blurred_heat_map_file(n)), b["sigma"], n, b["scale"][str(n)]))
    if r.get("adaptive"):
        p.append("<h2>Adaptive refinement at equal total samples</h2><table><tr><th>sampler</th><th>metric</th>"
                 "<th>threshold</th><th>mean spp</th><th>rounds</th><th>adaptive RMSE</th>"
                 "<th>uniform RMSE at equal samples</th><th>image</th><th>sample counts</th></tr>")
        for a in r["adaptive"]:
            p.append("<tr><td>%s</td><td>%s</td><td>%g</td><td>%.1f</td><td>%d</td><td>%s</td><td>%s</td>"
                     "<td><img src='%s' width=200></td><td><img src='%s' width=200></td></tr>" % (
                         e(a["sampler"]), e(a["metric"]), a["threshold"], a["spp_mean"], a["rounds"], fmt(a["rmse"]),
                         fmt(a["uniform_rmse_at_equal_samples"]), e(a["image"]), e(a["sample_map"])))
        p.append("</table><figure><img src='images/adaptive-samples.png'><figcaption>Samples traced per pixel "
                 "by adaptive refinement at the default threshold.</figcaption></figure>")
    if r.get("adaptive_sweep"):
        tgt = r["adaptive_target"]
        p.append("<h2>Adaptive threshold sweep</h2><img src='adaptive_vs_spp.png'>")
        p.append("<h3>Samples adaptive needs to reach the uniform %d-spp RMSE</h3><table><tr><th>sampler</th>"
                 "<th>uniform RMSE</th><th>uniform samples</th><th>adaptive samples</th><th>ratio</th></tr>" % tgt["spp"])
        for s in samplers:
            t = tgt["samplers"][s]
            ratio = "not reached" if t["ratio"] is None else ("&le; " if t["upper_bound"] else "") + "%.3f" % t["ratio"]
            samples = "n/a" if t["adaptive_samples"] is None else "%.0f" % t["adaptive_samples"]
            p.append("<tr><td>%s</td><td>%s</td><td>%d</td><td>%s</td><td>%s</td></tr>" % (
                e(s), fmt(t["uniform_rmse"]), t["uniform_samples"], samples, ratio))
        p.append("</table><h3>Sweep</h3><table><tr><th>sampler</th><th>threshold</th><th>mean spp</th>"
                 "<th>rounds</th><th>RMSE</th></tr>")
        for a in r["adaptive_sweep"]:
            p.append("<tr><td>%s</td><td>%g</td><td>%.1f</td><td>%d</td><td>%s</td></tr>" % (
                e(a["sampler"]), a["threshold"], a["spp_mean"], a["rounds"], fmt(a["rmse"])))
        p.append("</table><p>Every run: <a href='adaptive.csv'>adaptive.csv</a>.</p>")
    p.append("<p>Numbers: <a href='results.json'>results.json</a>, <a href='results.csv'>results.csv</a>.</p>")
    p.append("</body></html>")
    tmp = os.path.join(out, "index.html.tmp")
    with open(tmp, "w") as f:
        f.write("\n".join(p))
    os.replace(tmp, os.path.join(out, "index.html"))


if __name__ == "__main__":
    main(sys.argv[1])
