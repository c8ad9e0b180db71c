#!/usr/bin/env bash
# The contract of `irid display`: scene colours (CSV on stdin) through the ACES 2.0 display
# transform to CIE XYZ (1.0 = 100 cd/m²) or an RGB space, and back with --inverse; --list; exit
# statuses 0, 1 (bad data, with <stdin>:LINE) and 2 (usage, the valid values named). Expected
# values are OpenColorIO's published outputs (data/ocio-aces2/builtin_displays_20.csv) and
# consistency with `irid convert`.
#
#   bash tests/cli/display_test.sh <path-to-irid>
set -u

if [[ $# -ne 1 ]]; then
    echo "usage: bash $0 <path-to-irid>" >&2
    exit 2
fi
IRID=$1
# shellcheck source=lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

# --- OpenColorIO's published outputs (BuiltinTransform_tests.cpp, tolerance 1e-4) -------------
run $'0.5,0.4,0.3\n' display --view aces2 --display hdr-1000nit-p3-d65
expect_close "0.46536559,0.43852845,0.33688101" 1e-4
expect_stdout_has "X,Y,Z"
run $'0.5,0.4,0.3\n' display --view aces2 --display sdr-100nit-rec709 --to xyz
expect_close "0.26260215,0.25207460,0.20617345" 1e-4
run $'0.5,0.4,0.3\n' display --view ACES2 --display sdr-100nit-rec709 --to xyz   # a view's name in any case
expect_close "0.26260215,0.25207460,0.20617345" 1e-4
run $'0.5,0.4,0.3\n' display --display 'ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-100nit-REC709-D60-in-REC709-D65_2.0'
expect_close "0.25147712,0.24029461,0.18221153" 1e-4
run $'0.5,0.4,0.3\n' display --display hdr-108nit-p3-d65
expect_close "0.16253395,0.15513620,0.12449738" 1e-4

# --- --inverse returns the scene values -------------------------------------------------------
run $'0.46536559,0.43852845,0.33688101\n' display --display hdr-1000nit-p3-d65 --inverse
expect_close "0.5,0.4,0.3" 1e-5
run $'0.26260215,0.25207460,0.20617345\n' display --display sdr-100nit-rec709 --inverse --to aces2065-1
expect_close "0.5,0.4,0.3" 1e-5

# --- --inverse notes the display colours without a scene value ----------------------------------
# Rec.2020's blue at 36 cd/m² on a 4000 cd/m² display: its ACES source lies beyond AP1, which the
# chain clamps (docs/DISPLAY.md, "The inverse"); mid grey has one.
run $'0.2,0.2,0.2\n0,0,0.36\n' display --display hdr-4000nit-rec2020 --inverse --from rec2020-linear
expect_status 0
expect_stderr_has "1 of 2 display colours (stdin line 2) has no scene value"
run $'0.2,0.2,0.2\n' display --display hdr-4000nit-rec2020 --inverse --from rec2020-linear
expect_status 0
expect_stderr_lacks "scene value"

# --- 18 % grey: neutral at 10 cd/m² on a 100 cd/m² display (aces-docs) ------------------------
run $'0.18,0.18,0.18\n' display --display sdr-100nit-rec709 --to srgb-linear
expect_close "0.1,0.1,0.1" 1e-4

# --- --to SPACE and --from SPACE agree with irid convert --------------------------------------
printf '0.5,0.4,0.3\n0.02,0.9,1.7\n' >"$TMP/scene"
"$IRID" display --display sdr-100nit-p3-d65 <"$TMP/scene" | tail -n +2 >"$TMP/xyz"
"$IRID" convert --from xyz --to display-p3 <"$TMP/xyz" | tail -n +2 >"$TMP/want"
run_file "$TMP/scene" display --display sdr-100nit-p3-d65 --to display-p3
tail -n +2 "$TMP/out" >"$TMP/got"
verdict=$(compare_csv "$TMP/want" "$TMP/got" 1e-12)
if [[ $STATUS -eq 0 && -z $verdict ]]; then pass; else fail "--to display-p3 as convert" "$(outcome) $verdict"; fi

"$IRID" convert --from aces2065-1-linear --to acescg-linear <"$TMP/scene" | tail -n +2 >"$TMP/cg"
run_file "$TMP/cg" display --display hdr-1000nit-rec2020 --from acescg-linear
tail -n +2 "$TMP/out" >"$TMP/got"
"$IRID" display --display hdr-1000nit-rec2020 <"$TMP/scene" | tail -n +2 >"$TMP/want"
verdict=$(compare_csv "$TMP/want" "$TMP/got" 1e-9)
if [[ $STATUS -eq 0 && -z $verdict ]]; then pass; else fail "--from acescg-linear as aces2065-1" "$(outcome) $verdict"; fi

# --- --list ------------------------------------------------------------------------------------
run '' display --list
expect_status 0
lines=$(wc -l <"$TMP/out")
if [[ $lines -eq 32 ]]; then pass; else fail "header and 31 displays" "$lines lines"; fi
expect_stdout_has "display,peak_nits,limiting_primaries,limiting_white,encoding_primaries,encoding_white,linear_scale"
expect_stdout_has "hdr-108nit-p3-d65,108,0.68 0.32 0.265 0.69 0.15 0.06,0.3127 0.329,"
expect_stdout_has "sdr-100nit-p3-d60-in-xyz-e,100,0.68 0.32 0.265 0.69 0.15 0.06,0.32168 0.33767,CIE XYZ,E,1"

expect_stdout_has ",linear_scale,file_encoding"
expect_stdout_has ",1,srgb"
expect_stdout_has "hdr-1000nit-rec2020,1000,"
expect_stdout_has ",1,rec2100-pq"
expect_stdout_has ",0.48,p3-d65-pq"
expect_stdout_has ",CIE XYZ,E,1,none"

# --- the display encodings are spaces of irid convert: PQ of 100 cd/m² (linear 1) is 0.50808 ----
run $'1,1,1\n0,0,0\n100,100,100\n' convert --from rec2100-pq-linear --to rec2100-pq
expect_status 0
expect_stdout_has "0.50807"
expect_stdout_has $'\n1,1,1'
run $'0.5,0.5,0.5\n' convert --from rec1886 --to rec1886-linear
expect_close "0.18946457081379978,0.18946457081379978,0.18946457081379978" 1e-12

# --- rec2100-hlg (issue 37, item 7): BT.2100 HLG on a 1000 cd/m² display; the HDR reference white
# 203 cd/m² is a 75 % signal (ITU-R BT.2408), 1000 cd/m² is 1 ----------------------------------------
run $'2.03,2.03,2.03\n10,10,10\n' convert --from rec2100-hlg-linear --to rec2100-hlg
expect_close $'0.75,0.75,0.75\n1,1,1' 1e-3
run $'0.5,0.5,0.5\n' convert --from REC2100-HLG --to rec2100-hlg-linear
expect_close "0.50697028,0.50697028,0.50697028" 1e-7   # 1000 (1/12)^1.2 cd/m²
run $'0.5,0.4,0.3\n' display --display hdr-1000nit-rec2020 --to rec2100-hlg
expect_status 0

# --- a custom display: the built-in one it repeats ------------------------------------------------
run $'0.5,0.4,0.3\n' display --display custom:peak=1000,limiting=display-p3
expect_status 0
custom=$(cat "$TMP/out")
run $'0.5,0.4,0.3\n' display --display hdr-1000nit-p3-d65
if [[ "$(cat "$TMP/out")" == "$custom" ]]; then pass; else fail "custom display equals its built-in" "$custom"; fi
# Every form of the white the message names works, x,y included (issue 37, item 4), and the XYZ
# displays have custom twins that say whether they scale the white (item 5).
run $'0.5,0.4,0.3\n' display --display sdr-100nit-rec709-d60-in-rec2020-d65
slurp builtin "$TMP/out"
for white in aces 0.32168,0.33767 0.32168:0.33767; do
    run $'0.5,0.4,0.3\n' display --display "custom:peak=100,limiting=srgb,white=$white,encoding=rec2020"
    expect_output "$builtin"
done
run $'0.5,0.4,0.3\n' display --display sdr-100nit-p3-d60-in-xyz-e
slurp builtin "$TMP/out"
run $'0.5,0.4,0.3\n' display --display custom:peak=100,limiting=p3-d65,white=aces,encoding=xyz,scale-white=no
expect_output "$builtin"
run $'0.5,0.4,0.3\n' display --display hdr-300nit-p3-d60-in-xyz-e
slurp builtin "$TMP/out"
run $'0.5,0.4,0.3\n' display --display custom:peak=625,limiting=p3-d65,white=aces,encoding=xyz,linear-scale=0.48
expect_output "$builtin"
run $'0.5,0.4,0.3\n' display --display custom:peak=100,limiting=srgb,white=blue
expect_status 2
expect_stderr_has "white=0.3127,0.329"
run $'0.5,0.4,0.3\n' display --display custom:peak=50,limiting=srgb
expect_status 2
expect_stderr_has "100 to 10000"
run $'0.5,0.4,0.3\n' display --display custom:peak=500,limiting=nonsense
expect_status 2
expect_stderr_has "rec2100-pq"
run $'0.5,0.4,0.3\n' display --display sdr-100nit-rec709 --bits 16
expect_status 2
expect_stderr_has "--bits"

# --- an image OpenImageIO reads but irid does not write (.hdr) is read as any other -----------
if command -v oiiotool >/dev/null; then
    oiiotool --pattern constant:color=0.18,0.18,0.18 4x2 3 -d float -o "$TMP/grey.hdr" 2>/dev/null
    "$IRID" display --display sdr-100nit-rec709 "$TMP/grey.hdr" "$TMP/grey.png" </dev/null >"$TMP/out" 2>"$TMP/err"
    STATUS=$?
    RAN="irid display --display sdr-100nit-rec709 grey.hdr grey.png"
    expect_status 0
    # 18 % grey is shown at 10 cd/m² on the 100 cd/m² display: sRGB 0.349, code 89.
    code=$(oiiotool --dumpdata "$TMP/grey.png" 2>/dev/null | awk '/Pixel \(0, 0\)/ { print $4 }')
    if [[ "$code" == "89" || "$code" == "89.0" ]]; then pass; else fail "the grey's code 89" "${code:-nothing}"; fi
else
    fail "oiiotool (openimageio-tools) for the .hdr check" "not found"
fi

# --- usage errors (2) and bad data (1) ---------------------------------------------------------
run $'1,1,1\n' display --display hdr-9000nit-p3
expect_status 2
expect_stderr_has "sdr-100nit-rec709"
expect_empty_stdout
run $'1,1,1\n' display
expect_status 2
expect_stderr_has "--display"
run $'1,1,1\n' display --view aces1 --display sdr-100nit-rec709
expect_status 2
expect_stderr_has "aces2"
run $'1,1,1\n' display --display sdr-100nit-rec709 --to lab
expect_status 2
expect_stderr_has "'lab' is not a display space"
run $'1,1,1\n' display --display custom:peak=100
expect_status 2
expect_stderr_has "has no limiting="
run $'1,1,1\n' display --display sdr-100nit-rec709 --inverse --from oklab
expect_status 2
run $'1,1,1\n' display --display sdr-100nit-rec709 --to nonsense
expect_status 2
run $'0.1,0.2,0.3\n1,nan,2\n' display --display sdr-100nit-rec709
expect_bad_data 2

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
