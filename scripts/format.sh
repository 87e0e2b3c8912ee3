#!/usr/bin/env bash
# clang-format on every C++ file of the repository (style: .clang-format).
#   scripts/format.sh           reformat in place
#   scripts/format.sh --check   change nothing; list the files that differ and fail if any does (CI)
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang-format >/dev/null; then
  echo "format: installing Debian's clang-format"
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends clang-format >/dev/null
fi
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [[ ${1:-} == --check ]]; then
  differ=()
  for file in "${files[@]}"; do
    clang-format --style=file "$file" | cmp -s - "$file" || differ+=("$file")
  done
  if ((${#differ[@]})); then
    printf 'format: %s is not formatted (run scripts/format.sh)\n' "${differ[@]}" >&2
    exit 1
  fi
  echo "format: ${#files[@]} files formatted as .clang-format says ($(clang-format --version))"
else
  clang-format --style=file -i "${files[@]}"
  echo "format: ${#files[@]} files formatted"
fi
