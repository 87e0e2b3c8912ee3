#!/usr/bin/env bash
# Rate-distortion of the demo oak: asset bytes against held-out RGB PSNR and alpha PSNR, over
# codebook sizes (colour / alpha) and the two on-disk layouts (raw chunks, `compress --no-zstd`, and
# zstd, the default). For each pair of codebook sizes it runs `voltree compress` twice (raw and zstd) into
# OUT/assets/ (the workspace's own tree.vtree is never touched), reads each file's bytes on disk
# and `voltree info`'s GPU-resident total, and runs `voltree eval` (held-out views, the renderer's
# LOD) on it. The zstd file holds the same in-memory asset as the raw one (same codebooks, same
# seed), so by default only the raw asset is evaluated and the zstd row carries its metrics;
# EVAL_ZSTD lists the pairs whose zstd asset is evaluated as well, as a check. One
# `eval --budget` run on the workspace's asset gives the uncompressed billboards' row (held-out
# views), sized as billboards x 4x4 texels x 4 bytes plus the cells. Linz et al. 2006 published
# texture memory for their own trees (no PSNR on ours): those sizes are drawn as labelled
# vertical lines.
# Writes OUT/rate_distortion.md (the table, also printed), OUT/rate_distortion.json,
# OUT/codebook_sweep.json (the format `voltree eval --codebook-sweep` plots) and
# OUT/rate_distortion.png (gnuplot).
# Usage: bench/rate_distortion.sh DIR [OUT=DIR/bench-rd] [VOLTREE=build/voltree]
#   DIR: a workspace made by `voltree demo -o DIR` (volume/, truth/, tree.vtree)
#   SIZES="64 128 ... 4096" (equal colour/alpha sizes), PAIRS="4096/512 512/4096" (unequal
#   colour/alpha pairs), EVAL_ZSTD="512/512" override the defaults from the environment.
set -euo pipefail
[[ $# -ge 1 ]] || {
  sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'
  exit 2
}
ws=$1 out=${2:-$1/bench-rd} voltree=${3:-build/voltree}
sizes=${SIZES-64 128 256 512 1024 2048 4096}
pairs=${PAIRS-4096/512 512/4096}
eval_zstd=${EVAL_ZSTD-512/512}
for need in "$ws/volume" "$ws/truth" "$ws/tree.vtree"; do
  [[ -e $need ]] || { echo "rate_distortion: $need missing (make DIR with voltree demo -o DIR)" >&2; exit 1; }
done
command -v jq >/dev/null || { echo "rate_distortion: needs jq" >&2; exit 1; }
mkdir -p "$out/assets" "$out/reports" "$out/info"
bench_start=$(date +%s.%N)

# info's human-readable "N.NN MiB" / "N.N KiB" / "N bytes" after a label, as bytes (rounded as printed)
info_bytes() {
  awk -v label="$2" 'index($0, label) {
    sub(".*" label "[ ]+", ""); v = $1; u = $2
    if (u == "MiB") v *= 1048576; else if (u == "KiB") v *= 1024
    printf "%d\n", v + 0.5; exit }' "$1"
}
eval_args=(--eval-levels auto --no-images --no-plots --no-input --quiet --force)

# The uncompressed billboards: one eval --budget run of the workspace's own asset.
if [[ ! -f $out/reports/budget/metrics.json ]]; then
  start=$(date +%s.%N)
  "$voltree" eval "$ws" --asset "$ws/tree.vtree" --report "$out/reports/budget" --budget "${eval_args[@]}" \
    >"$out/reports/budget.log" 2>&1
  printf "budget eval: %.1f s\n" "$(echo "$(date +%s.%N) - $start" | bc)" >&2
