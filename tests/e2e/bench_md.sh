#!/bin/sh
# sanitizers: not rerun (it checks the sources, the docs or the build, and runs no tool on an input)
# The measured figures live in docs/benchmarks.md (issue 29): every
# `make bench-NAME` writes its output into the block after
# <!-- bench: NAME --> there (tools/bench_md.sh), and no benchmark writes
# figures elsewhere under docs/ (the plot docs/aa_cost.svg is an image the
# document shows).  tools/bench_md.sh --write replaces exactly its block.
# Runs no benchmark.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
doc=docs/benchmarks.md
targets=$(sed -n 's/^\(bench-[a-z]*\):.*/\1/p' Makefile)
[ -n "$targets" ] || fail bench_md_targets "no bench-* targets in the Makefile"
for tg in $targets; do
    n=${tg#bench-}
    # the target's recipe: the lines after its rule up to the next blank or rule line
    recipe=$(awk -v t="$tg:" 'index($0, t) == 1 { on = 1; next } on && /^\t/ { print; next } { on = 0 }' Makefile)
    if ! grep -qx "<!-- bench: $n -->" "$doc"; then
        fail "bench_md_block_$n" "$doc has no <!-- bench: $n --> block"
    elif ! echo "$recipe" | grep -q "BENCH_MD) $n \$(B)/bench/$n.txt"; then
        fail "bench_md_block_$n" "make $tg does not write its block: $(echo "$recipe" | tr '\n' ' ')"
    else
        ok "bench_md_block_$n"
    fi
done
# the scripts write their output under the build directory, not docs/
bad=$(grep -n '^[^#]*\(>\|cp .*\|OUT=\|out=\)[^#]*docs/[a-z_]*\.txt' bench/*.sh)
[ -z "$bad" ] && ok bench_md_no_docs_txt || fail bench_md_no_docs_txt "$bad"
ls docs/*.txt >/dev/null 2>&1 && fail bench_md_no_docs_txt_files "$(ls docs/*.txt | tr '\n' ' ')" || ok bench_md_no_docs_txt_files

# --write replaces exactly its block, --print reads it back
cp "$doc" "$t/b.md"
printf 'machine: test\n| a | b |\n' >"$t/run.txt"
if BENCH_MD=$t/b.md sh tools/bench_md.sh --write scaling "$t/run.txt" &&
    [ "$(BENCH_MD=$t/b.md sh tools/bench_md.sh --print scaling)" = "$(cat "$t/run.txt")" ] &&
    [ "$(BENCH_MD=$t/b.md sh tools/bench_md.sh --print aa)" = "$(sh tools/bench_md.sh --print aa)" ]; then
    ok bench_md_write_print
else
    fail bench_md_write_print "--write/--print did not round-trip"
fi
# the rest of the document is unchanged: writing the old block back restores it
sh tools/bench_md.sh --print scaling >"$t/old.txt"
BENCH_MD=$t/b.md sh tools/bench_md.sh --write scaling "$t/old.txt" && cmp -s "$doc" "$t/b.md" && ok bench_md_write_only_its_block ||
    fail bench_md_write_only_its_block "$(diff "$doc" "$t/b.md" | head -5 | tr '\n' ' ')"
BENCH_MD=$t/b.md sh tools/bench_md.sh --write nosuch "$t/run.txt" 2>"$t/err"
[ $? -eq 1 ] && grep -q "has no line '<!-- bench: nosuch -->'" "$t/err" && ok bench_md_unknown_name ||
    fail bench_md_unknown_name "$(cat "$t/err")"
sh tools/bench_md.sh --write 2>/dev/null
[ $? -eq 2 ] && ok bench_md_usage || fail bench_md_usage "no usage status"
