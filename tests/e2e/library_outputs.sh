#!/bin/sh
# suite: long (tests/run.sh starts it first, so that it does not run alone at the end)
# libglscene renders every output glsplay writes, with the same values
# (docs/api.md "Every output as arrays"): tests/py/check_library_outputs.py
# renders the same inputs with glsplay and with the library
# (glscene_play_render) and compares every file, decoded, with the
# library's array.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
# an ASan-built libglscene.so cannot be loaded into python (python_binding.sh)
[ "$GLS_SANITIZED" = 1 ] && exit 0
PYTHONDONTWRITEBYTECODE=1 $PY tests/py/check_library_outputs.py "$B" "$t" 2>"$t/err" ||
    echo "FAIL library_outputs: $(tail -5 "$t/err")"