fi
"$voltree" info "$ws/tree.vtree" >"$out/info/workspace.txt"
billboards=$(awk '/^total cells/ { print $5 }' "$out/info/workspace.txt")
cells=$(awk '/^total cells/ { gsub(",", "", $3); print $3 }' "$out/info/workspace.txt")
cell_chunks=$(awk '$1 == "CELL" { sum += $(NF - 1) } END { print sum + 0 }' "$out/info/workspace.txt")
uncompressed=$((billboards * 4 * 4 * 4 + cell_chunks))
jq --argjson bytes "$uncompressed" --argjson billboards "$billboards" --argjson cells "$cells" \
  --argjson cell_bytes "$cell_chunks" '
  [.budget[] | select(.step == "billboards" and .views == "held_out")][0] as $b |
  {colour_codebook: null, alpha_codebook: null, layout: "uncompressed billboards", bytes: $bytes,
   billboards: $billboards, cells: $cells, cell_bytes: $cell_bytes,
   rgb_psnr: $b.rgb_psnr, alpha_psnr: $b.alpha_psnr, precision: $b.precision, recall: $b.recall,
   held_out_views: $b.count}' "$out/reports/budget/metrics.json" >"$out/reference.json"

rows=()
run_pair() { # colour alpha
  local c=$1 a=$2 name="c$1_a$2" layout file report start metrics_from
  for layout in raw zstd; do
    file=$out/assets/$name.$layout.vtree
    local zflag=()
    [[ $layout == raw ]] && zflag=(--no-zstd)
    start=$(date +%s.%N)
    [[ -f $file ]] || "$voltree" compress "$ws" -o "$file" --codebook "$c" --alpha-codebook "$a" "${zflag[@]}" \
      --max-bytes 0 --force --quiet
    local compress_s
    compress_s=$(echo "$(date +%s.%N) - $start" | bc)
    "$voltree" info "$file" >"$out/info/$name.$layout.txt"
    report=$out/reports/$name.$layout
    metrics_from=$layout
    if [[ $layout == raw || " $eval_zstd " == *" $c/$a "* ]]; then
      start=$(date +%s.%N)
      [[ -f $report/metrics.json ]] || "$voltree" eval "$ws" --asset "$file" --report "$report" "${eval_args[@]}" \
        >"$report.log" 2>&1
      local eval_s
      eval_s=$(echo "$(date +%s.%N) - $start" | bc)
    else
      report=$out/reports/$name.raw metrics_from=raw eval_s=0
    fi
    local bytes gpu
    bytes=$(stat -c %s "$file")
    gpu=$(info_bytes "$out/info/$name.$layout.txt" "GPU resident total")
    printf "%5s / %-5s %-4s %9d bytes  compress %5.1f s  eval %5.1f s\n" "$c" "$a" "$layout" "$bytes" \
      "$compress_s" "$eval_s" >&2
    jq -c --argjson c "$c" --argjson a "$a" --arg layout "$layout" --argjson bytes "$bytes" --argjson gpu "$gpu" \
      --arg from "$metrics_from" --argjson cs "$compress_s" --argjson es "$eval_s" '
      .overall.held_out as $h |
      {colour_codebook: $c, alpha_codebook: $a, layout: $layout, bytes: $bytes, gpu_resident_bytes: $gpu,
       rgb_psnr: $h.rgb_psnr.mean, alpha_psnr: $h.alpha_psnr.mean, precision: $h.precision.mean,
       recall: $h.recall.mean, rgb_ssim: $h.rgb_ssim.mean, metrics_from: $from,
       compress_s: $cs, eval_s: $es}' "$report/metrics.json" >>"$out/rows.jsonl"
  done
}
rm -f "$out/rows.jsonl"
for s in $sizes; do run_pair "$s" "$s"; done
for p in $pairs; do run_pair "${p%/*}" "${p#*/}"; done

