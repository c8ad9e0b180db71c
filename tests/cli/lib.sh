# Shared by the command-line contract tests: running irid, counting checks, reporting failures.
# Source it after setting IRID (the program under test); it makes a temporary folder $TMP
# (removed at exit) and defines run, run_file, pass, fail, outcome, expect_status and
# expect_output. Each script ends with: echo "$passed passed, $failed failed".
# shellcheck shell=bash

TMP=$(mktemp -d) || exit 2
trap 'rm -rf "$TMP"' EXIT

passed=0
failed=0
STATUS=0
RAN=

# --- running the program ------------------------------------------------------------------

# run_file FILE ARGS...: runs `irid ARGS` with FILE on stdin. Sets STATUS and RAN; stdout and
# stderr are left in $TMP/out and $TMP/err.
run_file() {
    local input=$1 args
    shift
    "$IRID" "$@" <"$input" >"$TMP/out" 2>"$TMP/err"
    STATUS=$?
    printf -v args ' %q' "$@"
    RAN="irid${args} < $input"
}

# run TEXT ARGS...: runs `irid ARGS` with TEXT (written as is, e.g. $'1,1,1\n') on stdin.
run() {
    local text=$1 args shown
    shift
    printf '%s' "$text" >"$TMP/in"
    run_file "$TMP/in" "$@"
    printf -v args ' %q' "$@"
    shown=${text@Q}
    RAN="printf '%s' ${shown} | irid${args}"
}

# --- reporting ----------------------------------------------------------------------------

# show TEXT: TEXT quoted on one line (newlines escaped), cut short when long.
show() {
    local s=${1@Q}
    ((${#s} > 240)) && s="${s:0:240}..."
    printf '%s' "$s"
}

# slurp VAR FILE: sets VAR to the exact contents of FILE, trailing newline included.
slurp() {
    local s
    s=$(cat "$2" && printf x)
    printf -v "$1" '%s' "${s%x}"
}

pass() { passed=$((passed + 1)); }

# fail EXPECTED GOT: one line naming the command that ran.
fail() {
    failed=$((failed + 1))
    printf 'FAIL: %s | expected: %s | got: %s\n' "$RAN" "$1" "$2"
}

# What came out, for messages: the status, stdout and (when there is any) stderr.
outcome() {
    local out err s
    slurp out "$TMP/out"
    slurp err "$TMP/err"
    s="status $STATUS, stdout $(show "$out")"
    [[ -n $err ]] && s+=", stderr $(show "$err")"
    printf '%s' "$s"
}

# --- checks on the last run ---------------------------------------------------------------

# expect_status N
expect_status() {
    if [[ $STATUS -eq $1 ]]; then pass; else fail "exit status $1" "$(outcome)"; fi
}

# expect_output TEXT: stdout is exactly TEXT (give the trailing newline) and the status is 0.
expect_output() {
    local got
    slurp got "$TMP/out"
    if [[ $STATUS -eq 0 && $got == "$1" ]]; then pass; else fail "status 0, stdout $(show "$1")" "$(outcome)"; fi
}

# compare_csv WANT_FILE GOT_FILE TOL: prints nothing when both files hold the same number of
# CSV lines whose fields are numbers within TOL of each other (TOL: one tolerance for every
# field, or a comma-separated tolerance per field); otherwise prints what differs.
compare_csv() {
    awk -F, -v tol="$3" '
        function abs(x) { return x < 0 ? -x : x }
        function is_number(s) { return s ~ /^-?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
        BEGIN { ntol = split(tol, t, ",") }
        NR == FNR { want[++n] = $0; next }
        { got[++m] = $0 }
        END {
            if (m != n) { printf "%d lines instead of %d", m, n; exit }
            for (i = 1; i <= n; ++i) {
                nw = split(want[i], w, ",")
                ng = split(got[i], g, ",")
                if (ng != nw) { printf "line %d has %d fields instead of %d", i, ng, nw; exit }
                for (j = 1; j <= nw; ++j) {
                    tj = (ntol == 1) ? t[1] : t[j]
                    if (!is_number(g[j])) { printf "line %d field %d (%s) is not a number", i, j, g[j]; exit }
                    if (!(abs(g[j] - w[j]) <= tj + 0)) {
                        printf "line %d field %d: %s differs from %s by %.3g", i, j, g[j], w[j], g[j] - w[j]
                        exit
                    }
                }
            }
        }' "$1" "$2"
}

# expect_bad_data LINE: exit status 1, "<stdin>:LINE:" on stderr, nothing on stdout.
expect_bad_data() {
    expect_status 1
    expect_stderr_has "<stdin>:$1:"
    expect_empty_stdout
}

# expect_close WANT TOL: status 0 and the lines after stdout's header are, field by field,
# within TOL of the lines of WANT (CSV numbers, one line per colour).
expect_close() {
    local verdict
    printf '%s\n' "$1" >"$TMP/want"
    tail -n +2 "$TMP/out" >"$TMP/data"
    verdict=$(compare_csv "$TMP/want" "$TMP/data" "$2")
    if [[ $STATUS -eq 0 && -z $verdict ]]; then
        pass
    else
        fail "values $(show "$1") within $2" "$(outcome)${verdict:+ ($verdict)}"
    fi
}

# expect_empty_stdout: a failed run prints nothing on stdout.
expect_empty_stdout() {
    if [[ ! -s $TMP/out ]]; then pass; else fail "empty stdout" "$(outcome)"; fi
}

# expect_stderr_has TEXT / expect_stdout_has TEXT: a fixed string occurs in the stream.
expect_stderr_has() {
    if grep -qF -- "$1" "$TMP/err"; then pass; else fail "stderr containing $(show "$1")" "$(outcome)"; fi
}

expect_stdout_has() {
    if grep -qF -- "$1" "$TMP/out"; then pass; else fail "stdout containing $(show "$1")" "$(outcome)"; fi
}

# expect_stderr_lacks TEXT: the fixed string does not occur on stderr.
expect_stderr_lacks() {
    if ! grep -qF -- "$1" "$TMP/err"; then pass; else fail "stderr without $(show "$1")" "$(outcome)"; fi
}
