# Shared by the image benchmarks (image_clip_bench.sh, image_display_bench.sh), sourced after
# they set `set -Eeuo pipefail`: their usage from their header comment, the checks of their
# common arguments IRID [WORKDIR] [RUNS] [LIST], the work folder, and the timing helpers.
# shellcheck shell=bash

# usage: the script's header comment, from its second line to the first blank one.
usage() { sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//'; }

# image_bench_args DEFAULT_RUNS "$@": checks the arguments and sets irid, runs and work (a new
# temporary folder removed at exit unless WORKDIR is given and not empty); exits 0 after --help,
# 2 on a usage or tool error.
image_bench_args() {
    local default_runs=$1
    shift
    if [[ $# -ge 1 && ("$1" == "-h" || "$1" == "--help") ]]; then
        usage
        exit 0
    fi
    if [[ $# -lt 1 || $# -gt 4 ]]; then
        usage >&2
        exit 2
    fi
    irid=$1
    runs=${3:-$default_runs}
    if [[ ! -x "$irid" ]]; then
        echo "error: $irid is not an executable" >&2
        exit 2
    fi
    if ! command -v oiiotool > /dev/null; then
        echo "error: oiiotool not found (Debian: apt-get install openimageio-tools)" >&2
        exit 2
    fi
    if ! [[ "$runs" =~ ^[1-9][0-9]*$ ]]; then
        echo "error: RUNS must be a positive integer, not '$runs'" >&2
        exit 2
    fi
    if [[ $# -ge 2 && -n "$2" ]]; then
        work=$2
        mkdir -p "$work"
    else
        work=$(mktemp -d)
        # shellcheck disable=SC2064  # expand now: $work is set
        trap "rm -rf '$work'" EXIT
    fi
}

# seconds COMMAND...: wall-clock seconds of one run of the command (its output discarded).
seconds() {
    local start end
    start=$(date +%s.%N)
    "$@" > /dev/null 2>&1
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.6f", b - a }'
}

# smaller A B: the smaller of two numbers (B when A is empty).
smaller() {
    if [[ -z "$1" ]] || awk -v a="$2" -v b="$1" 'BEGIN { exit !(a < b) }'; then echo "$2"; else echo "$1"; fi
}
