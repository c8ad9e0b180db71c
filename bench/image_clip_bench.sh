#!/usr/bin/env bash
# Image benchmark of `irid clip`: the cost of clipping a 4096×4096 RGB float EXR compared with
# the pure read + write of the same file by OpenImageIO's oiiotool.
#
#   bench/image_clip_bench.sh IRID [WORKDIR] [RUNS] [METHODS]
#
#   IRID     path of the irid binary (e.g. build/irid)
#   WORKDIR  where the images are written (default: a new temporary directory, removed at exit;
#            "" for the default); about 3 × 90 MB
#   RUNS     timed runs of each command, the best (fastest) kept (default 5)
#   METHODS  comma-separated clip methods (default smits), or "all": every method of
#            `irid clip --help` except luv-hue, which has no batch kernel
#
# Needs oiiotool (Debian: openimageio-tools). Steps:
#   1. oiiotool writes in.exr: a 4-corner gradient whose corners are all outside the sRGB cube
#      (1.6, -0.3, 0.2), (-0.2, 1.4, 0.1), (0.3, 0.2, 1.7), (1.2, 1.2, -0.4), so that many pixels
#      (42 %) are out of gamut; 3 float channels, OpenImageIO's default EXR compression (zip).
#   2. Times, best of RUNS (wall clock; the two commands alternate):
#        io:   oiiotool in.exr -o out_io.exr                               read + write
#        clip: IRID clip --method M in.exr out_clip.exr, per method M      read + clip + write
#      Both run on all hardware threads (their defaults) and write a float EXR with the same
#      default compression.
#   3. Prints the times and each method's overhead (clip − io) / io in percent, and the fraction
#      of the input's pixels out of gamut as a check of the test image.
# The requirement: every overhead is no more than 25 %. The exit status is 0 when it holds, 1 when
# it does not, 2 on a usage or tool error.

set -Eeuo pipefail
trap 'echo "error: command failed at line $LINENO" >&2; exit 2' ERR

# shellcheck source=bench/image_bench_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/image_bench_lib.sh"
image_bench_args 5 "$@"
methods=${4:-smits}
size=4096

if [[ "$methods" == all ]]; then
    # The method list of --method's help line ("Clipping method: clamp, smits, ...").
    methods=$("$irid" clip --help | sed -n 's/.*--method TEXT *Clipping method: //p' | tr -d ' ' |
        tr ',' '\n' | grep -vx 'luv-hue' | paste -sd, -)
    if [[ -z "$methods" ]]; then
        echo "error: could not read the method list from '$irid clip --help'" >&2
        exit 2
    fi
fi
IFS=, read -r -a method_list <<< "$methods"

in=$work/in.exr
oiiotool --pattern fill:topleft=1.6,-0.3,0.2:topright=-0.2,1.4,0.1:bottomleft=0.3,0.2,1.7:bottomright=1.2,1.2,-0.4 \
    "${size}x${size}" 3 -d float -o "$in"

# Out-of-gamut pixels: all minus those with every channel in [0, 1] ("within range" of
# oiiotool's --rangecheck; its "<" and ">" counts may both include the same pixel).
pixels=$((size * size))
within=$(oiiotool "$in" --rangecheck 0,0,0 1,1,1 2>&1 | awk '/within range/ { print $1 }' || true)
outside=""
if [[ "$within" =~ ^[0-9]+$ ]]; then outside=$((pixels - within)); fi

# One untimed run of each to warm the page cache and the binaries.
oiiotool "$in" -o "$work/out_io.exr" > /dev/null
"$irid" clip --method "${method_list[0]}" "$in" "$work/out_clip.exr" > /dev/null

# The commands alternate, so that a burst of other work on the machine hits all alike.
io=""
declare -A clip=()
for ((i = 0; i < runs; ++i)); do
    io=$(smaller "$io" "$(seconds oiiotool "$in" -o "$work/out_io.exr")")
    for m in "${method_list[@]}"; do
        clip[$m]=$(smaller "${clip[$m]:-}" "$(seconds "$irid" clip --method "$m" "$in" "$work/out_clip.exr")")
    done
done

echo "image:                 ${size}x${size} RGB float EXR, $(du -h "$in" | cut -f1) on disk"
if [[ -n "$outside" ]]; then
    echo "out of gamut:          $outside of $pixels pixels" \
        "($(awk -v o="$outside" -v p="$pixels" 'BEGIN { printf "%.1f", 100 * o / p }') %)"
fi
echo "runs:                  best of $runs (wall clock)"
echo "oiiotool (read+write): ${io} s"
status=0
for m in "${method_list[@]}"; do
    overhead=$(awk -v io="$io" -v c="${clip[$m]}" 'BEGIN { printf "%.1f", 100 * (c - io) / io }')
    verdict=PASS
    if ! awk -v o="$overhead" 'BEGIN { exit !(o <= 25) }'; then verdict=FAIL; status=1; fi
    printf 'irid clip --method %-18s %s s  overhead %6s %%  %s\n' "$m" "${clip[$m]}" "$overhead" "$verdict"
done
echo "requirement: overhead <= 25 % for every method"
exit "$status"
