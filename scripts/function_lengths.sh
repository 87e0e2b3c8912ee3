#!/usr/bin/env bash
# Lines per function definition (first line to closing brace, as Universal Ctags reports them) in
# the C++ sources outside tests/ and fuzz/: the count, the median, how many exceed 60 lines, and
# the longest. The README's seams figures come from it.
#   scripts/function_lengths.sh [LONGEST (default 5)]    needs Debian's universal-ctags
set -euo pipefail
cd "$(dirname "$0")/.."
longest=${1:-5}
git ls-files '*.cpp' '*.h' | grep -v -E '^(tests|fuzz)/' |
  ctags -L - -o - --languages=C++ --langmap=C++:+.h --kinds-C++=f --fields=+ne --extras=-q |
  awk -F'\t' '{ line = 0; end = 0
                for (i = 4; i <= NF; ++i) { if ($i ~ /^line:/) line = substr($i, 6); if ($i ~ /^end:/) end = substr($i, 5) }
                if (line && end) print end - line + 1 "\t" $2 ":" line "\t" $1 }' |
  sort -n -k1,1 |
  awk -F'\t' -v longest="$longest" '{ length_[NR] = $1; row[NR] = $0 }
    END { over = 0; for (i = 1; i <= NR; ++i) over += length_[i] > 60
          printf "functions %d, median %d lines, %d over 60 lines; the longest:\n", NR, length_[int((NR + 1) / 2)], over
          for (i = NR - longest + 1; i <= NR; ++i) if (i > 0) print row[i] }'
