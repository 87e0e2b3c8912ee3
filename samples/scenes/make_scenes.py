#!/usr/bin/env python3
"""Writes the sample scenes forest_290.json and square_12.json next to this script.

Deterministic (a fixed seed, Python's Mersenne Twister): running it again gives the same files.
  python3 samples/scenes/make_scenes.py
"""
import json
import math
import pathlib
import random

HERE = pathlib.Path(__file__).resolve().parent
ASSETS = {"oak": "oak.vtree", "pine": "pine.vtree", "young-oak": "young-oak.vtree"}
MESHES = {"oak": "oak", "pine": "pine", "young-oak": "young-oak"}  # the presets the assets were captured from
GROUND = [96, 110, 70]


def instance(asset, x, y, rotation, scale):
    return {"asset": asset, "position": [round(x, 2), round(y, 2), 0], "rotation": round(rotation, 1),
            "scale": round(scale, 2)}


def forest(count=290, side=140.0, min_distance=6.0, seed=2006):
    """Dart throwing (Poisson disc) in a square: a forest like Linz 2006, Fig. 1."""
    rng = random.Random(seed)
    points = []
    while len(points) < count:
        x, y = rng.uniform(-side / 2, side / 2), rng.uniform(-side / 2, side / 2)
        if all(math.hypot(x - px, y - py) >= min_distance for px, py in points):
            points.append((x, y))
    trees = []
    for x, y in points:
        asset = rng.choices(["oak", "pine", "young-oak"], weights=[45, 35, 20])[0]
        trees.append(instance(asset, x, y, rng.uniform(0, 360), rng.uniform(0.75, 1.2)))
    return {"assets": ASSETS, "meshes": MESHES, "ground": {"size": side + 30, "colour": GROUND}, "instances": trees}


def square(spacing=14.0):
    """12 trees on the border of a 4 x 4 grid (Linz 2006, Fig. 7), assets in turn."""
    coords = [spacing * (i - 1.5) for i in range(4)]
    border = [(x, y) for y in coords for x in coords if x in (coords[0], coords[-1]) or y in (coords[0], coords[-1])]
    names = ["oak", "pine", "young-oak"]
    trees = [instance(names[i % 3], x, y, 30.0 * i, 1.0) for i, (x, y) in enumerate(border)]
    return {"assets": ASSETS, "meshes": MESHES, "ground": {"size": 5 * spacing, "colour": GROUND}, "instances": trees}


def write(name, scene):
    # One instance per line, so that the file reads (and diffs) like a table.
    lines = ["{", '  "assets": ' + json.dumps(scene["assets"]) + ",", '  "meshes": ' + json.dumps(scene["meshes"]) + ",",
             '  "ground": ' + json.dumps(scene["ground"]) + ",",
             '  "instances": [']
    lines += ["    " + json.dumps(t) + ("," if i + 1 < len(scene["instances"]) else "") for i, t in enumerate(scene["instances"])]
    text = "\n".join(lines + ["  ]", "}"])
    (HERE / name).write_text(text + "\n")
    print(HERE / name, len(scene["instances"]), "instances")


if __name__ == "__main__":
    write("forest_290.json", forest())
    write("square_12.json", square())
