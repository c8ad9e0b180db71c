#!/usr/bin/env bash
# What a new user and a hostile input hit (issue 10, part 3), checked end to end on the program:
# where outputs go (devices, FIFOs, links, modes, standard output, long names), full disks,
# input limits, CSV headers, standard input that is closed or a folder, escaping of untrusted
# bytes, scene files (duplicate keys, huge numbers, sections of another scene, work limits),
# OBJ and environment paths, and the smaller contract points. Each check failed before its fix.
#
#   bash tests/cli/reliability_test.sh <path-to-irid> <path-to-scenes-dir> <path-to-examples>
#
# Prints one line per failed check and ends with "N passed, M failed"; exits 0 only when every
# check passed. Checks that need root (mknod, mount) are skipped, and say so, without it. A full
# disk is made two ways: a file-size limit (ulimit -f, with SIGXFSZ ignored, so writes fail with
# EFBIG) for anyone, and a 64 KiB tmpfs where mount is allowed.
# shellcheck disable=SC2016  # commands are written in single quotes and run by bash -c
set -u

if [[ $# -ne 3 ]]; then
    echo "usage: bash $0 <path-to-irid> <path-to-scenes-dir> <path-to-examples>" >&2
    exit 2
fi
IRID=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SCENES=$(cd "$2" && pwd) || exit 2
EXAMPLES=$(cd "$3" && pwd) || exit 2
export IRID SCENES EXAMPLES
# shellcheck source=lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
W=$TMP/w
mkdir -p "$W"
export W

# sh_run COMMAND: runs COMMAND with bash in $W (irid is "$IRID"), for at most 120 s (a hang
# fails with status 124); stdout and stderr go to $TMP/out and $TMP/err.
sh_run() {
    RAN=$1
    (cd "$W" && timeout 120 bash -c "$1") >"$TMP/out" 2>"$TMP/err"
    STATUS=$?
}

# check WHAT TEST...: TEST (a command) succeeds.
check() {
    local what=$1
    shift
    if "$@"; then pass; else fail "$what" "not so (after: $RAN)"; fi
}

# expect_stderr_lacks TEXT: a fixed string does not occur on stderr.
expect_stderr_lacks() {
    if grep -qF -- "$1" "$TMP/err"; then fail "stderr without $(show "$1")" "$(outcome)"; else pass; fi
}

is_root() { [[ $(id -u) -eq 0 ]]; }
# A 1 GB address-space limit shows that a huge declared image is refused before it is allocated;
# AddressSanitizer reserves terabytes of address space, so under it the limit is left out.
VMEM='ulimit -v 1000000;'
if ldd "$IRID" 2>/dev/null | grep -q libasan; then VMEM=''; fi
skip() { echo "skipped: $1"; }

FILM='"$IRID" film-table --layer water --thickness 0:100:50'

# === 1. Where outputs go ====================================================================

# A FIFO is written into and stays a FIFO.
mkfifo "$W/fifo"
(timeout 20 cat "$W/fifo" >"$W/from-fifo") &  # bounded: a writer that never opens it must fail
reader=$!
sh_run "$FILM -o fifo"
wait "$reader"
expect_status 0
check "fifo is still a FIFO" test -p "$W/fifo"
check "the reader got the table" grep -q '^thickness_nm,' "$W/from-fifo"

# A symbolic link is followed: the target is replaced, the link stays, the mode is kept.
printf 'old\n' >"$W/real.csv"
chmod 600 "$W/real.csv"
ln -s real.csv "$W/link.csv"
sh_run "$FILM -o link.csv"
expect_status 0
check "link.csv is still a link" test -L "$W/link.csv"
check "real.csv holds the table" grep -q '^thickness_nm,' "$W/real.csv"
check "real.csv keeps mode 600" test "$(stat -c %a "$W/real.csv")" = 600

# Standard output by name: the table reaches the pipe, and >> keeps appending. Named through a
# link of the test's own to /proc/self/fd/1 (what /dev/stdout is), and as /dev/fd/1, which no
# program can replace: a writer that replaced its target would only replace the test's link.
ln -s /proc/self/fd/1 "$W/stdout"
sh_run "$FILM -o stdout | head -1"
expect_output $'thickness_nm,angle_deg,cos_theta,X,Y,Z,R_linear,G_linear,B_linear\n'
sh_run "$FILM -o /dev/fd/1 | head -1"
expect_output $'thickness_nm,angle_deg,cos_theta,X,Y,Z,R_linear,G_linear,B_linear\n'
printf 'first line\n' >"$W/log"
sh_run "$FILM -o stdout >> log"
check "log keeps its first line" test "$(head -1 "$W/log")" = "first line"
check "log gains the table's 4 lines" test "$(wc -l <"$W/log")" -eq 5

# A 250-character name fits beside its temporary file.
long=$(printf 'n%.0s' {1..250}).csv
sh_run "$FILM -o $long"
expect_status 0
check "the 254-byte name was written" test -s "$W/$long"

# Character devices: copies of /dev/null and /dev/full made in the test's folder.
if is_root; then
    mknod "$W/null" c 1 3
    mknod "$W/full" c 1 7
    sh_run "$FILM -o null"
    expect_status 0
    check "null is still a character device" test -c "$W/null"
    sh_run "$FILM -o full"
    expect_status 1
    expect_stderr_has "full: writing failed: No space left on device"
    check "full is still a character device" test -c "$W/full"
    ln -s full "$W/full.png"
    sh_run '"$IRID" render morpho --width 16 --height 12 --spp 1 -q -o full.png'
    expect_status 1
    expect_stderr_has "No space left on device"
    check "full is still a character device" test -c "$W/full"
else
    skip "character devices (mknod needs root)"
fi

# === 2. Full disks: every writer reports failure and leaves the target as it was ==========

# ulimit -f 16: files may grow to 16 KiB; SIGXFSZ ignored, so a write beyond fails (EFBIG).
FULL='trap "" XFSZ; ulimit -f 16;'
printf 'old image\n' >"$W/r.png"
sh_run "$FULL"' "$IRID" render oil-slick --width 200 --height 150 --spp 1 -q -o r.png'
expect_status 1
expect_stderr_has "r.png: writing failed: File too large"
check "r.png is as it was" test "$(cat "$W/r.png")" = "old image"
for ext in tif exr; do
    printf 'old\n' >"$W/r.$ext"
    sh_run "$FULL"' "$IRID" render oil-slick --width 200 --height 150 --spp 1 -q -o r.'"$ext"
    expect_status 1
    expect_stderr_has "r.$ext: writing failed: File too large"
    expect_stderr_lacks "Could not open"
    check "r.$ext is as it was" test "$(cat "$W/r.$ext")" = "old"
done
# With SIGXFSZ at its default (which kills a process), irid ignores it itself: "File too large",
# exit 1, and no temporary file left beside the target.
mkdir -p "$W/xfsz"
sh_run 'cd xfsz && ulimit -f 16; "$IRID" render oil-slick --width 200 --height 150 --spp 1 -q -o r.exr'
expect_status 1
expect_stderr_has "r.exr: writing failed: File too large"
check "no temporary file is left under the default SIGXFSZ" test -z "$(ls -A "$W/xfsz")"
# --linear: the message names the file asked for, never a temporary name. (At 40 × 30 the PNG
# takes about 2 KiB, which fits in 8 KiB, and the EXR about 15 KiB, which does not.)
sh_run 'trap "" XFSZ; ulimit -f 8; "$IRID" render oil-slick --width 40 --height 30 --spp 1 -q -o small.png --linear raw.exr'
expect_status 1
expect_stderr_has "raw.exr: writing failed"
expect_stderr_lacks ".irid-"
expect_stderr_lacks ".tmp-"
check "neither output was left" test ! -e "$W/small.png" -a ! -e "$W/raw.exr"
# Clipping a PNG onto itself on a full disk keeps the input.
"$IRID" render soap-bubbles --width 256 --height 192 --spp 1 -q -o "$W/in.png"  # about 50 KiB
cp "$W/in.png" "$W/in-copy.png"
sh_run "$FULL"' "$IRID" clip --method smits --from srgb --to srgb in.png in.png'
expect_status 1
check "in.png is unchanged" cmp -s "$W/in.png" "$W/in-copy.png"
# The gallery stops at its first failed image and leaves no empty or half-written file.
# every_png_whole DIR: every PNG in DIR reads back whole.
every_png_whole() {
    local f
    for f in "$1"/*.png; do
        [[ -e $f ]] || continue
        oiiotool --info "$f" >/dev/null 2>&1 && oiiotool "$f" -o "$W/reread.exr" >/dev/null 2>&1 || return 1
    done
}
sh_run 'trap "" XFSZ; ulimit -f 1; "$IRID" gallery -o gal --width 64 --height 48 --spp 1 -q'
expect_status 1
check "no empty file in the gallery's folder" test -z "$(find "$W/gal" -type f -empty 2>/dev/null)"
check "no temporary file in the gallery's folder" test -z "$(find "$W/gal" -name '.irid-*' 2>/dev/null)"
check "every PNG in the gallery's folder is whole" every_png_whole "$W/gal"

# A real full file system: a 64 KiB tmpfs.
if is_root && mkdir -p "$W/tiny" && mount -t tmpfs -o size=64k tmpfs "$W/tiny" 2>/dev/null; then
    # Unmounted however the script ends, before its folder is removed.
    trap 'umount "$W/tiny" 2>/dev/null; rm -rf "$TMP"' EXIT
    head -c 60000 /dev/zero >"$W/tiny/filler"
    printf 'keep\n' >"$W/tiny/keep.png"
    sh_run '"$IRID" render oil-slick --width 200 --height 150 --spp 1 -q -o tiny/keep.png'
    expect_status 1
    expect_stderr_has "tiny/keep.png: writing failed: No space left on device"
    check "keep.png is as it was" test "$(cat "$W/tiny/keep.png")" = "keep"
    check "no temporary file on the full disk" test -z "$(find "$W/tiny" -name '.irid-*')"
    sh_run '"$IRID" gallery -o tiny/gal --width 64 --height 48 --spp 1 -q'
    expect_status 1
    expect_stderr_has "No space left on device"
    check "no empty file in the gallery on the full disk" test -z "$(find "$W/tiny/gal" -type f -empty)"
    check "every PNG of the gallery on the full disk is whole" every_png_whole "$W/tiny/gal"
    umount "$W/tiny"
else
    skip "a full tmpfs (mount needs root)"
fi

# Standard output on a full device.
sh_run '"$IRID" figure --list > /dev/full'
expect_status 1
expect_stderr_has "cannot write to standard output"
sh_run 'echo 1,0,0 | "$IRID" convert --from srgb --to lab > /dev/full'
expect_status 1
# The gallery prints its page's path last (the smallest gallery: about 12 s in Release).
sh_run '"$IRID" gallery -o full-gallery --width 32 --height 24 --spp 1 --figure-width 320 -q > /dev/full'
expect_status 1
expect_stderr_has "irid gallery: cannot write to standard output: No space left on device"

# === 3. CSV: headers, standard input, limits, escaping =====================================

run $'0.1,abc,0.3\n' clip --method smits
expect_bad_data 1
expect_stderr_has "<stdin>:1: field 2 'abc' is not a number"
run $'R,G,B\n0.1,0.2,0.3\n' clip --method smits
expect_output $'R,G,B\n0.1,0.2,0.3\n'

# A first line is a header only when it is one (numeric_table.h): a name for each column, each
# beginning with a letter. Numbers with other separators, or one name where three columns are
# read, are data, and an error naming line 1 and what the line may hold; on every command that
# reads CSV (issue 37, item 1).
for args in "display --display sdr-100nit-rec709" "convert --from srgb --to lab" "clip --method smits"; do
    for line in '0.1;0.2;0.3' '0.1 0.2 0.3' 'R;G;B' '#R,G,B' 'X,Y'; do
        # shellcheck disable=SC2086  # the arguments are words
        run "$line"$'\n' $args
        expect_bad_data 1
        expect_stderr_has "or a header of 3 names"
    done
    # shellcheck disable=SC2086
    run $'R,G,B\n0.1,0.2,0.3\n' $args
    expect_status 0
    # A header of two names above rows of three numbers does not name the columns.
    # shellcheck disable=SC2086
    run $'X,Y\n0.1,0.2,0.3\n' $args
    expect_bad_data 1
done
run $'0.1;0.2;0.3;0.4;0.5;0.6\n' delta-e --metric ciede2000
expect_bad_data 1
expect_stderr_has "field 1 '0.1;0.2;0.3;0.4;0.5;0.6' is not a number; line 1 holds 6 numbers separated by commas, or a header of 6 names"
run $'L1,a1,b1,L2,a2,b2\n50,0,0,50,0,0\n' delta-e --metric ciede2000
expect_output $'delta_e\n0\n'
run $'400;0.5\n500;0.5\n' xyz
expect_bad_data 1
expect_stderr_has "at least 2 numbers separated by commas, or a header of at least 2 names"
run $'wavelength_nm,grey\n400,0.5\n700,0.5\n' xyz
expect_status 0
run $'λ,grey\n400,0.5\n700,0.5\n' xyz
expect_status 0

# A folder or a closed standard input is a read error, not empty input.
sh_run '"$IRID" convert --from srgb --to lab < /'
expect_status 1
expect_stderr_has "<stdin>: standard input is a directory"
sh_run '"$IRID" clip --method smits <&-'
expect_status 1
expect_stderr_has "<stdin>: standard input is closed"
# Empty input: every CSV command answers with its header alone, and exit 0.
run "" convert --from srgb --to lab
expect_output $'L,a,b\n'
run "" clip --method smits
expect_output $'R,G,B\n'
run "" delta-e --metric ciede2000
expect_output $'delta_e\n'
run "" xyz
expect_output $'X,Y,Z\n'
run $'400,0.5\n' xyz
expect_bad_data 1

# Endless input stops at the limit.
sh_run '"$IRID" clip --method smits < /dev/zero'
expect_status 1
expect_stderr_has "<stdin>: more than 256 MiB of input"

# Untrusted bytes are escaped and cut short on the terminal.
run $'1,\e[31mred\e[0m,3\n' clip --method smits
expect_status 1
expect_stderr_has "'\\x1b[31mred\\x1b[0m'"
check "no escape byte reached stderr" test "$(grep -c $'\e' "$TMP/err")" -eq 0

# === 4. Images: limits, channels, depth =====================================================

# PNGs that declare 16000² and 100000² pixels in a few hundred bytes.
python3 - "$W" <<'EOF'
import struct, sys, zlib
def png(w, h):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(b"\0" * 64)) + chunk(b"IEND", b""))
open(sys.argv[1] + "/huge.png", "wb").write(png(16000, 16000))
open(sys.argv[1] + "/vast.png", "wb").write(png(100000, 100000))
EOF
sh_run "$VMEM"' "$IRID" clip --method smits --from srgb --to srgb huge.png out.png'
expect_status 1
expect_stderr_has "huge.png: the image declares 16000 x 16000 pixels (256.0 Mpixel); irid reads at most 67108864 pixels (64 Mpixel)"
sh_run '"$IRID" clip --method smits --from srgb --to srgb vast.png out.png'
expect_status 1
expect_stderr_has "vast.png: the image declares 100000 x 100000 pixels"
expect_stderr_lacks "bad_alloc"
sh_run "$VMEM"' "$IRID" render soap-bubbles --width 16 --height 12 --spp 1 -q -o env.png --set light.environment_image="$W/huge.png"'
expect_status 1
expect_stderr_has "huge.png: the image declares 16000 x 16000 pixels"

# An EXR whose channels are X, Y, Z is CIE XYZ: clipped as XYZ, written as R, G, B.
oiiotool --pattern constant:color=0.2,0.1,0.9 4x2 3 --chnames X,Y,Z -d float -o "$W/xyz.exr"
sh_run '"$IRID" clip --method smits --to srgb-linear xyz.exr from-xyz.exr'
expect_status 0
sh_run 'oiiotool --info -v from-xyz.exr | grep "channel list"'
expect_stdout_has "R, G, B"
printf '0.2,0.1,0.9\n' >"$W/xyz.csv"
sh_run '"$IRID" clip --method smits --from xyz --to srgb-linear < xyz.csv | tail -1'
want=$(cat "$TMP/out")
sh_run 'oiiotool from-xyz.exr --cut 1x1+0+0 --printstats 2>/dev/null | grep -o "Avg: .*" | head -1'
check "the XYZ EXR gives the CSV's colour ($want)" python3 - "$want" "$(cat "$TMP/out")" <<'EOF'
import sys
want = [float(v) for v in sys.argv[1].split(",")]
got = [float(v) for v in sys.argv[2].split()[1:4]]
sys.exit(0 if all(abs(a - b) < 1e-6 for a, b in zip(want, got)) and len(got) == 3 else 1)
EOF
sh_run '"$IRID" clip --method smits --from srgb-linear --to srgb xyz.exr out.exr'
expect_status 2
expect_stderr_has "holds X, Y and Z channels (CIE XYZ) but --from is srgb-linear"

# A 16-bit PNG stays 16-bit unless --bits says otherwise.
oiiotool --pattern fill:top=0.1,0.2,0.3:bottom=0.9,0.5,0.1 8x8 3 -d uint16 -o "$W/deep.png"
sh_run '"$IRID" clip --method smits --from srgb --to srgb deep.png deep-out.png && oiiotool --info deep-out.png'
expect_stdout_has "uint16"
sh_run '"$IRID" clip --method smits --from srgb --to srgb --bits 8 deep.png eight.png && oiiotool --info eight.png'
expect_stdout_has "uint8"

# A FIFO is not read as an image (nobody writes to it: reading would block forever).
mkfifo "$W/in-fifo.png"
sh_run '"$IRID" clip --method smits in-fifo.png out.png'
expect_status 1
expect_stderr_has "in-fifo.png: is not a regular file (a FIFO)"

# === 5. Scene files and the files they name ==================================================

printf '{"scene": "oil-slick", "oil": {"k1": 1, "k1": 2}}\n' >"$W/dup.json"
sh_run '"$IRID" render dup.json -q -o dup.png'
expect_status 1
expect_stderr_has "dup.json: the key 'oil.k1' is given twice, at line 1, column 32 and at line 1, column 41"
printf '{"scene": "oil-slick",\n "oil": {"k1": 1e999}}\n' >"$W/big.json"
sh_run '"$IRID" render big.json -q -o big.png'
expect_status 1
expect_stderr_has "big.json: the number '1e999' at line 2, column 16 is beyond the range of a double"
sh_run '"$IRID" render oil-slick --set morpho.periods=5 -q -o x.png'
expect_status 2
expect_stderr_has "'morpho' is a section of the morpho scene; this scene is oil-slick"
# In-range values that together would run for minutes before the first ray.
sh_run '"$IRID" render morpho --set render.optics=exact --set morpho.periods=100 --set morpho.blend_samples=201 --width 8 --height 6 -q -o m.png'
expect_status 2
expect_stderr_has "ask for 1.71e+09 layer evaluations"
check "nothing was written" test ! -e "$W/m.png"

# A mesh path that names another file quotes a short token of it, escaped, never its line.
printf 'secret-password-line-abcdefghijklmnopqrstuvwxyz-0123456789\n' >"$W/secret"
sh_run '"$IRID" render morpho --set morpho.wing_mesh="$W/secret" --width 8 --height 6 -q -o m.png'
expect_status 1
expect_stderr_lacks "0123456789"
# A 10 MB bad token is not printed whole.
python3 -c 'import sys; sys.stdout.write("v 0 0 " + "7" * 10000000 + "x\n")' >"$W/long.obj"
sh_run '"$IRID" render morpho --set morpho.wing_mesh="$W/long.obj" --width 8 --height 6 -q -o m.png'
expect_status 1
check "the message is short" test "$(wc -c <"$TMP/err")" -lt 400
# An empty OBJ is named as empty, not at a line 0; a FIFO fails at once instead of blocking.
: >"$W/empty.obj"
sh_run '"$IRID" render morpho --set morpho.wing_mesh="$W/empty.obj" --width 8 --height 6 -q -o m.png'
expect_stderr_has "empty.obj: the file is empty"
expect_stderr_lacks ":0:"
mkfifo "$W/mesh-fifo.obj"
sh_run 'timeout 10 "$IRID" render morpho --set morpho.wing_mesh="$W/mesh-fifo.obj" --width 8 --height 6 -q -o m.png'
expect_status 1
expect_stderr_has "mesh-fifo.obj: is not a regular file (a FIFO)"

# === 6. The smaller points ====================================================================

sh_run '"$IRID" gallery -o ""'
expect_status 2
sh_run '"$IRID" render oil-slick --width abc'
expect_status 2
expect_stderr_has "'abc' is not a whole number; allowed: 1 to 16384"
expect_stderr_has "Usage: irid render"
# --width alone keeps the scene's aspect ratio (oil-slick is 1024 × 768).
sh_run '"$IRID" render oil-slick --width 64 --spp 1 -q -o aspect.png && oiiotool --info aspect.png'
expect_stdout_has "64 x   48"
sh_run '"$IRID" render oil-slick --height 30 --spp 1 -q -o aspect2.png && oiiotool --info aspect2.png'
expect_stdout_has "40 x   30"
# A conversion between two forms of one space is exact.
run $'0.5,0.25,0.1\n' convert --from srgb --to srgb
expect_output $'R,G,B\n0.5,0.25,0.1\n'
run $'0.5,0.25,0.1\n' convert --from lab --to lab
expect_output $'L,a,b\n0.5,0.25,0.1\n'
# The render summary counts the colour tables apart from the rays.
sh_run '"$IRID" render morpho --set render.optics=exact --set morpho.periods=2 --set morpho.blend_samples=2 --width 16 --height 12 --spp 1 -o m.png'
expect_status 0
expect_stderr_has "s building colour tables"
check "the ray rate is not printed as 0.00" grep -Eq 'tracing [1-9][0-9.e+-]* M rays/s|tracing 0\.0*[1-9]' "$TMP/err"
# Illuminant C: a white point, not a spectrum; the message says so.
run $'400,0.5\n700,0.5\n' xyz --illuminant C
expect_status 2
expect_stderr_has "illuminant C has no spectral table in irid; it is available as a white point"

# === 7. The README's sample files ship and its commands run =================================

sh_run '"$IRID" xyz --illuminant A --observer cie1964 < "$EXAMPLES/spectra.csv"'
expect_status 0
expect_stdout_has "X,Y,Z"
sh_run '"$IRID" delta-e --metric ciede2000 < "$EXAMPLES/pairs.csv"'
expect_status 0
sh_run '"$IRID" clip --method css --from srgb-linear --to srgb "$EXAMPLES/in.exr" out.png'
expect_status 0
sh_run '"$IRID" clip --method smits < "$EXAMPLES/colours.csv"'
expect_status 0
# The tagged photo: its space from its ICC profile, without a note that sRGB was assumed.
sh_run '"$IRID" clip --method oklab-cusp --to srgb "$EXAMPLES/p3-sweep.png" photo-srgb.png'
expect_status 0
expect_stderr_lacks "no ICC profile"

echo "$passed passed, $failed failed"
((failed == 0))
