#!/usr/bin/env python3
"""The forest of docs/lod_scenes.md: samples/scenes/forest_290.json drawn with each mesh LOD method
(render --lod mesh|points|ellipsoids|cook|neubert) from two cameras, a table of frame time, fragments,
primitives and the trees neubert's occlusion test pruned per method and view, and a contact sheet
of the edge view (needs oiiotool).

  scripts/lod_scene_forest.py build/voltree OUTDIR [--scene SCENE] [--size WxH] [--methods cook,neubert]

Views: "edge", standing at the forest's edge 1.7 m above the ground looking in (near trees full
meshes, the rest reduced), and "above", the scene orbit's first frame (25 degrees above the
horizon at 1.7 times the forest's radius: every tree far). Each view is drawn 3 times and the
median frame time kept, so that the first frame's shader compilation is not counted (and, for
neubert, the first frame's depth pre-pass: frames 2 and 3 test against the frame before).
"""
import argparse
import json
import math
import pathlib
import re
import subprocess

METHODS = ["mesh", "points", "ellipsoids", "cook", "neubert"]


def look_at(eye, target):
    """COLMAP pose (world to camera: quaternion w x y z, translation) of a camera at eye looking at target, +z up."""
    sub = [t - e for t, e in zip(target, eye)]
    norm = math.sqrt(sum(c * c for c in sub))
    z = [c / norm for c in sub]
    x = [z[1] * 1 - z[2] * 0, z[2] * 0 - z[0] * 1, 0.0]  # z cross up(0, 0, 1)
    n = math.sqrt(sum(c * c for c in x))
    x = [c / n for c in x]
    y = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]]  # z cross x: down
    r = [x, y, z]  # rows: world to camera
    w = math.sqrt(max(0.0, 1 + r[0][0] + r[1][1] + r[2][2])) / 2
    q = [w, (r[2][1] - r[1][2]) / (4 * w), (r[0][2] - r[2][0]) / (4 * w), (r[1][0] - r[0][1]) / (4 * w)]
    t = [-sum(r[i][k] * eye[k] for k in range(3)) for i in range(3)]
    return q, t


def write_model(folder, width, height, fov_degrees, eye, target, name):
    folder.mkdir(parents=True, exist_ok=True)
    f = 0.5 * width / math.tan(math.radians(fov_degrees) / 2)
    (folder / "cameras.txt").write_text(f"1 PINHOLE {width} {height} {f} {f} {width / 2} {height / 2}\n")
    q, t = look_at(eye, target)
    lines = [" ".join(str(v) for v in [i + 1, *q, *t, 1, f"{name}_{i + 1}.png"]) + "\n\n" for i in range(3)]
    (folder / "images.txt").write_text("".join(lines))


def render(voltree, scene, method, cameras, out):
    command = [voltree, "render", scene, "--lod", method, "--cameras", str(cameras), "--stats",
               "--background", "150,185,225", "--force", "-o", str(out)]
    text = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    ms = float(re.search(r"median ([\d.]+) ms per frame", text).group(1))
    fragments = re.search(r"fragments per frame: (\d+)", text)
    frames = json.loads((out / "frames.json").read_text())["frames"]
    return {"ms": ms, "fragments": int(fragments.group(1)) if fragments else None, **frames[-1]}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("voltree")
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("--scene", default="samples/scenes/forest_290.json")
    parser.add_argument("--size", default="1024x576")
    parser.add_argument("--methods", default=",".join(METHODS), help="comma-separated, of " + ", ".join(METHODS))
    args = parser.parse_args()
    methods = args.methods.split(",")
    if not methods or any(m not in METHODS for m in methods):
        parser.error(f"--methods {args.methods}: expected a comma-separated list of " + ", ".join(METHODS))
    width, height = (int(v) for v in args.size.split("x"))
    views = {"edge": ((0.0, -78.0, 1.7), (0.0, 0.0, 4.0), 60), "above": ((-75.0, -130.0, 85.0), (0.0, 0.0, 0.0), 50)}
    rows = []
    for view, (eye, target, fov) in views.items():
        cameras = args.out / f"cameras_{view}"
        write_model(cameras, width, height, fov, eye, target, view)
        for method in methods:
            result = render(args.voltree, args.scene, method, cameras, args.out / f"{view}_{method}")
            rows.append({"view": view, "method": method, **result})
            print(view, method, result, flush=True)
    (args.out / "forest.json").write_text(json.dumps(rows, indent=2) + "\n")
    table = ["| view | --lod | frame ms | fragments | triangles | points | lines | ellipsoids | trees full | trees reduced "
             "| trees occluded | mean visible |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        fragments = f"{r['fragments']:,}" if r["fragments"] is not None else "n/a"
        table.append(f"| {r['view']} | {r['method']} | {r['ms']:.0f} | {fragments} | {r['triangles']:,} | {r['points']:,} | "
                     f"{r['lines']:,} | {r['ellipsoids']:,} | {r['instances_full']} | {r['instances_reduced']} | "
                     f"{r.get('instances_occluded', '')} | {format(r['mean_visible'], '.3f') if 'mean_visible' in r else ''} |")
    (args.out / "table.md").write_text("\n".join(table) + "\n")
    print("\n".join(table))
    tiles = [str(args.out / f"edge_{m}" / "edge_3.png") for m in methods]
    grid = "2x2" if len(tiles) == 4 else f"{len(tiles)}x1"
    subprocess.run(["oiiotool", *tiles, "--mosaic:pad=4", grid, "--resize", f"{width}x0", "--ch", "R,G,B",
                    "-o", str(args.out / "forest_methods.jpg")], check=True)


if __name__ == "__main__":
    main()