bench_s=$(echo "$(date +%s.%N) - $bench_start" | bc)
# Linz et al. 2006, Sec. 6: octree texture memory after VQ (their codebooks: 512 for the oak and
# the pine, 1024 for the third tree), their own captures; MB taken as 10^6 bytes.
linz='[{"tree":"oak","bytes":3100000,"uncompressed_bytes":72000000,"codebook":512},
       {"tree":"pine","bytes":2100000,"uncompressed_bytes":60000000,"codebook":512},
       {"tree":"small oak","bytes":6300000,"uncompressed_bytes":86000000,"codebook":1024}]'
jq -s --slurpfile ref "$out/reference.json" --argjson linz "$linz" --arg ws "$ws" --argjson s "$bench_s" '
  {workspace: $ws, views: "held_out", renderer: "LOD", bench_seconds: $s, rows: .,
   uncompressed_billboards: $ref[0],
   linz_2006: {source: "Linz et al. 2006, Sec. 6: octree texture memory before compression 72, 60 and 86 MB, after VQ 3.1, 2.1 and 6.3 MB (7 levels; their oak, pine, small oak); DXT5 a further 4:1",
               trees: $linz}}' "$out/rows.jsonl" >"$out/rate_distortion.json"
jq '{points: [.rows[] | select(.layout == "raw" and .colour_codebook == .alpha_codebook) |
  ({codebook: .colour_codebook, rgb_psnr: .rgb_psnr, series: "held-out RGB PSNR"},
   {codebook: .colour_codebook, rgb_psnr: .alpha_psnr, series: "held-out alpha PSNR"})]}' \
  "$out/rate_distortion.json" >"$out/codebook_sweep.json"

{
  echo "| codebooks (colour / alpha) | layout | bytes | MiB | GPU resident MiB | held-out RGB PSNR | alpha PSNR | P | R |"
  echo "|---|---|---|---|---|---|---|---|---|"
  jq -r '(.rows[] | ["\(.colour_codebook) / \(.alpha_codebook)", .layout, .bytes, .gpu_resident_bytes, .rgb_psnr,
      .alpha_psnr, .precision, .recall]),
    (.uncompressed_billboards | ["uncompressed billboards", "-", .bytes, -1, .rgb_psnr, .alpha_psnr, .precision,
      .recall]) | map(tostring) | join("\t")' "$out/rate_distortion.json" |
    awk -F'\t' '{ gpu = $4 < 0 ? "-" : sprintf("%.2f", $4 / 1048576)
      printf "| %s | %s | %d | %.2f | %s | %.2f | %.2f | %.3f | %.3f |\n", $1, $2, $3, $3 / 1048576, gpu, $5, $6, $7, $8 }'
} | tee "$out/rate_distortion.md"
printf "\nbench: %.0f s wall\n" "$bench_s"

# The plot: bytes (log x) against held-out RGB PSNR and alpha PSNR.
for layout in raw zstd; do
  for kind in equal unequal; do
    jq -r --arg l "$layout" --arg k "$kind" '.rows[] | select(.layout == $l) |
      select((.colour_codebook == .alpha_codebook) == ($k == "equal")) |
      "\(.bytes) \(.rgb_psnr) \(.alpha_psnr) \(if $k == "equal" then .colour_codebook else "\(.colour_codebook)/\(.alpha_codebook)" end)"' \
      "$out/rate_distortion.json" >"$out/${kind}_$layout.dat"
  done
