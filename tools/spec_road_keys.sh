#!/bin/sh
# usage: sh tools/spec_road_keys.sh --check|--write GLSROAD [SPEC]
# spec/road.md's tables of keys are generated from the parser's table
# (roads/road_keys.c) by `GLSROAD --list-keys`, which writes each between
# "<!-- keys: SECTION -->" and "<!-- end of keys -->".  --write replaces
# each such block of SPEC (default spec/road.md) with the generated one
# (`make spec-road-keys`); --check only compares, printing a diff and
# exiting 1 if they differ (tests/e2e/road_keys.sh).  Exit 2: cannot run.
mode=$1 R=$2 spec=${3:-spec/road.md}
case "$mode" in --check | --write) ;; *) echo "usage: sh $0 --check|--write GLSROAD [SPEC]" >&2; exit 2 ;; esac
t=$(mktemp -d) && trap 'rm -rf "$t"' EXIT || exit 2
"$R" --list-keys >"$t/keys" || exit 2
# every block of the spec replaced by the generated block of its section;
# a section the spec lacks or the generator does not know is an error
awk -v keys="$t/keys" '
BEGIN {
    while ((getline l <keys) > 0) {
        if (l ~ /^<!-- keys: /) name = l
        if (name != "") blk[name] = blk[name] l "\n"
        if (l == "<!-- end of keys -->") name = ""
    }
}
/^<!-- keys: / {
    if (!($0 in blk)) { print "spec_road_keys: error: " $0 " is no section of --list-keys" | "cat 1>&2"; bad = 1; print; next }
    printf "%s", blk[$0]; seen[$0] = 1; skip = 1; next
}
skip { if ($0 == "<!-- end of keys -->") skip = 0; next }
{ print }
END {
    for (b in blk) if (!(b in seen)) { print "spec_road_keys: error: the spec has no block " b | "cat 1>&2"; bad = 1 }
    exit bad
}' "$spec" >"$t/spec" || exit 1
if [ "$mode" = --check ]; then
    diff -u "$spec" "$t/spec" && exit 0
    echo "spec_road_keys: $spec's key tables differ from $R --list-keys (make spec-road-keys)" >&2
    exit 1
fi
cmp -s "$spec" "$t/spec" || cp "$t/spec" "$spec"
