#!/usr/bin/env bash
# The contract of `irid gallery -o DIR`: DIR/index.html and every file it references are
# written into DIR, and only there; stdout is the one line naming index.html (absolute path);
# the page works from the file system: every reference stays inside DIR and resolves to a file,
# every <img> is a valid image of exactly the size its tag states, and headless Chromium loads
# the page with every image decoded and no failed resource.
#
#   bash tests/cli/gallery_test.sh <path-to-irid>
#
# Prints one line per failed check (what was run, what was expected, what came out) and ends
# with "N passed, M failed"; exits 0 only when every check passed. Image sizes are read with
# oiiotool (openimageio-tools). The Chromium part is skipped, with a "SKIP:" line, when
# chromium is not installed (scripts/install-deps installs it).
# shellcheck disable=SC2016  # awk programs use $1, $2, ... inside single quotes
set -u

if [[ $# -ne 1 ]]; then
    echo "usage: bash $0 <path-to-irid>" >&2
    exit 2
fi
IRID=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
# shellcheck source=lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

if ! command -v oiiotool >/dev/null; then
    RAN="command -v oiiotool"
    fail "oiiotool (openimageio-tools) to read the images" "not found"
    echo "$passed passed, $failed failed"
    exit 1
fi

# Small sizes, so that the whole gallery takes seconds: scenes of SW × SH pixels.
SW=96
SH=72
# Any run gets at most this many seconds.
LIMIT=300

# image_size FILE: "WIDTH HEIGHT" from oiiotool's one-line description, or nothing when
# oiiotool cannot read FILE as an image.
image_size() {
    oiiotool --info "$1" 2>/dev/null | sed -nE 's/^.*: +([0-9]+) x +([0-9]+), [0-9]+ channel.*$/\1 \2/p'
}

# attribute NAME TAG: the value of attribute NAME in the HTML tag TAG (double, single or no
# quotes), with &amp; decoded; nothing when absent.
attribute() {
    printf '%s\n' "$2" |
        sed -nE "s/^.*[[:space:]]$1[[:space:]]*=[[:space:]]*(\"([^\"]*)\"|'([^']*)'|([^[:space:]>\"']+)).*\$/\\2\\3\\4/Ip" |
        sed 's/&amp;/\&/g'
}

# === 1. The run ===========================================================================

cd "$TMP" || exit 2
DIR=gallery
# A page written into DIR beforehand (as scripts/run writes iridescence.html), linked by --page.
mkdir -p "$DIR/live"
printf '<!doctype html><title>live</title>\n' >"$DIR/live/page.html"
LIVE_TITLE="A live page & more"

# --page refuses, before anything is rendered, a page that is not in DIR or not inside it.
for page in missing.html ../outside.html /abs/page.html; do
    run '' gallery -o "$DIR" --page "$page=x" --quiet
    expect_status 1
    if grep -qF "'$page'" "$TMP/err"; then pass; else fail "a message naming '$page'" "$(outcome)"; fi
done
run '' gallery -o "$DIR" --page "no-title.html" --quiet
expect_status 2

ARGS=(gallery -o "$DIR" --width "$SW" --height "$SH" --spp 1 --figure-width 320 --quiet
      --page "live/page.html=$LIVE_TITLE")
timeout -k 5 "$LIMIT" "$IRID" "${ARGS[@]}" </dev/null >"$TMP/out" 2>"$TMP/err"
STATUS=$?
printf -v shown ' %q' "${ARGS[@]}"
RAN="(cd \$TMP && irid${shown})"
# DIR was given relative to the current folder; stdout names index.html by its absolute path
# (the current folder as the system resolves it, without symbolic links).
ABS=$(pwd -P)/$DIR
expect_output "$ABS/index.html"$'\n'
if [[ ! -s $TMP/err ]]; then pass; else fail "nothing on stderr with --quiet" "$(outcome)"; fi
PAGE=$ABS/index.html
if [[ ! -s $PAGE ]]; then
    fail "$PAGE written" "missing or empty"
    echo "$passed passed, $failed failed"
    exit 1
fi

# === 2. The references ====================================================================

# Every reference of the page: src and href attributes of any tag (img, a, link, script,
# source, ...) and CSS url(...), one per line, &amp; decoded.
grep -oiE "[[:space:]](src|href)[[:space:]]*=[[:space:]]*(\"[^\"]*\"|'[^']*'|[^[:space:]>\"']+)" "$PAGE" |
    sed -E "s/^[^=]*=[[:space:]]*//; s/^[\"']//; s/[\"']\$//; s/&amp;/\\&/g" >"$TMP/refs"
grep -oiE "url\\([^)]*\\)" "$PAGE" | sed -E "s/^url\\([[:space:]]*[\"']?//I; s/[\"']?[[:space:]]*\\)\$//" >>"$TMP/refs"

RAN="references in index.html"
nrefs=$(wc -l <"$TMP/refs")
# At least an <a href> and an <img src> for each of the three scenes.
if ((nrefs >= 6)); then pass; else fail "at least 6 references (the three scenes, linked and shown)" "$nrefs"; fi

while IFS= read -r ref; do
    RAN="reference '$ref' in index.html"
    case $ref in
        '#'*) pass; continue ;;   # a place in the page itself
    esac
    # Inside DIR: no scheme (http:, https:, file:, data:, ...), no network path (//), no
    # absolute path, no way up (..), no backslash.
    if [[ -z $ref || $ref == *:* || $ref == *//* || $ref == /* || $ref == *\\* ||
          /$ref/ == */../* ]]; then
        fail "a relative path inside $DIR" "'$ref'"
        continue
    fi
    pass
    file=${ref%%[?#]*}
    if [[ -f $ABS/$file && -s $ABS/$file ]]; then pass; else fail "$DIR/$file, a non-empty file" "missing"; continue; fi
    case ${file,,} in
        *.png | *.jpg | *.jpeg | *.gif | *.tif | *.tiff | *.exr)
            size=$(image_size "$ABS/$file")
            if [[ -n $size ]]; then pass; else fail "$file a valid image (oiiotool --info)" "$(oiiotool --info "$ABS/$file" 2>&1)"; fi
            ;;
    esac
done <"$TMP/refs"

# Every <img>: a src, a width and a height, and the file has exactly that size.
grep -oiE '<img[[:space:]][^>]*>' "$PAGE" >"$TMP/imgs"
nimgs=$(wc -l <"$TMP/imgs")
: >"$TMP/stated"
while IFS= read -r tag; do
    RAN="$tag in index.html"
    src=$(attribute src "$tag")
    w=$(attribute width "$tag")
    h=$(attribute height "$tag")
    if [[ -n $src && $w =~ ^[0-9]+$ && $h =~ ^[0-9]+$ ]]; then
        pass
    else
        fail "src, width and height (in pixels)" "src '$src', width '$w', height '$h'"
        continue
    fi
    printf '%s %s %s\n' "$src" "$w" "$h" >>"$TMP/stated"
    size=$(image_size "$ABS/${src%%[?#]*}")
    if [[ $size == "$w $h" ]]; then pass; else fail "$src of $w x $h pixels" "'$size'"; fi
done <"$TMP/imgs"

# The scenes at the size asked for, each shown and linked.
for s in oil-slick soap-bubbles morpho; do
    RAN="<img> of $s in index.html"
    if grep -qxF "$s.png $SW $SH" "$TMP/stated"; then pass; else fail "$s.png stated as $SW x $SH" "$(show "$(cat "$TMP/stated")")"; fi
    size=$(image_size "$ABS/$s.png")
    if [[ $size == "$SW $SH" ]]; then pass; else fail "$DIR/$s.png of $SW x $SH pixels" "'$size'"; fi
    if grep -qF "href=\"$s.png\"" "$PAGE"; then pass; else fail "a link to $s.png" "none"; fi
done

# The linked page: a link with its title (HTML-escaped); the reference checks above found it.
RAN="the link of --page live/page.html in index.html"
if grep -qF '<a href="live/page.html">A live page &amp; more</a>' "$PAGE"; then pass; else fail "a link to live/page.html" "none"; fi

# === 3. The page in headless Chromium =====================================================

CHROMIUM=$(command -v chromium || command -v chromium-browser || true)
if [[ -z $CHROMIUM ]]; then
    echo "SKIP: chromium is not installed: the page was not loaded in a browser (scripts/install-deps installs it)"
    echo "$passed passed, $failed failed"
    [[ $failed -eq 0 ]]
    exit
fi

# Chromium wants a writable home and profile; --no-sandbox because containers (and root) have
# no user namespaces for its sandbox.
mkdir -p "$TMP/home"
# browse URL OUT: the DOM of URL after its load event (virtual time lets every image load and
# the page's scripts run first) into OUT, Chromium's log into OUT.log.
browse() {
    HOME=$TMP/home timeout -k 5 "$LIMIT" "$CHROMIUM" --headless --no-sandbox --disable-gpu \
        --no-first-run --user-data-dir="$TMP/profile" --enable-logging=stderr --v=0 \
        --virtual-time-budget=5000 --dump-dom "$1" >"$2" 2>"$2.log"
    STATUS=$?
    RAN="chromium --headless --dump-dom $1"
}

# file_url PATH: a file:// URL of an absolute path (the characters URLs reserve escaped).
file_url() {
    local p=$1
    p=${p//%/%25}
    p=${p// /%20}
    p=${p//#/%23}
    p=${p//\?/%3F}
    printf 'file://%s' "$p"
}

# The page as it is: Chromium loads it and its DOM holds every image; the log names no file
# that failed to load (Chromium writes such console messages to the log in some versions).
browse "$(file_url "$PAGE")" "$TMP/dom.html"
expect_status 0
n=$(grep -oiE '<img[[:space:]]' "$TMP/dom.html" | wc -l)
if [[ $n -eq $nimgs && $n -gt 0 ]]; then pass; else fail "$nimgs <img> in the DOM" "$n; $(outcome)"; fi
if ! grep -qE 'ERR_FILE_NOT_FOUND|Failed to load resource' "$TMP/dom.html.log"; then
    pass
else
    fail "no failed resource in Chromium's log" "$(grep -E 'ERR_FILE_NOT_FOUND|Failed to load resource' "$TMP/dom.html.log" | head -3)"
fi

# probe FOLDER OUT: loads a copy of FOLDER/index.html, kept outside FOLDER, with two additions
# at the top of <head>: <base href> pointing at FOLDER (so that its relative references resolve
# as they do for the page itself) and a script that records every resource that fails to load
# and, after the load event, every <img>'s decoded (natural) size. The DOM dump then holds
# "IMG src width height" per image, "ERROR ref" per failed resource, and "DONE count".
probe() {
    local folder=$1 out=$2
    {
        printf '<base href="%s/">\n' "$(file_url "$folder")"
        cat <<'EOF'
<script>
var iridFailed = [];
window.addEventListener('error', function (e) {
    var t = e.target;
    if (t && t !== window && t.getAttribute)
        iridFailed.push(t.getAttribute('src') || t.getAttribute('href') || t.tagName);
}, true);
window.addEventListener('load', function () {
    var lines = [];
    for (var i = 0; i < document.images.length; ++i) {
        var im = document.images[i];
        lines.push('IMG ' + im.getAttribute('src') + ' ' + im.naturalWidth + ' ' + im.naturalHeight);
    }
    for (var j = 0; j < iridFailed.length; ++j) lines.push('ERROR ' + iridFailed[j]);
    lines.push('DONE ' + document.images.length);
    var pre = document.createElement('pre');
    pre.id = 'irid-probe';
    pre.textContent = lines.join('\n');
    document.body.appendChild(pre);
});
</script>
EOF
    } >"$TMP/probe-head.html"
    # After the <head> line (the page writes it on a line of its own).
    sed "/<head>/r $TMP/probe-head.html" "$folder/index.html" >"$TMP/probe.html"
    browse "$(file_url "$TMP/probe.html")" "$out"
    sed -n '/<pre id="irid-probe">/,/<\/pre>/p' "$out" | sed -E 's/<[^>]*>//g; /^$/d' >"$out.result"
}

# Every <img> decodes to the size its tag states, and nothing fails to load.
probe "$ABS" "$TMP/probe-dom.html"
expect_status 0
RAN="Chromium's natural sizes of the <img> of index.html (probe)"
if grep -qxF "DONE $nimgs" "$TMP/probe-dom.html.result"; then pass; else fail "DONE $nimgs" "$(show "$(cat "$TMP/probe-dom.html.result")")"; fi
sed -n 's/^IMG //p' "$TMP/probe-dom.html.result" >"$TMP/natural"
if cmp -s "$TMP/stated" "$TMP/natural"; then
    pass
else
    fail "the natural sizes of the <img> tags' width and height" \
        "$(show "$(diff "$TMP/stated" "$TMP/natural" | grep '^[<>]' | sed 's/^</stated:/; s/^>/natural:/')")"
fi
if ! grep -q '^ERROR' "$TMP/probe-dom.html.result"; then
    pass
else
    fail "no resource failing to load" "$(grep '^ERROR' "$TMP/probe-dom.html.result" | tr '\n' ' ')"
fi

# The probe can fail: in a copy of the gallery without its first image, Chromium reports that
# image as failed, with no natural size.
cp -r "$ABS" "$TMP/broken"
first=$(head -n 1 "$TMP/stated" | cut -d' ' -f1)
rm -f "$TMP/broken/$first"
probe "$TMP/broken" "$TMP/broken-dom.html"
RAN="the probe on a copy of the gallery without $first"
if grep -qxF "IMG $first 0 0" "$TMP/broken-dom.html.result" && grep -qxF "ERROR $first" "$TMP/broken-dom.html.result"; then
    pass
else
    fail "IMG $first 0 0 and ERROR $first" "$(show "$(cat "$TMP/broken-dom.html.result")")"
fi

# ===========================================================================================

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
