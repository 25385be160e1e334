#!/bin/sh
# The Python binding (python/glscene over libglscene.so) under
# /usr/bin/python3: tests/py/check_python.py, and the README's Python
# example (README "Use it from Python") runs as written.  Prints "ok NAME"
# / "FAIL NAME: why".
. tests/e2e/lib.sh
# an ASan-built libglscene.so cannot be loaded into python (the sanitizer
# runtime must come first); the C API's test (test_glscene) covers it there
[ "$GLS_SANITIZED" = 1 ] && exit 0
PYTHONDONTWRITEBYTECODE=1 $PY tests/py/check_python.py "$B" "$t" 2>"$t/err" || echo "FAIL python_binding: $(tail -5 "$t/err")"

# README "Use it from Python": its python block, run as the README says
# (repository root after make, PYTHONPATH=python), in a directory that
# has the checkout's examples/ and build/, so that out/ is written there
awk '/^## Use it from Python/ { sec = 1 } sec && /^```python/ { on = 1; next } on && /^```/ { exit } on' README.md \
    >"$t/example.py"
mkdir "$t/root"
ln -s "$(pwd)/examples" "$t/root/examples"
ln -s "$(cd "$B" && pwd)" "$t/root/build"
want=$(sed -n 's/^It prints `\(.*\)`: the image.*/\1/p' README.md)
lib=$(cd "$B" && pwd)/libglscene.so.0
got=$(cd "$t/root" && GLSCENE_LIBRARY=$lib PYTHONDONTWRITEBYTECODE=1 PYTHONPATH="$OLDPWD/python" $PY "$t/example.py" 2>&1)
if [ "$(wc -l <"$t/example.py")" -eq 5 ] && [ -n "$want" ] && [ "$got" = "$want" ]; then
    echo "ok readme_python_example"
else
    echo "FAIL readme_python_example: $(wc -l <"$t/example.py") lines; printed '$got', the README says '$want'"
fi
