#!/usr/bin/env bash
# Builds the three assets the sample scenes use (oak.vtree, pine.vtree, young-oak.vtree) into
# OUTDIR: each tree is photographed in the studio (24 views at 384x384), reconstructed with 6
# levels and compressed. Workspaces go to OUTDIR/work/<tree>/ and are kept for inspection.
#   samples/scenes/make_assets.sh OUTDIR [VOLTREE_BINARY]
# About a minute per tree on 2 cores. The scenes' default asset folder is samples/scenes/ itself,
# so `make_assets.sh samples/scenes` lets `voltree render samples/scenes/square_12.json` work as is;
# otherwise pass `--assets OUTDIR` to `voltree render`.
set -euo pipefail
if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 OUTDIR [VOLTREE_BINARY]" >&2
  exit 2
fi
out=$1
voltree=${2:-$(dirname "$0")/../../build/voltree}
if [[ ! -x $voltree ]]; then
  echo "$0: voltree binary not found at $voltree (build it, or pass its path as the second argument)" >&2
  exit 1
fi
mkdir -p "$out/work"
for tree in oak pine young-oak; do
  if [[ -e $out/$tree.vtree ]]; then
    echo "$out/$tree.vtree exists, skipped (delete it to rebuild)"
    continue
  fi
  work=$out/work/$tree
  "$voltree" synth --tree "$tree" --views 24 --size 384x384 --quiet --force -o "$work"
  "$voltree" reconstruct "$work" --levels 6 --quiet --force
  "$voltree" compress "$work" -o "$out/$tree.vtree" --quiet
  echo "$out/$tree.vtree"
done
