#!/usr/bin/env bash
# The contract of `irid clip`: CSV in on stdin, R,G,B out on stdout; images IN -> OUT; Table 1.
# Exit statuses 0 (success), 1 (bad data or I/O, the file or "<stdin>:LINE" named on stderr,
# nothing on stdout) and 2 (usage, the valid values listed).
#
#   bash tests/cli/clip_test.sh <path-to-irid> <path-to-data-dir>
#
# Prints one line per failed check (what was run, what was expected, what came out) and ends
# with "N passed, M failed"; exits 0 only when every check passed. Expected values come from
# closed forms (the sRGB luminance row from its primaries, the sRGB transfer function, the
# clamp), never from the program's own output. Images are made and inspected with oiiotool
# (openimageio-tools).
# shellcheck disable=SC2016  # awk conditions on $1, $2, $3 are passed in single quotes
set -u

if [[ $# -ne 2 ]]; then
    echo "usage: bash $0 <path-to-irid> <path-to-data-dir>" >&2
    exit 2
fi
IRID=$1
# shellcheck source=lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
# The data folder is not needed: every expected value is a closed form.

# --- running the program ------------------------------------------------------------------

# --- reporting ----------------------------------------------------------------------------

# --- checks on the last run ---------------------------------------------------------------

# expect_rows_where N CONDITION WHAT: status 0, exactly N lines after stdout's header, and the
# awk CONDITION (on $1, $2, $3, with abs(), inside(v) = v in [0, 1], and the sRGB luminance
# row LR, LG, LB) holds for every one of them; WHAT describes it for the message.
expect_rows_where() {
    if [[ $STATUS -eq 0 ]] && awk -F, -v n="$1" -v LR="$LR" -v LG="$LG" -v LB="$LB" "
            function abs(x) { return x < 0 ? -x : x }
            function inside(v) { return v >= 0 && v <= 1 }
            NR > 1 { ++rows; if (!($2)) bad = 1 }
            END { exit !(rows == n && !bad) }" "$TMP/out"; then
        pass
    else
        fail "$3 ($1 rows)" "$(outcome)"
    fi
}

# expect_usage_error TEXT: exit status 2, TEXT on stderr, nothing on stdout.
expect_usage_error() {
    expect_status 2
    expect_stderr_has "$1"
    expect_empty_stdout
}

# --- reference values ---------------------------------------------------------------------

# The luminance row (A, B, C) of the sRGB RGB -> XYZ matrix from the primaries' and D65's
# chromaticities (SMPTE RP 177): the scales S = P^-1 W of the primaries' XYZ columns
# P = (x/y, 1, z/y), with W the white's XYZ at Y = 1; the Y row of the matrix is S itself.
# Rounded, it is IEC 61966-2-1's 0.2126, 0.7152, 0.0722.
read -r LR LG LB < <(awk 'BEGIN {
    split("0.64 0.30 0.15", x, " "); split("0.33 0.60 0.06", y, " ")
    for (i = 1; i <= 3; ++i) { p[1, i] = x[i] / y[i]; p[2, i] = 1; p[3, i] = (1 - x[i] - y[i]) / y[i] }
    w[1] = 0.3127 / 0.3290; w[2] = 1; w[3] = (1 - 0.3127 - 0.3290) / 0.3290
    det = p[1,1] * (p[2,2] * p[3,3] - p[2,3] * p[3,2]) - p[1,2] * (p[2,1] * p[3,3] - p[2,3] * p[3,1]) \
        + p[1,3] * (p[2,1] * p[3,2] - p[2,2] * p[3,1])
    for (c = 1; c <= 3; ++c) {   # Cramer: replace column c by w
        for (i = 1; i <= 3; ++i) for (j = 1; j <= 3; ++j) q[i, j] = (j == c) ? w[i] : p[i, j]
        d = q[1,1] * (q[2,2] * q[3,3] - q[2,3] * q[3,2]) - q[1,2] * (q[2,1] * q[3,3] - q[2,3] * q[3,1]) \
          + q[1,3] * (q[2,1] * q[3,2] - q[2,2] * q[3,1])
        s[c] = d / det
    }
    printf "%.17g %.17g %.17g\n", s[1], s[2], s[3]
}')

# Every method, from the help text (the contract tests below name the ones they check).
mapfile -t METHODS < <("$IRID" clip --help | sed -n 's/.*--method TEXT *Clipping method: //p' |
    tr -d ' ' | tr ',' '\n')
# The methods that keep in-gamut colours and whose output is always inside the cube.
HARD_METHODS=(clamp smits smits-xyz luv-lightness-hue luv-hue css oklab css-raytrace
    oklab-adaptive oklab-cusp)

# === 1. CSV: the contract's defaults and shape ============================================

RAN="the sRGB luminance row from the primaries"
if awk -v a="$LR" -v b="$LG" -v c="$LB" 'BEGIN { exit !(a > 0.21255 && a < 0.21265 && b > 0.71515 && b < 0.71525 && c > 0.07215 && c < 0.07225) }'; then
    pass
else
    fail "0.2126, 0.7152, 0.0722 to 4 decimals" "$LR $LG $LB"
fi

# In-gamut colours (inside, on faces, on edges, black and white) come back unchanged, for every
# hard method, with the header R,G,B and shortest round-trip numbers. (The soft ones, aces-rgc
# and smits-soft, compress what lies beyond their threshold, inside or not: section 9.)
IN_GAMUT=$'0.2,0.3,0.4\n0,0,0\n1,1,1\n0.5,0,1\n1,0,0\n0.25,0.75,0\n0.001,0.999,0.5\n'
for m in "${HARD_METHODS[@]}"; do
    run "$IN_GAMUT" clip --method "$m"
    expect_output "R,G,B"$'\n'"$IN_GAMUT"
done
# The same with the defaults spelled out, and an input header (skipped).
run $'R,G,B\n0.2,0.3,0.4\n' clip --method smits --from srgb-linear --to srgb-linear
expect_output $'R,G,B\n0.2,0.3,0.4\n'
# No colours: just the header.
run '' clip --method smits
expect_output $'R,G,B\n'

# === 2. CSV: the methods' closed forms ====================================================

# clamp is per channel.
run $'1.5,-0.2,0.3\n' clip --method clamp
expect_output $'R,G,B\n1,0,0.3\n'
run $'-3,7,0.5\n2,2,2\n-1,0.1,0.2\n' clip --method clamp
expect_output $'R,G,B\n0,1,0.5\n1,1,1\n0,0.1,0.2\n'

# smits keeps the luminance Y = A r + B g + C b when 0 < Y < 1, and the result lies inside the
# cube with at least one channel on a face (0 or 1). smits-xyz is the same clip in XYZ form.
OUT_OF_GAMUT=$'1.5,-0.2,0.3\n-0.3,0.8,0.2\n0.2,0.3,1.4\n1.1,0.9,-0.1\n-0.05,-0.02,0.9\n1.3,-0.2,-0.1\n0.3,1.2,0.05\n'
printf '%s' "$OUT_OF_GAMUT" | awk -F, -v LR="$LR" -v LG="$LG" -v LB="$LB" \
    '{ printf "%.17g\n", LR * $1 + LG * $2 + LB * $3 }' >"$TMP/y_in"
for m in smits smits-xyz; do
    run "$OUT_OF_GAMUT" clip --method "$m"
    expect_rows_where 7 'inside($1) && inside($2) && inside($3) &&
        (abs($1) < 1e-12 || abs($2) < 1e-12 || abs($3) < 1e-12 ||
         abs($1 - 1) < 1e-12 || abs($2 - 1) < 1e-12 || abs($3 - 1) < 1e-12)' \
        "every channel in [0, 1] and one on a face (within 1e-12)"
    tail -n +2 "$TMP/out" | awk -F, -v LR="$LR" -v LG="$LG" -v LB="$LB" \
        '{ printf "%.17g\n", LR * $1 + LG * $2 + LB * $3 }' >"$TMP/y_out"
    verdict=$(compare_csv "$TMP/y_in" "$TMP/y_out" 1e-9)
    if [[ -z $verdict ]]; then pass; else fail "Y = ${LR} r + ${LG} g + ${LB} b kept within 1e-9" "$verdict"; fi
done
# Both forms give the same colour.
run "$OUT_OF_GAMUT" clip --method smits
tail -n +2 "$TMP/out" >"$TMP/smits_rgb"
run "$OUT_OF_GAMUT" clip --method smits-xyz
expect_close "$(cat "$TMP/smits_rgb")" 1e-9
# One worked example: (1.5, -0.2, 0.3) goes toward the grey w = Y / (A + B + C) = Y (A + B + C
# = 1 for the sRGB row) and stops where green reaches 0: t = 0.2 / (0.2 + w).
W=$(awk -v LR="$LR" -v LG="$LG" -v LB="$LB" 'BEGIN { y = LR * 1.5 - LG * 0.2 + LB * 0.3; w = y / (LR + LG + LB)
    t = 0.2 / (0.2 + w); printf "%.17g,%.17g,%.17g", 1.5 + t * (w - 1.5), 0, 0.3 + t * (w - 0.3) }')
run $'1.5,-0.2,0.3\n' clip --method smits
expect_close "$W" 1e-12

# The methods that keep a lightness: Y (or Oklab L) <= 0 gives black, at or above the white's
# gives white. clamp works per channel.
for m in smits smits-xyz luv-lightness-hue css oklab css-raytrace smits-soft; do
    run $'-0.1,-0.1,-0.2\n-1,0.1,0.2\n0,0,-1e-3\n' clip --method "$m"
    expect_output $'R,G,B\n0,0,0\n0,0,0\n0,0,0\n'
    run $'2,1.5,1.2\n' clip --method "$m"
    expect_rows_where 1 'abs($1 - 1) < 1e-9 && abs($2 - 1) < 1e-9 && abs($3 - 1) < 1e-9' "white (1, 1, 1)"
done
# The methods that move lightness have no such rule (GAMUT.md): a colour brighter than the white
# keeps a hue, red stays red, and lands on the cube's surface, not on white.
for m in luv-hue oklab-adaptive oklab-cusp; do
    run $'2,1.5,1.2\n10,0,0\n' clip --method "$m"
    expect_rows_where 2 '$1 == 1 && $2 < 0.999 && $3 < 0.999 && $2 >= 0 && $3 >= 0' "a colour of red's hue on the face r = 1, not white"
done

# Every method accepts every name and returns colours inside the cube.
RAN="the method list read from irid clip --help"
if [[ ${#METHODS[@]} -eq 12 && " ${METHODS[*]} " == *" aces-rgc "* ]]; then pass; else
    fail "12 methods incl. aces-rgc" "${METHODS[*]}"; fi
# (aces-rgc confines its output only with clip=true; section 9 checks it without.)
for m in "${METHODS[@]}"; do
    extra=()
    [[ $m == aces-rgc ]] && extra=(--param clip=true)
    run "$OUT_OF_GAMUT" clip --method "$m" "${extra[@]}"
    expect_rows_where 7 'inside($1) && inside($2) && inside($3)' "$m: every channel in [0, 1]"
done

# === 3. CSV: spaces, encoding, HDR peak ===================================================

# --to srgb encodes: 1.055 * 0.5^(1/2.4) - 0.055.
ENC_HALF=$(awk 'BEGIN { printf "%.17g", 1.055 * exp(log(0.5) / 2.4) - 0.055 }')
run $'0.5,0.5,0.5\n' clip --method smits --to srgb
expect_close "$ENC_HALF,$ENC_HALF,$ENC_HALF" 1e-12
expect_stdout_has "0.7353569830524495"
# Encoded in, encoded out, in gamut: unchanged (to rounding).
run $'0.7353569830524495,0.2,1\n' clip --method smits --from srgb --to srgb
expect_close "0.7353569830524495,0.2,1" 1e-12
# Clipping happens on linear values even for encoded names: clamp of encoded (1.2, 0.5, -0.1).
run $'1.2,0.5,-0.1\n' clip --method clamp --from srgb --to srgb
expect_close "1,0.5,0" 1e-12

# Rec.2020 green is outside sRGB (negative red there) and becomes a valid sRGB colour.
run $'0,1,0\n' convert --from rec2020-linear --to srgb-linear
expect_rows_where 1 '$1 < -0.5 && $2 > 1' "Rec.2020 green out of the sRGB gamut"
for m in "${HARD_METHODS[@]}"; do
    run $'0,1,0\n' clip --method "$m" --from rec2020-linear
    expect_rows_where 1 'inside($1) && inside($2) && inside($3) && $2 > 0.5' \
        "$m: Rec.2020 green as a valid, green sRGB colour"
done
# smits keeps its luminance: Rec.2020's green has Y = 0.6780 (ITU-R BT.2020 luminance row).
run $'0,1,0\n' clip --method smits --from rec2020-linear
expect_rows_where 1 "abs(LR * \$1 + LG * \$2 + LB * \$3 - 0.6780) < 1e-4" "Y = 0.6780 kept"

# XYZ source: the D65 white (Y = 1) is sRGB white.
D65_XYZ=$(awk 'BEGIN { x = 0.3127; y = 0.3290; printf "%.17g,1,%.17g", x / y, (1 - x - y) / y }')
run "$D65_XYZ"$'\n' clip --method smits --from xyz
expect_close "1,1,1" 1e-9
# Other destinations: display-p3's gamut holds sRGB red.
run $'1,0,0\n' clip --method smits --from srgb-linear --to display-p3-linear
expect_rows_where 1 'inside($1) && inside($2) && inside($3) && $1 > 0.8' "sRGB red inside Display P3, unclipped"

# An HDR peak: the cube is [0, max].
run $'1.5,1.2,0.9\n' clip --method smits --max 2
expect_output $'R,G,B\n1.5,1.2,0.9\n'
run $'3,2.5,2.2\n' clip --method smits --max 2
expect_close "2,2,2" 1e-9
run $'3,-0.2,0.5\n' clip --method clamp --max 2
expect_output $'R,G,B\n2,0,0.5\n'

# === 4. Table 1 ============================================================================

run '' clip --count-ops
expect_status 0
for text in "| in gamut |" "| 1 plane |" "| 2 planes |" "| 3 planes |" "comparisons" "additions" \
            "multiplications" "divisions" "7 (7)" "9 (7)" "11 (7)" "1 (1)" "1 (2)" "1 (3)" "(5)" \
            "(6)" "9 (9)" "10 (10)" "11 (11)" "Smits 1990"; do
    expect_stdout_has "$text"
done
# Clipped rows (cross-multiplication, clip.h): 7 + 2 (n - 1) multiplications and 1 division for
# n planes, against the thesis' 7 and n.
if awk -F'|' '/^\| [0-9] plane/ { n = $2 + 0; m = 7 + 2 * (n - 1);
                                  if ($5 !~ ("^ *" m " \\(7\\) *$") || $6 !~ ("^ *1 \\(" n "\\) *$")) bad = 1; ++rows }
        END { exit !(rows == 3 && !bad) }' "$TMP/out"; then
    pass
else
    fail "7 + 2 (n - 1) multiplications and 1 division for n planes" "$(outcome)"
fi

# === 5. Errors ============================================================================

run $'1,1,1\n' clip --method no-such-method
expect_usage_error "css-raytrace"
run $'1,1,1\n' clip --method smits-corrected
expect_usage_error "retired"
run $'1,1,1\n' clip
expect_usage_error "luv-lightness-hue"
run $'1,1,1\n' clip --method smits --to lab
expect_usage_error "srgb-linear"
expect_stderr_has "display-p3"
run $'1,1,1\n' clip --method smits --to no-such-space
expect_usage_error "rec2020-linear"
run $'1,1,1\n' clip --method smits --from no-such-space
expect_usage_error "oklab"
run $'1,1,1\n' clip --method smits --max 0
expect_usage_error "--max"
run $'1,1,1\n' clip --method smits --max -1
expect_usage_error "--max"
run $'1,1,1\n' clip --method smits --white no-such-white
expect_usage_error "D65"
run $'1,1,1\n' clip --method smits --no-such-option
expect_usage_error "--no-such-option"
run $'1,1,1\n' clip --method smits --bits 16
expect_usage_error "--bits"
run $'1,1,1\n' clip --method smits only-one-file.exr
expect_usage_error "OUT"

# Bad data: status 1, the line on stderr, nothing on stdout even after good lines.
run $'0.1,0.2,0.3\n0.4,0.5\n' clip --method smits
expect_bad_data 2
run $'0.1,0.2,0.3\n2,-1,0\nnan,0,0\n' clip --method smits
expect_bad_data 3
run $'R,G,B\n0.1,0.2,0.3\n0.1,abc,0.3\n' clip --method clamp
expect_bad_data 3
run $'0.3,0.3,0.5\n0.3,0,0.5\n' clip --method smits --from xyy
expect_bad_data 2

# === 6. Images ============================================================================

if ! command -v oiiotool >/dev/null; then
    RAN="command -v oiiotool"
    fail "oiiotool (openimageio-tools) for the image checks" "not found"
    echo "$passed passed, $failed failed"
    exit 1
fi
IMG=$TMP/img
mkdir -p "$IMG"

# pixels FILE: every pixel's samples as CSV lines (integer codes for 8/16-bit files), as stored
# (alpha not multiplied in).
pixels() {
    oiiotool --iconfig oiio:UnassociatedAlpha 1 --dumpdata "$1" |
        awk '/Pixel \(/ { sub(/^[^:]*: */, ""); sub(/ *\(.*$/, ""); gsub(/ +/, ","); print }'
}

# run_image ARGS...: runs `irid ARGS` (no stdin).
run_image() {
    local args
    "$IRID" "$@" </dev/null >"$TMP/out" 2>"$TMP/err"
    STATUS=$?
    printf -v args ' %q' "$@"
    RAN="irid${args}"
}

# expect_pixels FILE N CONDITION WHAT: FILE has N pixels and CONDITION (awk, on $1.. of each
# pixel, with abs() and inside()) holds for all.
expect_pixels() {
    pixels "$1" >"$TMP/pixels" 2>/dev/null
    if awk -F, -v n="$2" "
            function abs(x) { return x < 0 ? -x : x }
            function inside(v) { return v >= 0 && v <= 1 }
            { ++rows; if (!($3)) bad = 1 }
            END { exit !(rows == n && !bad) }" "$TMP/pixels"; then
        pass
    else
        fail "$4 ($2 pixels)" "$(outcome); pixels $(show "$(head -c 300 "$TMP/pixels")")"
    fi
}

# expect_info FILE TEXT: oiiotool's one-line description of FILE contains TEXT.
expect_info() {
    local info
    info=$(oiiotool --info -v "$1" 2>&1)
    if [[ $info == *"$2"* ]]; then pass; else fail "$1: $(show "$2")" "$(show "$info")"; fi
}

# expect_folder_holds NAMES...: the image folder holds exactly these files (no temporaries).
expect_folder_holds() {
    local got want
    got=$(cd "$IMG" && ls -A | sort | tr '\n' ' ')
    want=$(printf '%s\n' "$@" | sort | tr '\n' ' ')
    if [[ $got == "$want" ]]; then pass; else fail "files: $want" "files: $got; $(outcome)"; fi
}

# --- EXR (linear float) with alpha -----------------------------------------------------------
# EXR colour is premultiplied by alpha (OpenEXR's convention): (0.75, -0.1, 0.15) at alpha 0.5
# is the colour (1.5, -0.2, 0.3), which is what gets clipped.
oiiotool --pattern constant:color=0.75,-0.1,0.15,0.5 4x4 4 -d float -o "$IMG/in.exr"
run_image clip --method smits "$IMG/in.exr" "$IMG/out.exr"
expect_status 0
expect_empty_stdout
expect_info "$IMG/out.exr" "4 x    4, 4 channel, float openexr"
expect_info "$IMG/out.exr" "channel list: R, G, B, A"
expect_info "$IMG/out.exr" 'irid:ColorSpace: "srgb-linear"'
# The same colour as the CSV clip (float precision), premultiplied again, alpha untouched.
expect_pixels "$IMG/out.exr" 16 "abs(\$1 - 0.5 * ${W%%,*}) < 1e-6 && abs(\$2) < 1e-6 && abs(\$3 - 0.5 * ${W##*,}) < 1e-6 && \$4 == 0.5" \
    "the CSV result $W times alpha 0.5, alpha 0.5"
# Alpha conventions: EXR (0.4, 0.4, 0.4) at alpha 0.5 is the colour 0.8, which a PNG stores
# unpremultiplied as sRGB code round(255 × 0.9063) = 231; an unpremultiplied PNG pixel at alpha
# 0 is premultiplied into an EXR as 0.
oiiotool --pattern constant:color=0.4,0.4,0.4,0.5 2x2 4 -d float -o "$IMG/grey.exr"
run_image clip --method smits --to srgb "$IMG/grey.exr" "$IMG/grey.png"
expect_status 0
expect_pixels "$IMG/grey.png" 4 '$1 == 231 && $2 == 231 && $3 == 231 && $4 == 128' "sRGB 231 at alpha 128"
oiiotool --pattern constant:color=1,0,0,0 2x2 4 -d uint8 --attrib oiio:UnassociatedAlpha 1 -o "$IMG/clear.png"
run_image clip --method smits --from srgb "$IMG/clear.png" "$IMG/clear.exr"
expect_status 0
expect_pixels "$IMG/clear.exr" 4 '$1 == 0 && $2 == 0 && $3 == 0 && $4 == 0' "transparent pixel premultiplied to 0"
rm -f "$IMG/grey.exr" "$IMG/grey.png" "$IMG/clear.png" "$IMG/clear.exr"
expect_pixels "$IMG/out.exr" 16 'inside($1) && inside($2) && inside($3)' "RGB inside [0, 1]"

# Every method on an image, including NaN and infinities: finite output inside the cube, and
# no other channel touched (alpha, depth). oiiotool prints 9 significant digits, which name a
# float exactly: 0.200000003 is the float nearest 0.2.
oiiotool --pattern constant:color=nan,inf,-inf,0.25,7 2x1 5 -d float --chnames R,G,B,A,Z \
    --pattern constant:color=-0.3,0.8,0.2,1,-2 2x1 5 -d float --chnames R,G,B,A,Z \
    --pattern constant:color=0.2,0.3,0.4,0,3 2x1 5 -d float --chnames R,G,B,A,Z \
    --mosaic 1x3 -o "$IMG/odd.exr"
for m in "${METHODS[@]}"; do
    run_image clip --method "$m" "$IMG/odd.exr" "$IMG/odd_$m.exr"
    expect_status 0
    expect_pixels "$IMG/odd_$m.exr" 6 'inside($1) && inside($2) && inside($3) && (NR > 4 ? $1 == 0.200000003 && $2 == 0.300000012 && $3 == 0.400000006 : 1)' \
        "$m: RGB finite and inside [0, 1], the in-gamut row unchanged"
    expect_pixels "$IMG/odd_$m.exr" 6 '(NR <= 2 && $4 == 0.25 && $5 == 7) || (NR > 2 && NR <= 4 && $4 == 1 && $5 == -2) || (NR > 4 && $4 == 0 && $5 == 3)' \
        "$m: A and Z untouched"
    rm -f "$IMG/odd_$m.exr"
done

# --threads does not change the result.
run_image clip --method smits --threads 1 "$IMG/in.exr" "$IMG/out1.exr"
expect_status 0
if [[ $(pixels "$IMG/out1.exr") == "$(pixels "$IMG/out.exr")" ]]; then pass; else RAN="--threads 1 vs default"; fail "same pixels" "different"; fi
rm -f "$IMG/out1.exr"

# --- PNG (encoded) with alpha ----------------------------------------------------------------
# Written unassociated (as PNG stores it), so the codes are exactly 51, 102, 153, 64.
oiiotool --pattern constant:color=0.2,0.4,0.6,0.25 3x2 4 -d uint8 --attrib oiio:UnassociatedAlpha 1 \
    -o "$IMG/in.png"
expect_pixels "$IMG/in.png" 6 '$1 == 51 && $2 == 102 && $3 == 153 && $4 == 64' "the test PNG as made"
# In gamut, decoded and encoded again with sRGB: the same codes, alpha untouched.
run_image clip --method smits --from srgb --to srgb "$IMG/in.png" "$IMG/same.png"
expect_status 0
expect_empty_stdout
expect_info "$IMG/same.png" "3 x    2, 4 channel, uint8 png"
expect_pixels "$IMG/same.png" 6 '$1 == 51 && $2 == 102 && $3 == 153 && $4 == 64' "in-gamut PNG unchanged"
# 16 bits: the same values on the 16-bit scale (257 × the 8-bit codes).
run_image clip --method oklab --from srgb --to srgb --bits 16 "$IMG/in.png" "$IMG/same16.png"
expect_status 0
expect_info "$IMG/same16.png" "uint16 png"
expect_pixels "$IMG/same16.png" 6 '$1 == 51 * 257 && $2 == 102 * 257 && $3 == 153 * 257 && $4 == 64 * 257' \
    "16-bit codes 257 × the 8-bit ones"
# Without --from an untagged PNG is sRGB, and a note on stderr says it was assumed: its
# in-gamut codes come back as they were.
run_image clip --method smits "$IMG/in.png" "$IMG/assumed.png"
expect_status 0
expect_stderr_has "has no ICC profile; its values are taken as sRGB"
expect_pixels "$IMG/assumed.png" 6 '$1 == 51 && $2 == 102 && $3 == 153 && $4 == 64' "codes 51, 102, 153 and alpha 64 unchanged"
rm -f "$IMG/assumed.png"
# With --from srgb-linear the PNG's values are taken as linear light (a note on stderr says
# so): code 51 is linear 0.2, written back encoded as round(255 × enc(0.2)).
run_image clip --method smits --from srgb-linear "$IMG/in.png" "$IMG/aslinear.png"
expect_status 0
expect_stderr_has "--from srgb"
ENC=$(awk 'function enc(v) { return 1.055 * exp(log(v) / 2.4) - 0.055 }
    BEGIN { printf "%d %d %d", int(enc(51 / 255) * 255 + 0.5), int(enc(102 / 255) * 255 + 0.5), int(enc(153 / 255) * 255 + 0.5) }')
read -r C1 C2 C3 <<<"$ENC"
expect_pixels "$IMG/aslinear.png" 6 "\$1 == $C1 && \$2 == $C2 && \$3 == $C3 && \$4 == 64" "codes $C1, $C2, $C3 and alpha 64"
rm -f "$IMG/aslinear.png"
# A -linear destination still writes encoded values to PNG: 8-bit code 188 for linear 0.5
# (round(255 × 0.7353569830524495)), and the metadata says srgb.
oiiotool --pattern constant:color=0.5,0.5,0.5 2x2 3 -d float -o "$IMG/half.exr"
run_image clip --method smits --to srgb-linear "$IMG/half.exr" "$IMG/half.png"
expect_status 0
expect_pixels "$IMG/half.png" 4 '$1 == 188 && $2 == 188 && $3 == 188' "linear 0.5 as sRGB code 188"
expect_info "$IMG/half.png" 'oiio:ColorSpace: "srgb"'
# Out of gamut into PNG and TIFF: encoded, inside the codes' range, alpha kept.
run_image clip --method css "$IMG/in.exr" "$IMG/out.png"
expect_status 0
expect_pixels "$IMG/out.png" 16 '$1 >= 0 && $1 <= 255 && $2 <= 1 && $4 == 128' "PNG: clipped colour, alpha 128"
run_image clip --method smits --bits 16 "$IMG/in.exr" "$IMG/out.tif"
expect_status 0
expect_info "$IMG/out.tif" "4 x    4, 4 channel, uint16 tiff"
# Encoded sRGB of the smits result, on 16 bits.
CODES=$(awk -v w="$W" 'function enc(v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * exp(log(v) / 2.4) - 0.055 }
    BEGIN { split(w, c, ","); printf "%d %d %d", int(enc(c[1]) * 65535 + 0.5), int(enc(c[2]) * 65535 + 0.5), int(enc(c[3]) * 65535 + 0.5) }')
read -r C1 C2 C3 <<<"$CODES"
expect_pixels "$IMG/out.tif" 16 "abs(\$1 - $C1) <= 1 && abs(\$2 - $C2) <= 1 && abs(\$3 - $C3) <= 1 && \$4 == 32768" \
    "TIFF codes $C1, $C2, $C3 (±1), alpha 32768"

# Rec.2020 green, an image: a valid sRGB colour.
oiiotool --pattern constant:color=0,1,0 2x2 3 -d float -o "$IMG/green2020.exr"
run_image clip --method smits --from rec2020-linear --to srgb "$IMG/green2020.exr" "$IMG/green.exr"
expect_status 0
expect_pixels "$IMG/green.exr" 4 'inside($1) && inside($2) && inside($3) && $2 > 0.5' "Rec.2020 green inside sRGB"
expect_info "$IMG/green.exr" 'irid:ColorSpace: "srgb-linear"'   # EXR: linear, whatever --to

expect_folder_holds in.exr out.exr odd.exr in.png same.png same16.png half.exr half.png out.png \
    out.tif green2020.exr green.exr

# --- failures leave no OUT (and no temporary file) ---------------------------------------------
run_image clip --method smits "$IMG/missing.exr" "$IMG/fail1.exr"
expect_status 1
expect_stderr_has "missing.exr"
expect_empty_stdout
run_image clip --method smits "$IMG/in.exr" "$IMG/no-such-folder/fail2.exr"
expect_status 1
expect_stderr_has "fail2.exr"
run_image clip --method smits "$IMG/in.exr" "$IMG/fail3.bmp"
expect_usage_error ".exr"
# JPEG holds no alpha: refused, nothing written (in.exr has an A channel).
run_image clip --method smits "$IMG/in.exr" "$IMG/fail3.jpg"
expect_status 1
expect_stderr_has "JPEG holds 1 (grey) or 3 (RGB), no alpha"
# PQ and HLG in a JPEG: 8 lossy bits, and no tag says the curve (readers take sRGB). Refused
# before the work, nothing written.
run_image clip --method smits --to rec2100-pq "$IMG/green2020.exr" "$IMG/fail-pq.jpg"
expect_usage_error "write PNG or TIFF (16 bits)"
run_image clip --method smits --to rec2100-hlg "$IMG/green2020.exr" "$IMG/fail-hlg.jpg"
expect_usage_error "HLG"
run_image clip --method smits --max 2 "$IMG/in.exr" "$IMG/fail4.png"
expect_usage_error "--max"
run_image clip --method smits --bits 12 "$IMG/in.exr" "$IMG/fail5.png"
expect_usage_error "16"
run_image clip --method smits --bits 16 "$IMG/in.exr" "$IMG/fail6.exr"
expect_usage_error "--bits"
run_image clip --method no-such-method "$IMG/in.exr" "$IMG/fail7.exr"
expect_usage_error "smits"
# Not an image.
printf 'R,G,B\n1,0,0\n' >"$IMG/colours.csv"
run_image clip --method smits "$IMG/colours.csv" "$IMG/fail8.exr"
expect_status 1
expect_stderr_has "colours.csv"
# Five channels cannot go into a PNG: OpenImageIO refuses after the work is done.
run_image clip --method smits "$IMG/odd.exr" "$IMG/fail9.png"
expect_status 1
expect_stderr_has "fail9.png"
# One channel is not a colour.
oiiotool --pattern constant:color=0.5 2x2 1 -d float -o "$IMG/grey.exr"
run_image clip --method smits "$IMG/grey.exr" "$IMG/fail10.exr"
expect_status 1
expect_stderr_has "grey.exr"
expect_folder_holds in.exr out.exr odd.exr in.png same.png same16.png half.exr half.png out.png \
    out.tif green2020.exr green.exr colours.csv grey.exr
# A failed run does not touch an existing OUT.
cp "$IMG/out.png" "$IMG/keep.png"
run_image clip --method smits "$IMG/odd.exr" "$IMG/keep.png"
expect_status 1
if cmp -s "$IMG/out.png" "$IMG/keep.png"; then pass; else fail "keep.png unchanged" "changed"; fi

# --- a colour within rounding of the gamut comes back within rounding of itself -------------
# The defect: sRGB blue one ulp above 1 came back from oklab as 0,0.0303,0.786 (21 % of its chroma
# lost), because Oklab's line of constant lightness and hue through blue leaves the cube and
# meets it again only at the vertex. Expected: the colour itself, 0,0,1, to rounding; for every
# method (the ones that move toward a grey move it by about 1e-16 here).
run $'0,0,1.0000000000000002\n' clip --method oklab
expect_close "0,0,1" 1e-12
for method in "${HARD_METHODS[@]}"; do
    # Blue and red a hair outside, and a colour 1e-9 below the face g = 0 next to the blue edge.
    run $'0,0,1.0000000000000002\n1.0000000000000002,0,0\n0,-1e-9,0.75\n' clip --method "$method"
    expect_close $'0,0,1\n1,0,0\n0,0,0.75' 1e-7
done
# The image path (float batches): an EXR of blue one float ulp above 1 (1.0000001 is read as
# 1 + 2^-23) stays blue to float precision.
EDGE=$TMP/edge
mkdir -p "$EDGE"
oiiotool --pattern constant:color=0,0,1.0000001 2x2 3 -d float -o "$EDGE/blue.exr"
run_image clip --method oklab "$EDGE/blue.exr" "$EDGE/blue-clipped.exr"
expect_status 0
expect_pixels "$EDGE/blue-clipped.exr" 4 'abs($1) < 1e-6 && abs($2) < 1e-6 && abs($3 - 1) < 1e-6' \
    "blue kept: 0, 0, 1 to float precision"
# The clip report on a set inside its own gamut: no colour is out of it, and so no method may
# move any colour: every ΔE2000 (mean, 95th percentile, maximum) prints as 0.00. oklab printed a
# maximum of 5.83, from colours a rounding error outside the cube after the conversions.
run '' clip-report --set rec2020 --to rec2020
expect_stdout_has "729 colours, 0 out of the rec2020 gamut"
for method in clamp smits smits-xyz luv-lightness-hue luv-hue css oklab css-raytrace; do
    expect_stdout_has "| $method | 0.00 | 0.00 | 0.00 |"
done
# The second table: every colour is inside, so in-gamut ΔE2000 is that of the whole set (0 for
# the methods that leave in-gamut colours alone), and the set has no ramps ("–").
expect_stdout_has "ΔE00 of the 729 colours inside the gamut"
expect_stdout_has "| method | in-gamut ΔE00 mean / max | banding mean / max | collapse | collapse ½ step |"
for method in clamp smits smits-xyz luv-lightness-hue luv-hue css oklab css-raytrace; do
    expect_stdout_has "| $method | 0.00 / 0.00 | – | – | – |"
done

# --- clip-report --set ramps: the gradients ---------------------------------------------------
# 24 hues × 2 ends × 3 luminances = 144 ramps of 256 steps, every method a row of both tables.
run '' clip-report --set ramps --to display-p3
expect_status 0
expect_stdout_has "Set ramps: 36864 colours, "
expect_stdout_has " out of the display-p3 gamut."
expect_stdout_has "over 144 ramps; the input ramps' own banding is 1.0"
for method in clamp smits smits-xyz luv-lightness-hue luv-hue css oklab \
              css-raytrace oklab-adaptive oklab-cusp smits-soft aces-rgc; do
    rows=$(grep -c "^| $method | " "$TMP/out")
    RAN="irid clip-report --set ramps --to display-p3: rows of $method"
    if [[ $rows -eq 2 ]]; then pass; else fail "2 rows (one per table)" "$rows"; fi
done
# The hard clips that leave in-gamut colours alone move none of them; smits sends every ramp's
# tail to one point of the boundary, so each of its out-of-gamut steps collapses.
for method in clamp smits smits-xyz luv-lightness-hue luv-hue css oklab css-raytrace; do
    expect_stdout_has "| $method | 0.00 / 0.00 | "
done
RAN="irid clip-report --set ramps --to display-p3: smits' collapse"
if grep -qE '^\| smits \| 0\.00 / 0\.00 \| [0-9.]+ / [0-9.]+ \| 1\.000 \| 1\.000 \|$' "$TMP/out"; then pass; else
    fail "| smits | 0.00 / 0.00 | B / B | 1.000 | 1.000 |" "$(grep '^| smits |' "$TMP/out" | tail -1)"
fi
# --set all: the four sets, then their union (39 800 colours); an unknown set lists ramps.
run '' clip-report --set all
expect_status 0
expect_stdout_has "Set all: 39800 colours, "
expect_stdout_has "The union of spectrum, interference, rec2020 and ramps."
run '' clip-report --set gradients
expect_usage_error "spectrum, interference, rec2020, ramps, all"


# === 9. Method parameters, inverses and the ACES spaces ====================================
# --param and --inverse are checked against the method: exit 2, the allowed names and ranges.
run $'1.2,-0.1,0.3\n' clip --method aces-rgc --param no-such=1
expect_usage_error "method aces-rgc has no parameter 'no-such'; its parameters: limit-cyan in ["
run $'1.2,-0.1,0.3\n' clip --method aces-rgc --param power=0.5
expect_usage_error "parameter power = 0.5 must be in [1, "
run $'1.2,-0.1,0.3\n' clip --method aces-rgc --param power=abc
expect_usage_error "value 'abc' is not a number nor true/false"
run $'1.2,-0.1,0.3\n' clip --method aces-rgc --param power
expect_usage_error "'power' is not of the form name=value"
run $'1.2,-0.1,0.3\n' clip --method aces-rgc --param clip=2
expect_usage_error "parameter clip = 2 must be true or false"
run $'1.2,-0.1,0.3\n' clip --method smits --param alpha=1
expect_usage_error "method smits has no parameter 'alpha'; it takes none"
run $'1.2,-0.1,0.3\n' clip --method oklab --inverse
expect_usage_error "method oklab has no inverse; methods with one: smits-soft, aces-rgc"
run $'1.2,-0.1,0.3\n' clip --method smits-soft --param threshold=1.5
expect_usage_error "parameter threshold = 1.5 must be in [0, "

# aces-rgc in ACEScg, closed forms of the ACES 1.3 curve (LMT.Academy.ReferenceGamutCompress.ctl):
# with the achromatic a = max(r, g, b), each channel's distance d = (a - c)/|a|; d below its
# threshold is untouched; above, d' = t + s x/(1 + x^p)^(1/p), x = (d - t)/s, with
# s = (l - t)/(((1 - t)/(l - t))^-p - 1)^(1/p), so that the limit l maps to 1; c' = a - d' |a|.
# (1, -0.5, 0.2): d = (0, 1.5, 0.8); green (magenta: l 1.264, t 0.803, p 1.2) is compressed,
# blue (yellow threshold 0.880) is not.
ACES_G=$(awk 'BEGIN { l = 1.264; t = 0.803; p = 1.2; d = 1.5
    s = (l - t) / ((((1 - t) / (l - t)) ^ -p - 1) ^ (1 / p)); x = (d - t) / s
    printf "%.17g", 1 - (t + s * x / ((1 + x ^ p) ^ (1 / p))) }')
run $'1,-0.5,0.2\n' clip --method aces-rgc --from acescg --to acescg
expect_close "1,$ACES_G,0.2" 1e-12
# Beyond the limit the curve leaves the colour outside the cube (printed exactly, as OCIO does) ...
expect_rows_where 1 '$2 < 0 && $2 > -0.5' "compressed toward the cube but still outside"
# ... and clip=true adds the final clip.
run $'1,-0.5,0.2\n' clip --method aces-rgc --from acescg --to acescg --param clip=true
expect_close "1,0,0.2" 1e-12
# The limit maps to the face: green at distance 1.264 lands on 0; at the threshold it is untouched.
run $'1,-0.264,1\n1,0.197,0.5\n' clip --method aces-rgc --from acescg --to acescg
expect_close $'1,0,1\n1,0.197,0.5' 1e-12
# The parameters are the curve's: with the magenta limit at 1.5 the colour above lands on 0.
run $'1,-0.5,0.2\n' clip --method aces-rgc --from acescg --to acescg --param limit-magenta=1.5
expect_close "1,0,0.2" 1e-12
# --inverse undoes the forward curve.
run $'1,-0.5,0.2\n0.3,0.9,-0.1\n' clip --method aces-rgc --from acescg --to acescg
cp "$TMP/out" "$TMP/aces_forward"
run "$(tail -n +2 "$TMP/aces_forward")"$'\n' clip --method aces-rgc --inverse --from acescg --to acescg
expect_close $'1,-0.5,0.2\n0.3,0.9,-0.1' 1e-9
# smits-soft: its inverse undoes it too (an in-gamut colour beyond the threshold and an
# out-of-gamut one short of the limit), and a colour inside the threshold does not move.
run $'0.9,0.2,0.05\n1.2,0.1,0\n0.45,0.5,0.55\n' clip --method smits-soft
cp "$TMP/out" "$TMP/soft_forward"
expect_rows_where 3 'inside($1) && inside($2) && inside($3)' "smits-soft inside the cube"
run "$(tail -n +2 "$TMP/soft_forward")"$'\n' clip --method smits-soft --inverse
expect_close $'0.9,0.2,0.05\n1.2,0.1,0\n0.45,0.5,0.55' 1e-9
run $'0.45,0.5,0.55\n' clip --method smits-soft
expect_close "0.45,0.5,0.55" 1e-15

# The ACES spaces by name, and -linear as an alias: AP1 -> AP0 is S-2014-004's published matrix
# (first column 0.6954522414, 0.0447945634, -0.0055258826), both with the ACES white.
for to in aces2065-1 aces2065-1-linear; do
    run $'1,0,0\n' convert --from acescg-linear --to "$to"
    expect_close "0.6954522414,0.0447945634,-0.0055258826" 1e-9
done

# Images: aces-rgc clips by default (a file cannot hold what a display cannot show); clip=false
# keeps the curve's output in an EXR.
oiiotool --pattern constant:color=1,-0.5,0.2 2x2 3 -d float -o "$IMG/aces.exr"
run_image clip --method aces-rgc --from acescg --to acescg "$IMG/aces.exr" "$IMG/aces-clipped.exr"
expect_status 0
expect_pixels "$IMG/aces-clipped.exr" 4 'abs($1 - 1) < 1e-6 && abs($2) < 1e-6 && abs($3 - 0.2) < 1e-6' \
    "aces-rgc image clipped into the cube"
run_image clip --method aces-rgc --from acescg --to acescg --param clip=false "$IMG/aces.exr" "$IMG/aces-raw.exr"
expect_status 0
expect_pixels "$IMG/aces-raw.exr" 4 "abs(\$1 - 1) < 1e-6 && abs(\$2 - ($ACES_G)) < 1e-5 && abs(\$3 - 0.2) < 1e-6" \
    "aces-rgc image with clip=false: the curve's output"
expect_info "$IMG/aces-raw.exr" "--param clip=0"

# ===========================================================================================

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
