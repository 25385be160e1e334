#!/bin/sh
# suite: long (tests/run.sh starts it first, so that it does not run alone at the end)
# Every command in README.md and in the guides of docs/ runs as written in
# a fresh copy of the repository after `make demo`, and leaves that
# checkout clean: outputs go only under out/ and build/, which git
# ignores.  Also `make demo` is incremental: a second run renders nothing,
# and touching one camera file renders again only the scene that camera
# belongs to.  Samples of output marked <!-- sample: COMMAND --> in
# README.md, docs/ and spec/ are what their commands print in that copy
# (tools/md_samples.sh --check).  Prints "ok NAME" / "FAIL NAME: why".
#
# The commands: the lines of a file's indented code blocks whose first
# line starts with "build/", "make " or "parallel ", and in README.md also
# "cc " (its C example's build; docs/api.md's and docs/install.md's cc
# lines need `make install`, which install.sh runs) (a trailing backslash
# joins the next line), in order; README.md's first, whose first
# is `make demo`, then each guide's of GUIDES in that order (a guide's
# commands may read what the README's and the guides before it wrote).
# `make test` is not run: it is the suite this script belongs to.  A file
# of docs/ with commands that is not in GUIDES fails
# (docs_commands_all_run), so that no guide's commands go untested.
# The copy: the files git tracks or would track (not ignored) in this
# checkout, as they are now, in a new git repository under mktemp -d, with
# $GLS_BIN copied as its build/ (timestamps kept: make rebuilds nothing).
# Nothing is written in this checkout.
. tests/e2e/lib.sh
# Under the sanitizers (CI's second pass, GLS_SANITIZED=1) the same
# commands would only take minutes longer: they run once, on the normal build.
[ "$GLS_SANITIZED" = 1 ] && exit 0
need readme_commands glsc glsdis glsplay glsroad scenelib.glsb
command -v git >/dev/null || { fail readme_commands "no git"; exit 0; }
repo=$t/repo
mkdir "$repo"
git ls-files -z --cached --others --exclude-standard |
    tar --null -T - --ignore-failed-read -cf - 2>/dev/null | tar -xf - -C "$repo" || { fail readme_copy "tar"; exit 0; }
cp -a "$B/." "$repo/build/" 2>/dev/null || { fail readme_copy "cannot copy $B"; exit 0; }
rm -f "$repo/build/test.log"
(cd "$repo" && git init -q && git add -A && git -c user.name=readme -c user.email=readme@localhost commit -qm copy) ||
    { fail readme_copy "git"; exit 0; }
# the commands see the environment a user has, not this suite's make
unset MAKEFLAGS MFLAGS MAKELEVEL B GLS_BIN

# ---- the README is a front door (issue 29): at most 300 lines; the rest
# is in the guides of docs/
n=$(wc -l <README.md)
[ "$n" -le 300 ] && ok readme_at_most_300_lines || fail readme_at_most_300_lines "README.md has $n lines"

# ---- the commands ----------------------------------------------------------------
GUIDES="docs/scenes.md docs/outputs.md docs/antialiasing.md docs/effects.md docs/roads.md docs/cluster.md"
# commands FILE: its commands, one a line
commands() {
    awk -v readme=$([ "$1" = README.md ] && echo 1) '
        /^    / && (blank || inblock) {
            if (!inblock) { inblock = 1; cmds = ($0 ~ /^    (build\/|make |parallel )/ || (readme && $0 ~ /^    cc /)) }
            if (cmds) {
                line = substr($0, 5)
                if (line ~ /\\$/) { acc = acc substr(line, 1, length(line) - 1); next }
                sub(/^ +/, "", line)
                print acc line
                acc = ""
            }
            blank = 0; next
        }
        { inblock = 0; blank = ($0 ~ /^[ \t]*$/) }
        BEGIN { blank = 1 }' "$1"
}
commands README.md >"$t/commands"
n=$(wc -l <"$t/commands")
[ "$n" -ge 10 ] && [ "$(head -1 "$t/commands" | cut -c1-9)" = "make demo" ] && ok readme_commands_found ||
    fail readme_commands_found "$n commands, the first '$(head -1 "$t/commands")' (want make demo first, and at least 10)"
