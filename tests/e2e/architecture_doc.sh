#!/bin/sh
# sanitizers: not rerun (it checks the sources, the docs or the build, and runs no tool on an input)
# docs/ARCHITECTURE.md stays true as the code changes (issue 12): every
# source, header, script or spec file it names in backquotes (`name.c`,
# `runtime/render/render.c`, `spec/bundle.md`, ...) exists in the tree, by its
# path when it gives one, else by its name (gen/...: generated, in the
# build directory).  Prints "ok NAME" /
# "FAIL NAME: why".
. tests/e2e/lib.sh
doc=docs/ARCHITECTURE.md
[ -f "$doc" ] || { fail architecture_doc_files "no $doc"; exit 0; }
grep -o '`[A-Za-z0-9_./-]*\.\(c\|h\|re\|y\|sh\|py\|md\)`' "$doc" | tr -d '`' | sort -u >"$t/named"
missing=""
n=0
while read -r f; do
    n=$((n + 1))
    case $f in
    gen/*) [ -e "$B/$f" ] || missing="$missing $f" ;; # generated into the build
    */*) [ -e "$f" ] || missing="$missing $f" ;;
    *) [ -n "$(git ls-files "*/$f" "$f" 2>/dev/null | head -1)" ] || missing="$missing $f" ;;
    esac
done <"$t/named"
if [ "$n" -lt 20 ]; then
    fail architecture_doc_files "only $n file names found in $doc"
elif [ -n "$missing" ]; then
    fail architecture_doc_files "$doc names files that do not exist:$missing"
else
    ok architecture_doc_files
fi
