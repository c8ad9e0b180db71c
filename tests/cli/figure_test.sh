#!/usr/bin/env bash
# The contract of `irid figure`: every figure of the catalog writes a valid PNG of exactly the
# requested size and a valid SVG (tables: Markdown and HTML); success prints nothing on stdout
# unless --caption is given; usage errors exit 2 naming what is allowed, I/O failures exit 1;
# nothing is left behind on failure.
#
#   bash tests/cli/figure_test.sh <path-to-irid> <path-to-data-dir>
#
# Prints one line per failed check (what was run, what was expected, what came out) and ends
# with "N passed, M failed"; exits 0 only when every check passed. PNG sizes are read from the
# IHDR chunk's bytes with od, independently of irid.
set -u

if [[ $# -ne 2 ]]; then
    echo "usage: bash $0 <path-to-irid> <path-to-data-dir>" >&2
    exit 2
fi
IRID=$1
# shellcheck source=lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
# The data folder is not needed.

EMPTY=$TMP/empty-stdin
: >"$EMPTY"

# --- checks on the last run ---------------------------------------------------------------

# expect_usage_error TEXT...: exit status 2, every TEXT on stderr, nothing on stdout.
expect_usage_error() {
    expect_status 2
    local t
    for t in "$@"; do expect_stderr_has "$t"; done
    expect_empty_stdout
}

# png_size FILE: "WIDTH HEIGHT" from the IHDR chunk (bytes 16..23, big-endian), or nothing
# when FILE does not start with the PNG signature and an IHDR chunk.
png_size() {
    local sig ihdr
    sig=$(od -An -tx1 -N8 "$1" 2>/dev/null | tr -d ' \n')
    ihdr=$(od -An -c -j12 -N4 "$1" 2>/dev/null | tr -d ' \n')
    [[ $sig == 89504e470d0a1a0a && $ihdr == IHDR ]] || return 0
    od -An -tu1 -j16 -N8 "$1" | awk '{
        w = (($1 * 256 + $2) * 256 + $3) * 256 + $4
        h = (($5 * 256 + $6) * 256 + $7) * 256 + $8
        print w, h }'
}

# expect_png FILE W H: status 0, nothing on stdout, FILE a PNG of W x H pixels.
expect_png() {
    local size
    size=$(png_size "$1")
    if [[ $STATUS -eq 0 && ! -s $TMP/out && $size == "$2 $3" ]]; then
        pass
    else
        fail "a $2x$3 PNG in $1 and empty stdout" "$(outcome), PNG size '${size}'"
    fi
}

# expect_svg FILE: status 0, nothing on stdout, FILE starts with <?xml and has <svg and </svg>.
expect_svg() {
    if [[ $STATUS -eq 0 && ! -s $TMP/out ]] && head -c 5 "$1" | grep -qF '<?xml' &&
        grep -qF '<svg' "$1" && grep -qF '</svg>' "$1"; then
        pass
    else
        fail "an SVG document in $1 and empty stdout" "$(outcome)"
    fi
}

# expect_file_has FILE TEXT: status 0 and TEXT occurs in FILE.
expect_file_has() {
    if [[ $STATUS -eq 0 ]] && grep -qF -- "$2" "$1"; then
        pass
    else
        fail "$1 containing $(show "$2")" "$(outcome)"
    fi
}

# expect_file_matches FILE REGEX: status 0 and a line of FILE matches the extended REGEX.
expect_file_matches() {
    if [[ $STATUS -eq 0 ]] && grep -qE -- "$2" "$1"; then
        pass
    else
        fail "$1 with a line matching $(show "$2")" "$(outcome)"
    fi
}

# expect_only_files DIR N: DIR holds exactly N entries (no temporary file left behind).
expect_only_files() {
    local n
    n=$(find "$1" -mindepth 1 | wc -l)
    if [[ $n -eq $2 ]]; then pass; else fail "$2 files in $1" "$n: $(ls -A "$1" | tr '\n' ' ')"; fi
}

# --- the catalog ----------------------------------------------------------------------------

run_file "$EMPTY" figure --list
expect_status 0
for name in cmf-primaries cmf-xyz chromaticity clip-geometry spectrum-clip film-spectra table1; do
    expect_stdout_has "$name"
done
expect_stdout_has "Figure 2"
expect_stdout_has "Table 1"

# Names and extensions from the list: "NAME  [FIGURE]  TITLE  (.ext .ext)" lines.
mapfile -t entries < <(awk '/^[a-z0-9-]+  \[/ {
    name = $1; ext = $0; sub(/.*\(/, "", ext); sub(/\).*/, "", ext); print name " " ext }' "$TMP/out")
if [[ ${#entries[@]} -ge 7 ]]; then pass; else fail "at least 7 figures listed" "${#entries[@]}"; fi

# --- every figure writes valid files ----------------------------------------------------------

OUT=$TMP/figures
mkdir -p "$OUT"
files=0
for entry in "${entries[@]}"; do
    read -r name exts <<<"$entry"
    if [[ " $exts " == *" .png "* ]]; then
        run_file "$EMPTY" figure "$name" -o "$OUT/$name.png" --width 333 --height 222
        expect_png "$OUT/$name.png" 333 222
        run_file "$EMPTY" figure "$name" -o "$OUT/$name.svg" --width 400 --height 300
        expect_svg "$OUT/$name.svg"
        files=$((files + 2))
    fi
    if [[ " $exts " == *" .md "* ]]; then
        run_file "$EMPTY" figure "$name" -o "$OUT/$name.md"
        expect_status 0
        expect_empty_stdout
        expect_file_matches "$OUT/$name.md" '^\| ?:?-{3,}'  # a Markdown table's rule
        run_file "$EMPTY" figure "$name" -o "$OUT/$name.html"
        expect_file_has "$OUT/$name.html" "<table>"
        expect_file_has "$OUT/$name.html" "</html>"
        files=$((files + 2))
    fi
done
expect_only_files "$OUT" "$files"

# The default size is 960 x 600; the limits are accepted.
run_file "$EMPTY" figure cmf-xyz -o "$OUT/default.png"
expect_png "$OUT/default.png" 960 600
run_file "$EMPTY" figure cmf-xyz -o "$OUT/small.png" --width 64 --height 64
expect_png "$OUT/small.png" 64 64
# Upper-case extensions are the same formats.
run_file "$EMPTY" figure cmf-xyz -o "$OUT/upper.PNG" --width 100 --height 90
expect_png "$OUT/upper.PNG" 100 90

# Options reach the figure: table1's HTML fragment has no page around it.
run_file "$EMPTY" figure table1 -o "$OUT/fragment.html" --set html=fragment
expect_status 0
if grep -qF '<!DOCTYPE' "$OUT/fragment.html"; then fail "an HTML fragment" "a page"; else pass; fi
run_file "$EMPTY" figure chromaticity -o "$OUT/uv.svg" --set diagram=uv --set spaces=srgb,ntsc1953
expect_svg "$OUT/uv.svg"
run_file "$EMPTY" figure clip-geometry -o "$OUT/all.png" --set method=all --set color=0.2,0.7,0.3
expect_png "$OUT/all.png" 960 600

# --caption prints the caption and the measurements.
run_file "$EMPTY" figure table1 -o "$OUT/t.md" --caption
expect_status 0
expect_stdout_has "Table 1 of Smits 1990"
expect_stdout_has "1 plane crossed: "
expect_stdout_has "multiplications"
run_file "$EMPTY" figure chromaticity -o "$OUT/c.png" --width 300 --height 200 --caption
expect_stdout_has "srgb triangle area (xy): 0.1121"

# --- usage errors: exit 2, what is allowed on stderr, no file ---------------------------------

BAD=$TMP/bad
mkdir -p "$BAD"
run_file "$EMPTY" figure no-such-figure -o "$BAD/x.png"
expect_usage_error "no-such-figure" "cmf-primaries" "table1"
run_file "$EMPTY" figure -o "$BAD/x.png"
expect_usage_error "NAME" "cmf-xyz"
run_file "$EMPTY" figure cmf-xyz
expect_usage_error "-o" ".svg, .png"
run_file "$EMPTY" figure cmf-xyz -o "$BAD/x.jpg"
expect_usage_error ".jpg" ".svg, .png"
run_file "$EMPTY" figure table1 -o "$BAD/x.png"
expect_usage_error ".md, .html"
run_file "$EMPTY" figure cmf-xyz -o "$BAD/x.png" --width 10
expect_usage_error "--width" "64"
run_file "$EMPTY" figure cmf-xyz -o "$BAD/x.png" --height 9000
expect_usage_error "--height" "8192"
run_file "$EMPTY" figure cmf-xyz -o "$BAD/x.png" --width abc
expect_usage_error "--width"
run_file "$EMPTY" figure cmf-xyz -o "$BAD/x.png" --set colour=red
expect_usage_error '"colour"' "observer"
run_file "$EMPTY" figure cmf-xyz -o "$BAD/x.png" --set observer=cie2000
expect_usage_error "observer=cie2000" "cie1931, cie1964, both"
run_file "$EMPTY" figure cmf-xyz -o "$BAD/x.png" --set observer
expect_usage_error "key=value" "observer"
run_file "$EMPTY" figure cmf-primaries -o "$BAD/x.png" --set primaries=444,526,900
expect_usage_error "primaries" "[360, 830]"
run_file "$EMPTY" figure spectrum-clip -o "$BAD/x.png" --set luminance=-1
expect_usage_error "luminance" "[0.01, 0.99]"
run_file "$EMPTY" figure film-spectra -o "$BAD/x.png" --set films=100@kryptonite
expect_usage_error "kryptonite" "soap-film"
expect_only_files "$BAD" 0

# --- I/O failure: exit 1, the file named ------------------------------------------------------

run_file "$EMPTY" figure cmf-xyz -o "$TMP/no-such-folder/x.png"
expect_status 1
expect_stderr_has "no-such-folder"
expect_empty_stdout
run_file "$EMPTY" figure table1 -o "$TMP/no-such-folder/x.md"
expect_status 1
expect_stderr_has "no-such-folder"
# A directory in the way of the output.
mkdir -p "$TMP/dir.png"
run_file "$EMPTY" figure cmf-xyz -o "$TMP/dir.png"
expect_status 1
expect_stderr_has "dir.png"

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
