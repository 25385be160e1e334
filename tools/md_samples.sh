#!/bin/sh
# Samples of tool output in the documentation, kept true by re-running
# them.  A sample is a fenced block (```) right after a line
#     <!-- sample: COMMAND -->
# and holds exactly what `sh -c COMMAND` prints, standard output and
# error together (the exit status is not looked at, so a sample may show
# an error).  COMMAND runs in the current directory, the repository root,
# as README commands do (after `make demo` and the commands of the README and the guides
# before it: tests/e2e/readme_commands.sh runs --check in such a copy).
#
# usage: md_samples.sh --check FILE...   exit 1 and a diff per sample that
#                                        differs from its command's output
#        md_samples.sh --write FILE...   put each command's output in its block
#        md_samples.sh --list FILE...    FILE:LINE: COMMAND for each sample
# (2: usage or a malformed sample: a sample line not followed by a block)
mode=$1
case $mode in --check | --write | --list) shift ;; *) mode= ;; esac
[ -n "$mode" ] && [ $# -gt 0 ] || { echo "usage: md_samples.sh --check|--write|--list FILE..." >&2; exit 2; }
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT
status=0
for f; do
    [ -r "$f" ] || { echo "md_samples.sh: error: cannot read $f" >&2; exit 2; }
    # LINE (of the comment) TAB END (the closing fence) TAB COMMAND
    awk -v f="$f" '
        want { if ($0 != "```") { printf "%s:%d: error: a sample comment must be followed by a ``` block\n", f, n > "/dev/stderr"; bad = 1; exit 2 }
               want = 0; inblock = 1; next }
        inblock && $0 == "```" { print n "\t" NR "\t" cmd; inblock = 0; next }
        /^<!-- sample: .* -->$/ && !inblock { n = NR; cmd = substr($0, 14, length($0) - 17); want = 1 }
        END { if (!bad && (want || inblock)) { printf "%s:%d: error: the sample block does not end\n", f, n > "/dev/stderr"; exit 2 } }
    ' "$f" >"$tmp/list" || exit 2
    : >"$tmp/outs"
    while IFS='	' read -r n end cmd; do
        if [ $mode = --list ]; then echo "$f:$n: $cmd"; continue; fi
        sh -c "$cmd" >"$tmp/out.$n" 2>&1 </dev/null
        sed -n "$((n + 2)),$((end - 1))p" "$f" >"$tmp/doc.$n"
        if [ $mode = --check ] && ! cmp -s "$tmp/doc.$n" "$tmp/out.$n"; then
            echo "$f:$n: the sample differs from what '$cmd' prints (md_samples.sh --write $f):"
            diff -u "$tmp/doc.$n" "$tmp/out.$n" | sed '1,2d'
            status=1
        fi
        echo "$n" >>"$tmp/outs"
    done <"$tmp/list"
    if [ $mode = --write ] && [ -s "$tmp/outs" ]; then
        # each block's lines replaced by its command's output
        awk -v d="$tmp" '
            skip && $0 == "```" { skip = 0 }
            skip { next }
            { print }
            n && $0 == "```" { while ((getline l < (d "/out." n)) > 0) print l; close(d "/out." n); n = 0; skip = 1 }
            /^<!-- sample: .* -->$/ { n = NR }
        ' "$f" >"$tmp/new" && { cmp -s "$tmp/new" "$f" || cat "$tmp/new" >"$f"; } || exit 2
    fi
done
exit $status
