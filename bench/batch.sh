#!/usr/bin/env bash
# Wall time of `voltree batch` on N studio captures, one job at a time (-j 1, all cores per job)
# and two at once (-j 2), then each tree's stage times and peak memory from Snakemake's benchmark
# files. The captures come with the studio's true cameras and mattes, so the batch runs
# reconstruct, compress, eval and the scene.
# Usage: bench/batch.sh [TREES=8] [VIEWS=24] [SIZE=384] [OUT=out/bench-batch] [VOLTREE=build/voltree]
set -euo pipefail
cd "$(dirname "$0")/.."
trees=${1:-8} views=${2:-24} size=${3:-384} out=${4:-out/bench-batch} voltree=${5:-build/voltree}
presets=(oak pine young-oak)
mkdir -p "$out/captures"
for ((i = 0; i < trees; i++)); do
  name=$(printf "tree_%02d" "$i")
  [[ -d $out/captures/$name ]] && continue
  "$voltree" synth --tree "${presets[i % 3]}" --seed $((i + 1)) --views "$views" --held-out 4 \
    --size "${size}x${size}" --backdrop plain --quiet -o "$out/captures/$name"
done
for jobs in 1 2; do
  root=$out/j$jobs
  rm -rf "$root" && mkdir -p "$root"
  for ((i = 0; i < trees; i++)); do cp -r "$out/captures/$(printf "tree_%02d" "$i")" "$root/"; done
  start=$(date +%s.%N)
  "$voltree" batch "$root" -j "$jobs" --quiet >"$out/j$jobs.txt" 2>&1 || true
  end=$(date +%s.%N)
  printf -- "-j %d: %.1f s wall for %d captures\n" "$jobs" "$(echo "$end - $start" | bc)" "$trees"
done
echo
echo "per tree (-j 1): seconds and peak resident MB per stage"
printf "%-8s %-10s %12s %12s %12s\n" tree preset reconstruct compress eval
for ((i = 0; i < trees; i++)); do
  name=$(printf "tree_%02d" "$i")
  row=""
  for stage in reconstruct compress eval; do
    tsv=$out/j1/$name/logs/$stage.tsv
    row+=$(awk -F'\t' 'NR==2 {printf "%12s", sprintf("%.1f / %.0f", $1, $3)}' "$tsv" 2>/dev/null || printf "%12s" -)
    row+=" "
  done
  printf "%-8s %-10s %s\n" "$name" "${presets[i % 3]}" "$row"
done
echo
cat "$out/j2.txt"
