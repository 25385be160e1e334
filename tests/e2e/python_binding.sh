#!/bin/sh
# The Python binding (python/glscene over libglscene.so) under
# /usr/bin/python3: tests/py/check_python.py, and the README's Python
# example (README "Use it from Python") runs as written.  Prints "ok NAME"
# / "FAIL NAME: why".
B=${GLS_BIN:-build}
PY=/usr/bin/python3
# an ASan-built libglscene.so cannot be loaded into python (the sanitizer
# runtime must come first); the C API's test (test_glscene) covers it there
[ "$GLS_SANITIZED" = 1 ] && exit 0
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
PYTHONDONTWRITEBYTECODE=1 $PY tests/py/check_python.py "$B" "$t" 2>"$t/err" || echo "FAIL python_binding: $(tail -5 "$t/err")"