unlisted=""
for f in docs/*.md; do
    case " $GUIDES " in *" $f "*) continue ;; esac
    commands "$f" >"$t/c"
    [ -s "$t/c" ] && unlisted="$unlisted $f"
done
[ -z "$unlisted" ] && ok docs_commands_all_run || fail docs_commands_all_run "commands in$unlisted, which GUIDES does not list"
# run NAME FILE: each command of FILE in the copy, "ok NAME_I" each
run() {
    i=0
    while IFS= read -r cmd; do
        i=$((i + 1))
        case "$cmd" in "make test"*) continue ;; esac
        echo "# $2 command $i: $cmd"
        if (cd "$repo" && timeout 600 sh -c "$cmd") >"$t/out" 2>&1 </dev/null; then
            ok "${1}_$i"
        else
            fail "${1}_$i" "'$cmd' failed: $(tail -3 "$t/out" | tr '\n' ' ')"
        fi
    done
}
run readme_command README.md <"$t/commands"
for f in $GUIDES; do
    commands "$f" >"$t/commands"
    name=docs_command_$(basename "$f" .md)
    [ -s "$t/commands" ] && ok "${name}_found" || fail "${name}_found" "no commands in $f"
    run "$name" "$f" <"$t/commands"
done
# ---- samples of output: each block marked <!-- sample: COMMAND --> in the
# README, docs/ and spec/ is what COMMAND prints now (tools/md_samples.sh);
# the README's --explain sample is one, and a stale sample is caught
if (cd "$repo" && sh tools/md_samples.sh --check README.md docs/*.md spec/*.md) >"$t/samples" 2>&1; then
    ok docs_samples_match_their_commands
else
    fail docs_samples_match_their_commands "$(head -12 "$t/samples")"
fi
(cd "$repo" && sh tools/md_samples.sh --list README.md) | grep -q -- ' --explain ' && ok docs_samples_explain_marked ||
    fail docs_samples_explain_marked "README.md has no sample of --explain"
sed 's/unique geometry [0-9.]* KiB/unique geometry 0.1 KiB/' "$repo/README.md" >"$t/stale.md"
cmp -s "$repo/README.md" "$t/stale.md" && fail docs_samples_stale_caught "the sed changed nothing"
(cd "$repo" && sh tools/md_samples.sh --check "$t/stale.md") >"$t/samples" 2>&1
if [ $? -eq 1 ] && grep -q "^$t/stale.md:[0-9]*: the sample differs" "$t/samples" && grep -q '^-.*unique geometry 0.1 KiB' "$t/samples" &&
    (cd "$repo" && sh tools/md_samples.sh --write "$t/stale.md") && cmp -s "$repo/README.md" "$t/stale.md"; then
    ok docs_samples_stale_caught
else
    fail docs_samples_stale_caught "--check passed a stale sample, or --write did not restore it: $(head -5 "$t/samples")"
fi
st=$(cd "$repo" && git status --porcelain)
[ -z "$st" ] && ok readme_commands_leave_checkout_clean ||
    fail readme_commands_leave_checkout_clean "untracked or changed: $(echo "$st" | tr '\n' ' ')"

# ---- the user's make targets write nothing tracked ----------------------------------
# make demo and make demo-road (README) write only under out/ and build/:
# what make -n shows them run names no docs/ path (the committed images
# are the maintainer's gallery-* targets'; demo-road rewrote
# docs/road_strip.png)
for tgt in demo demo-road; do
    name=make_$(echo $tgt | tr - _)_writes_no_docs
    (cd "$repo" && make -n $tgt) >"$t/n" 2>&1
    if grep -Eq '(^|[ ="/])docs(/|$| )' "$t/n"; then
        fail "$name" "$(grep -E '(^|[ ="/])docs(/|$| )' "$t/n" | head -3 | tr '\n' ' ')"
    elif grep -q 'render\.sh' "$t/n" || [ $tgt = demo ]; then
        ok "$name"
    else
        fail "$name" "make -n $tgt shows no render: $(head -5 "$t/n" | tr '\n' ' ')"
    fi
done

# ---- make demo is incremental ------------------------------------------------------
RENDERS='glsplay|render\.sh|/glsc |depth2png|pnghalf'
(cd "$repo" && make -n demo) >"$t/n" 2>&1
grep -Eq "$RENDERS" "$t/n" && fail demo_second_run_renders_nothing "$(grep -E "$RENDERS" "$t/n" | head -3)" ||
    ok demo_second_run_renders_nothing
# one camera file of one example: exactly that example again
touch "$repo/examples/stereo/bino_left.cam"
(cd "$repo" && make -n demo) >"$t/n" 2>&1
if [ "$(grep -E "$RENDERS" "$t/n")" = "EXAMPLES_ONLY=stereo sh examples/render.sh build out out/gallery" ]; then
    ok demo_camera_touch_plans_its_render
else
    fail demo_camera_touch_plans_its_render "make -n demo: $(grep -E "$RENDERS" "$t/n" | tr '\n' ' ')"
fi
touch "$t/mark"
sleep 1
(cd "$repo" && make demo) >"$t/out" 2>&1 || fail demo_camera_touch_rerenders "make demo: $(tail -3 "$t/out")"
new=$(cd "$repo" && find out -type f -newer "$t/mark" | sort)
other=$(echo "$new" | grep -v -e '^out/stereo/' -e '^out/gallery/ex_stereo')
if echo "$new" | grep -q '^out/stereo/bino_left/image_000000.png$' && [ -z "$other" ]; then
    ok demo_camera_touch_rerenders_only_its_scene
else
    fail demo_camera_touch_rerenders_only_its_scene "rewritten: $(echo "$new" | tr '\n' ' ')"
fi
# the demo's own camera: the demo render only
touch "$repo/examples/demo/left.cam"
(cd "$repo" && make -n demo) >"$t/n" 2>&1
want="build/glsplay build/demo.glsb --camera examples/demo/left.cam --camera examples/demo/right.cam --camera examples/demo/left_sensor.cam --aa 4 --background 0.55,0.7,0.9 -o out/demo
build/depth2png out/demo/left/depth_000000.pfm out/demo/left/depth_000000_view.png"
[ "$(grep -E "$RENDERS" "$t/n")" = "$want" ] && ok demo_camera_touch_plans_demo_render ||
    fail demo_camera_touch_plans_demo_render "make -n demo: $(grep -E "$RENDERS" "$t/n" | tr '\n' ' ')"
