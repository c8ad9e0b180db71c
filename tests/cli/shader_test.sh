#!/usr/bin/env bash
# The contract of `irid shader`: --lang glsl writes DIR/irid_iridescence.glsl (a GLSL ES 3.00
# chunk defining three.js's evalIridescence, one uniform), DIR/irid_film_table.f32 (width ×
# height RGBA float32 texels) and DIR/irid_film_table.json (exactly eight keys); bad usage exits 2
# naming the option and writes nothing; a folder that cannot be made exits 1. The chunk is
# compiled by glslangValidator as GLSL ES 3.00, alone and after stand-ins for the helpers
# three.js's own chunks define (a clash of names would fail). Its numbers are
# tests/optics/film_shader_test.cpp's.
#
#   bash tests/cli/shader_test.sh <path-to-irid>
set -u

if [[ $# -ne 1 ]]; then
    echo "usage: bash $0 <path-to-irid>" >&2
    exit 2
fi
IRID=$1
# shellcheck source=lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

# check CONDITION DESCRIPTION: passes when the command CONDITION succeeds.
check() {
    if eval "$1"; then pass; else fail "$2" "$(outcome)"; fi
}

# json_field FILE KEY: the value of KEY in the JSON object of FILE.
json_field() {
    python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])' "$1" "$2"
}

# --- the three files ----------------------------------------------------------------------
out=$TMP/shader
run '' shader --lang glsl -o "$out"
expect_status 0
for f in irid_iridescence.glsl irid_film_table.f32 irid_film_table.json; do
    check "[[ -s $out/$f ]]" "$out/$f written"
    expect_stdout_has "$out/$f"
done
keys=$(python3 -c 'import json, sys; print(",".join(sorted(json.load(open(sys.argv[1])))))' "$out/irid_film_table.json")
check '[[ $keys == "filter,height,illuminant,primaries,space,uniform,white,width" ]]' "the JSON's keys are exactly the eight (got $keys)"
check '[[ $(json_field "$out/irid_film_table.json" uniform) == iridFilmTable ]]' "uniform iridFilmTable"
check '[[ $(json_field "$out/irid_film_table.json" illuminant) == D65 ]]' "illuminant D65 by default"
check '[[ $(json_field "$out/irid_film_table.json" space) == srgb-linear ]]' "space srgb-linear by default (the chunk's values are linear)"
check '[[ $(json_field "$out/irid_film_table.json" primaries) == "[0.64, 0.33, 0.3, 0.6, 0.15, 0.06]" ]]' "sRGB's primaries recorded"
check '[[ $(json_field "$out/irid_film_table.json" white) == "[0.3127, 0.329]" ]]' "D65's white recorded"
check '[[ $(json_field "$out/irid_film_table.json" filter) == nearest ]]' "filter nearest (texelFetch)"
width=$(json_field "$out/irid_film_table.json" width)
height=$(json_field "$out/irid_film_table.json" height)
size=$(stat -c %s "$out/irid_film_table.f32")
check '[[ $size -eq $((width * height * 16)) ]]' "the table is width x height x 16 bytes ($width x $height, got $size)"
# Texel 1 of row 0 is Re V(0), the white: 1 in R, G and B (little-endian float32), 0 in A.
white=$(python3 -c 'import struct, sys; d = open(sys.argv[1], "rb").read(); print(" ".join("%.4f" % v for v in struct.unpack("<4f", d[16:32])))' "$out/irid_film_table.f32")
check '[[ $white == "1.0000 1.0000 1.0000 0.0000" ]]' "texel 1 is the white (got $white)"

chunk=$out/irid_iridescence.glsl
check 'grep -qF "vec3 evalIridescence(float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0)" "$chunk"' "evalIridescence with three.js's signature"
check '[[ $(grep -c "^uniform " "$chunk") -eq 1 ]] && grep -q "^uniform highp sampler2D iridFilmTable;" "$chunk"' "one uniform, the table"
check '! grep -q "#version" "$chunk"' "no version line in the chunk"

# --- compiled as GLSL ES 3.00 -------------------------------------------------------------
{
    printf '#version 300 es\nprecision highp float;\n'
    cat "$chunk"
    printf 'uniform vec4 probe;\nout vec4 colour;\n'
    printf 'void main() { colour = vec4(evalIridescence(probe.x, probe.y, probe.z, probe.w, vec3(0.04)), 1.0); }\n'
} >"$TMP/alone.frag"
RAN="glslangValidator $TMP/alone.frag"
glslangValidator "$TMP/alone.frag" >"$TMP/out" 2>"$TMP/err"
STATUS=$?
expect_status 0
# After stand-ins for what three.js r187's shader chunks define around iridescence_fragment
# (their names, not their code): the chunk must add no clashing name.
{
    printf '#version 300 es\nprecision highp float;\n'
    printf 'const mat3 XYZ_TO_REC709 = mat3(1.0);\n'
    printf 'vec3 Fresnel0ToIor(vec3 f) { return f; }\nvec3 IorToFresnel0(vec3 a, float b) { return a; }\n'
    printf 'float IorToFresnel0(float a, float b) { return a; }\nvec3 evalSensitivity(float a, vec3 b) { return b; }\n'
    printf 'float iorToFresnel0(float a, float b) { return a; }\nfloat pow2(float x) { return x * x; }\n'
    cat "$chunk"
    printf 'uniform vec4 probe;\nout vec4 colour;\n'
    printf 'void main() { colour = vec4(evalIridescence(probe.x, probe.y, probe.z, probe.w, vec3(probe.x)), 1.0); }\n'
} >"$TMP/three.frag"
RAN="glslangValidator $TMP/three.frag"
glslangValidator "$TMP/three.frag" >"$TMP/out" 2>"$TMP/err"
STATUS=$?
expect_status 0

