#!/bin/sh
# Every installed tool answers --version with "TOOL VERSION" on standard
# output and exit status 0, VERSION being include/glscene.h's
# GLSCENE_VERSION (the one place it is written; the Makefile passes it to
# base/usage.c), also among other arguments; its --help and man page list
# --version.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
want=$(sed -n 's/^#define GLSCENE_VERSION "\(.*\)"$/\1/p' include/glscene.h)
[ -n "$want" ] || { fail version "no GLSCENE_VERSION in include/glscene.h"; exit 0; }
for tool in glsc glsdis glsplay glsroad; do
    "$BIN/$tool" --version >"$t/out" 2>"$t/err"
    rc=$?
    if [ $rc -ne 0 ] || [ "$(cat "$t/out")" != "$tool $want" ] || [ -s "$t/err" ]; then
        fail "version_$tool" "exit $rc, stdout '$(cat "$t/out")', stderr '$(cat "$t/err")', wanted '$tool $want'"
    else ok "version_$tool"; fi
    "$BIN/$tool" --help | grep -q -- '--version' && ok "version_${tool}_help" ||
        fail "version_${tool}_help" "--help does not list --version"
    grep -q -- '^\.BR\{0,1\} \\-\\-version' "docs/man/$tool.1" && ok "version_${tool}_man" ||
        fail "version_${tool}_man" "docs/man/$tool.1 has no --version entry"
done
# --version wins over the other arguments, as --help does
"$BIN/glsc" -I nowhere --version nothing.scene >"$t/out" 2>"$t/err" && [ "$(cat "$t/out")" = "glsc $want" ] &&
    ok version_among_arguments || fail version_among_arguments "$(cat "$t/out" "$t/err")"
