#!/usr/bin/env bash
# The command-line contract of `irid film`, `irid film-table` and `irid film-error`: reflectance
# spectra of thin films and stacks (CSV on stdout), their colour (--color), colour tables and the
# thesis-versus-exact error report; exit status 2 with the option and its valid range on stderr
# (and nothing on stdout) for a bad value.
#
#   bash tests/cli/film_test.sh <path-to-irid> <path-to-data-dir>
#
# Prints one line per failed check (what was run, what was expected, what came out) and ends
# with "N passed, M failed"; exits 0 only when every check passed. Every expected value comes
# from a closed form evaluated here in awk (Fresnel and Airy formulas, the thesis' eq. 21/22,
# 25/26 and 29) or from a published constant, never from the program's own output. The only
# checks of the program against itself are identities: R + T = 1 of a lossless stack, x, y
# against X, Y, Z on the same --color line, and film-table rows against `irid film --color`.
# shellcheck disable=SC2016  # awk code with $1, $2, ... is passed in single quotes
set -u

if [[ $# -ne 2 ]]; then
    echo "usage: bash $0 <path-to-irid> <path-to-data-dir>" >&2
    exit 2
fi
IRID=$1
# shellcheck source=lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
DATA=$2   # not read: every expectation here is a closed form (kept for the common interface)
: "$DATA"

# --- running the program ------------------------------------------------------------------

# run ARGS...: runs `irid ARGS` with nothing on stdin. Sets STATUS and RAN; stdout and stderr
# are left in $TMP/out and $TMP/err.
run() {
    local args
    "$IRID" "$@" </dev/null >"$TMP/out" 2>"$TMP/err"
    STATUS=$?
    printf -v args ' %q' "$@"
    RAN="irid${args}"
}

# num AWK_EXPRESSION: the value of an awk expression (pi is defined) printed with 17 digits.
num() {
    awk "BEGIN { pi = atan2(0, -1); printf \"%.17g\", ($1) }"
}

# --- reporting ----------------------------------------------------------------------------

# --- checks on the last run ---------------------------------------------------------------

# expect_header TEXT: status 0 and the first line of stdout is TEXT.
expect_header() {
    local first=
    IFS= read -r first <"$TMP/out"
    if [[ $STATUS -eq 0 && $first == "$1" ]]; then pass; else fail "status 0, first line $(show "$1")" "$(outcome)"; fi
}

# expect_stdout_lacks TEXT: the fixed string does not occur on stdout.
expect_stdout_lacks() {
    if ! grep -qF -- "$1" "$TMP/out"; then pass; else fail "stdout without $(show "$1")" "$(outcome)"; fi
}
# expect_stdout_matches REGEX: some line of stdout matches the extended regular expression.
expect_stdout_matches() {
    if grep -qE -- "$1" "$TMP/out"; then pass; else fail "a line of stdout matching /$1/" "$(outcome)"; fi
}

# expect_usage_error OPTION [TEXT...]: exit status 2, OPTION and every TEXT on stderr (the
# option and its valid range), nothing on stdout.
expect_usage_error() {
    local text
    expect_status 2
    for text in "$@"; do expect_stderr_has "$text"; done
    expect_empty_stdout
}

# expect_rows CODE TOL [COUNT [MODE]]: status 0 and every line after stdout's header agrees with
# the expectation that the awk CODE sets, field by field: CODE assigns w[j] (the expected value
# of field j) from $1 (the wavelength, or the first field), i (the number of the data line,
# from 1) and pi; fields it leaves unset are not compared. |got - want| <= TOL, or with MODE
# "rel" <= TOL * max(1, |want|). COUNT, when given and not empty, is the number of data lines
# there must be (otherwise at least one).
expect_rows() {
    local code=$1 tol=$2 count=${3:-} mode=${4:-abs} verdict shown
    verdict=$(awk -F, -v tol="$tol" -v count="$count" -v mode="$mode" '
        function abs(x) { return x < 0 ? -x : x }
        function is_number(s) { return s ~ /^-?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
        BEGIN { pi = atan2(0, -1); bad = "" }
        NR == 1 { next }
        bad != "" { next }
        {
            ++i
            split("", w)
            '"$code"'
            for (k in w) {
                j = k + 0
                if (j > NF || !is_number($j)) { bad = sprintf("line %d: field %d is %s", i, j, (j > NF ? "missing" : $j)); break }
                limit = (mode == "rel") ? tol * (abs(w[k]) > 1 ? abs(w[k]) : 1) : tol
                if (!(abs($j - w[k]) <= limit + 0)) {
                    bad = sprintf("line %d (%s): field %d is %s, want %.17g (off by %.3g)", i, $1, j, $j, w[k], $j - w[k])
                    break
                }
            }
        }
        END {
            if (bad != "") print bad
            else if (count != "" && i != count + 0) printf "%d data lines, want %d", i, count
            else if (i == 0) print "no data lines"
        }' "$TMP/out")
    if [[ $STATUS -eq 0 && -z $verdict ]]; then
        pass
    else
        shown=$(printf '%s' "$code" | tr -s ' \n' ' ')
        fail "each line: ${shown} (within $tol${mode/abs/})" "$verdict; $(outcome)"
    fi
}

# === 1. The exact model ====================================================================

AIRY='r = (1 - n) / (1 + n); F = 4 * r * r / (1 - r * r) ^ 2'

# Header and the default grid: 380..780 nm in steps of 5 nm, 81 lines.
run film --layer 1.33:100
expect_header "wavelength_nm,R,T"
expect_rows 'w[1] = 380 + 5 * (i - 1)' 1e-9 81

# A bare interface (a zero-thickness layer) at normal incidence, ambient 1 to substrate 1.5:
# R = ((1 - 1.5) / (1 + 1.5))^2 = 0.04 and T = 0.96 at every wavelength.
run film --ambient 1 --layer 1.5:0 --substrate 1.5
expect_rows 'w[2] = 0.04; w[3] = 0.96' 1e-12 81
# The default ambient is the material "air", standard air n = 1.0002771 (Ciddor 1996 at 589.3 nm,
# the constant documented in data/materials/README.md), not exactly 1.
run film --layer 1.5:0 --substrate 1.5
expect_rows 'na = 1.0002771; w[2] = ((1.5 - na) / (1.5 + na)) ^ 2; w[3] = 1 - w[2]' 1e-12 81
run film --ambient air --layer 1.5:0 --substrate 1.5 --wavelengths 400:700:100
expect_rows 'na = 1.0002771; w[2] = ((1.5 - na) / (1.5 + na)) ^ 2; w[3] = 1 - w[2]' 1e-12 4

# A lossless film conserves energy: R + T = 1 (field 4 = R + T computed here from the line).
for pol in s p unpolarized; do
    run film --layer 1.38:100 --substrate 1.52 --angle 40 --polarization "$pol"
    awk -F, 'NR == 1 { print; next } { printf "%s,%s,%s,%.17g\n", $1, $2, $3, $2 + $3 }' "$TMP/out" >"$TMP/sum"
    mv "$TMP/sum" "$TMP/out"
    expect_rows 'w[4] = 1' 1e-12 81
done

# A quarter-wave layer n1 = 1.38 on 1.52 at 550 nm: R = ((n0 ns - n1^2) / (n0 ns + n1^2))^2.
QW=$(num '550 / (4 * 1.38)')
run film --ambient 1 --layer "1.38:$QW" --substrate 1.52 --wavelengths 550:550:1
expect_rows 'w[1] = 550; w[2] = ((1.52 - 1.38 ^ 2) / (1.52 + 1.38 ^ 2)) ^ 2' 1e-12 1
# Two quarter-wave layers, listed from the ambient side: the admittance n1^2 ns / n2^2.
QW2=$(num '550 / (4 * 2.35)')
run film --ambient 1 --layer "1.38:$QW" --layer "2.35:$QW2" --substrate 1.52 --wavelengths 550:550:1
expect_rows 'y = 1.38 ^ 2 * 1.52 / 2.35 ^ 2; w[2] = ((1 - y) / (1 + y)) ^ 2' 1e-12 1
run film --ambient 1 --layer "2.35:$QW2" --layer "1.38:$QW" --substrate 1.52 --wavelengths 550:550:1
expect_rows 'y = 2.35 ^ 2 * 1.52 / 1.38 ^ 2; w[2] = ((1 - y) / (1 + y)) ^ 2' 1e-12 1

# A free soap film in vacuum (n = 1.33, d = 350 nm), Airy: R = F sin^2 b / (1 + F sin^2 b),
# b = 2 pi n d / lambda, F = 4 r^2 / (1 - r^2)^2, r = (1 - n) / (1 + n); T = 1 - R.
run film --ambient 1 --layer 1.33:350 --substrate 1 --wavelengths 400:700:25
expect_rows 'n = 1.33; '"$AIRY"'; b = 2 * pi * n * 350 / $1; s = sin(b) ^ 2
             w[2] = F * s / (1 + F * s); w[3] = 1 - w[2]' 1e-12 13
# ... and at 45 degrees, each polarization with its own Fresnel r (the film is symmetric):
# r_s = (c0 - n c1) / (c0 + n c1), r_p = (n c0 - c1) / (n c0 + c1), b = 2 pi n d c1 / lambda;
# unpolarized is the mean of the two.
OBLIQUE='n = 1.33; s0 = sin(pi / 4); c0 = cos(pi / 4); c1 = sqrt(1 - (s0 / n) ^ 2)
         b = 2 * pi * n * 350 * c1 / $1; sb = sin(b) ^ 2
         rs = (c0 - n * c1) / (c0 + n * c1); Fs = 4 * rs * rs / (1 - rs * rs) ^ 2; Rs = Fs * sb / (1 + Fs * sb)
         rp = (n * c0 - c1) / (n * c0 + c1); Fp = 4 * rp * rp / (1 - rp * rp) ^ 2; Rp = Fp * sb / (1 + Fp * sb)'
run film --ambient 1 --layer 1.33:350 --substrate 1 --angle 45 --polarization s --wavelengths 400:700:50
expect_rows "$OBLIQUE"'; w[2] = Rs; w[3] = 1 - Rs' 1e-12 7
run film --ambient 1 --layer 1.33:350 --substrate 1 --angle 45 --polarization p --wavelengths 400:700:50
expect_rows "$OBLIQUE"'; w[2] = Rp; w[3] = 1 - Rp' 1e-12 7
run film --ambient 1 --layer 1.33:350 --substrate 1 --angle 45 --wavelengths 400:700:50
expect_rows "$OBLIQUE"'; w[2] = (Rs + Rp) / 2; w[3] = 1 - w[2]' 1e-12 7

# A zero-thickness film between identical media is black: R = 0, T = 1.
run film --layer 1.33:0
expect_rows 'w[2] = 0; w[3] = 1' 1e-12 81
run film --ambient 1.33 --layer 1.7:0 --substrate 1.33 --angle 30
expect_rows 'w[2] = 0; w[3] = 1' 1e-12 81

# A metal substrate (N = 0.05 + 3.5i) at normal incidence: R = ((n-1)^2 + k^2) / ((n+1)^2 + k^2).
run film --ambient 1 --layer 1:0 --substrate 0.05+3.5i
expect_rows 'w[2] = (0.95 ^ 2 + 3.5 ^ 2) / (1.05 ^ 2 + 3.5 ^ 2)' 1e-12 81

# Brewster's angle atan(1.5) for p: no reflection.
BREWSTER=$(num 'atan2(1.5, 1) * 180 / pi')
run film --ambient 1 --layer 1.5:0 --substrate 1.5 --angle "$BREWSTER" --polarization p
expect_rows 'w[2] = 0' 1e-12 81

# Every named material is accepted as a layer and as a substrate.
for m in air water soap-film mineral-oil chitin fused-silica silver gold; do
    run film --layer "$m:100" --substrate "$m"
    expect_rows 'w[1] = 380 + 5 * (i - 1)' 1e-9 81
done

# === 2. The thesis' single film (eq. 21/22 with eq. 24) ===================================
# Sections 2-5 pass --K 1, the thesis' equations as written; the default K (the physical one)
# is checked in section 9.

# Soap in air: the reflection ambient -> film goes up, film -> air down: a phase change, eq. 21.
run film --model thesis --layer 1.33:350 --K 1
expect_header "wavelength_nm,R"
expect_rows 'w[1] = 380 + 5 * (i - 1); w[2] = sin(2 * pi * 350 * 1.33 / $1) ^ 2' 1e-12 81
run film --model thesis --layer 1.33:350 --no-phase-change --K 1
expect_rows 'w[2] = cos(2 * pi * 350 * 1.33 / $1) ^ 2' 1e-12 81
run film --model thesis --layer 1.33:350 --K 0.5
expect_rows 'w[2] = 0.25 * sin(2 * pi * 350 * 1.33 / $1) ^ 2' 1e-12 81
# At 30 degrees (ambient 1): t' = t n cos(theta1), sin(theta1) = sin(30 degrees) / n.
run film --model thesis --ambient 1 --layer 1.33:350 --angle 30 --K 1
expect_rows 'c1 = sqrt(1 - (0.5 / 1.33) ^ 2); w[2] = sin(2 * pi * 350 * 1.33 * c1 / $1) ^ 2' 1e-12 81
# 1 -> 1.38 -> 1.52 goes up twice: no phase change, eq. 22; forced back with --phase-change.
run film --model thesis --ambient 1 --layer 1.38:350 --substrate 1.52 --K 1
expect_rows 'w[2] = cos(2 * pi * 350 * 1.38 / $1) ^ 2' 1e-12 81
run film --model thesis --ambient 1 --layer 1.38:350 --substrate 1.52 --phase-change --K 1
expect_rows 'w[2] = sin(2 * pi * 350 * 1.38 / $1) ^ 2' 1e-12 81
# 1.5 -> 1.33 -> 1 goes down twice: no phase change either.
run film --model thesis --ambient 1.5 --layer 1.33:350 --substrate 1 --K 1
expect_rows 'w[2] = cos(2 * pi * 350 * 1.33 / $1) ^ 2' 1e-12 81

# === 3. The thesis' multilayer (eq. 25/26) ================================================

# eq. 25: R = K/2 (sin(2 pi (l+1) t / lambda) / sin(2 pi t / lambda))^2, K/2 (l+1)^2 at a pole.
EQ25='function eq25(t, lam, l, K,   s) {
          s = sin(2 * pi * t / lam)
          return abs(s) < 1e-12 ? K / 2 * (l + 1) ^ 2 : K / 2 * (sin(2 * pi * (l + 1) * t / lam) / s) ^ 2
      }'
# expect_eq25 T_AWK L K TOL [COUNT]: every line's R is eq. 25 with t_theta = T_AWK (computed
# here into a third field, which the comparison reads).
expect_eq25() {
    local saved=$TMP/out.eq25
    awk -F, -v t="$(num "$1")" -v l="$2" -v K="$3" "BEGIN { pi = atan2(0, -1) }
        function abs(x) { return x < 0 ? -x : x }
        $EQ25
        NR == 1 { print; next }
        { printf \"%s,%.17g\n\", \$0, eq25(t, \$1, l, K) }" "$TMP/out" >"$saved"
    cp "$TMP/out" "$TMP/out.orig"
    mv "$saved" "$TMP/out"
    expect_rows 'w[2] = $3' "$4" "${5:-}" rel
    mv "$TMP/out.orig" "$TMP/out"
}

# t = 100 nm of n = 1.56 at normal incidence: t_theta = 156 nm, a pole at 312 nm: 13^2 / 2.
run film --model thesis-multilayer --layer 1.56:100 --periods 12 --wavelengths 312:312:1 --K 1
expect_header "wavelength_nm,R"
expect_rows 'w[1] = 312; w[2] = 84.5' 1e-9 1
run film --model thesis-multilayer --layer 1.56:100 --periods 12 --K 1
expect_eq25 '100 * 1.56' 12 1 1e-9 81
run film --model thesis-multilayer --layer 1.56:100 --periods 5 --K 0.5 --wavelengths 300:800:7
expect_eq25 '100 * 1.56' 5 0.5 1e-9 72
# At 30 degrees: t_theta = t (n^2 - sin^2 theta)^(1/2).
run film --model thesis-multilayer --layer 1.56:100 --periods 12 --angle 30 --K 1
expect_eq25 '100 * sqrt(1.56 ^ 2 - 0.25)' 12 1 1e-9 81
# ... and its pole: 2 t_theta / lambda = 1.
POLE=$(num '2 * 100 * sqrt(1.56 ^ 2 - 0.25)')
run film --model thesis-multilayer --layer 1.56:100 --periods 12 --angle 30 --wavelengths "$POLE:$POLE:1" --K 1
expect_rows 'w[2] = 84.5' 1e-9 1 rel
# No film is no multilayer (eq. 25 would be one interface, a perfect mirror with the default K).
run film --model thesis-multilayer --layer 1.56:100 --periods 0 --K 1
expect_usage_error "--periods" "allowed: 1 to 1000000"
run film --model morpho --periods 0
expect_usage_error "--periods" "allowed: 1 to 1000000"
# A whole number in another notation is that number; a fraction is named as one.
run film --model morpho --periods 1e3 --color
expect_status 0
run film --model morpho --periods 2.5
expect_usage_error "--periods" "'2.5' is not a whole number; allowed: 1 to 1000000"
run film --model thesis-multilayer --layer 0.9:100 --periods 3
expect_usage_error "eq. 26" ">= 1"

# === 4. Morpho (eq. 25 with eq. 29) ========================================================

# Normal incidence: t_theta = d1 + d2 n = 150 + 50 * 1.56 = 228 nm, a pole at 456 nm.
run film --model morpho --wavelengths 456:456:1 --K 1
expect_header "wavelength_nm,R"
expect_rows 'w[1] = 456; w[2] = 84.5' 1e-9 1
run film --model morpho --K 1
expect_eq25 '150 + 50 * 1.56' 12 1 1e-9 81
# 30 degrees: t_theta = d1 cos(theta) + d2 (n^2 - sin^2 theta)^(1/2); the pole moves with it.
POLE=$(num '2 * (150 * cos(pi / 6) + 50 * sqrt(1.56 ^ 2 - 0.25))')
run film --model morpho --angle 30 --wavelengths "$POLE:$POLE:1" --K 1
expect_rows 'w[2] = 84.5' 1e-9 1 rel
run film --model morpho --angle 30 --K 1
expect_eq25 '150 * cos(pi / 6) + 50 * sqrt(1.56 ^ 2 - 0.25)' 12 1 1e-9 81
run film --model morpho --d1 100 --d2 60 --n 1.5 --periods 5 --angle 45 --K 1
expect_eq25 '100 * cos(pi / 4) + 60 * sqrt(1.5 ^ 2 - 0.5)' 5 1 1e-9 81

# === 5. --color ============================================================================

COLOR_HEADER="X,Y,Z,x,y,L,a,b,R_linear,G_linear,B_linear"
# A black film: XYZ = 0, L = 0, linear RGB = 0.
run film --layer 1.33:0 --color
expect_header "$COLOR_HEADER"
expect_rows 'w[1] = 0; w[2] = 0; w[3] = 0; w[6] = 0; w[9] = 0; w[10] = 0; w[11] = 0' 1e-12 1
# R = 1 everywhere (eq. 22 at zero thickness): the white of D65 (x, y = 0.3127, 0.3290, Y = 1),
# L = 100, a = b = 0, and linear sRGB 1, 1, 1.
D65_X=$(num '0.3127 / 0.3290')
D65_Z=$(num '(1 - 0.3127 - 0.3290) / 0.3290')
run film --model thesis --layer 1.33:0 --no-phase-change --color --K 1
expect_header "$COLOR_HEADER"
expect_rows "w[1] = $D65_X; w[3] = $D65_Z; w[4] = 0.3127; w[5] = 0.3290" 1e-3 1
expect_rows 'w[2] = 1; w[6] = 100; w[7] = 0; w[8] = 0; w[9] = 1; w[10] = 1; w[11] = 1' 1e-9 1
# Under illuminant A (x, y = 0.44757, 0.40745, CIE 015:2018) the white is still RGB 1, 1, 1
# (adapted white), as it is in Rec. 2020 and with the 1964 observer (x, y = 0.31382, 0.33100).
run film --model thesis --layer 1.33:0 --no-phase-change --color --illuminant A --K 1
expect_rows 'w[4] = 0.44757; w[5] = 0.40745' 2e-4 1
expect_rows 'w[2] = 1; w[6] = 100; w[9] = 1; w[10] = 1; w[11] = 1' 1e-9 1
run film --model thesis --layer 1.33:0 --no-phase-change --color --rgb rec2020 --K 1
expect_rows 'w[2] = 1; w[9] = 1; w[10] = 1; w[11] = 1' 1e-9 1
run film --model thesis --layer 1.33:0 --no-phase-change --color --observer cie1964 --K 1
expect_rows 'w[4] = 0.31382; w[5] = 0.33100' 2e-4 1
# x, y agree with X, Y, Z on the same line, and every model prints one colour line.
for model_args in "--layer water:350" "--layer 1.38:100 --layer 2.35:60 --substrate 1.52 --angle 20" \
                  "--model thesis --layer 1.33:350" "--model thesis-multilayer --layer 1.56:100 --periods 3" \
                  "--model morpho --angle 30"; do
    # shellcheck disable=SC2086  # the model's options are split on purpose
    run film $model_args --color
    expect_header "$COLOR_HEADER"
    expect_rows 's = $1 + $2 + $3; w[4] = $1 / s; w[5] = $2 / s' 1e-12 1
done

# --integration fourier (the Airy series against the transformed matching functions) reduces to
# the closed forms: at zero thickness the bare air | 1.5 interface, R = ((1.5 - 1)/(1.5 + 1))^2,
# and for a thick film (1 mm) the incoherent sum R01 + (1 - R01)^2 R12 / (1 - R01 R12) of the
# faces of a 1.33 film on 1.5, at normal incidence, in vacuum (--ambient 1: air's 1.0003 would
# shift R by 5e-5); XYZ = R times the white of D65.
run film --ambient 1 --layer 1.33:0 --substrate 1.5 --color --integration fourier
expect_header "$COLOR_HEADER"
R_BARE=$(num '(0.5 / 2.5) ^ 2')
expect_rows "w[1] = $R_BARE * $D65_X; w[2] = $R_BARE; w[9] = $R_BARE; w[10] = $R_BARE; w[11] = $R_BARE" 2e-4 1
expect_rows "w[2] = $R_BARE" 1e-6 1
R01=$(num '(0.33 / 2.33) ^ 2')
R12=$(num '(0.17 / 2.83) ^ 2')
R_THICK=$(num "$R01 + (1 - $R01) ^ 2 * $R12 / (1 - $R01 * $R12)")
run film --ambient 1 --layer 1.33:1000000 --substrate 1.5 --color --integration fourier
expect_rows "w[2] = $R_THICK; w[9] = $R_THICK; w[10] = $R_THICK; w[11] = $R_THICK" 1e-6 1
# At a film's thickness it agrees with the 1 nm sum (--integration sum, the default) to far
# better than a visible difference: Y within 1e-4 for these constant indices.
run film --layer 1.33:380 --substrate 1.5 --angle 35 --color
IFS=, read -r SUM_X SUM_Y SUM_Z _ < <(sed -n 2p "$TMP/out")
run film --layer 1.33:380 --substrate 1.5 --angle 35 --color --integration fourier
expect_rows "w[1] = $SUM_X; w[2] = $SUM_Y; w[3] = $SUM_Z" 1e-4 1
# irid film-error --model fourier: the series against the 1 nm sum on one of the grid's films
# (a constant-index film on Sellmeier water), its summary line's max within ΔE2000 0.1.
run film-error --model fourier --film n1.2-on-water --thickness 0:2000:50 --angles 0:85:17
RAN="$RAN (summary)"
max=$(awk -F, '$1 == "fourier" && $2 == "n1.2-on-water" { print $6 }' "$TMP/out")
if [[ $STATUS -eq 0 && -n $max ]] && awk -v m="$max" 'BEGIN { exit !(m < 0.1) }'; then pass; else fail "status 0, a summary max < 0.1" "$(outcome)"; fi
run film-error --model fourier --K 2
expect_usage_error "--K" "fourier"
# What the series does not cover is refused, naming the option.
run film --layer 1.33:380 --integration fourier
expect_usage_error "--integration" "--color"
run film --layer 1.33:380 --layer 2:50 --color --integration fourier
expect_usage_error "--integration fourier" "one layer"
run film --model thesis --layer 1.33:380 --color --integration fourier
expect_usage_error "--integration fourier" "exact"
run film --layer 1.5+0.1i:380 --color --integration fourier
expect_usage_error "--integration fourier" "lossless"
run film --layer 1.33:380 --polarization s --color --integration fourier
expect_usage_error "--integration fourier" "unpolarised"
run film --layer 1.33:380 --color --integration fft
expect_usage_error "--integration" "sum, fourier"

# === 6. film-table =========================================================================

TABLE_HEADER="thickness_nm,angle_deg,cos_theta,X,Y,Z,R_linear,G_linear,B_linear"
run film-table --layer water --thickness 0:100:50 --angles 0:60:30
cp "$TMP/out" "$TMP/table"
expect_header "$TABLE_HEADER"
expect_rows 'w[3] = cos($2 * pi / 180)' 1e-12 9
# The rows are thickness x angle, each pair once.
RAN="irid film-table --layer water --thickness 0:100:50 --angles 0:60:30 (thickness,angle pairs)"
pairs=$(tail -n +2 "$TMP/table" | awk -F, '{ printf "%.17g,%.17g\n", $1, $2 }' | sort | tr '\n' ' ')
want_pairs=$(for t in 0 50 100; do for a in 0 30 60; do echo "$t,$a"; done; done | sort | tr '\n' ' ')
if [[ $pairs == "$want_pairs" ]]; then pass; else fail "pairs $want_pairs" "$pairs"; fi
# Thickness 0 (soap in air) is black at every angle.
awk -F, 'NR == 1 || $1 == 0' "$TMP/table" >"$TMP/out"
RAN="irid film-table --layer water --thickness 0:100:50 --angles 0:60:30 (rows at thickness 0)"
expect_rows 'w[4] = 0; w[5] = 0; w[6] = 0; w[7] = 0; w[8] = 0; w[9] = 0' 1e-12 3
# Each row is `irid film --layer water:T --angle A --color`'s X,Y,Z and linear RGB.
while IFS=, read -r t a _ X Y Z R G B; do
    run film --layer "water:$t" --angle "$a" --color
    expect_rows "w[1] = $X; w[2] = $Y; w[3] = $Z; w[9] = $R; w[10] = $G; w[11] = $B" 1e-12 1
done < <(tail -n +2 "$TMP/table")
# Where the 1 nm grid aliases below the incoherent limit (water on gold near grazing light, its
# round trips strong for tens of micrometres), a table keeps the 1 nm sums and says so; `film
# --color` sums the one colour finely enough, and agrees with the Fourier series (issue 39: the
# 1 nm colour was ΔE2000 3.7 off at 55 µm, 85°).
run film-table --layer water --substrate gold --thickness 55000:56000:500 --angle 85
expect_status 0
expect_stderr_has "3 of the colours (the first at 55000 nm, 85 deg) are 1 nm sums that alias"
run film-table --layer water --substrate gold --thickness 0:1000:500 --angle 85
expect_stderr_lacks "alias"
run film --layer water:55511 --substrate gold --angle 85 --color --integration fourier
fourier_lab=$(tail -1 "$TMP/out" | cut -d, -f6-8)
run film --layer water:55511 --substrate gold --angle 85 --color
expect_rows "w[6] = $(cut -d, -f1 <<<"$fourier_lab"); w[7] = $(cut -d, -f2 <<<"$fourier_lab"); w[8] = $(cut -d, -f3 <<<"$fourier_lab")" 0.05 1
# Without --angles the table is at --angle.
run film-table --layer 1.38 --substrate 1.52 --thickness 0:200:10 --angle 20
expect_rows 'w[1] = 10 * (i - 1); w[2] = 20; w[3] = cos(20 * pi / 180)' 1e-12 21

# -o: the same content in the file, nothing on stdout, no temporary file left in the folder.
mkdir "$TMP/dir"
run film-table --layer water --thickness 0:100:50 --angles 0:60:30 -o "$TMP/dir/table.csv"
expect_status 0
expect_empty_stdout
RAN+=" (the folder afterwards)"
if cmp -s "$TMP/table" "$TMP/dir/table.csv"; then pass; else fail "the stdout table in the file" "$(show "$(cat "$TMP/dir/table.csv" 2>&1)")"; fi
listing=$(ls -A "$TMP/dir")
if [[ $listing == table.csv ]]; then pass; else fail "only table.csv" "$(show "$listing")"; fi
# A bad option writes no file.
rm -rf "$TMP/dir" && mkdir "$TMP/dir"
run film-table --layer water --thickness 0:100:-50 -o "$TMP/dir/table.csv"
expect_usage_error "--thickness"
run film-table --layer unobtainium --thickness 0:100:50 -o "$TMP/dir/table.csv"
expect_usage_error "--layer"
run film-table --layer water --thickness 0:100:50 --angles 0:90:30 -o "$TMP/dir/table.csv"
expect_usage_error "--angles" "90"
run film-table --layer water -o "$TMP/dir/table.csv"
expect_usage_error "--thickness"
RAN="ls -A (the -o folder after the failed runs)"
listing=$(ls -A "$TMP/dir")
if [[ -z $listing ]]; then pass; else fail "an empty folder" "$(show "$listing")"; fi

# === 7. film-error =========================================================================

run film-error
expect_status 0
expect_stdout_matches '^== soap'
expect_stdout_matches '^== oil-on-water'
expect_stdout_matches '^samples .*mean .*max '
expect_stdout_matches '^worst: thickness [0-9.]+ nm at [0-9.]+ degrees'
expect_stdout_matches '^angle_deg,'
run film-error --film soap
expect_status 0
expect_stdout_matches '^== soap'
expect_stdout_lacks '== oil-on-water'
run film-error --film oil-on-water
expect_status 0
expect_stdout_matches '^== oil-on-water'
expect_stdout_lacks '== soap'
run film-error --film all
expect_stdout_matches '^== soap'
expect_stdout_matches '^== oil-on-water'
run film-error --film nope
expect_usage_error "--film" "oil-on-water"

# === 7b. The renderers' film models ========================================================

# A film of the ambient's own index leaves the bare base: 1 | 1 | 1.5 reflects
# ((1.5 - 1) / (1.5 + 1))^2 = 0.04 in every channel (cycles: exact Fresnel, no series terms), and
# RGB (1, 1, 1) is D65's white, so Y = 0.04 too.
run film --model cycles --ambient 1 --layer 1:300 --substrate 1.5
expect_header "X,Y,Z,x,y,L,a,b,R_linear,G_linear,B_linear"
expect_rows 'w[2] = 0.04; w[9] = 0.04; w[10] = 0.04; w[11] = 0.04' 1e-9 1
# belcour: the same times the Gaussian fits' white, illuminant E through the Rec.709 matrix (its
# rows' sums: 3.2404542 - 1.5371385 - 0.4985314 = 1.2047843 ...), to the fits' 0.2 %.
run film --model belcour --ambient 1 --layer 1:300 --substrate 1.5 --color
expect_rows 'w[9] = 0.04 * 1.2047843; w[10] = 0.04 * 0.9483008; w[11] = 0.04 * 0.9088427' 3e-4 1
run film --model gltf --layer 1.33:300 --substrate gold --angle 30
expect_header "X,Y,Z,x,y,L,a,b,R_linear,G_linear,B_linear"
run film --model belcour --layer 1.33:300 --wavelengths 400:700:5
expect_usage_error "--wavelengths" "does not apply"
run film --model cycles --layer 1.5+0.1i:100
expect_usage_error "--layer 1" "absorbs"
run film --model gltf --layer 1.33:100 --rgb rec2020
expect_usage_error "--rgb" "srgb"
run film --model gltf --layer 1.33:100 --layer 1.5:100
expect_usage_error "exactly 1 --layer"
run film-table --model cycles --layer 1.33
expect_usage_error "--model cycles" "colour model"
run film-error --model nope
expect_usage_error "--model" "cycles"
run film-error --model cycles --film n1.33-on-air --thickness 0:200:50 --angles 0:60:30
expect_status 0
expect_stdout_matches '^samples 15 '
expect_stdout_matches '^cycles,n1.33-on-air,'
expect_stdout_matches '^limits: '
run film-error --model thesis --film n1.33-on-gold --thickness 0:100:50 --angles 0:30:30
expect_stdout_matches '^thesis,n1.33-on-gold,n/a'
run film-error --model gltf --K 1
expect_usage_error "--K"
run film-error --model gltf --illuminant A
expect_usage_error "--illuminant"
run film-error --model gltf --film nope
expect_usage_error "--film" "n1.33-on-air"

# === 8. Errors =============================================================================

# Exit 2, the option and its valid range on stderr, nothing on stdout.
run film --layer water:-5
expect_usage_error "--layer" ">= 0"
run film --layer 1.33:abc
expect_usage_error "--layer" ">= 0"
run film --layer 0:100
expect_usage_error "--layer" "> 0"
run film --layer -1.2:100
expect_usage_error "--layer" "> 0"
run film --layer 1.5-0.1i:100
expect_usage_error "--layer" ">= 0"
run film --layer unobtainium:100
expect_usage_error "--layer" "water"
run film --layer 1.33:100 --angle 90
expect_usage_error "--angle" "[0, 90)"
run film --layer 1.33:100 --angle -1
expect_usage_error "--angle" "[0, 90)"
run film --layer 1.33:100 --wavelengths 700:400:5
expect_usage_error "--wavelengths"
run film --layer 1.33:100 --wavelengths 400:700:0
expect_usage_error "--wavelengths" "> 0"
run film --layer 1.33:100 --wavelengths 400:700
expect_usage_error "--wavelengths" "START:END:STEP"
run film --layer 1.33:100 --polarization q
expect_usage_error "--polarization" "unpolarized"
run film --layer 1.33:100 --model nope
expect_usage_error "--model" "thesis-multilayer"
run film --model thesis --layer 1.33:100 --layer 1.5:100
expect_usage_error "--layer"
run film --model thesis-multilayer --layer 1.56:100
expect_usage_error "--periods"
run film --model thesis --layer 1.33:100 --phase-change --no-phase-change
expect_usage_error "--phase-change" "--no-phase-change"
run film --layer 1.33:100 --substrate 1.5+-0.1i
expect_usage_error "--substrate"
# The same checks hold with --color and for a later layer.
run film --layer 1.33:100 --layer 0:50 --color
expect_usage_error "--layer" "> 0"
run film --layer 1.33:100 --angle 95 --color
expect_usage_error "--angle" "[0, 90)"
# Every option is checked even when the run does not use it.
run film --layer 1.33:100 --color --wavelengths 700:400:5
expect_usage_error "--wavelengths" "reversed"
run film --layer 1.33:100 --illuminant foo
expect_usage_error "--illuminant" "D65"
# Options of another model are refused, not silently ignored.
run film --layer 1.33:100 --K 2
expect_usage_error "--K" "exact"
run film --model thesis --layer 1.33:100 --polarization s
expect_usage_error "--polarization" "thesis"
run film --model thesis-multilayer --layer 1.56:100 --periods 3 --substrate 1.5
expect_usage_error "--substrate" "thesis-multilayer"
run film --model morpho --layer 1.56:100
expect_usage_error "--layer" "morpho"
# Morpho parameters are named as typed, with their ranges.
run film --model morpho --d1 -5
expect_usage_error "--d1" "[0, 1e6]"
run film --model morpho --n 0.5
expect_usage_error "--n" ">= 1"
run film --model morpho --periods -1
expect_usage_error "--periods" "allowed: 1 to 1000000"

# ===========================================================================================

# === 9. The thesis' K defaults to the physical values =====================================

# expect_field_at_most FIELD MAX: status 0 and field FIELD of every data line is <= MAX.
expect_field_at_most() {
    local verdict
    verdict=$(awk -F, -v f="$1" -v max="$2" 'NR > 1 && !($f <= max + 0) { printf "line %d: field %d is %s", NR - 1, f, $f; exit }
                                            END { if (NR < 2) print "no data lines" }' "$TMP/out")
    if [[ $STATUS -eq 0 && -z $verdict ]]; then pass; else fail "field $1 <= $2 on every line" "$verdict; $(outcome)"; fi
}

# Eq. 25 with K = 2 / (l + 1)^2 peaks at 1 (the pole at 2 t_theta = lambda): 1/2 K (l+1)^2 = 1,
# where K = 1 gives 84.5 for the Morpho's twelve mullions.
run film --model morpho --wavelengths 456:456:1
expect_rows 'w[1] = 456; w[2] = 1' 1e-9 1
run film --model morpho
expect_eq25 '150 + 50 * 1.56' 12 "$(num '2 / 13 ^ 2')" 1e-9 81
run film --model morpho --periods 5 --angle 30
expect_eq25 '150 * cos(pi / 6) + 50 * sqrt(1.56 ^ 2 - 0.25)' 5 "$(num '2 / 6 ^ 2')" 1e-9 81
run film --model thesis-multilayer --layer 1.56:100 --periods 12 --wavelengths 312:312:1
expect_rows 'w[2] = 1' 1e-9 1
# So the wing's colour is a reflectance colour: Y <= 1, L* <= 100 (with K = 1: L* = 146).
run film --model morpho --color
expect_field_at_most 2 1
expect_field_at_most 6 100
run film --model morpho --blend --color
expect_field_at_most 2 1
run film-table --model morpho --angles 0:80:10
expect_field_at_most 5 1
# The single film's K is matched to its faces: K = |r01| + |r12| at normal incidence (Fresnel,
# r = (n_i - n_t) / (n_i + n_t)), so R = K^2 sin^2(2 pi t n / lambda) peaks at (|r01| + |r12|)^2.
run film --model thesis --ambient 1 --layer 1.33:350 --substrate 1
expect_rows 'K = 2 * 0.33 / 2.33; w[2] = K ^ 2 * sin(2 * pi * 350 * 1.33 / $1) ^ 2' 1e-12 81
run film --model thesis --ambient 1 --layer 1.47:300 --substrate 1.33
expect_rows 'K = 0.47 / 2.47 + 0.14 / 2.8; w[2] = K ^ 2 * sin(2 * pi * 300 * 1.47 / $1) ^ 2' 1e-12 81
run film --model thesis --ambient 1 --layer 1.38:200 --substrate 1.52 --color
expect_field_at_most 2 "$(num '(0.38 / 2.38 + 0.14 / 2.9) ^ 2')"
# --help says what the default is and where it comes from.
run film --help
expect_stdout_has "|r01| + |r12|"
expect_stdout_has "2/(l+1)^2"
expect_stdout_has "--K 1 is the thesis as written"

# === 10. The thesis' models refuse absorbing films ========================================

# Eq. 19-22 and 25 add beams of real amplitude with phase changes of 0 or pi: an absorbing film
# (or substrate) cannot be modelled and is refused, not its k dropped.
run film --model thesis --layer 1.5+0.5i:300
expect_usage_error "--layer 1 '1.5+0.5i:300'" "absorbing" "--model exact"
run film --model thesis --layer silver:300
expect_usage_error "--layer 1 'silver:300'" "absorbing" "--model exact"
run film --model thesis --layer 1.33:300 --substrate gold
expect_usage_error "--substrate 'gold'" "absorbing" "--model exact"
run film --model thesis --layer silver:300 --color
expect_usage_error "--layer" "absorbing"
run film --model thesis-multilayer --periods 3 --layer silver:100
expect_usage_error "--layer 1 'silver:100'" "absorbing" "--model exact"
run film-table --model thesis --layer 1.5+0.01i --thickness 0:100:10
expect_usage_error "--layer" "absorbing"
# The exact model takes them.
run film --layer silver:30 --substrate gold --wavelengths 400:700:100
expect_rows 'w[1] = 300 + 100 * i' 1e-9 4

# === 11. The work of a whole run is bounded ===============================================

# run_bounded ARGS...: like run, but stopped after 60 s (status 124), so that a run that ignores
# the limits fails here instead of hanging the suite.
run_bounded() {
    local args
    timeout 60 "$IRID" "$@" </dev/null >"$TMP/out" 2>"$TMP/err"
    STATUS=$?
    printf -v args ' %q' "$@"
    RAN="irid${args}"
}

# Each range is within its own limit; their product is not. 100 000 thicknesses x 8 901 angles
# x 2 films x 2 spectra = 3 560 400 000 spectra, against 10^9 film evaluations / 471 wavelengths
# = 2 123 142 spectra.
run_bounded film-error --thickness 0:99999:1 --angles 0:89:0.01
expect_usage_error "--thickness 0:99999:1 (100 000 values)" "--angles 0:89:0.01 (8 901 values)" \
    "asks for 3 560 400 000 spectra" "the limit is 2 123 142"
run_bounded film-error --model cycles --thickness 0:99999:1 --angles 0:89:0.01
expect_usage_error "--film grid (16 films)" "the exact model (1 spectrum per sample)" "the limit is 2 123 142"
run_bounded film-error --film soap --thickness 0:99999:1 --angles 0:89:0.01
expect_usage_error "asks for 1 780 200 000 spectra" "the limit is 2 123 142"
# 1 000 001 thicknesses x 9 angles = 9 000 009 lines (2.2 GB), against 10^6 lines; no file.
rm -rf "$TMP/dir" && mkdir "$TMP/dir"
run_bounded film-table --layer water --thickness 0:1e6:1 --angles 0:8:1 -o "$TMP/dir/big.csv"
expect_usage_error "--thickness 0:1e6:1 (1 000 001 values)" "--angles 0:8:1 (9 values)" \
    "asks for 9 000 009 lines of output" "the limit is 1 000 000"
RAN="ls -A (the -o folder after the refused run)"
listing=$(ls -A "$TMP/dir")
if [[ -z $listing ]]; then pass; else fail "an empty folder" "$(show "$listing")"; fi
# The Morpho blend costs 101 evaluations per wavelength: 10^9 / (471 x 101) = 21 021 spectra.
run_bounded film-table --model morpho --blend --angles 0:89:0.001
expect_usage_error "--angles 0:89:0.001 (89 001 values)" "asks for 89 001 spectra" \
    "the limit is 21 021 with --blend (101 samples per wavelength)"
# Wavelengths x layers of the transfer matrix: 200 001 x 1 000 = 200 001 000 > 2 x 10^8.
layers=()
for _ in $(seq 1000); do layers+=(--layer 1.5:100); done
run_bounded film "${layers[@]}" --wavelengths 200:2000:0.009
RAN="irid film --layer 1.5:100 (1000 times) --wavelengths 200:2000:0.009"
expect_usage_error "--wavelengths 200:2000:0.009 (200 001 values)" "--layer (1 000 layers)" \
    "asks for 200 001 000 layer evaluations" "the limit is 200 000 000"
# ... while the same stack at 1 801 wavelengths (1 801 000 evaluations) runs.
run_bounded film "${layers[@]}" --wavelengths 200:2000:1
RAN="irid film --layer 1.5:100 (1000 times) --wavelengths 200:2000:1"
expect_rows 'w[1] = 199 + i' 1e-9 1801
# The commands of the README, docs/OPTICS.md and scripts/demo stay within the limits.
run_bounded film-table --layer water --thickness 0:1500:4 --angles 0:80:10
expect_rows 'w[3] = cos($2 * pi / 180)' 1e-12 3384
run_bounded film-table --layer mineral-oil --substrate water --thickness 0:1500:2 --angles 0:80:2
expect_rows 'w[3] = cos($2 * pi / 180)' 1e-12 30791
run_bounded film-table --model morpho --K 0.0118 --angles 0:75:15
expect_rows 'w[2] = 15 * (i - 1)' 1e-12 6
run_bounded film-error --thickness 0:1500:10 --angles 0:80:20
expect_stdout_matches '^samples 755 '
run_bounded film-error --film soap --K 1 --angles 0:80:10
expect_stdout_matches '^samples 2709 '

# ===========================================================================================

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