# --- WGSL: the same table, the chunk in WebGPU's language ---------------------------------
run '' shader --lang wgsl -o "$TMP/wgsl"
expect_status 0
check '[[ -s $TMP/wgsl/irid_iridescence.wgsl && ! -e $TMP/wgsl/irid_iridescence.glsl ]]' "irid_iridescence.wgsl written"
check 'cmp -s "$TMP/wgsl/irid_film_table.f32" "$out/irid_film_table.f32"' "the same table as for GLSL"
check 'cmp -s "$TMP/wgsl/irid_film_table.json" "$out/irid_film_table.json"' "the same table description"
check 'grep -q "^fn evalIridescence(outsideIOR: f32, eta2: f32, cosTheta1: f32, thinFilmThickness: f32, baseF0: vec3f) -> vec3f {" "$TMP/wgsl/irid_iridescence.wgsl"' "evalIridescence of the GLSL signature"
check 'grep -q "^fn irid_eval(table: texture_2d<f32>, " "$TMP/wgsl/irid_iridescence.wgsl"' "irid_eval taking the table"
check '[[ $(grep -c "@binding" "$TMP/wgsl/irid_iridescence.wgsl") == 1 ]]' "one binding, the table's"

# --- another colorimeter ------------------------------------------------------------------
run '' shader --lang glsl --illuminant D50 --space display-p3 -o "$TMP/p3"
expect_status 0
check '[[ $(json_field "$TMP/p3/irid_film_table.json" illuminant) == D50 ]]' "illuminant D50 recorded"
check '[[ $(json_field "$TMP/p3/irid_film_table.json" space) == display-p3-linear ]]' "space display-p3-linear recorded"
# Names in any case, written one way: the same files as the canonical names give.
run '' shader --lang glsl --illuminant d50 --space Display-P3-Linear -o "$TMP/p3b"
expect_status 0
check 'cmp -s "$TMP/p3/irid_film_table.json" "$TMP/p3b/irid_film_table.json"' "d50 / Display-P3-Linear recorded as D50 / display-p3-linear"
check 'cmp -s "$TMP/p3/irid_iridescence.glsl" "$TMP/p3b/irid_iridescence.glsl"' "and the same chunk"
run '' shader --lang glsl --illuminant "D6500 " -o "$TMP/d6500"
expect_status 0
check '[[ $(json_field "$TMP/d6500/irid_film_table.json" illuminant) == D6500 ]]' "'D6500 ' recorded as D6500, with no space"
check '! cmp -s "$TMP/p3/irid_film_table.f32" "$out/irid_film_table.f32"' "another table for another colorimeter"
# Written again over itself: the same bytes.
cp "$out/irid_film_table.f32" "$TMP/before.f32"
run '' shader --lang glsl -o "$out"
expect_status 0
check 'cmp -s "$TMP/before.f32" "$out/irid_film_table.f32"' "the same table when written again"

# --- refusals: exit 2, the option named, nothing written ----------------------------------
run '' shader --lang hlsl -o "$TMP/no1"
expect_status 2
expect_stderr_has "glsl"
check '[[ ! -e $TMP/no1 ]]' "nothing written for an unknown language"
run '' shader -o "$TMP/no2"
expect_status 2
expect_stderr_has "--lang"
run '' shader --lang glsl
expect_status 2
expect_stderr_has "-o"
run '' shader --lang glsl --illuminant D12 -o "$TMP/no3"
expect_status 2
expect_stderr_has "--illuminant"
check '[[ ! -e $TMP/no3 ]]' "nothing written for an unknown illuminant"
run '' shader --lang glsl --space no-such-space -o "$TMP/no4"
expect_status 2
expect_stderr_has "--space"
expect_stderr_has "srgb"
check '[[ ! -e $TMP/no4 ]]' "nothing written for an unknown space"
# Encodings are refused, naming the working space of their primaries: the chunk returns linear
# light (their tables would be the linear ones under another name).
for encoding in rec2100-pq acescct p3-d65-pq rec1886; do
    run '' shader --lang glsl --space "$encoding" -o "$TMP/no-$encoding"
    expect_status 2
    expect_stderr_has "encoding"
    check '[[ ! -e $TMP/no-$encoding ]]' "nothing written for the encoding $encoding"
done
run '' shader --lang glsl --space rec2100-pq -o "$TMP/no5"
expect_stderr_has "rec2020-linear"
printf 'x' >"$TMP/a-file"
run '' shader --lang glsl -o "$TMP/a-file"
expect_status 2
expect_stderr_has "not a folder"
# A folder that cannot be made: exit 1, nothing on stdout.
run '' shader --lang glsl -o "$TMP/a-file/sub"
expect_status 1
expect_empty_stdout

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
