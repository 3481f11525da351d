#!/usr/bin/env bash
# Runs a command and checks its exit code and that its output (stdout + stderr) matches a regex.
# For error cases it also checks that the error is a single line.
#   expect_error.sh CODE REGEX -- COMMAND ARGS...
set -u
code=$1 regex=$2
shift 3
out=$("$@" 2>&1 </dev/null)
rc=$?
if [[ $rc -ne $code ]]; then
  printf 'expected exit code %s, got %s\noutput:\n%s\n' "$code" "$rc" "$out"; exit 1
fi
if ! grep -qE -- "$regex" <<<"$out"; then
  printf 'output does not match /%s/:\n%s\n' "$regex" "$out"; exit 1
fi
if [[ $code -eq 2 ]]; then
  # exactly one error line, and nothing after it (a multi-line message would continue there)
  n=$(grep -c '^abrade: error: ' <<<"$out")
  [[ $n -eq 1 ]] || { printf 'expected one error line, got %s:\n%s\n' "$n" "$out"; exit 1; }
  [[ $(tail -n 1 <<<"$out") == "abrade: error: "* ]] || { printf 'error message spans several lines:\n%s\n' "$out"; exit 1; }
fi
echo "ok: exit code $rc, output matches /$regex/"
