#!/usr/bin/env bash
# The contract of `irid lut` and `irid ocio-config`: a clip method (or, with --view, a display
# transform) baked as a .cube, .clf or .spi3d file (-o FILE, the
# format by the extension); exit statuses 0, 1 (the file cannot be written) and 2 (usage: the
# valid values named). Expected files come from closed forms: clamp of a space onto itself is
# the identity, so its nodes are the node inputs. Whether OpenColorIO and ffmpeg read the files
# as irid means them is tests/python/test_lut.py's.
#
#   bash tests/cli/lut_test.sh <path-to-irid>
set -u

if [[ $# -ne 1 ]]; then
    echo "usage: bash $0 <path-to-irid>" >&2
    exit 2
fi
IRID=$1
# shellcheck source=lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

# expect_file_data FILE SKIP WANT: the lines of FILE after the first SKIP are exactly WANT.
expect_file_data() {
    local got
    got=$(tail -n +"$(($2 + 1))" "$1" 2>/dev/null)
    if [[ $STATUS -eq 0 && $got == "$3" ]]; then pass; else fail "$1 data $(show "$3")" "$(outcome), data $(show "$got")"; fi
}

# expect_file_line FILE N TEXT: line N of FILE is TEXT.
expect_file_line() {
    local got
    got=$(sed -n "$2p" "$1" 2>/dev/null)
    if [[ $got == "$3" ]]; then pass; else fail "line $2 of $1: $(show "$3")" "$(show "$got")"; fi
}

IDENTITY_RED_FASTEST=$'0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1'

# .cube: two comment lines (the title, the spaces), LUT_3D_SIZE, then red fastest.
run '' lut --method clamp --from srgb-linear --to srgb-linear --size 2 -o "$TMP/id.cube"
expect_status 0
expect_empty_stdout
expect_file_line "$TMP/id.cube" 3 "LUT_3D_SIZE 2"
expect_file_data "$TMP/id.cube" 3 "$IDENTITY_RED_FASTEST"
if grep -q "^# irid .* lut --method clamp --from srgb-linear --to srgb-linear --size 2" "$TMP/id.cube"; then
    pass
else
    fail "a title naming the version, method and spaces" "$(head -2 "$TMP/id.cube")"
fi

# Another range: LUT_3D_INPUT_RANGE ahead of the size; the nodes at 0 and 4 clamp to 0 and 1.
run '' lut --method clamp --from srgb-linear --to srgb-linear --size 2 --domain 0,4 -o "$TMP/wide.cube"
expect_status 0
expect_file_line "$TMP/wide.cube" 3 "LUT_3D_INPUT_RANGE 0 4"
expect_file_line "$TMP/wide.cube" 4 "LUT_3D_SIZE 2"
expect_file_data "$TMP/wide.cube" 4 "$IDENTITY_RED_FASTEST"

# .spi3d: explicit indices, the comment after the last entry.
run '' lut --method clamp --from srgb-linear --to srgb-linear --size 2 -o "$TMP/id.spi3d"
expect_status 0
expect_file_line "$TMP/id.spi3d" 1 "SPILUT 1.0"
expect_file_line "$TMP/id.spi3d" 3 "2 2 2"
expect_file_line "$TMP/id.spi3d" 5 "1 0 0 1 0 0"
expect_file_line "$TMP/id.spi3d" 11 "1 1 1 1 1 1"

# .clf: the Range and the log2 shaper ahead of the cube, blue fastest.
run '' lut --method clamp --from srgb-linear --to srgb-linear --size 2 --shaper log2 --domain 0,16 -o "$TMP/id.clf"
expect_status 0
if grep -q 'style="linToLog"' "$TMP/id.clf" && grep -q '<Array dim="2 2 2 3">' "$TMP/id.clf"; then
    pass
else
    fail "a linToLog shaper and a 2x2x2 array" "$(show "$(cat "$TMP/id.clf")")"
fi
# The nodes of a log2 shaper over [0, 16] are 0 and 16, clamped to 0 and 1: (0,0,1) second.
if awk '/<Array/ { on = 1; next } on && n < 2 { print; ++n }' "$TMP/id.clf" | tr '\n' ' ' | grep -qx '0 0 0 0 0 1 '; then
    pass
else
    fail "blue fastest: 0 0 0 then 0 0 1" "$(show "$(cat "$TMP/id.clf")")"
fi

# Parameters are named in the file.
run '' lut --method smits-soft --param threshold=0.7 --from rec2020 --to srgb --size 5 -o "$TMP/soft.cube"
expect_status 0
if grep -q "threshold=0.7" "$TMP/soft.cube" && grep -q "input: rec2020; output: srgb" "$TMP/soft.cube"; then
    pass
else
    fail "the parameter and both spaces in the comments" "$(head -3 "$TMP/soft.cube")"
fi

# --- refusals -----------------------------------------------------------------------------
run '' lut --method smits --size 1 -o "$TMP/x.cube"
expect_status 2
expect_stderr_has "2 to 129"
run '' lut --method smits --size 130 -o "$TMP/x.cube"
expect_status 2
run '' lut --method smits -o "$TMP/x.3dl"
expect_status 2
expect_stderr_has ".cube"
run '' lut --method smits
expect_status 2
expect_stderr_has "-o FILE"
run '' lut --method nope -o "$TMP/x.cube"
expect_status 2
expect_stderr_has "smits"
run '' lut --method smits --shaper log2 -o "$TMP/x.cube"
expect_status 2
expect_stderr_has ".clf"
run '' lut --method smits --domain 0,2 -o "$TMP/x.spi3d"
expect_status 2
expect_stderr_has "[0, 1]"
run '' lut --method smits --domain 2,1 -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "min < max"
run '' lut --method smits --domain 0 -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "LO,HI"
# A range float32 readers cannot tell apart (OpenColorIO: "maxInValue is too close to minInValue").
run '' lut --method smits --shaper log2 --domain 0,1e-10 -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "max - min must be at least"
run '' lut --method smits --stops 8 -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "--shaper log2"
run '' lut --method smits --from lab -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "RGB space or xyz"
if [[ ! -e $TMP/x.cube && ! -e $TMP/x.clf && ! -e $TMP/x.spi3d ]]; then
    pass
else
    fail "no file after a refusal" "$(ls "$TMP")"
fi

# A directory is never replaced; a missing folder is named.
mkdir -p "$TMP/dir.cube"
run '' lut --method smits -o "$TMP/dir.cube"
expect_status 1
[[ -d $TMP/dir.cube ]] && pass || fail "the directory kept" "it is gone"
run '' lut --method smits -o "$TMP/missing/x.cube"
expect_status 1
expect_stderr_has "missing"

# --- irid lut --view: a display transform baked ---------------------------------------------
run '' lut --view aces2 --display sdr-100nit-rec709 --size 5 -o "$TMP/aces2.clf"
expect_status 0
expect_empty_stdout
# The defaults: from aces2065-1 to the display's encoding, a log2 shaper up to the forward limit
# (8 × 128 at 100 cd/m², ACES 2.0).
grep -q -- "--from aces2065-1 --to srgb --size 5; domain log2 shaper over \[0, 1024\]" "$TMP/aces2.clf" &&
    pass || fail "the title names the defaults" "$(head -3 "$TMP/aces2.clf")"
run '' lut --view aces2 --display hdr-1000nit-p3-d65 --size 3 -o "$TMP/hdr.clf"
expect_status 0
grep -q -- "--to p3-d65-pq --size 3; domain log2 shaper over \[0, 4096\]" "$TMP/hdr.clf" &&
    pass || fail "an HDR display's PQ encoding and limit" "$(head -3 "$TMP/hdr.clf")"
# --stops and --domain override parts of the default domain, the log2 shaper staying.
run '' lut --view aces2 --display sdr-100nit-rec709 --stops 20 --size 3 -o "$TMP/stops.clf"
expect_status 0
grep -q -- "domain log2 shaper over \[0, 1024\], 20 stops" "$TMP/stops.clf" &&
    pass || fail "--stops with the default range" "$(head -3 "$TMP/stops.clf")"
run '' lut --view aces2 --display sdr-100nit-rec709 --domain 0,64 --size 3 -o "$TMP/dom.clf"
expect_status 0
grep -q -- "domain log2 shaper over \[0, 64\], 16 stops in acescg-linear" "$TMP/dom.clf" &&
    pass || fail "--domain with the default stops, the cube still in AP1" "$(head -3 "$TMP/dom.clf")"
# Issue 37: the LUT's source must be light or RGB code values. Lab, Luv, Oklab and their LCh
# forms (and xyY) are refused, naming the source and what is allowed; XYZ is light.
for space in lab luv lchab oklab oklch xyy; do
    run '' lut --view aces2 --display sdr-100nit-rec709 --from "$space" --size 3 -o "$TMP/x.clf"
    expect_status 2
    expect_stderr_has "--from $space"
    expect_stderr_has "aces2065-1 or acescct"
done
run '' lut --view aces2 --display sdr-100nit-rec709 --from xyz --size 3 -o "$TMP/xyz.clf"
expect_status 0
grep -q -- "<Matrix" "$TMP/xyz.clf" && pass || fail "an XYZ .clf takes its matrix to AP1" "$(head -12 "$TMP/xyz.clf")"
run '' lut --view aces2 --display sdr-100nit-rec709 --from acescct --stops 20 -o "$TMP/x.cube"
expect_status 2
expect_stderr_has "--stops applies to --shaper log2"
run '' lut --view aces2 --display sdr-100nit-rec709 --method clamp -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "no --method, --param or --inverse"
run '' lut --view aces2 --display sdr-100nit-rec709 --inverse -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "--inverse"
run '' lut --view aces2 -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "--display"
run '' lut --view aces2 --display sdr-100nit-rec709 --white D50 -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "--white and --adaptation apply to --method"
run '' lut --view aces2 --display sdr-100nit-rec709 --adaptation none -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "--white and --adaptation apply to --method"
run '' lut --view aces3 --display sdr-100nit-rec709 -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "aces2"
run '' lut --view aces2 --display nope -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "sdr-100nit-rec709"
run '' lut --view aces2 --display sdr-100nit-p3-d60-in-xyz-e -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "--to"
# A .cube has no shaper: over linear ACES2065-1 it is refused, saying what to write instead;
# over ACEScct code values it is uniform over [0, 1] (no LUT_3D_INPUT_RANGE).
run '' lut --view aces2 --display sdr-100nit-rec709 -o "$TMP/x.cube"
expect_status 2
expect_stderr_has "acescct"
expect_stderr_has ".clf"
run '' lut --view aces2 --display sdr-100nit-rec709 --from srgb -o "$TMP/x.cube"
expect_status 2
expect_stderr_has "acescct"
run '' lut --view aces2 --display sdr-100nit-rec709 --from acescct --size 3 -o "$TMP/cct.cube"
expect_status 0
expect_file_line "$TMP/cct.cube" 3 "LUT_3D_SIZE 3"
grep -q "^# input: acescct; output: srgb" "$TMP/cct.cube" && pass || fail "the .cube names its spaces" "$(head -3 "$TMP/cct.cube")"
run '' lut --display sdr-100nit-rec709 --method clamp -o "$TMP/x.clf"
expect_status 2
expect_stderr_has "--display applies to --view"
[[ ! -e $TMP/x.clf && ! -e $TMP/x.cube ]] && pass || fail "nothing written after a refusal" "$(ls "$TMP")"

# --- irid ocio-config ----------------------------------------------------------------------
run '' ocio-config --methods smits,aces-rgc --size 5 -o "$TMP/cfg"
expect_status 0
expect_stdout_has "2 looks"
[[ -f $TMP/cfg/config.ocio && -f $TMP/cfg/luts/irid-smits.clf && -f $TMP/cfg/luts/irid-aces-rgc.clf ]] &&
    pass || fail "config.ocio and two LUTs" "$(ls -R "$TMP/cfg" 2>&1)"
grep -q "looks: irid-aces-rgc" "$TMP/cfg/config.ocio" && pass || fail "a view with the look" "$(cat "$TMP/cfg/config.ocio")"
# By default the ACES 2.0 displays encoded in sRGB are views, each through its baked LUT.
expect_stdout_has "2 ACES 2.0 views"
grep -q "name: ACES 2.0 sdr-100nit-rec709, colorspace: aces2-sdr-100nit-rec709" "$TMP/cfg/config.ocio" &&
    [[ -f $TMP/cfg/luts/aces2-sdr-100nit-rec709.clf ]] && pass ||
    fail "the ACES 2.0 view and its LUT" "$(ls -R "$TMP/cfg" 2>&1)"
run '' ocio-config --methods clamp --size 5 --aces2 none -o "$TMP/noaces"
expect_status 0
expect_stdout_has "0 ACES 2.0 views"
# Into the folder of an earlier config: the folder then holds this config alone (the earlier
# config's LUTs under irid's names removed, and said so), and other files stay.
printf 'mine\n' >"$TMP/cfg/luts/notes.txt"
run '' ocio-config --methods clamp --size 5 --aces2 none -o "$TMP/cfg"
expect_status 0
expect_stdout_has "removed 4 LUTs of an earlier config"
[[ "$(ls "$TMP/cfg/luts" | tr '\n' ' ')" == "irid-clamp.clf notes.txt " ]] && pass ||
    fail "only this config's LUT and the user's file remain" "$(ls "$TMP/cfg/luts")"
# A symbolic link to a folder that does not exist is named as one (not "File exists").
ln -s "$TMP/missing-folder" "$TMP/dangling"
run '' ocio-config --methods clamp --size 5 -o "$TMP/dangling"
expect_status 1
expect_stderr_has "is a symbolic link to"
expect_stderr_has "which does not exist"
# The range's rule, stated in full: within ±1e5, and an interval at most 4096 wide in the
# display's linear space (ACEScg on sRGB: ±849 passes, ±850 does not).
run '' ocio-config --methods clamp --size 5 --aces2 none --range=-849,849 -o "$TMP/range"
expect_status 0
run '' ocio-config --methods clamp --size 5 --aces2 none --range=-850,850 -o "$TMP/range"
expect_status 2
expect_stderr_has "at most 4096 wide"
run '' ocio-config --help
expect_stdout_has "interval at most 4096 wide"
run '' ocio-config --aces2 sdr-100nit-rec709,nope -o "$TMP/cfg2"
expect_status 2
expect_stderr_has "nope"
run '' ocio-config --aces2 sdr-100nit-rec709,sdr-100nit-rec709 -o "$TMP/cfg2"
expect_status 2
expect_stderr_has "named twice"
# Issue 37: an HDR display on an SDR display space is refused, naming its own encoding.
run '' ocio-config --to srgb --aces2 hdr-1000nit-p3-d65 --methods clamp --size 5 -o "$TMP/cfg2"
expect_status 2
expect_stderr_has "1000 cd/m²"
expect_stderr_has "p3-d65-pq"
[[ ! -e $TMP/cfg2 ]] && pass || fail "nothing written after the refusal" "$(ls "$TMP/cfg2")"
run '' ocio-config --to p3-d65-pq --aces2 hdr-1000nit-p3-d65 --methods clamp --size 5 -o "$TMP/cfg-pq"
expect_status 0
expect_stdout_has "1 look and 1 ACES 2.0 view on"
# A wider gamut than the display space's is refused too (review of issue 37: P3 on sRGB baked
# codes from -0.51 to 1.09), and the P3 views fit Rec.2100-PQ as OpenColorIO's configs pair them.
run '' ocio-config --to srgb --aces2 sdr-100nit-p3-d65 --methods clamp --size 5 -o "$TMP/cfg2"
expect_status 2
expect_stderr_has "gamut"
expect_stderr_has "display-p3"
[[ ! -e $TMP/cfg2 ]] && pass || fail "nothing written after the refusal" "$(ls "$TMP/cfg2")"
run '' ocio-config --to rec2100-pq --aces2 hdr-1000nit-p3-d65,hdr-1000nit-rec2020 --methods clamp --size 5 -o "$TMP/cfg-2100"
expect_status 0
run '' ocio-config --aces2 custom:peak=100,limiting=rec709 -o "$TMP/cfg2"
expect_status 2
expect_stderr_has "built-in displays"
run '' ocio-config
expect_status 2
expect_stderr_has "-o DIR"
run '' ocio-config --from lab -o "$TMP/cfg2"
expect_status 2
expect_stderr_has "valid RGB spaces"
run '' ocio-config --methods smits,nope -o "$TMP/cfg2"
expect_status 2
expect_stderr_has "nope"
run '' ocio-config --methods smits,smits -o "$TMP/cfg2"
expect_status 2
expect_stderr_has "named twice"
run '' ocio-config --range 4,1 -o "$TMP/cfg2"
expect_status 2
expect_stderr_has "source range"
run '' ocio-config --range x -o "$TMP/cfg2"
expect_status 2
expect_stderr_has "LO,HI"
run '' ocio-config --size 4 -o "$TMP/cfg2"
expect_status 2
expect_stderr_has "--size"
printf x >"$TMP/plain"
run '' ocio-config -o "$TMP/plain"
expect_status 2
expect_stderr_has "not a folder"
[[ ! -e $TMP/cfg2 ]] && pass || fail "no folder after a refusal" "$(ls "$TMP")"
# One space as source and display: scene-linear negatives and values above 1 still need the clip.
run '' ocio-config --from srgb-linear --to srgb-linear --methods clamp --size 5 -o "$TMP/same"
expect_status 0
expect_stdout_has "1 look and"

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
