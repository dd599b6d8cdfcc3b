# Sourced by cli_test.sh and malformed_inputs.sh: the shape every failed shadowlab command
# must have.
# one_line_error_problem RC STDERR_FILE: prints what is wrong with a run that should have
# failed with exactly one stderr line "shadowlab: error: ...", or nothing.
one_line_error_problem() {
    local rc=$1 err=$2 lines
    lines=$(wc -l <"$err")
    if [ "$rc" -eq 0 ]; then echo "exited 0, expected an error"
    elif [ "$rc" -gt 128 ]; then echo "died of signal $((rc - 128))"
    elif [ "$lines" -ne 1 ]; then echo "printed $lines lines on stderr, expected 1"
    elif ! head -n 1 "$err" | grep -q "^shadowlab: error: "; then echo "stderr does not start with 'shadowlab: error: '"
    fi
}