done
jq -r '.uncompressed_billboards | "\(.bytes) \(.rgb_psnr) \(.alpha_psnr)"' "$out/rate_distortion.json" >"$out/billboards.dat"
command -v gnuplot >/dev/null || { echo "gnuplot not installed: no plot" >&2; exit 0; }
# gnuplot's plot clauses for PSNR column $1 (2: RGB, 3: alpha), leaving out empty series
clauses() {
  local c=$1 d=$out list=()
  [[ -s $d/equal_raw.dat ]] && list+=("\"$d/equal_raw.dat\" using 1:$c with linespoints pt 7 lc rgb \"#1f77b4\" title \"raw chunks\""
    "\"$d/equal_raw.dat\" using 1:$c:4 with labels right offset -1.2,0 font \",8\" notitle")
  [[ -s $d/equal_zstd.dat ]] && list+=("\"$d/equal_zstd.dat\" using 1:$c with linespoints pt 5 lc rgb \"#2ca02c\" title \"zstd\"")
  [[ -s $d/unequal_raw.dat ]] && list+=("\"$d/unequal_raw.dat\" using 1:$c with points pt 6 ps 1.5 lc rgb \"#1f77b4\" title \"unequal colour/alpha (raw)\""
    "\"$d/unequal_raw.dat\" using 1:$c:4 with labels left offset 1.2,0 font \",8\" notitle")
  [[ -s $d/unequal_zstd.dat ]] && list+=("\"$d/unequal_zstd.dat\" using 1:$c with points pt 4 ps 1.5 lc rgb \"#2ca02c\" title \"unequal colour/alpha (zstd)\"")
  list+=("\"$d/billboards.dat\" using 1:$c with points pt 9 ps 2 lc rgb \"#d62728\" title \"uncompressed billboards\""
    "\"$d/billboards.dat\" using 1:$c:(\"uncompressed billboards\") with labels right offset -1.5,0 font \",8\" notitle")
  local IFS=,
  echo "${list[*]}"
}
xmin=$(jq '[.rows[].bytes] | min * 0.6' "$out/rate_distortion.json")
gnuplot <<EOF
xmin = $xmin
set terminal pngcairo size 1500,620 font "sans,11"
set output "$out/rate_distortion.png"
set multiplot layout 1,2 title "Asset bytes against held-out PSNR (renderer's LOD; equal colour/alpha codebook sizes labelled by size). Dashed: Linz 2006's published texture memory for their own trees (no PSNR on ours)"
set logscale x
set xrange [xmin:1.2e8]
set format x "%.0s %cB"
set grid
set key bottom right opaque box
set offsets graph 0, graph 0, graph 0.1, graph 0.1
set xlabel "asset bytes (log)"
mib = 1048576.0
set arrow 1 from 3.1e6, graph 0 to 3.1e6, graph 1 nohead dt 2 lc rgb "#aa5500"
set arrow 2 from 2.1e6, graph 0 to 2.1e6, graph 1 nohead dt 2 lc rgb "#aa5500"
set arrow 3 from 6.3e6, graph 0 to 6.3e6, graph 1 nohead dt 2 lc rgb "#aa5500"
set arrow 4 from 7.2e7, graph 0 to 7.2e7, graph 1 nohead dt 3 lc rgb "#aa5500"
set arrow 5 from mib, graph 0 to mib, graph 1 nohead dt 4 lc rgb "#888888"
set label 1 "Linz oak VQ 3.1 MB" at 3.1e6, graph 0.97 rotate by 90 right offset -0.8,0 tc rgb "#aa5500" font ",9"
set label 2 "Linz pine VQ 2.1 MB" at 2.1e6, graph 0.97 rotate by 90 right offset -0.8,0 tc rgb "#aa5500" font ",9"
set label 3 "Linz small oak VQ 6.3 MB" at 6.3e6, graph 0.97 rotate by 90 right offset -0.8,0 tc rgb "#aa5500" font ",9"
set label 4 "Linz oak uncompressed 72 MB" at 7.2e7, graph 0.97 rotate by 90 right offset -0.8,0 tc rgb "#aa5500" font ",9"
set label 5 "1 MiB" at mib, graph 0.97 rotate by 90 right offset -0.8,0 tc rgb "#888888" font ",9"
set ylabel "held-out RGB PSNR (dB)"
set title "RGB"
plot $(clauses 2)
set ylabel "held-out alpha PSNR (dB)"
set title "alpha"
plot $(clauses 3)
unset multiplot
EOF
echo "plot: $out/rate_distortion.png"
