#!/bin/sh
# docs/python.md runs as written: its python blocks, in order, as one
# session, from a directory that has the checkout's examples/ and build/
# (as the repository root after make), with PYTHONPATH=python.  Each
# example checks what it says (asserts: disparity against fx B / Z, boxes
# against the instance image, flow against the camera model, a lens's
# landmarks against cv2.projectPoints); the first prints what the guide
# says it prints.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
# an ASan-built libglscene.so cannot be loaded into python (python_binding.sh)
[ "$GLS_SANITIZED" = 1 ] && exit 0
awk '/^```python/ { on = 1; n++; print "# block " n; next } on && /^```/ { on = 0; next } on' docs/python.md \
    >"$t/guide.py"
blocks=$(grep -c '^```python' docs/python.md)
mkdir "$t/root"
ln -s "$(pwd)/examples" "$t/root/examples"
ln -s "$(cd "$B" && pwd)" "$t/root/build"
lib=$(cd "$B" && pwd)/libglscene.so.0
if (cd "$t/root" && GLSCENE_LIBRARY=$lib PYTHONDONTWRITEBYTECODE=1 PYTHONPATH="$OLDPWD/python" \
    $PY "$t/guide.py") >"$t/out" 2>"$t/err"; then
    ok python_guide_runs
else
    fail python_guide_runs "$(tail -5 "$t/err")"
fi
want=$(sed -n 's/^It prints `\(.*\)`\. .*/\1/p' docs/python.md | head -1)
got=$(head -1 "$t/out")
[ -n "$want" ] && [ "$got" = "$want" ] && ok python_guide_first_print ||
    fail python_guide_first_print "printed '$got', the guide says '$want'"
[ "$blocks" -ge 6 ] && ok python_guide_has_examples || fail python_guide_has_examples "$blocks python blocks"
