#!/bin/sh
# spec/road.md's tables of keys are the parser's: glsroad --list-keys
# writes them from the table the parser reads (roads/road_keys.c), and the
# spec must hold exactly that text (tools/spec_road_keys.sh, make
# spec-road-keys).  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
R=$B/glsroad
[ -x "$R" ] || { fail road_keys "no $R"; exit 0; }

if sh tools/spec_road_keys.sh --check "$R" spec/road.md >"$t/diff" 2>&1; then ok road_keys_spec_matches
else fail road_keys_spec_matches "spec/road.md's key tables are not glsroad --list-keys' (make spec-road-keys): $(head -20 "$t/diff")"; fi

# the check sees a changed row, a missing table and an unknown one
sed 's/^| `lanes` | 1\.\.16 |/| `lanes` | 1..8 |/' spec/road.md >"$t/row.md"
cmp -s spec/road.md "$t/row.md" && fail road_keys_check_row "the sed found no 'lanes' row"
if sh tools/spec_road_keys.sh --check "$R" "$t/row.md" >"$t/out" 2>&1; then fail road_keys_check_row "a changed row passes"
elif grep -q '^-| `lanes` | 1\.\.8 |' "$t/out"; then ok road_keys_check_row
else fail road_keys_check_row "no diff of the row: $(head -5 "$t/out")"; fi
awk '/^<!-- keys: motion -->/ { skip = 1 } !skip { print } /^<!-- end of keys -->/ { skip = 0 }' spec/road.md >"$t/missing.md"
sh tools/spec_road_keys.sh --check "$R" "$t/missing.md" >/dev/null 2>"$t/err" &&
    fail road_keys_check_missing "a missing table passes" ||
    { grep -q "the spec has no block <!-- keys: motion -->" "$t/err" && ok road_keys_check_missing ||
        fail road_keys_check_missing "$(cat "$t/err")"; }

# --write puts the tables back
cp "$t/row.md" "$t/write.md"
if sh tools/spec_road_keys.sh --write "$R" "$t/write.md" && cmp -s spec/road.md "$t/write.md"; then ok road_keys_write
else fail road_keys_write "--write did not restore spec/road.md's tables"; fi

# every key listed is one the parser knows: alone on a line it is never
# an unknown key (it may lack values)
"$R" --list-keys | sed -n 's/^| `\([a-z_]*\)` |.*/\1/p' >"$t/keys"
n=$(wc -l <"$t/keys")
bad=""
while read -r k; do
    printf '%s\n' "$k" >"$t/one.road"
    "$R" "$t/one.road" -o "$t/o" 2>"$t/err" >/dev/null
    grep -q "unknown key" "$t/err" && bad="$bad $k"
done <"$t/keys"
[ "$n" -ge 40 ] && [ -z "$bad" ] && ok road_keys_known_to_parser || fail road_keys_known_to_parser "$n keys; unknown:$bad"
