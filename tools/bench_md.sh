#!/bin/sh
# The latest run of each benchmark lives in docs/benchmarks.md, in a fenced
# block right after a line
#     <!-- bench: NAME -->
# (NAME: compile, play, instances, scaling, backends, encode, distortion, gpu,
# aa, effects).  `make bench-NAME` runs bench/NAME.sh, which writes its
# output (machine, load, command, tables) to $B/bench/NAME.txt, and then
# this script puts that text in the block: the figures have one home, the
# document beside the prose that explains them (issue 29).
#
# usage: bench_md.sh --write NAME FILE   the block of NAME becomes FILE's text
#        bench_md.sh --print NAME        print the block of NAME (the last run)
# BENCH_MD names another document (the test's copy).  Exit 1 when the
# document has no block for NAME, 2 for a usage error.
doc=${BENCH_MD:-docs/benchmarks.md}
case $1 in
--write) [ $# -eq 3 ] && [ -r "$3" ] || { echo "usage: bench_md.sh --write NAME FILE (a readable file)" >&2; exit 2; } ;;
--print) [ $# -eq 2 ] || { echo "usage: bench_md.sh --print NAME" >&2; exit 2; } ;;
*) echo "usage: bench_md.sh --write NAME FILE | --print NAME" >&2; exit 2 ;;
esac
mark="<!-- bench: $2 -->"
# the block: the line after the mark opens it, the next ``` closes it
awk -v m="$mark" '$0 == m { n = NR } END { exit !n }' "$doc" || {
    echo "bench_md.sh: error: $doc has no line '$mark' followed by a \`\`\` block" >&2
    exit 1
}
if [ "$1" = --print ]; then
    awk -v m="$mark" 'on && $0 == "```" { exit } on { print } $0 == m { getline; on = 1 }' "$doc"
    exit 0
fi
tmp=$(mktemp) || exit 2
trap 'rm -f "$tmp"' EXIT
awk -v m="$mark" -v f="$3" '
    skip && $0 == "```" { skip = 0 }
    skip { next }
    { print }
    $0 == m { getline; print; while ((getline l < f) > 0) print l; skip = 1 }
' "$doc" >"$tmp" && cat "$tmp" >"$doc"
