#!/usr/bin/env python3
"""Prints a scene's film size divided by SCALE ("W H"): JSON film.width/height; pbrt Film
xresolution/yresolution (pbrt's defaults 1280x720 where absent). Usage: film-size.py SCENE [SCALE]"""
import json, re, sys

path, scale = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 1
if path.endswith(".pbrt"):
    text = re.sub(r"#[^\n]*", "", open(path).read())
    res = lambda k, d: int(re.search(r'"integer %s"\s*\[?\s*(\d+)' % k, text).group(1)) if re.search(r'"integer %s"' % k, text) else d
    w, h = res("xresolution", 1280), res("yresolution", 720)
else:
    f = json.load(open(path))["film"]
    w, h = f["width"], f["height"]
print(max(1, w // scale), max(1, h // scale))
