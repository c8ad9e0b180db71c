#!/usr/bin/env bash
# The contract of `irid render`: a built-in scene or a JSON scene file in, one image out (PNG,
# TIFF or EXR, by OUT's extension; SCENE.png in the current folder by default), plus the
# unclipped linear image with --linear FILE.exr. Exit statuses 0 (success, nothing on stdout),
# 1 (bad scene file or failed I/O, the file named on stderr) and 2 (usage, what is allowed named
# on stderr). A failed run creates no file and leaves an existing OUT as it was.
#
#   bash tests/cli/render_test.sh <path-to-irid> <path-to-scenes-dir>
#
# Prints one line per failed check (what was run, what was expected, what came out) and ends
# with "N passed, M failed"; exits 0 only when every check passed. Sizes and formats are read
# with oiiotool (openimageio-tools); the position of a JSON syntax error is counted here from
# the file's text; the limits are those documented in include/irid/render/scene.h. Images are
# tiny (48 × 36, 1 sample per pixel) so that the script runs in seconds.
# shellcheck disable=SC2016  # awk programs use $1, $2, ... inside single quotes
set -u

if [[ $# -ne 2 ]]; then
    echo "usage: bash $0 <path-to-irid> <path-to-scenes-dir>" >&2
    exit 2
fi
# Absolute paths: the checks run irid from several folders.
IRID=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SCENES=$(cd "$2" && pwd) || exit 2
# shellcheck source=lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

if ! command -v oiiotool >/dev/null; then
    RAN="command -v oiiotool"
    fail "oiiotool (openimageio-tools) to read the images" "not found"
    echo "$passed passed, $failed failed"
    exit 1
fi

WORK=$TMP/work
mkdir -p "$WORK"
# Every run gets at most this many seconds, so that a size that should be refused cannot start
# a render that never ends (timeout's status 124 then fails the check).
LIMIT=120
# Small images: W × H pixels at 1 sample per pixel.
W=48
H=36
SMALL=(--width "$W" --height "$H" --spp 1)

# --- running the program ------------------------------------------------------------------

# run_in DIR ARGS...: runs `irid ARGS` in folder DIR with no stdin; STATUS, RAN, $TMP/out and
# $TMP/err as lib.sh's run.
run_in() {
    local dir=$1 args
    shift
    (cd "$dir" && timeout -k 5 "$LIMIT" "$IRID" "$@" </dev/null >"$TMP/out" 2>"$TMP/err")
    STATUS=$?
    printf -v args ' %q' "$@"
    RAN="(cd ${dir#"$TMP"/} && irid${args})"
}

# run_render ARGS...: `irid render ARGS` in $WORK.
run_render() { run_in "$WORK" render "$@"; }

# --- checks -------------------------------------------------------------------------------

# image_info FILE: "WIDTH HEIGHT CHANNELS TYPE FORMAT" from oiiotool's one-line description
# ("f.png : 48 x 36, 3 channel, uint8 png"), or nothing when oiiotool cannot read FILE.
image_info() {
    oiiotool --info "$1" 2>/dev/null |
        sed -nE 's/^.*: +([0-9]+) x +([0-9]+), ([0-9]+) channel, ([a-z0-9]+) ([a-z]+).*$/\1 \2 \3 \4 \5/p'
}

# expect_image FILE W H TYPE FORMAT: status 0, nothing on stdout, and FILE an image of W x H
# pixels with 3 channels of TYPE (uint8, float) in FORMAT (png, tiff, openexr).
expect_image() {
    local info
    info=$(image_info "$1")
    if [[ $STATUS -eq 0 && ! -s $TMP/out && $info == "$2 $3 3 $4 $5" ]]; then
        pass
    else
        fail "a $2x$3 RGB $4 $5 in ${1#"$TMP"/} and empty stdout" "$(outcome), image '${info}'"
    fi
}

# expect_folder_holds DIR NAMES...: DIR holds exactly these files (no temporaries, no extras).
expect_folder_holds() {
    local dir=$1 got want
    shift
    got=$(find "$dir" -mindepth 1 -maxdepth 1 -printf '%f\n' | sort | tr '\n' ' ')
    want=$( (($# > 0)) && printf '%s\n' "$@" | sort | tr '\n' ' ')
    if [[ $got == "$want" ]]; then pass; else fail "${dir#"$TMP"/} holding: $want" "holding: $got; $(outcome)"; fi
}

# expect_refused STATUS EXT TEXT ARGS...: `irid render ARGS -o FILE.EXT` exits with STATUS,
# names TEXT on stderr and prints nothing on stdout; run once with FILE absent (afterwards the
# folder is still empty: no OUT, no --linear file, no temporary) and once with FILE present
# (left byte for byte as it was, nothing else created). ARGS may name files in $REFUSED.
REFUSED=$WORK/refused
expect_refused() {
    local status=$1 ext=$2 text=$3
    shift 3
    rm -rf "$REFUSED" && mkdir -p "$REFUSED"
    run_render "$@" -o "$REFUSED/new.$ext"
    expect_status "$status"
    expect_stderr_has "$text"
    expect_empty_stdout
    expect_folder_holds "$REFUSED"
    printf 'the previous contents\n' >"$REFUSED/old.$ext"
    run_render "$@" -o "$REFUSED/old.$ext"
    expect_status "$status"
    if [[ $(cat "$REFUSED/old.$ext") == 'the previous contents' ]]; then
        pass
    else
        fail "old.$ext left as it was" "changed; $(outcome)"
    fi
    expect_folder_holds "$REFUSED" "old.$ext"
}

# pixels FILE: one line "R G B" per pixel, as oiiotool prints them (9 significant digits).
pixels() {
    oiiotool --dumpdata "$1" | awk '/Pixel \(/ { sub(/^[^:]*: */, ""); print $1, $2, $3 }'
}

# === 1. Built-in scenes: the requested size, PNG by default ===============================

for s in oil-slick soap-bubbles morpho; do
    run_render "$s" "${SMALL[@]}" -o "$s.png"
    expect_image "$WORK/$s.png" "$W" "$H" uint8 png
done
# Odd, portrait sizes (width and height not swapped, partial tiles kept).
run_render morpho --width 29 --height 41 --spp 1 -o portrait.png
expect_image "$WORK/portrait.png" 29 41 uint8 png

# The default output is SCENE.png in the current folder, for a built-in name and for a file
# (its stem, in the current folder, not beside the scene).
mkdir -p "$WORK/default" "$WORK/scene-folder"
cp "$SCENES/soap-bubbles.json" "$WORK/scene-folder/bubbles-copy.json"
run_in "$WORK/default" render morpho "${SMALL[@]}"
expect_image "$WORK/default/morpho.png" "$W" "$H" uint8 png
run_in "$WORK/default" render ../scene-folder/bubbles-copy.json "${SMALL[@]}"
expect_image "$WORK/default/bubbles-copy.png" "$W" "$H" uint8 png
expect_folder_holds "$WORK/default" morpho.png bubbles-copy.png
expect_folder_holds "$WORK/scene-folder" bubbles-copy.json

# === 2. TIFF and EXR; --linear ============================================================

run_render oil-slick "${SMALL[@]}" -o oil.tif
expect_image "$WORK/oil.tif" "$W" "$H" uint8 tiff
run_render oil-slick "${SMALL[@]}" -o oil.tiff
expect_image "$WORK/oil.tiff" "$W" "$H" uint8 tiff
run_render oil-slick "${SMALL[@]}" -o oil.exr --linear oil-linear.exr --set render.view=thesis
expect_image "$WORK/oil.exr" "$W" "$H" float openexr
expect_image "$WORK/oil-linear.exr" "$W" "$H" float openexr

# The EXR OUT holds the displayed colours: every sample in [0, 1] (to float rounding, 1e-6). The
# --linear file holds them before the view transform and the clip: the sun's reflection makes
# some samples exceed 1, and with render.view=thesis (the clip alone, no highlight roll-off)
# every pixel already inside the RGB cube [0, 1]^3, which no clip method changes, is the same in
# both files (to float rounding of the encoding round trip, 1e-5).
pixels "$WORK/oil-linear.exr" >"$TMP/linear.txt"
pixels "$WORK/oil.exr" >"$TMP/clipped.txt"
RAN="irid render oil-slick ${SMALL[*]} -o oil.exr --linear oil-linear.exr --set render.view=thesis"
verdict=$(paste -d' ' "$TMP/linear.txt" "$TMP/clipped.txt" | awk -v n=$((W * H)) '
    function abs(x) { return x < 0 ? -x : x }
    function in01(v) { return v >= 0 && v <= 1 }
    function near01(v) { return v >= -1e-6 && v <= 1 + 1e-6 }
    { ++rows
      if (!(near01($4) && near01($5) && near01($6))) {
          printf "clipped pixel %d (%s %s %s) outside [0, 1]", NR, $4, $5, $6; bad = 1; exit }
      if ($1 > 1 || $2 > 1 || $3 > 1) ++above
      if (in01($1) && in01($2) && in01($3) &&
          (abs($1 - $4) > 1e-5 || abs($2 - $5) > 1e-5 || abs($3 - $6) > 1e-5)) {
          printf "in-gamut pixel %d changed: %s %s %s -> %s %s %s", NR, $1, $2, $3, $4, $5, $6; bad = 1; exit }
    }
    END { if (bad) exit
          if (rows != n) printf "%d pixels instead of %d", rows, n
          else if (above == 0) printf "no linear sample above 1" }')
if [[ -z $verdict ]]; then pass; else fail "clipped EXR in [0, 1], linear EXR unclipped, in-gamut pixels equal" "$verdict"; fi

# --linear must be an EXR (exit 2), and not the output itself.
expect_refused 2 png ".exr" oil-slick "${SMALL[@]}" --linear "$REFUSED/linear.tif"
expect_refused 2 png ".exr" oil-slick "${SMALL[@]}" --linear "$REFUSED/linear.jpg"
# An HDR display's PQ in a JPEG (8 lossy bits, no tag for the curve): refused before the render.
expect_refused 2 jpg "PNG or TIFF (16 bits)" oil-slick "${SMALL[@]}" --set render.view=aces2 \
    --set 'render.display="hdr-1000nit-p3-d65"'
rm -rf "$REFUSED" && mkdir -p "$REFUSED"
printf 'the previous contents\n' >"$REFUSED/same.exr"
run_render oil-slick "${SMALL[@]}" -o "$REFUSED/same.exr" --linear "$REFUSED/same.exr"
expect_status 2
expect_stderr_has "--linear"
if [[ $(cat "$REFUSED/same.exr") == 'the previous contents' ]]; then pass; else fail "same.exr left as it was" "changed; $(outcome)"; fi
expect_folder_holds "$REFUSED" same.exr

# === 3. Determinism =======================================================================

run_render soap-bubbles "${SMALL[@]}" --threads 1 -o threads1.png
expect_status 0
run_render soap-bubbles "${SMALL[@]}" --threads 2 -o threads2.png
expect_status 0
RAN="cmp threads1.png threads2.png (irid render soap-bubbles ${SMALL[*]} --threads 1 / 2)"
if cmp -s "$WORK/threads1.png" "$WORK/threads2.png"; then pass; else fail "byte-identical PNGs" "they differ"; fi
run_render soap-bubbles "${SMALL[@]}" --threads 2 --seed 18446744073709551615 -o seed.png
expect_image "$WORK/seed.png" "$W" "$H" uint8 png
RAN="pixels of threads2.png and seed.png (irid render soap-bubbles ${SMALL[*]} --seed 18446744073709551615)"
if [[ -n $(pixels "$WORK/seed.png") && $(pixels "$WORK/seed.png") != "$(pixels "$WORK/threads2.png")" ]]; then
    pass
else
    fail "a different seed gives different pixels" "the same pixels"
fi

# === 4. A JSON scene file, copied and edited ==============================================

# The copy gets its own size, a steeper slick (k1) and an environment image named relative to
# the scene file; irid runs from another folder, so the image is found only if relative paths
# are taken from the scene's folder.
mkdir -p "$WORK/my-scenes" "$WORK/elsewhere"
sed -e 's/"width": 1024/"width": 40/' -e 's/"height": 768/"height": 30/' -e 's/"spp": 4/"spp": 1/' \
    -e 's/"k1": 1.0,/"k1": 2.5,/' -e 's/"environment_image": ""/"environment_image": "sky.exr"/' \
    "$SCENES/oil-slick.json" >"$WORK/my-scenes/my-oil.json"
RAN="sed edits of oil-slick.json"
edits=$(grep -oE '"width": 40|"height": 30|"spp": 1|"k1": 2.5|"environment_image": "sky.exr"' "$WORK/my-scenes/my-oil.json" | wc -l)
if [[ $edits -eq 5 ]]; then pass; else fail "5 edited values" "$edits (has scenes/oil-slick.json changed?)"; fi
oiiotool --pattern constant:color=0.4,0.6,1.2 32x16 3 -d float -o "$WORK/my-scenes/sky.exr"

run_in "$WORK/elsewhere" render ../my-scenes/my-oil.json -o edited.png
expect_image "$WORK/elsewhere/edited.png" 40 30 uint8 png
run_in "$WORK/my-scenes" render my-oil.json -o ../elsewhere/edited-again.png -q
expect_image "$WORK/elsewhere/edited-again.png" 40 30 uint8 png
# The edits are used: the built-in scene at the same size gives other pixels.
run_render oil-slick --width 40 --height 30 --spp 1 -o unedited.png
expect_status 0
RAN="pixels of edited.png and unedited.png"
if [[ $(pixels "$WORK/elsewhere/edited.png") != "$(pixels "$WORK/unedited.png")" ]]; then
    pass
else
    fail "the edited scene renders differently" "the same pixels"
fi
# Without the environment image beside the scene: exit 1 naming it.
mv "$WORK/my-scenes/sky.exr" "$WORK/sky.exr"
expect_refused 1 png "my-scenes/sky.exr" "$WORK/my-scenes/my-oil.json"

# === 5. Bad scene files: exit 1, the file and what was wrong on stderr ====================

BAD=$WORK/bad
mkdir -p "$BAD"

# A JSON syntax error: the comma before "}" on line 3. Its column is counted from the text.
printf '{\n  "scene": "oil-slick",\n  "image": { "width": 16, "height": 12, },\n  "oil": { "k1": 1 }\n}\n' \
    >"$BAD/comma.json"
COL=$(awk 'NR == 3 { print index($0, ", }") + 2 }' "$BAD/comma.json")   # the "}"
expect_refused 1 png "line 3, column $COL" "$BAD/comma.json"
expect_stderr_has "comma.json"
# A bracket that closes nothing, first on line 5.
printf '{\n  "scene": "oil-slick",\n  "oil": {\n    "k1": 1.5\n]\n}\n' >"$BAD/bracket.json"
expect_refused 1 png "line 5, column 1" "$BAD/bracket.json"
expect_stderr_has "bracket.json"
# An unknown key: its path and the word "unknown".
printf '{ "scene": "oil-slick", "oil": { "k1": 1.5, "k3": 2 } }\n' >"$BAD/key.json"
expect_refused 1 png "'oil.k3'" "$BAD/key.json"
expect_stderr_has "unknown"
expect_stderr_has "key.json"
# Values out of range: the key path and the allowed range (scene.h: images up to 16384 pixels
# a side; albedos are reflectances, 0 to 1).
printf '{ "scene": "morpho", "image": { "width": 20000 } }\n' >"$BAD/width.json"
expect_refused 1 png "'image.width'" "$BAD/width.json"
expect_stderr_has "16384"
expect_stderr_has "width.json"
printf '{ "scene": "oil-slick", "pavement": { "albedo": [0.5, 1.5, 0.5] } }\n' >"$BAD/albedo.json"
expect_refused 1 png "'pavement.albedo'" "$BAD/albedo.json"
expect_stderr_has "[0, 1]"
# A missing file and an unknown built-in name: the built-in scenes are listed.
expect_refused 1 png "no-such-scene.json" "$BAD/no-such-scene.json"
expect_stderr_has "oil-slick"
expect_stderr_has "soap-bubbles"
expect_stderr_has "morpho"
expect_refused 1 png "soap-bubles" soap-bubles
expect_stderr_has "oil-slick"
expect_stderr_has "soap-bubbles"
expect_stderr_has "morpho"

# === 6. Usage errors: exit 2, what is allowed on stderr, no file ==========================

expect_refused 2 png "--width" oil-slick --width 0 --height "$H" --spp 1
expect_refused 2 png "--width" oil-slick --width 99999 --height "$H" --spp 1
expect_refused 2 png "--height" oil-slick --width "$W" --height 0 --spp 1
expect_refused 2 png "--spp" oil-slick --width "$W" --height "$H" --spp 0
# Seeds are 64-bit unsigned integers: 0 to 2^64 - 1 = 18446744073709551615.
expect_refused 2 png "--seed" oil-slick "${SMALL[@]}" --seed -1
expect_refused 2 png "--seed" oil-slick "${SMALL[@]}" --seed 18446744073709551616
expect_refused 2 png "--seed" oil-slick "${SMALL[@]}" --seed 1.5
expect_refused 2 png "smits" oil-slick "${SMALL[@]}" --clip nosuch
expect_stderr_has "nosuch"
expect_refused 2 png "oil.k1" oil-slick "${SMALL[@]}" --set oil.k1
expect_stderr_has "key.path=value"
expect_refused 2 png "'oil.k3'" oil-slick "${SMALL[@]}" --set oil.k3=1
expect_stderr_has "unknown"
expect_refused 2 png "'render.path'" oil-slick "${SMALL[@]}" --set render.path=curved
expect_stderr_has "spectral"
expect_refused 2 png "'pavement.albedo'" oil-slick "${SMALL[@]}" --set 'pavement.albedo=[2, 0, 0]'
expect_stderr_has "[0, 1]"
expect_refused 2 bmp ".png" oil-slick "${SMALL[@]}"
expect_stderr_has ".exr"
expect_refused 2 png "--no-such-option" oil-slick "${SMALL[@]}" --no-such-option
# Each side within its limit but too many pixels in all: refused before any work, naming the
# limit (scene.h: max_pixels = 64 × 1024 × 1024).
expect_refused 2 png "$((64 * 1024 * 1024))" oil-slick --width 16384 --height 16384 --spp 1
run_render
expect_status 2

# === 7. Failed output: exit 1, the path named, no file left ===============================

rm -rf "$REFUSED" && mkdir -p "$REFUSED"
run_render oil-slick "${SMALL[@]}" -o "$REFUSED/no-such-folder/out.png"
expect_status 1
expect_stderr_has "$REFUSED/no-such-folder/out.png"
expect_empty_stdout
expect_folder_holds "$REFUSED"
run_render oil-slick "${SMALL[@]}" -o "$REFUSED/no-such-folder/out.png" --linear "$REFUSED/linear.exr"
expect_status 1
expect_stderr_has "$REFUSED/no-such-folder/out.png"
expect_empty_stdout
expect_folder_holds "$REFUSED"
run_render oil-slick "${SMALL[@]}" -o "$REFUSED/out.png" --linear "$REFUSED/no-such-folder/linear.exr"
expect_status 1
expect_stderr_has "$REFUSED/no-such-folder/linear.exr"
expect_folder_holds "$REFUSED"
# A folder where nothing can be created (Linux's /proc, even for root): the main output fails
# after the render, and the --linear image is not left behind either (both files or neither).
if [[ -d /proc/self ]]; then
    printf 'the previous contents\n' >"$REFUSED/linear.exr"
    run_render oil-slick "${SMALL[@]}" -o /proc/irid-render-test.png --linear "$REFUSED/linear.exr"
    expect_status 1
    expect_stderr_has "/proc/irid-render-test.png"
    expect_folder_holds "$REFUSED" linear.exr
    if [[ $(cat "$REFUSED/linear.exr") == 'the previous contents' ]]; then
        pass
    else
        fail "linear.exr left as it was" "changed; $(outcome)"
    fi
fi

# === 8. --quiet and the summary ===========================================================

run_render morpho "${SMALL[@]}" -o quiet.png --quiet
expect_image "$WORK/quiet.png" "$W" "$H" uint8 png
if [[ ! -s $TMP/err ]]; then pass; else fail "nothing on stderr with --quiet" "$(outcome)"; fi
run_render morpho "${SMALL[@]}" -o quiet-short.png -q
expect_image "$WORK/quiet-short.png" "$W" "$H" uint8 png
if [[ ! -s $TMP/err ]]; then pass; else fail "nothing on stderr with -q" "$(outcome)"; fi
# Without it: one line naming the file, and no progress bar (stderr is not a terminal here).
run_render morpho "${SMALL[@]}" -o loud.png
expect_image "$WORK/loud.png" "$W" "$H" uint8 png
lines=$(wc -l <"$TMP/err")
if [[ $lines -eq 1 && $(tail -c 1 "$TMP/err") == '' ]] && ! grep -q $'\r' "$TMP/err"; then
    pass
else
    fail "one line on stderr, without carriage returns" "$(outcome)"
fi
expect_stderr_has "loud.png"

# ===========================================================================================

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
