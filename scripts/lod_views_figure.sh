#!/usr/bin/env bash
# The figure of docs/lod_points.md and docs/lod_ellipsoids.md: one view of a tree at 128, 64 and
# 32 px (rows) drawn as the full mesh (the reference), PR-optimal pruning, points and ellipsoids
# (columns), cropped to the tree and enlarged without smoothing to one size. Needs ImageMagick.
#   build/voltree lod-bench TREE --sizes 128,64,32 --save-views -o DIR
#   scripts/lod_views_figure.sh DIR/views OUT.jpg
set -euo pipefail
views=$1
out=$2
tmp=$(mktemp -d)
trap 'rm -r "$tmp"' EXIT
# The tree's box in the reference at 128 px, squared with a margin, scaled to each size.
box=$(convert "$views/reference_128.png" -alpha extract -threshold 0 -format '%@' info:)
read -r w h x y <<<"${box//[x+]/ }"
side=$(((w > h ? w : h) + 8))
cx=$((x + w / 2))
cy=$((y + h / 2))
tiles=()
for size in 128 64 32; do
  f=$((128 / size))
  crop=$((side / f))
  for method in reference neubert points ellipsoids; do
    convert "$views/${method}_$size.png" -background '#c8c8c8' -flatten \
      -crop "${crop}x${crop}+$((cx / f - crop / 2))+$((cy / f - crop / 2))" +repage \
      -filter point -resize '200x200!' "$tmp/${size}_$method.png"
    tiles+=("$tmp/${size}_$method.png")
  done
done
montage "${tiles[@]}" -tile 4x3 -geometry +2+2 -background white -quality 88 "$out"
