#!/bin/sh
# sanitizers: not rerun (it checks the sources, the docs or the build, and runs no tool on an input)
# Files stay small and functions short, or say why (docs/ARCHITECTURE.md
# "Sizes", issue 27 item 6): a source file of the layers (base, format,
# compiler, runtime's rooms, lib, roads) over 500 lines has "Over 500
# lines because" in its head comment, and a function over 100 lines (from
# its first line, one that starts with a letter and holds '(', to the next
# line that is exactly '}') has "Over 100 lines because" in the comment
# just above it.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
files=$(ls base/*.c format/*.c compiler/*.c runtime/*/*.c lib/*.c roads/*.c 2>/dev/null)
[ -n "$files" ] || { fail code_size_files_say_why "no sources found (run from the repository root)"; exit 0; }

# long_files FILE...: those over 500 lines whose head comment (the one
# the file starts with) does not say why, as "FILE(LINES)"
long_files() {
    for lf_f; do
        lf_n=$(wc -l <"$lf_f")
        [ "$lf_n" -gt 500 ] || continue
        awk 'NR == 1 && !/^\/\*/ { exit 1 }
             /Over 500 lines because/ { found = 1; exit }
             /\*\// { exit }
             END { exit !found }' "$lf_f" || echo "$lf_f($lf_n)"
    done
}

# long_functions FILE...: the functions over 100 lines without the reason
# in the comment that ends on the line above them, one a line
long_functions() {
    for lfn_f; do
        awk -v F="$lfn_f" '
            /^\/\*/ { incom = 1; text = "" }
            incom { text = text $0 }
            incom && /\*\// { incom = 0; cend = NR; ctext = text }
            /^[A-Za-z].*\(/ && !infn {
                start = NR; sig = $0; why = cend == NR - 1 && ctext ~ /Over 100 lines because/
            }
            /^\{/ && start { infn = 1 }
            /^}$/ && infn {
                if (NR - start + 1 > 100 && !why)
                    print F ":" start ": " NR - start + 1 " lines: " sig
                infn = 0; start = 0
            }' "$lfn_f"
    done
}

long=$(long_files $files | tr '\n' ' ')
[ -z "$long" ] && ok code_size_files_say_why ||
    fail code_size_files_say_why "over 500 lines, no 'Over 500 lines because' in the head comment: $long"

long_functions $files >"$t/long"
if [ -s "$t/long" ]; then
    fail code_size_functions_say_why "over 100 lines, no 'Over 100 lines because' above: $(tr '\n' ';' <"$t/long")"
else
    ok code_size_functions_say_why
fi

# the checks find what they should, on made-up files: a function of 101
# lines without a reason and the same with one; 501 lines with and
# without a head comment that says why
body() {
    echo 'int f(void)'
    echo '{'
    i=0
    while [ $i -lt "$1" ]; do echo '    g();'; i=$((i + 1)); done
    echo '}'
}
{ echo '/* a helper */'; body 98; } >"$t/long.c"
{ echo '/* a helper.  Over 100 lines because it is a test */'; body 98; } >"$t/why.c"
{ echo '/* a helper */'; body 97; } >"$t/short.c"
got=$(long_functions "$t/long.c" "$t/why.c" "$t/short.c" | sed "s|$t/||g" | tr '\n' ';')
[ "$got" = "long.c:2: 101 lines: int f(void);" ] && ok code_size_functions_found ||
    fail code_size_functions_found "want only long.c's 101-line f, got '$got'"
{ echo '/* a file */'; body 497; } >"$t/big.c"
{ echo '/* a file.'; echo ' * Over 500 lines because it is a test. */'; body 496; } >"$t/bigwhy.c"
got=$(long_files "$t/big.c" "$t/bigwhy.c" "$t/short.c" | sed "s|$t/||g" | tr '\n' ';')
[ "$got" = "big.c(501);" ] && ok code_size_files_found || fail code_size_files_found "want only big.c(501), got '$got'"
