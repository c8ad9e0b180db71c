#!/usr/bin/env bash
# The command-line contract of irid: CSV in on stdin, CSV out on stdout, exit statuses 0
# (success), 1 (bad data, "<stdin>:LINE: ..." on stderr, nothing on stdout) and 2 (usage).
#
#   bash tests/cli/cli_test.sh <path-to-irid> <path-to-data-dir>
#
# Prints one line per failed check (what was run, what was expected, what came out) and ends
# with "N passed, M failed"; exits 0 only when every check passed. Every expected value comes
# from a published table or a closed form, never from the program's own output.
# shellcheck disable=SC2016  # awk conditions on $1, $2, $3 are passed in single quotes
set -u

if [[ $# -ne 2 ]]; then
    echo "usage: bash $0 <path-to-irid> <path-to-data-dir>" >&2
    exit 2
fi
IRID=$1
# shellcheck source=lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
DATA=$2

# --- running the program ------------------------------------------------------------------

# --- reporting ----------------------------------------------------------------------------

# --- checks on the last run ---------------------------------------------------------------

# expect_header TEXT: the first line of stdout is TEXT.
expect_header() {
    local first=
    IFS= read -r first <"$TMP/out"
    if [[ $first == "$1" ]]; then pass; else fail "first line $(show "$1")" "$(outcome)"; fi
}

# expect_chromaticity X Y TOL: status 0 and the chromaticity x = X/(X+Y+Z), y = Y/(X+Y+Z) of
# the single XYZ line after stdout's header is within TOL of (X, Y).
expect_chromaticity() {
    local verdict
    printf '%s,%s\n' "$1" "$2" >"$TMP/want"
    awk -F, 'NR > 1 { s = $1 + $2 + $3; printf "%.17g,%.17g\n", (s ? $1 / s : 0), (s ? $2 / s : 0) }' \
        "$TMP/out" >"$TMP/data"
    verdict=$(compare_csv "$TMP/want" "$TMP/data" "$3")
    if [[ $STATUS -eq 0 && -z $verdict ]]; then
        pass
    else
        fail "chromaticity x,y = $1,$2 within $3" "$(outcome)${verdict:+ ($verdict)}"
    fi
}

# expect_first_row_where CONDITION WHAT: status 0 and the awk CONDITION (on $1, $2, $3, with
# abs()) holds for the first line after stdout's header; WHAT describes it for the message.
# CONDITION is pasted into the awk program, so its $1, $2, $3 are awk's fields.
expect_first_row_where() {
    if [[ $STATUS -eq 0 ]] && awk -F, "function abs(x) { return x < 0 ? -x : x }
            NR == 2 { found = 1; ok = ($1) } END { exit !(found && ok) }" "$TMP/out"; then
        pass
    else
        fail "$2" "$(outcome)"
    fi
}

# expect_usage_error TEXT: exit status 2, TEXT on stderr, nothing on stdout.
expect_usage_error() {
    expect_status 2
    expect_stderr_has "$1"
    expect_empty_stdout
}

# --- reference values ---------------------------------------------------------------------

# The D65 white of XYZ with Y = 1 from its chromaticity x = 0.3127, y = 0.3290:
# X = x / y, Z = (1 - x - y) / y.
D65_XYZ=$(awk 'BEGIN { x = 0.3127; y = 0.3290; printf "%.17g,1,%.17g", x / y, (1 - x - y) / y }')
# The same for D50 (x = 0.3457, y = 0.3585).
D50_XYZ=$(awk 'BEGIN { x = 0.3457; y = 0.3585; printf "%.17g,1,%.17g", x / y, (1 - x - y) / y }')

# === 1. delta-e ciede2000: the 34 pairs of Sharma, Wu and Dalal (2005) ===================

SHARMA=$DATA/sharma2005_ciede2000_pairs.csv
cut -d, -f1-6 "$SHARMA" >"$TMP/sharma_pairs"                # header line kept
tail -n +2 "$SHARMA" | cut -d, -f7 >"$TMP/sharma_delta_e"   # the published ΔE00
RAN="reading $SHARMA"
if [[ $(wc -l <"$TMP/sharma_delta_e") -eq 34 ]]; then pass; else fail "34 published pairs" "$(wc -l <"$TMP/sharma_delta_e") rows"; fi

run_file "$TMP/sharma_pairs" delta-e --metric ciede2000
expect_header "delta_e"
expect_close "$(cat "$TMP/sharma_delta_e")" 1e-4   # one value line per pair: 34

# === 2. delta-e: the Euclidean metrics (3-4-5 triangles) ==================================

run $'50,0,0,53,4,0\n' delta-e --metric cie76
expect_output $'delta_e\n5\n'
run $'50,0,0,53,4,0\n' delta-e --metric cieuv
expect_output $'delta_e\n5\n'
run $'0.5,0,0,0.5,0.3,0.4\n' delta-e --metric oklab
expect_close 0.5 1e-12
# Several lines: one value each, in order.
run $'L1,a1,b1,L2,a2,b2\n50,0,0,53,4,0\n50,0,0,50,0,0\n10,0,0,22,0,-5\n' delta-e --metric cie76
expect_output $'delta_e\n5\n0\n13\n'

# === 3. convert: whites and primaries ======================================================

# sRGB white is D65 (IEC 61966-2-1).
run $'1,1,1\n' convert --from srgb --to xyz
expect_header "X,Y,Z"
expect_close "$D65_XYZ" 1e-6
# sRGB red primary: the first column of the IEC 61966-2-1 matrix.
run $'1,0,0\n' convert --from srgb --to xyz
expect_close 0.4124,0.2126,0.0193 1e-4
# The reference white has L* = 100, a* = b* = 0; black is 0, 0, 0.
run "$D65_XYZ"$'\n' convert --from xyz --to lab
expect_header "L,a,b"
expect_close 100,0,0 1e-9
run $'0,0,0\n' convert --from xyz --to lab
expect_output $'L,a,b\n0,0,0\n'
# The white is also L = 100, u* = v* = 0 in CIELUV and L = 100, C = 0 in the LCh forms.
run "$D65_XYZ"$'\n' convert --from xyz --to luv
expect_header "L,u,v"
expect_close 100,0,0 1e-9
run "$D65_XYZ"$'\n' convert --from xyz --to lchab
expect_header "L,C,h"
expect_first_row_where 'abs($1 - 100) <= 1e-9 && abs($2) <= 1e-9' "L = 100, C = 0 within 1e-9"
# xyY of the white is its chromaticity.
run "$D65_XYZ"$'\n' convert --from xyz --to xyy
expect_header "x,y,Y"
expect_close 0.3127,0.3290,1 1e-12

# === 4. convert: round trips xyz -> SPACE -> xyz for every space =========================

COLOURS="$D65_XYZ"$'\n0.3,0.25,0.2\n0.05,0.04,0.03\n0.18,0.19,0.2'
printf '%s\n' "$COLOURS" >"$TMP/colours"
SPACES=(xyz xyy luv lab lchuv lchab oklab oklch
        srgb srgb-linear display-p3 display-p3-linear rec2020 rec2020-linear
        adobe-rgb adobe-rgb-linear smpte-c smpte-c-linear ntsc1953 ntsc1953-linear)
for space in "${SPACES[@]}"; do
    run_file "$TMP/colours" convert --from xyz --to "$space"
    if [[ $STATUS -ne 0 ]]; then
        fail "status 0" "$(outcome)"
        continue
    fi
    cp "$TMP/out" "$TMP/there"   # its header line is the next run's (skipped) header
    run_file "$TMP/there" convert --from "$space" --to xyz
    RAN="irid convert --from xyz --to $space < $TMP/colours | $RAN"
    expect_close "$COLOURS" 1e-9
done

# The header of each space as implemented.
for pair in xyz:X,Y,Z xyy:x,y,Y luv:L,u,v lab:L,a,b lchuv:L,C,h lchab:L,C,h oklab:L,a,b \
            oklch:L,C,h srgb:R,G,B srgb-linear:R,G,B display-p3:R,G,B rec2020-linear:R,G,B; do
    run $'0.5,0.5,0.5\n' convert --from xyz --to "${pair%%:*}"
    expect_header "${pair#*:}"
done

# === 5. convert: transfer function, Oklab, reference white, adaptation ====================

# The sRGB decoding ((V + 0.055) / 1.055)^2.4 of V = 0.5.
run $'0.5,0.5,0.5\n' convert --from srgb --to srgb-linear
expect_close 0.21404114048223255,0.21404114048223255,0.21404114048223255 1e-12
# ... and its encoding back (the linear segment below 0.0031308: 12.92 V).
run $'0.21404114048223255,0.001,0\n' convert --from srgb-linear --to srgb
expect_close 0.5,0.01292,0 1e-12
# Oklab of the sRGB white is L = 1, a = b = 0 (Ottosson 2020), up to his published XYZ->LMS
# matrix: it takes the D65 white (x, y = 0.3127, 0.3290) to b = -1.2e-4, not to 0 (CSS Color 4
# recomputes that matrix for this reason), hence 2e-4 rather than 1e-4.
run $'1,1,1\n' convert --from srgb --to oklab
expect_close 1,0,0 2e-4
run $'1,1,1\n' convert --from srgb --to oklch
expect_first_row_where 'abs($1 - 1) <= 2e-4 && abs($2) <= 2e-4' "Oklch L = 1, C = 0 within 2e-4"
# Ottosson's table of XYZ -> Oklab examples (published to 3 decimals).
run $'0.950,1.000,1.089\n1,0,0\n0,1,0\n0,0,1\n' convert --from xyz --to oklab
expect_close $'1.000,0.000,0.000\n0.450,1.236,-0.019\n0.922,-0.671,0.263\n0.153,-1.415,-0.449' 6e-4
# The D65 white is neutral in CIELAB relative to D65 (the default) but not relative to D50.
run $'0.9505,1,1.089\n' convert --from xyz --to lab
expect_close 100,0,0 0.02
run $'0.9505,1,1.089\n' convert --from xyz --to lab --white D50
expect_first_row_where 'abs($1 - 100) <= 1e-9 && (abs($2) > 1 || abs($3) > 1)' \
    "L = 100 and a or b away from 0 (more than 1)"
# RGB whites are adapted to --white: sRGB white becomes the D50 white (Bradford and CAT02 map
# white to white); without adaptation it stays D65's XYZ.
run $'1,1,1\n' convert --from srgb --to xyz --white D50
expect_close "$D50_XYZ" 1e-3
run $'1,1,1\n' convert --from srgb --to xyz --white D50 --adaptation cat02
expect_close "$D50_XYZ" 1e-3
run $'1,1,1\n' convert --from srgb --to xyz --white D50 --adaptation none
expect_close "$D65_XYZ" 1e-6

# === 6. Output formatting and headers of the input ========================================

run $'0.1,0.2,0.3\n' convert --from xyz --to xyz
expect_output $'X,Y,Z\n0.1,0.2,0.3\n'
run $'X,Y,Z\n0.1,0.2,0.3\n' convert --from xyz --to xyz
expect_output $'X,Y,Z\n0.1,0.2,0.3\n'
# Shortest round trip needs all 17 digits here, and prints integers without a fraction.
run $'0.30000000000000004,1e-300,-2\n' convert --from xyz --to xyz
expect_output $'X,Y,Z\n0.30000000000000004,1e-300,-2\n'
# Blank lines are skipped; spaces around fields are allowed.
run $'x,y,Y\n\n0.1, 0.2 ,0.3\n' convert --from xyz --to xyz
expect_output $'X,Y,Z\n0.1,0.2,0.3\n'

# === 7. xyz: reflectance spectra to tristimulus values ====================================

# A perfect white (flat 1 at 380 and 780 nm, held beyond) under D65, CIE 1931 observer: the
# D65 white of CIE 015:2018 (95.047, 100, 108.883) / 100, Y = 1 by definition.
run $'380,1\n780,1\n' xyz
expect_header "X,Y,Z"
expect_close 0.95047,1,1.08883 1e-3,1e-12,1e-3
# The same with a header, explicit defaults, and another spacing of the same flat spectrum.
run $'nm,white\n380,1\n500,1\n555.5,1\n780,1\n' xyz --illuminant D65 --observer cie1931
expect_close 0.95047,1,1.08883 1e-3,1e-12,1e-3
# A flat 0.5 is half of it; two columns give two lines.
run $'380,0.5\n780,0.5\n' xyz
expect_close 0.475235,0.5,0.544415 5e-4,1e-12,5e-4
run $'380,1,0.5\n780,1,0.5\n' xyz
expect_close $'0.95047,1,1.08883\n0.475235,0.5,0.544415' 1e-3,1e-12,1e-3
# Published white chromaticities (CIE 015:2018): A and D50 with the 1931 observer, D65 with
# the 1964 observer.
run $'380,1\n780,1\n' xyz --illuminant A
expect_chromaticity 0.44757 0.40745 2e-4
run $'380,1\n780,1\n' xyz --illuminant D50
expect_chromaticity 0.34567 0.35850 2e-4
run $'380,1\n780,1\n' xyz --illuminant D65 --observer cie1964
expect_chromaticity 0.31382 0.33100 2e-4
run $'380,1\n780,1\n' xyz --illuminant D65
expect_chromaticity 0.31272 0.32903 2e-4

# === 8. Errors =============================================================================

# Usage errors: status 2, the valid names on stderr, nothing on stdout.
run $'1,1,1\n' convert --from srgb --to no-such-space
expect_usage_error "srgb-linear"
run $'1,1,1\n' convert --from no-such-space --to xyz
expect_usage_error "srgb-linear"
run $'1,1,1\n' convert --from xyz --to lab --white no-such-white
expect_usage_error "D65"
run $'1,1,1\n' convert --from srgb --to xyz --white D50 --adaptation no-such-method
expect_usage_error "bradford"
run $'1,1,1\n' convert --to xyz
expect_usage_error "--from"
run $'50,0,0,53,4,0\n' delta-e --metric no-such-metric
expect_usage_error "ciede2000"
run $'50,0,0,53,4,0\n' delta-e
expect_usage_error "--metric"
expect_stderr_has "cieuv"   # a missing option's message lists its valid values too
run $'1,1,1\n' convert --from xyz --to xyz --no-such-option
expect_usage_error "--no-such-option"
run $'380,1\n780,1\n' xyz --illuminant no-such-illuminant
expect_usage_error "D65"
run $'380,1\n780,1\n' xyz --observer no-such-observer
expect_usage_error "cie1964"
run '' no-such-command
expect_usage_error "delta-e"

# Bad data: status 1, the line number on stderr, nothing on stdout (even when earlier lines
# were fine).
run $'0.1,0.2,0.3\n0.4,0.5,0.6\n0.7,0.8\n' convert --from xyz --to lab
expect_bad_data 3
run $'X,Y,Z\n0.1,0.2,0.3\n\n0.4,0.5,0.6,0.7\n' convert --from xyz --to lab   # header and blank count
expect_bad_data 4
run $'0.1,0.2,0.3\n0.4,0.5,0.6\n0.7,abc,0.9\n' convert --from xyz --to lab
expect_bad_data 3
run $'0.1,0.2,0.3\nnan,0.5,0.6\n' convert --from xyz --to lab
expect_bad_data 2
run $'0.1,0.2,0.3\n0.4,inf,0.6\n' convert --from xyz --to lab
expect_bad_data 2
run $'50,0,0,53,4,0\n50,0,0,53,-inf,0\n' delta-e --metric cie76
expect_bad_data 2
run $'50,0,0,53,4,0\n50,0,0,53,4\n' delta-e --metric ciede2000
expect_bad_data 2
run $'380,1\n780,1\n700,1\n' xyz
expect_bad_data 3
run $'nm,r\n380,1\n500,1\n500,1\n780,1\n' xyz
expect_bad_data 4
run $'380,1,1\n500,1\n780,1,1\n' xyz
expect_bad_data 2
# xyY with y = 0 has no XYZ unless it is black; a spectrum too large for XYZ is bad data.
run $'0.3,0.3,0.5\n0.3,0,0.5\n' convert --from xyy --to xyz
expect_bad_data 2
run $'400,1e308\n700,1e308\n' xyz
expect_status 1
expect_empty_stdout
# A first line with an empty field, or starting with a byte-order mark, is still data.
run $'1,,0\n' convert --from xyz --to xyz
expect_bad_data 1
run $'\xEF\xBB\xBF0.1,0.2,0.3\n' convert --from xyz --to xyz
expect_output $'X,Y,Z\n0.1,0.2,0.3\n'
# A first line of number-like fields is data with a typo, not a header to skip silently.
run $'1e400,0,0\n' convert --from xyz --to xyz
expect_bad_data 1
run $'0.1,0.2,0.3\n1e400,0,0\n' convert --from xyz --to xyz
expect_bad_data 2

# NTSC 1953 has illuminant C for white: XYZ relative to the default D65 is adapted to it, so
# its white comes out as D65; relative to its own white (FCC's C, 0.310, 0.316) the primaries
# keep their FCC chromaticities.
run $'1,1,1\n' convert --from ntsc1953-linear --to xyz
expect_close "$D65_XYZ" 1e-12
run $'1,0,0\n0,1,0\n' convert --from ntsc1953-linear --to xyy --white 0.310,0.316
expect_close $'0.67,0.33,0.298911\n0.21,0.71,0.586611' "1e-12,1e-12,1e-3"

# Help and no command.
run '' --help
expect_status 0
expect_stdout_has "convert"
run ''
expect_status 2
expect_empty_stdout

# === 9. Empty input ========================================================================

run '' convert --from xyz --to srgb
expect_output $'R,G,B\n'
run $'X,Y,Z\n' convert --from xyz --to lab
expect_output $'L,a,b\n'
run '' delta-e --metric ciede2000
expect_output $'delta_e\n'

# === 10. --threads: a whole number in [0, 2^20], as Python has it (issue 37, item 6) ========

for args in "clip --method smits" "display --display sdr-100nit-rec709" "lut --method smits -o $TMP/t.cube" \
    "ocio-config -o $TMP/cfg" "render soap-bubbles --width 8 --height 6 --spp 1 -q -o $TMP/t.png" \
    "gallery -o $TMP/gallery -q"; do
    for threads in -1 1048577 two 1.5; do
        # shellcheck disable=SC2086  # the arguments are words
        run '' $args --threads "$threads"
        expect_status 2
        expect_stderr_has "--threads"
        expect_stderr_has "allowed: 0 to 1048576"
    done
done
# The bound itself is a number of threads to ask for (irid uses what the machine has).
run $'0.5,0.5,0.5\n' clip --method smits --threads 1048576
expect_output $'R,G,B\n0.5,0.5,0.5\n'

# === 11. Space names in any case, as display names (issue 37, item 9) =========================

run $'1,1,1\n' convert --from SRGB-Linear --to XYZ
expect_close "$D65_XYZ" 1e-12
run $'1,1,1\n' convert --from srgb-linear --to xyz
slurp lower "$TMP/out"
for args in "convert --from sRGB --to LAB" "convert --from Display-P3 --to OkLCh" "clip --method smits --from SRGB --to Display-P3" \
    "display --display sdr-100nit-rec709 --to SRGB" "display --display custom:peak=1000,limiting=Display-P3,encoding=Rec2100-PQ --to P3-D65-PQ" \
    "display --display hdr-1000nit-p3-d65 --inverse --from P3-D65-PQ --to ACEScg"; do
    lowered=${args,,}
    # shellcheck disable=SC2086  # the arguments are words
    run $'0.5,0.4,0.3\n' $lowered
    slurp want "$TMP/out"
    # shellcheck disable=SC2086
    run $'0.5,0.4,0.3\n' $args
    expect_output "$want"
done
run "" film --layer water:300 --color --rgb Display-P3
expect_status 0
expect_stdout_has "R_linear"
run '' lut --method smits --from ACEScg-Linear --to SRGB --size 5 -o "$TMP/case.cube"
expect_status 0
run '' ocio-config --from ACEScg-Linear --to SRGB --methods clamp --size 5 --aces2 none -o "$TMP/case-cfg"
expect_status 0
# An unknown name still lists the canonical names.
run $'1,1,1\n' convert --from SRGBX --to xyz
expect_status 2
expect_stderr_has "srgb, srgb-linear"

# ===========================================================================================

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
