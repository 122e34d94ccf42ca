#!/usr/bin/env python3
"""Verdicts of one sampler against others over `pdrt compare` results (docs/results.md).

Usage: tools/sampler-verdicts.py [--sampler poisson] [--against jitter,sobol] RESULTS.json|DIR ...

For every scene (a results.json, or DIR/results.json, or DIR/*/results.json) and spp it prints
one markdown row: the sampler's RMSE with its 95 % interval, its ratio to each other sampler
with the verdict (win: its interval lies entirely below the other's; loss: entirely above;
tie otherwise), bias^2 as a share of its variance, the mean rho of its lens and pixel samples,
and its share of the render CPU. A last table counts the verdicts.
"""
import argparse
import glob
import json
import os
import sys


def load(paths):
    files = []
    for p in paths:
        if os.path.isdir(p):
            direct = os.path.join(p, "results.json")
            files += [direct] if os.path.exists(direct) else sorted(glob.glob(os.path.join(p, "*", "results.json")))
        else:
            files.append(p)
    out = []
    for f in files:
        r = json.load(open(f))
        name = os.path.splitext(os.path.basename(f))[0]
        if name == "results":
            name = os.path.basename(os.path.dirname(f))
        out.append((name, r))
    return out


def verdict(a, b):
    (ma, ca), (mb, cb) = a, b
    if ma + ca < mb - cb:
        return "win"
    if ma - ca > mb + cb:
        return "loss"
    return "tie"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sampler", default="poisson")
    ap.add_argument("--against", default="jitter,sobol")
    ap.add_argument("paths", nargs="+")
    a = ap.parse_args()
    others = [s for s in a.against.split(",") if s]
    counts = {o: {"win": 0, "tie": 0, "loss": 0} for o in others}
    worst = {o: 0.0 for o in others}
    head = "| scene | spp | %s RMSE | " % a.sampler + " | ".join("/ %s" % o for o in others)
    print(head + " | bias² / variance | ρ lens / pixel | sampler share |")
    print("|---|---|---|" + "---|" * len(others) + "---|---|---|")
    for scene, r in load(a.paths):
        runs = {(u["sampler"], u["spp"]): u for u in r["runs"]}
        for n in r["spp"]:
            me = runs.get((a.sampler, n))
            if not me:
                continue
            cells = []
            for o in others:
                u = runs.get((o, n))
                if not u:
                    cells.append("–")
                    continue
                v = verdict((me["rmse"], me["rmse_ci95"]), (u["rmse"], u["rmse_ci95"]))
                counts[o][v] += 1
                ratio = me["rmse"] / u["rmse"]
                worst[o] = max(worst[o], ratio)
                cells.append("%.3f %s" % (ratio, v))
            rho = {s["family"]: s.get("rho_mean") for s in me.get("used_samples", [])}
            fmt = lambda x: "%.2f" % x if isinstance(x, (int, float)) else "–"
            b = me["bias2"] / me["variance"] if me["variance"] > 0 else float("nan")
            share = (me.get("sampler_share") or {}).get("share")
            print("| %s | %d | %.4g ± %.2g | %s | %+.4f | %s / %s | %s |" % (
                scene, n, me["rmse"], me["rmse_ci95"], " | ".join(cells), b, fmt(rho.get("lens")), fmt(rho.get("pixel")),
                "%.1f %%" % (100 * share) if isinstance(share, (int, float)) else "–"))
    print()
    print("| against | wins | ties | losses | worst ratio |")
    print("|---|---|---|---|---|")
    for o in others:
        c = counts[o]
        print("| %s | %d | %d | %d | %.3f |" % (o, c["win"], c["tie"], c["loss"], worst[o]))


if __name__ == "__main__":
    sys.exit(main())
