#!/usr/bin/env bash
# The gallery: installs what is missing (Debian packages), builds
# snell-gallery (Release) and runs it: Sousa's water (three masks), glass and
# heat haze, the ice block with clipped cracks and G. Oliveira's refractive
# texture mapping, rendered on Mesa llvmpipe and checked against C++. Prints
# the table; pictures, frame strips, animated PNGs (apngasm), table.md and
# table.json go to gallery-out/ (or --out DIR). Extra arguments are passed to
# snell-gallery (`bash scripts/gallery.sh --help`). Under a minute on 2 cores
# after the build. Paths in the arguments are relative to where it is run from.
set -euo pipefail
gallery=$(bash "$(dirname "$0")/build-target.sh" snell-gallery)/examples/gallery/snell-gallery
"$gallery" "$@"
# The output directory as snell-gallery took it (the last --out, else its default).
out=gallery-out
args=("$@")
for ((i = 0; i < ${#args[@]}; ++i)); do
  case "${args[$i]}" in
    --out) out=${args[$((i + 1))]:-$out} ;;
    --out=*) out=${args[$i]#--out=} ;;
    --help|-h) exit 0 ;;
  esac
done
# Animated PNGs of the frame strips, 4 frames per second, looping.
for effect in water glass rtm; do
  frames=()
  [ -e "$out/frames/${effect}_0.png" ] && mapfile -t frames < <(printf '%s\n' "$out/frames/${effect}"_*.png | sort -V)
  [ ${#frames[@]} -gt 0 ] || continue
  apngasm "$out/$effect.apng.png" "${frames[@]}" 1 4 >/dev/null
  echo "snell-gallery: $out/$effect.apng.png"
done
