#!/bin/sh
# sanitizers: not rerun (it checks the sources, the docs or the build, and runs no tool on an input)
# spec/camera.md "File format"'s table of keys is the parser's: the keys
# its rows name (the first column, in backquotes) are exactly those of
# runtime/camera/camera.c's key_name table (the sensor's keys have their own
# table, "Sensor effects").  A row that stands outside the table, after
# a blank line or a paragraph, is not in it, so its keys are missing.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh

# code_keys FILE: the names in FILE's key_name initialiser, one a line, sorted
code_keys() {
    awk '/key_name\[K_COUNT\] = \{/ { on = 1 } on { print } on && /\};/ { exit }' "$1" |
        grep -o '"[A-Za-z_]*"' | tr -d '"' | sort
}
# spec_keys FILE: the backquoted names in the first column of the table
# whose header is "| key | values | meaning |", up to its first line not a
# row, one a line, sorted
spec_keys() {
    awk '/^\| key +\| values +\| meaning/ { on = 1; next }
         on && !/^\|/ { exit }
         on && !/^\|-/ { split($0, c, "|"); print c[2] }' "$1" | grep -o '`[A-Za-z_]*`' | tr -d '`' | sort
}

code_keys runtime/camera/camera.c >"$t/code"
spec_keys spec/camera.md >"$t/spec"
if [ "$(wc -l <"$t/code")" -lt 15 ]; then
    fail camera_keys_spec_table "only $(wc -l <"$t/code") keys found in runtime/camera/camera.c's key_name"
elif cmp -s "$t/code" "$t/spec"; then
    ok camera_keys_spec_table
else
    fail camera_keys_spec_table "spec/camera.md's key table and runtime/camera/camera.c differ (< code, > spec): $(diff "$t/code" "$t/spec" | grep '^[<>]' | tr '\n' ' ')"
fi

# the check sees a row left outside the table (issue 26: the effects' row
# stood after the paragraph that follows the table)
awk '/^\| `shutter`, / { held = $0; next } { print } held && /^effects" below\.$/ { print held; held = "" }' \
    spec/camera.md >"$t/outside.md"
spec_keys "$t/outside.md" >"$t/spec2"
if cmp -s spec/camera.md "$t/outside.md"; then
    fail camera_keys_spec_outside_row "the awk moved no row (no '| \`shutter\`, ' row, or no 'effects\" below.' line)"
elif ! cmp -s "$t/code" "$t/spec2" && diff "$t/code" "$t/spec2" | grep -qx '< exposure_samples'; then
    ok camera_keys_spec_outside_row
else
    fail camera_keys_spec_outside_row "a row outside the table passes"
fi
